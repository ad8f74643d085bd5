# Task: clear the table by putting every object lying on it into the basket; leave the basket, the bowl and the plate.
# Plan:
# 1. Detect everything. The objects to move are plum, medication_bottle, golf_ball, white_and_pink_box and
#    strawberry; the basket, red_plate and white_bowl stay where they are.
# 2. Measure the basket's box: its top is the height each object must clear when carried in.
# 3. For each object: choose the grasp from its box (top-down at the middle if narrower than the fingers open,
#    else the adaptive grasp), grasp it, attach it, lift it (a Pose from the gripper's) above the basket's rim.
# 4. Place it into the basket (the planner finds a free spot in it), release it, move up.
detect_objects()
to_move = ['plum', 'medication_bottle', 'golf_ball', 'white_and_pink_box', 'strawberry']
basket_box = get_3d_bbox('basket')
basket_top = basket_box[5]


def grasp_pose_for(name):
    box = get_3d_bbox(name)
    narrow_side = min(box[3] - box[0], box[4] - box[1])
    if narrow_side < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])


def pick(name, clear_z):
    # Grasp and attach, then lift until the object's bottom is 5 cm above clear_z.
    bottom_z = get_object_pose(name).position.z
    open_gripper()
    grasp_pose = grasp_pose_for(name)
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    hold = grasp_pose.position.z - bottom_z
    lift = get_gripper_pose()
    lift.position.z = max(lift.position.z + 0.1, clear_z + hold + 0.05)
    move_to_pose(lift)


def place(name, receptacle=None, position=None):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)


for name in to_move:
    pick(name, basket_top)
    place(name, receptacle='basket')
