# Task: put the rubiks cube on the red plate
# Plan:
# 1. Detect everything; a dict maps the object to move to the plate it goes on.
# 2. For each pair: pick the object (top-down when narrow enough, else the adaptive grasp from above), lift it.
# 3. Place it onto the plate, release it and move up.
def grasp_pose_for(name):
    box = get_3d_bbox(name)
    narrow = min(box[3] - box[0], box[4] - box[1]) < 0.07
    if narrow and 'mug' not in name and 'cup' not in name:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put(name, receptacle=None, position=None, retreat=0.1):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


detect_objects()
destination = {'rubiks_cube': 'red_plate'}
for name, plate in destination.items():
    pick(name)
    put(name, receptacle=plate)
