# Task: swap the positions of the pear and the blue block.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the pear to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the blue block to where the pear was, then the pear to where the blue block was.
detect_objects()
pear_at = get_object_center_position('pear')
block_at = get_object_center_position('blue_block')


def move_object(name, position):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


move_object('pear', [pear_at[0] - 0.2, pear_at[1], pear_at[2]])
move_object('blue_block', pear_at)
move_object('pear', block_at)
