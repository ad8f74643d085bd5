# Task: put the strawberry next to the red block.
# Plan:
# 1. Detect; read the boxes of the red block, the strawberry, the table and the other objects on the table.
# 2. Candidate targets beside the block on each of its four sides (left +y, right -y, towards the robot -x,
#    away +x): the strawberry's centre half its width plus 3 cm beyond the block's face, level with the block.
# 3. Keep the candidates whose footprint is on the table and reachable (0.3 to 0.75 m from the base at
#    x = -0.45, y = 0); take the one with the most clearance from the other objects (left first on ties).
# 4. Grasp the strawberry from above, lift it, place it at the chosen target on the table, release, move up.
# 5. Detect again and print the gap between the strawberry and the block.

BASE = np.array([-0.45, 0.0])


def footprint_gap(x, y, hx, hy, box):
    # Horizontal distance between a footprint centred at (x, y) with half sizes hx, hy and a box.
    dx = max(box[0] - (x + hx), (x - hx) - box[3], 0.0)
    dy = max(box[1] - (y + hy), (y - hy) - box[4], 0.0)
    return float(np.hypot(dx, dy))


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


detect_objects()
block = get_3d_bbox('red_block')
berry = get_3d_bbox('strawberry')
table = get_3d_bbox('table')
hx, hy = (berry[3] - berry[0]) / 2, (berry[4] - berry[1]) / 2
bx, by = (block[0] + block[3]) / 2, (block[1] + block[4]) / 2
gap = 0.03
candidates = [('left', bx, block[4] + gap + hy),
              ('right', bx, block[1] - gap - hy),
              ('towards the robot', block[0] - gap - hx, by),
              ('away from the robot', block[3] + gap + hx, by)]
others = [n for n in get_object_name_list()
          if n not in ('table', 'strawberry', 'red_block') and not n.startswith('cabinet')]
obstacles = [get_3d_bbox(n) for n in others]

best = None
for side, x, y in candidates:
    if x - hx < table[0] + 0.02 or x + hx > table[3] - 0.02 or y - hy < table[1] + 0.02 or y + hy > table[4] - 0.02:
        continue
    reach = np.hypot(x - BASE[0], y - BASE[1])
    if reach < 0.3 or reach > 0.75:
        continue
    clearance = min([footprint_gap(x, y, hx, hy, b) for b in obstacles] + [1.0])
    print(side, round(float(x), 3), round(float(y), 3), 'clearance', round(clearance, 3))
    if best is None or clearance > best[0] + 0.01:
        best = (clearance, side, x, y)
if best is None:
    best = (0.0, candidates[0][0], candidates[0][1], candidates[0][2])
target = [best[2], best[3], table[5]]
print('placing the strawberry', best[1], 'of the red block at', np.round(target, 3))

open_gripper()
grasp(top_grasp_pose('strawberry'))
close_gripper()
attach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='strawberry', position=target))
open_gripper()
detach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)

detect_objects()
block = get_3d_bbox('red_block')
berry = get_3d_bbox('strawberry')
c = get_object_center_position('strawberry')
print('strawberry at', np.round(c, 3), 'gap to the block',
      round(footprint_gap(c[0], c[1], (berry[3] - berry[0]) / 2, (berry[4] - berry[1]) / 2, block), 3), 'm')
