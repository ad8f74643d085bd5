# Task: exchange the places of the toy car and the red mug
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the toy car to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the red mug to where the car was, then the car to where the mug was.
# 4. The car is grasped from above across its width, the mug with the adaptive grasp from above (its rim).
detect_objects()
car_at = get_object_center_position('toy_car')
mug_at = get_object_center_position('red_mug')


def move_object(name, position):
    open_gripper()
    if name == 'red_mug':
        grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    else:
        grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


move_object('toy_car', [car_at[0] - 0.2, car_at[1], car_at[2]])
move_object('red_mug', car_at)
move_object('toy_car', mug_at)
