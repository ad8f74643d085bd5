# Task: exchange the places of the brown box and the red block.
# Plan:
# 1. Detect everything; remember both centres before anything moves.
# 2. A helper moves one object: detect it anew (it may have moved), grasp it from above at its middle if its narrower
#    side fits the gripper (< 7.5 cm), else with the adaptive grasp from above; close, attach, lift, place, release, move up.
# 3. Move the brown box aside on the table (its old place stays free), then the red block to the box's old place,
#    then the box to the block's old place.
detect_objects()
box, blk = get_object_center_position('brown_box'), get_object_center_position('red_block')


def move(n, r=None, p=None):
    detect_objects([n])
    b = get_3d_bbox(n)
    open_gripper()
    grasp(parse_central_lift_grasp_pose(n, 'center') if min(b[3:5] - b[:2]) < 0.075 else parse_adaptive_shape_grasp_pose(n, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(n)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(n, r, p))
    open_gripper()
    detach_object(n)
    move_in_direction([0, 0, 1], 0.1)


move('brown_box', 'table')
move('red_block', p=box)
move('brown_box', p=blk)
