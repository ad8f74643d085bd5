# Task: put the wooden block on the brown box.
# Plan:
# 1. Detect the scene.
# 2. Work out from the boxes how high to lift the block so that its bottom clears the brown box's top.
# 3. Pick the wooden block with a top-down grasp at its middle, lift it.
# 4. Get a place pose on top of the brown box, move there, release, move up.

ITEM = 'wooden_block'
BASE = 'brown_box'


def lift_over(name, obstacle, margin=0.05, minimum=0.1):
    return max(minimum, get_3d_bbox(obstacle)[5] - get_3d_bbox(name)[2] + margin)


def grasp_pose_for(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place(name, pose, retreat=0.1):
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


def main():
    detect_objects()
    pick(ITEM, lift_over(ITEM, BASE))
    place(ITEM, parse_place_pose(object_name=ITEM, receptacle_name=BASE))


main()
