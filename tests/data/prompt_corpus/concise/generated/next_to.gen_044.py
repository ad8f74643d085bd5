# Task: put the blue cup next to the soup can.
# Plan:
# 1. Measure the soup can and the blue cup.
# 2. Candidate spots: left, right, in front of and behind the can, far enough that the cup's box
#    does not touch the can's, plus 2 cm.
# 3. Keep the candidates on the table and in reach; take the one farthest from the other objects.
# 4. Grasp the cup from above (adaptive, by its rim or body), lift it, place it there, release it.
detect_objects()
can = get_3d_bbox('soup_can')
can_at = get_object_center_position('soup_can')
cup = get_3d_bbox('blue_cup')
half = max(cup[3] - cup[0], cup[4] - cup[1]) / 2
others = [n for n in get_object_name_list() if n not in ('table', 'blue_cup', 'soup_can') and not n.startswith('cabinet.')]


def clearance(p, names):
    # Smallest horizontal distance from p to the boxes of names.
    d = []
    for n in names:
        b = get_3d_bbox(n)
        d.append(np.hypot(max(b[0] - p[0], 0, p[0] - b[3]), max(b[1] - p[1], 0, p[1] - b[4])))
    return min(d)


table = get_3d_bbox('table')
off_x = (can[3] - can[0]) / 2 + half + 0.02
off_y = (can[4] - can[1]) / 2 + half + 0.02
best, best_d = None, -1
for dx, dy in [(0, off_y), (0, -off_y), (-off_x, 0), (off_x, 0)]:
    p = np.array([can_at[0] + dx, can_at[1] + dy, can_at[2]])
    r = np.hypot(p[0], p[1])
    if not (table[0] < p[0] < table[3] and table[1] < p[1] < table[4]) or r < 0.3 or r > 0.75:
        continue
    d = clearance(p, others)
    if d > best_d:
        best, best_d = p, d
if best is None:
    raise PlacementError('no reachable spot next to the soup can')

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='blue_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('blue_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_cup', position=best))
open_gripper()
detach_object('blue_cup')
move_in_direction([0, 0, 1], 0.1)
