# Task: swap the positions of the red block and the lime.
# Plan:
# 1. Define helpers: choose a grasp from the object's name, pick an object, place it at a position, move an object to a position.
# 2. Remember where the red block and the lime are before anything moves.
# 3. Move the red block aside, 20 cm towards the robot, so that its place is free.
# 4. Move the lime to where the red block was, then the red block to where the lime was.


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


def move_object(name, position):
    pick(name)
    place_at(name, position)


detect_objects()
red_block_at = get_object_center_position('red_block')
lime_at = get_object_center_position('lime')
move_object('red_block', [red_block_at[0] - 0.2, red_block_at[1], red_block_at[2]])
move_object('lime', red_block_at)
move_object('red_block', lime_at)
