# Task: move the wooden block next to the green bowl
# Plan:
# 1. Detect everything; measure the block's and the bowl's boxes and the table's.
# 2. Candidate spots: beside the bowl on each of its four sides (left +y, right -y, towards the robot -x,
#    away +x), the block's middle a gap of 3 cm plus half the block beyond the bowl's box.
# 3. Keep the spots whose footprint (with a 1 cm margin) lies on the table and overlaps no other object's box
#    (the block's own place does not count, it will be gone); take the one nearest to the block now.
#    Where none is free, take the nearest anyway (the placement moves it to a free spot close by).
# 4. Pick the block (top-down when narrow enough, else adaptive from above), lift it, place it there, release.
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


def spots_beside(anchor_box, half_x, half_y, gap):
    cx = (anchor_box[0] + anchor_box[3]) / 2
    cy = (anchor_box[1] + anchor_box[4]) / 2
    return [
        (cx, anchor_box[4] + gap + half_y),  # left
        (cx, anchor_box[1] - gap - half_y),  # right
        (anchor_box[0] - gap - half_x, cy),  # towards the robot
        (anchor_box[3] + gap + half_x, cy),  # away from the robot
    ]


def is_free(x, y, half_x, half_y, obstacles, table_box, margin=0.01):
    lo_x, hi_x = x - half_x - margin, x + half_x + margin
    lo_y, hi_y = y - half_y - margin, y + half_y + margin
    if lo_x < table_box[0] or hi_x > table_box[3] or lo_y < table_box[1] or hi_y > table_box[4]:
        return False
    for b in obstacles:
        if lo_x < b[3] and hi_x > b[0] and lo_y < b[4] and hi_y > b[1]:
            return False
    return True


def move_next_to(name, anchor, gap=0.03):
    names = get_object_name_list()
    obj_box = get_3d_bbox(name)
    half_x, half_y = (obj_box[3] - obj_box[0]) / 2, (obj_box[4] - obj_box[1]) / 2
    table_box = get_3d_bbox('table')
    obstacles = [get_3d_bbox(n) for n in names
                 if n not in ('table', name) and not n.startswith('cabinet.')]
    here = get_object_center_position(name)
    candidates = sorted(spots_beside(get_3d_bbox(anchor), half_x, half_y, gap),
                        key=lambda s: np.hypot(s[0] - here[0], s[1] - here[1]))
    free = [s for s in candidates if is_free(s[0], s[1], half_x, half_y, obstacles, table_box)]
    x, y = (free or candidates)[0]
    pick(name)
    put(name, position=[x, y, table_box[5]])


detect_objects()
move_next_to('wooden_block', 'green_bowl')
