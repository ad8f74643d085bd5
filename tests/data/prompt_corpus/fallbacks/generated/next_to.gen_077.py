# Task: place the tea box beside the green plate.
# Plan:
# 1. Detect everything. The object is tea_box; the green plate stays where it is. The cabinet plays no part but is an
#    obstacle to keep clear of.
# 2. Work out four spots on the table next to the plate (left, right, robot side, far side), 3 cm from its edge and
#    sized for the tea box; order them by how much room they leave to the other things.
# 3. Pick the tea box: a central top-down grasp first; if that fails, an adaptive grasp from above, then a horizontal one.
# 4. Place it at the best spot (the object's middle over it, on the table); if that spot fails, the next one. Let go,
#    move up.
# 5. Look again: the tea box must stand on the table, not overlapping the plate, at most 10 cm from its edge. If not,
#    pick it up and place it once more, on another side first; if that fails too, raise an error.

def approach_axis(pose):
    # The gripper's approach (z) axis, from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance=0.1):
    # Let go and draw the hand back the way it came in.
    open_gripper()
    move_in_direction(-approach_axis(get_gripper_pose()), distance)


def grasp_pose_for(name, method):
    if method == 'central':
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    if method == 'central_top':
        return parse_central_lift_grasp_pose(object_name=name, description='top')
    if method == 'adaptive':
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    return parse_horizontal_grasp_pose(object_name=name)


def pick(name, methods):
    # Try the grasps in order; the first that holds the object lifts it 10 cm. Raise the last error if none does.
    detect_objects(object_list=[name])
    last_error = None
    for i, method in enumerate(methods):
        reached = False
        try:
            open_gripper()
            grasp(grasp_pose_for(name, method))
            reached = True
            close_gripper()
            attach_object(name)
            move_in_direction([0, 0, 1], 0.1)
            print(f'Picked {name} with the {method} grasp')
            return
        except (GraspError, IKError, PlanningError) as error:
            last_error = error
            following = f'the {methods[i + 1]} grasp' if i + 1 < len(methods) else 'nothing left to try'
            print(f'Picking {name} with the {method} grasp failed ({error}); next: {following}')
            if reached:
                back_off()
    raise last_error


def describe(request):
    receptacle, position = request
    where = []
    if receptacle is not None:
        where.append(f'in/on {receptacle}')
    if position is not None:
        where.append(f'at ({position[0]:.2f}, {position[1]:.2f})')
    return ' '.join(where)


def place(name, requests, lift=0.1):
    # Try the place requests (receptacle, position) in order; set the object down at the first that works,
    # let go and move up. Return the index of the request used; raise the last error if none works.
    last_error = None
    for i, (receptacle, position) in enumerate(requests):
        try:
            move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
        except (PlacementError, ReceptacleFullError, IKError, PlanningError) as error:
            last_error = error
            following = describe(requests[i + 1]) if i + 1 < len(requests) else 'nothing left to try'
            print(f'Placing {name} {describe(requests[i])} failed ({error}); next: {following}')
            continue
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], lift)
        print(f'Placed {name} {describe(requests[i])}')
        return i
    raise last_error


def box_gap(a, b):
    # Horizontal gap between two boxes: positive when apart, negative when they overlap.
    return max(b[0] - a[3], a[0] - b[3], b[1] - a[4], a[1] - b[4])


def ranked_sides(name, anchor, gap=0.03):
    # Spots on the table on the anchor's four sides, a few cm from its edge, sized for the object as it stands now;
    # best first: those with the most room to the other things. Spots off the table are left out.
    a = get_3d_bbox(anchor)
    o = get_3d_bbox(name)
    t = get_3d_bbox('table')
    hx = (o[3] - o[0]) / 2
    hy = (o[4] - o[1]) / 2
    cx = (a[0] + a[3]) / 2
    cy = (a[1] + a[4]) / 2
    top = t[5]
    sides = [
        ('left of', [cx, a[4] + gap + hy, top]),
        ('right of', [cx, a[1] - gap - hy, top]),
        ('in front of (robot side)', [a[0] - gap - hx, cy, top]),
        ('behind', [a[3] + gap + hx, cy, top]),
    ]
    sides = [(side, [float(v) for v in target]) for side, target in sides]
    others = [n for n in get_object_name_list() if n not in ('table', name, anchor) and not n.startswith('cabinet.')]
    scored = []
    for side, target in sides:
        if not (t[0] + hx <= target[0] <= t[3] - hx and t[1] + hy <= target[1] <= t[4] - hy):
            continue
        foot = [target[0] - hx, target[1] - hy, 0.0, target[0] + hx, target[1] + hy, 0.0]
        room = float(min([box_gap(foot, get_3d_bbox(n)) for n in others] + [1.0]))
        scored.append((room, side, target))
    if not scored:
        print(f'No side of {anchor} lies on the table by the boxes; trying all four')
        return sides
    scored.sort(reverse=True)
    return [(side, target) for room, side, target in scored]


def is_beside(name, anchor, max_gap=0.1):
    # Not overlapping the anchor, at most max_gap from it, and standing on the table.
    o = get_3d_bbox(name)
    gap = box_gap(o, get_3d_bbox(anchor))
    on_table = o[2] <= get_3d_bbox('table')[5] + 0.02
    return -0.01 <= gap <= max_gap and on_table


def put_beside(name, anchor, methods):
    # Pick, place on the best side of the anchor (the other sides as alternatives), look again and check;
    # one more try, another side first, if the check fails.
    last_side = None
    for attempt in (1, 2):
        detect_objects()
        ranked = ranked_sides(name, anchor)
        if last_side is not None:
            ranked = [r for r in ranked if r[0] != last_side] + [r for r in ranked if r[0] == last_side]
        pick(name, methods)
        used = place(name, [(None, target) for side, target in ranked])
        last_side = ranked[used][0]
        detect_objects(object_list=[name, anchor])
        if is_beside(name, anchor):
            print(f'Check passed: {name} stands {last_side} {anchor}')
            return
        if attempt == 1:
            print(f'Check failed: {name}, placed {last_side} {anchor}, is not beside it; picking it up and trying another side')
    raise RuntimeError(f'{name} did not end up beside {anchor} after two attempts')


detect_objects()
put_beside('tea_box', 'green_plate', ['central', 'adaptive', 'horizontal'])
