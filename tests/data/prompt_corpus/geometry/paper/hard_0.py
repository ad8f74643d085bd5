# Task: place all fruits on the table into the white plate.
# Plan:
# 1. From the names, the fruits are apple and banana; the boxes, bottles, cleanser and bowl stay.
# 2. Detect; measure the white plate's box and its middle in x, y.
# 3. Order the fruits by footprint (largest first): the largest goes to the plate's middle; the next is placed
#    with the plate alone, so that the planner finds it a free spot on the plate beside the first.
# 4. For each fruit: grasp it top-down at its middle if its box is narrower than the fingers open, else with the
#    adaptive grasp near its middle; attach it, lift it (a Pose from the gripper's), place it, release, move up.
detect_objects()
plate = 'white_ceramic_plate'
fruits = ['apple', 'banana']
plate_box = get_3d_bbox(plate)
middle = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]


def footprint(name):
    b = get_3d_bbox(name)
    return (b[3] - b[0]) * (b[4] - b[1])


def grasp_pose_for(name):
    b = get_3d_bbox(name)
    if min(b[3] - b[0], b[4] - b[1]) < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])


fruits.sort(key=footprint, reverse=True)
for i, fruit in enumerate(fruits):
    open_gripper()
    grasp(grasp_pose_for(fruit))
    close_gripper()
    attach_object(fruit)
    lift = get_gripper_pose()
    lift.position.z += 0.1
    move_to_pose(lift)
    if i == 0:
        place_pose = parse_place_pose(object_name=fruit, receptacle_name=plate, position=middle)
    else:
        place_pose = parse_place_pose(object_name=fruit, receptacle_name=plate)
    move_to_pose(place_pose)
    open_gripper()
    detach_object(fruit)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)
