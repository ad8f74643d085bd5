# Task: put the yellow box on the yellow plate.
# Plan:
# 1. Detect the scene.
# 2. Work out from the boxes how high to lift the yellow box so that it clears the plate.
# 3. Pick the yellow box with a top-down grasp at its middle (the best grasp of its shape if it is too
#    wide for that), lift it.
# 4. Get a place pose on the plate, move there, release, move up.

ITEM = 'yellow_box'
PLATE = 'yellow_plate'


def top(name):
    return get_3d_bbox(name)[5]


def bottom(name):
    return get_3d_bbox(name)[2]


def lift_over(name, obstacle, margin=0.05, minimum=0.1):
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
    pick(ITEM, lift_over(ITEM, PLATE))
    place(ITEM, parse_place_pose(object_name=ITEM, receptacle_name=PLATE))


main()
