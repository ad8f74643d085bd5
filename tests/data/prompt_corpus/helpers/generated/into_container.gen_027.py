# Task: move the wooden block into the green bowl.
# Plan:
# 1. Define helpers: choose a grasp from the object's name, pick an object, place it into a receptacle.
# 2. Pick the wooden block (a block: top-down grasp at its centre).
# 3. Place it into the green bowl, release it and move up.


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
pick('wooden_block')
place_into('wooden_block', 'green_bowl')
