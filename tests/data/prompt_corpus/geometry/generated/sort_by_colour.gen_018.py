# Task: sort the objects on the table by colour: red objects on the red plate, green objects on the green plate.
# Plan:
# 1. From the names: red_block is red; green_block and lime are green. tennis_ball, white_cup and pink_saucer are
#    neither (the plates stay where they are).
# 2. Detect; for each plate measure its box and its middle in x, y.
# 3. For each plate's objects: grasp each top-down at its middle, attach it, lift it (a Pose from the gripper's).
#    The first object on a plate goes to the plate's middle; the next one onto the same plate is placed with the
#    plate alone, so that the planner finds it a free spot on it beside the first.
# 4. Release each and move up.
detect_objects()
groups = {'red_plate': ['red_block'], 'green_plate': ['green_block', 'lime']}


def plate_middle(plate):
    box = get_3d_bbox(plate)
    return [(box[0] + box[3]) / 2.0, (box[1] + box[4]) / 2.0, box[5]]


def pick(name):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    lift = get_gripper_pose()
    lift.position.z += 0.1
    move_to_pose(lift)


def place(name, receptacle, position=None):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)


for plate, names in groups.items():
    middle = plate_middle(plate)
    for i, name in enumerate(names):
        pick(name)
        if i == 0:
            place(name, plate, position=middle)
        else:
            place(name, plate)
