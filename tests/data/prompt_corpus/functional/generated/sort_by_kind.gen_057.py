# Task: sort the objects on the table by kind: put the boxes into the basket.
# Plan:
# 1. Detect the scene. A thing's kind is the last word of its name: the boxes are red_box and gelatin_box
#    (not the block, mug, cup, plate or saucer).
# 2. For each box: pick it with a top-down grasp at its middle (the best grasp of its shape if it is too
#    wide for that), lift it over the basket's rim, place it into the basket, release, move up.

BASKET = 'basket'
KIND = 'box'


def kind_of(name):
    return name.split('_')[-1]


def is_furniture(name):
    return name == 'table' or name == 'cabinet' or name.startswith('cabinet.')


def of_kind(names, kind):
    return [n for n in names if not is_furniture(n) and kind_of(n) == kind]


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


def put_into(name, container):
    pick(name, lift_over(name, container))
    place(name, parse_place_pose(object_name=name, receptacle_name=container))


def main():
    detect_objects()
    for name in of_kind(get_object_name_list(), KIND):
        put_into(name, BASKET)


main()
