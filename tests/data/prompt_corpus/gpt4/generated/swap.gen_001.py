# Task: exchange the places of the toy car and the red mug.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the toy car to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the red mug to where the toy car was, then the toy car to where the red mug was.
# 4. Grasp each from above with an adaptive grasp (the mug by its rim or handle).
detect_objects()
car_at = get_object_center_position('toy_car')
mug_at = get_object_center_position('red_mug')


def move_object(name, position):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(name, preferred_approach_direction=np.array([0, 0, -1])))
    close_gripper()
    attach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)
    move_to_pose(parse_place_pose(name, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)


temporary_spot = car_at + np.array([-0.2, 0.0, 0.0])
move_object('toy_car', temporary_spot)
move_object('red_mug', car_at)
move_object('toy_car', mug_at)
