# Task: exchange the places of the green apple and the red box.
# Plan:
# 1. Look at the scene and remember where the green apple and the red box stand, before anything moves.
# 2. Move the green apple aside to a free spot on the table (at least 15 cm away), so its place is free.
# 3. Move the red box to where the green apple stood.
# 4. Move the green apple to where the red box stood.
#    Each move: grasp (top-down across the narrow side where it fits the gripper with margin, else the
#    adaptive grasp from above), close, attach, lift, look again, place, release, move up.


def grasp_pose_for(name):
    box = get_3d_bbox(object_name=name)
    narrow_side = min(box[3] - box[0], box[4] - box[1])
    if narrow_side < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name,
                                           preferred_position=get_object_center_position(object_name=name),
                                           preferred_approach_direction=[0, 0, -1])


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
apple_at = get_object_center_position(object_name='green_apple')
box_at = get_object_center_position(object_name='red_box')

# Step 2: the green apple aside on a free spot of the table.
move_object('green_apple', receptacle_name='table')

# Step 3: the red box to the green apple's old place.
move_object('red_box', position=[apple_at[0], apple_at[1], apple_at[2]])

# Step 4: the green apple to the red box's old place.
move_object('green_apple', position=[box_at[0], box_at[1], box_at[2]])
