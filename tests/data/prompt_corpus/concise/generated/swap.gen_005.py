# Task: swap the positions of the blue cup and the rubiks cube.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the rubiks cube to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the blue cup (grasped by its rim from above) to where the cube was, then the cube to where the cup was.
detect_objects()
cup_at = get_object_center_position('blue_cup')
cube_at = get_object_center_position('rubiks_cube')


def move_object(name, position):
    open_gripper()
    if name == 'blue_cup':
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


move_object('rubiks_cube', [cube_at[0] - 0.2, cube_at[1], cube_at[2]])
move_object('blue_cup', cube_at)
move_object('rubiks_cube', cup_at)
