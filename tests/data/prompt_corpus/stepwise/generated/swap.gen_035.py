# Task: swap the positions of the red block and the white cup.
# Plan:
# 1. Look at the scene and remember where the red block and the white cup stand, before anything moves.
# 2. Move the red block aside to a free spot on the table (at least 15 cm away), so its place is free.
# 3. Move the white cup to where the red block stood.
# 4. Move the red block to where the white cup stood.
#    Each move: grasp (the block top-down at its middle; the cup with the adaptive grasp from above, by its
#    rim), close, attach, lift, look again, place, release, move up.


def grasp_pose_for(name):
    # Cups are taken from above by the adaptive grasp (rim); other small things top-down at their middle.
    if 'cup' in name or 'mug' in name:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def move_object(name, position=None, receptacle_name=None):
    open_gripper()
    grasp(grasp_pose=grasp_pose_for(name))
    close_gripper()
    attach_object(object_name=name)
    move_in_direction(axis=[0, 0, 1], distance=0.1)
    # Look again before placing (everything but the held object).
    detect_objects(object_list=[n for n in get_object_name_list() if n != name])
    move_to_pose(pose=parse_place_pose(object_name=name, receptacle_name=receptacle_name, position=position))
    open_gripper()
    detach_object(object_name=name)
    move_in_direction(axis=[0, 0, 1], distance=0.1)


# Step 1: look and remember both places.
detect_objects()
block_at = get_object_center_position(object_name='red_block')
cup_at = get_object_center_position(object_name='white_cup')

# Step 2: the red block aside on a free spot of the table.
move_object('red_block', receptacle_name='table')

# Step 3: the white cup to the red block's old place.
move_object('white_cup', position=[block_at[0], block_at[1], block_at[2]])

# Step 4: the red block to the white cup's old place.
move_object('red_block', position=[cup_at[0], cup_at[1], cup_at[2]])
