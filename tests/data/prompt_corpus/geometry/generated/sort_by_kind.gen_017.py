# Task: sort the objects on the table by kind: put the fruits into the basket.
# Plan:
# 1. From the names, the fruits are lime and orange; red_mug, tea_box, red_block and white_bowl stay.
# 2. Detect; measure the basket's box: its top is the height each fruit must clear when carried in.
# 3. For each fruit: grasp it top-down at its middle, attach it, lift it (a Pose from the gripper's) until its
#    bottom is above the basket's rim.
# 4. Place it into the basket (the planner finds a free spot in it), release it, move up.
detect_objects()
fruits = ['lime', 'orange']
basket_top = get_3d_bbox('basket')[5]

for fruit in fruits:
    bottom_z = get_object_pose(fruit).position.z
    open_gripper()
    grasp_pose = parse_central_lift_grasp_pose(object_name=fruit, description='center')
    grasp(grasp_pose)
    close_gripper()
    attach_object(fruit)
    hold = grasp_pose.position.z - bottom_z
    lift = get_gripper_pose()
    lift.position.z = max(lift.position.z + 0.1, basket_top + hold + 0.05)
    move_to_pose(lift)
    move_to_pose(parse_place_pose(object_name=fruit, receptacle_name='basket'))
    open_gripper()
    detach_object(fruit)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)
