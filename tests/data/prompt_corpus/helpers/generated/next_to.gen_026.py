# Task: put the toy car next to the red box.
# Plan:
# 1. Define helpers: choose a grasp from the object's name, pick an object, place it at a position, find a spot beside another object.
# 2. Before anything moves, work out a spot beside the red_box: its centre shifted sideways (along y) by half of both widths plus a
#    3 cm gap, on the side where the toy_car is now.
# 3. Pick the toy car (an odd shape: adaptive grasp from above).
# 4. Place it at that spot on the table, release it and move up.


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


def place_at(name, position):
    move_to_pose(parse_place_pose(object_name=name, position=position))
    release(name)


def spot_beside(name, anchor, gap=0.03):
    anchor_box = get_3d_bbox(anchor)
    name_box = get_3d_bbox(name)
    anchor_center = get_object_center_position(anchor)
    side = 1.0 if get_object_center_position(name)[1] >= anchor_center[1] else -1.0
    offset = (anchor_box[4] - anchor_box[1]) / 2 + (name_box[4] - name_box[1]) / 2 + gap
    return [anchor_center[0], anchor_center[1] + side * offset, anchor_center[2]]


detect_objects()
target = spot_beside('toy_car', 'red_box')
pick('toy_car')
place_at('toy_car', target)
