# Task: put the green block into the green bowl.
# Plan:
# 1. Look at the scene.
# 2. Open the gripper and grasp the green block from above at its middle.
# 3. Close the gripper, attach the block, lift it.
# 4. Look again, find a place pose inside the green bowl, move there.
# 5. Release the block and move up.

# Step 1: look at the scene.
detect_objects()

# Step 2: grasp the green block from above.
open_gripper()
grasp(grasp_pose=parse_central_lift_grasp_pose(object_name='green_block', description='center'))

# Step 3: close, attach, lift.
close_gripper()
attach_object(object_name='green_block')
move_in_direction(axis=[0, 0, 1], distance=0.1)

# Step 4: look again (everything but the held block), then move to a place pose in the bowl.
detect_objects(object_list=[name for name in get_object_name_list() if name != 'green_block'])
move_to_pose(pose=parse_place_pose(object_name='green_block', receptacle_name='green_bowl'))

# Step 5: release and move up.
open_gripper()
detach_object(object_name='green_block')
move_in_direction(axis=[0, 0, 1], distance=0.1)
