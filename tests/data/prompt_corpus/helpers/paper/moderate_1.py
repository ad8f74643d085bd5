# Task: move the white mug into a container of the same colour; colours are read from the names.
# Plan:
# 1. Define helpers: choose a grasp from the object's name, pick an object, place it into a receptacle.
# 2. The containers are the plates, saucers, bowls and baskets; the mug is the name with the word 'mug'.
# 3. The mug's colour is the first word of its name ('white'); pick the container whose name starts with it
#    (white_ceramic_plate).
# 4. Pick the mug with the adaptive grasp from above (by its rim) and place it into that container.


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
things = [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet')]
containers = [n for n in things if {'plate', 'saucer', 'bowl', 'basket'} & set(n.split('_'))]
mug = [n for n in things if 'mug' in n.split('_')][0]
colour = mug.split('_')[0]
same_colour = [c for c in containers if c.split('_')[0] == colour]
pick(mug)
place_into(mug, same_colour[0])
