# Task: sort the objects on the table by kind: put the blocks on the green plate.
# Plan:
# 1. From the names, the only block is green_block (the rubiks_cube, the boxes, the mug, the bowl and the saucer
#    are other kinds).
# 2. Detect; the target is the middle of the green plate's box in x, y.
# 3. Grasp the block top-down at its middle, attach it, lift it (a Pose from the gripper's).
# 4. Place it on the plate at the target, release it, move up.
detect_objects()
blocks = ['green_block']
plate_box = get_3d_bbox('green_plate')
target = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]

for i, block in enumerate(blocks):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=block, description='center'))
    close_gripper()
    attach_object(block)
    lift = get_gripper_pose()
    lift.position.z += 0.1
    move_to_pose(lift)
    if i == 0:
        place_pose = parse_place_pose(object_name=block, receptacle_name='green_plate', position=target)
    else:
        place_pose = parse_place_pose(object_name=block, receptacle_name='green_plate')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(block)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)
