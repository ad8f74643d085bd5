# Task: exchange the places of the green block and the white cup.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the green block to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the white cup (grasped by its rim from above) to where the block was, then the block to where the cup was.
detect_objects()
block_at = get_object_center_position('green_block')
cup_at = get_object_center_position('white_cup')


def move_object(name, position):
    open_gripper()
    if name == 'white_cup':
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


move_object('green_block', [block_at[0] - 0.2, block_at[1], block_at[2]])
move_object('white_cup', block_at)
move_object('green_block', cup_at)
