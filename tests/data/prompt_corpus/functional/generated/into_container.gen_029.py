# Task: move the medication bottle into the basket.
# Plan:
# 1. Detect the scene.
# 2. Work out from the boxes how high to lift the bottle: its bottom must clear the basket's rim.
# 3. Pick the medication bottle with a top-down grasp at its middle (the best grasp of its shape if it
#    is too wide for that), lift it.
# 4. Get a place pose inside the basket, move there, release, move up.

ITEM = 'medication_bottle'
CONTAINER = 'basket'


def top(name):
    return get_3d_bbox(name)[5]


def bottom(name):
    return get_3d_bbox(name)[2]


def lift_over(name, obstacle, margin=0.05, minimum=0.1):
    # Height to lift `name` so that its bottom clears the top of `obstacle`.
    return max(minimum, top(obstacle) - bottom(name) + margin)


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
    lift = lift_over(ITEM, CONTAINER)
    pick(ITEM, lift)
    place(ITEM, parse_place_pose(object_name=ITEM, receptacle_name=CONTAINER))


main()
