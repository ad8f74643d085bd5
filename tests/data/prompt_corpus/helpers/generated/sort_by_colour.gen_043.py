# Task: sort the objects on the table by colour: put the yellow objects on the yellow plate.
# Plan:
# 1. Define helpers: the colour a name tells (a colour word in it, else the usual colour of the thing it names),
#    a grasp chosen from the name, pick an object, place it onto a receptacle.
# 2. The objects on the table are all names except the table, the cabinet with its parts and the yellow plate itself.
# 3. The yellow ones are those whose colour is 'yellow' (the lemon: lemons are yellow; the tea box's name gives no colour).
# 4. Pick each of them and place it onto the yellow plate.
COLOUR_WORDS = {'red', 'green', 'blue', 'yellow', 'white', 'brown', 'pink', 'orange', 'black', 'purple', 'turquoise'}
USUAL_COLOUR = {'apple': 'red', 'strawberry': 'red', 'lemon': 'yellow', 'banana': 'yellow', 'lime': 'green', 'plum': 'purple'}


def colour_of(name):
    words = name.split('_')
    named = [w for w in words if w in COLOUR_WORDS]
    if named:
        return named[0]
    return USUAL_COLOUR.get(words[-1])


def grasp_pose_for(name):
    # Mugs and odd shapes: adaptive grasp from above; upright cups and bottles: level grasp; small boxes, blocks, fruit: top-down.
    words = name.split('_')
    if 'mug' in words or 'toy' in words or 'banana' in words:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    if 'cup' in words or 'bottle' in words or 'cleanser' in words:
        return parse_horizontal_grasp_pose(object_name=name)
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def release(name):
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def place_into(name, receptacle):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    release(name)


detect_objects()
things = [n for n in get_object_name_list() if n not in ('table', 'yellow_plate') and not n.startswith('cabinet')]
yellow_things = [n for n in things if colour_of(n) == 'yellow']
for name in yellow_things:
    pick(name)
    place_into(name, 'yellow_plate')
