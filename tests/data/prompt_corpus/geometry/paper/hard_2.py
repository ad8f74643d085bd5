# Task: clear the table by moving all table objects into the basket.
# Plan:
# 1. The objects on the table are orange and toy_bus (the cabinet is furniture, the basket is the receptacle).
# 2. Detect; measure the basket's box: its top is the height each object must clear when carried in.
# 3. For each object: grasp it top-down at its middle if its box is narrower than the fingers open, else with the
#    adaptive grasp near its middle; attach it, lift it (a Pose from the gripper's) until its bottom is above the
#    basket's rim.
# 4. Place it into the basket (the planner finds a free spot in it), release it, move up.
detect_objects()
basket = 'basket_with_fabric_liner'
to_move = ['orange', 'toy_bus']
basket_top = get_3d_bbox(basket)[5]


def grasp_pose_for(name):
    b = get_3d_bbox(name)
    if min(b[3] - b[0], b[4] - b[1]) < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])


for name in to_move:
    bottom_z = get_object_pose(name).position.z
    open_gripper()
    grasp_pose = grasp_pose_for(name)
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    hold = grasp_pose.position.z - bottom_z
    lift = get_gripper_pose()
    lift.position.z = max(lift.position.z + 0.1, basket_top + hold + 0.05)
    move_to_pose(lift)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=basket))
    open_gripper()
    detach_object(name)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)
