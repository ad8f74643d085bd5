# Task: place the rubiks cube onto the white saucer.
# Plan:
# 1. Look at the scene.
# 2. Grasp the rubiks cube from above at its middle.
# 3. Close the gripper, attach the cube, lift it.
# 4. Look again, find a place pose on the white saucer, move there.
# 5. Release the cube and move up.

# Step 1: look at the scene.
detect_objects()

# Step 2: grasp the rubiks cube from above.
open_gripper()
grasp(grasp_pose=parse_central_lift_grasp_pose(object_name='rubiks_cube', description='center'))

# Step 3: close, attach, lift.
close_gripper()
attach_object(object_name='rubiks_cube')
move_in_direction(axis=[0, 0, 1], distance=0.1)

# Step 4: look again (everything but the held cube), then move to a place pose on the saucer.
detect_objects(object_list=[name for name in get_object_name_list() if name != 'rubiks_cube'])
move_to_pose(pose=parse_place_pose(object_name='rubiks_cube', receptacle_name='white_saucer'))

# Step 5: release and move up.
open_gripper()
detach_object(object_name='rubiks_cube')
move_in_direction(axis=[0, 0, 1], distance=0.1)
