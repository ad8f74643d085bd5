# Task: swap the positions of the red box and the baseball
# Plan:
# 1. Detect everything and remember both centres before anything moves.
# 2. Move the red box aside onto a free spot of the table (placing on 'table' keeps its old place free).
# 3. Move the baseball to where the red box was, then the red box to where the baseball was.
# 4. Each move: pick (top-down when narrow enough, else adaptive from above), lift, place, release, move up.
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


def swap(a, b):
    a_at = get_object_center_position(a)
    b_at = get_object_center_position(b)
    pick(a)
    put(a, receptacle='table')
    pick(b)
    put(b, position=a_at)
    pick(a)
    put(a, position=b_at)


detect_objects()
swap('red_box', 'baseball')
