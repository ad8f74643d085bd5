# Task: place the brown cup onto an empty plate; a plate is empty when no object's centre lies in its 2D region (x, y) on the table.
# Plan:
# 1. Define helpers: choose a grasp from the object's name, pick an object, place it onto a receptacle, list the objects over a plate.
# 2. The plates are the names with the word 'plate'; the other things are the rest, without the table, the cabinet and the cup.
# 3. A plate is empty when none of those things has its centre inside the plate's x-y box; take the first empty plate
#    (if none is, the one with the fewest objects on it).
# 4. Pick the brown cup with a level grasp across its body, place it onto that plate, release it and move up.


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


def objects_over(plate, candidates):
    box = get_3d_bbox(plate)
    inside = []
    for name in candidates:
        c = get_object_center_position(name)
        if box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4]:
            inside.append(name)
    return inside


detect_objects()
things = [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet')]
plates = [n for n in things if 'plate' in n.split('_')]
others = [n for n in things if n not in plates and n != 'brown_ceramic_cup']
empty_plates = [p for p in plates if not objects_over(p, others)]
if empty_plates:
    target_plate = empty_plates[0]
else:
    target_plate = min(plates, key=lambda p: len(objects_over(p, others)))
pick('brown_ceramic_cup')
place_into('brown_ceramic_cup', target_plate)
