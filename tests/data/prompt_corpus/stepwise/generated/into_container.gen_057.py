# Task: put the gelatin box into the basket.
# Plan:
# 1. Look at the scene and measure the gelatin box.
# 2. Choose a grasp: top-down across its narrow side if that side fits the gripper with margin,
#    else the adaptive grasp from above.
# 3. Grasp, close the gripper, attach the box, lift it.
# 4. Look again, find a place pose inside the basket, move there.
# 5. Release the box and move up.

# Step 1: look at the scene and measure the box.
detect_objects()
box = get_3d_bbox(object_name='gelatin_box')
narrow_side = min(box[3] - box[0], box[4] - box[1])

# Step 2: choose the grasp (the gripper opens about 8 cm).
if narrow_side < 0.07:
    grasp_pose = parse_central_lift_grasp_pose(object_name='gelatin_box', description='center')
else:
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name='gelatin_box',
                                                 preferred_position=get_object_center_position(object_name='gelatin_box'),
                                                 preferred_approach_direction=[0, 0, -1])

# Step 3: grasp, close, attach, lift.
open_gripper()
grasp(grasp_pose=grasp_pose)
close_gripper()
attach_object(object_name='gelatin_box')
move_in_direction(axis=[0, 0, 1], distance=0.12)

# Step 4: look again (everything but the held box), then move to a place pose in the basket.
detect_objects(object_list=[name for name in get_object_name_list() if name != 'gelatin_box'])
move_to_pose(pose=parse_place_pose(object_name='gelatin_box', receptacle_name='basket'))

# Step 5: release and move up.
open_gripper()
detach_object(object_name='gelatin_box')
move_in_direction(axis=[0, 0, 1], distance=0.1)
