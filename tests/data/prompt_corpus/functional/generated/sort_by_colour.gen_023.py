# Task: sort the objects on the table by colour: put the yellow objects on the yellow plate.
# Plan:
# 1. Detect the scene. A thing's colour comes from its name: a leading colour word (yellow_plate), else the
#    natural colour of its kind (a lemon is yellow, an orange is orange).
# 2. The yellow objects to move are those whose colour is yellow, leaving out the table, furniture and the
#    things that stay put (plates, saucers, bowls, baskets) - the yellow plate itself among them.
#    Here that is the lemon.
# 3. For each: pick it with a top-down grasp at its middle, lift it, place it on the yellow plate, release,
#    move up.

PLATE = 'yellow_plate'
TARGET_COLOUR = 'yellow'
COLOUR_WORDS = ('red', 'green', 'blue', 'yellow', 'white', 'black', 'brown', 'pink', 'purple', 'orange',
                'grey', 'gray')
NATURAL_COLOUR = {'lemon': 'yellow', 'banana': 'yellow', 'orange': 'orange', 'strawberry': 'red',
                  'tomato': 'red', 'plum': 'purple'}
STAYING_KINDS = ('basket', 'bowl', 'plate', 'saucer')
VESSEL_KINDS = ('mug', 'cup')


def kind_of(name):
    return name.split('_')[-1]


def colour_of(name):
    words = name.split('_')
    if len(words) > 1 and words[0] in COLOUR_WORDS:
        return words[0]
    return NATURAL_COLOUR.get(name)


def is_furniture(name):
    return name == 'table' or name == 'cabinet' or name.startswith('cabinet.')


def movable(name):
    return not is_furniture(name) and kind_of(name) not in STAYING_KINDS


def of_colour(names, colour):
    return [n for n in names if movable(n) and colour_of(n) == colour]


def lift_over(name, obstacle, margin=0.05, minimum=0.1):
    return max(minimum, get_3d_bbox(obstacle)[5] - get_3d_bbox(name)[2] + margin)


def grasp_pose_for(name):
    if kind_of(name) in VESSEL_KINDS:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
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


def put_on(name, receptacle):
    pick(name, lift_over(name, receptacle))
    place(name, parse_place_pose(object_name=name, receptacle_name=receptacle))


def main():
    detect_objects()
    for name in of_colour(get_object_name_list(), TARGET_COLOUR):
        put_on(name, PLATE)


main()
