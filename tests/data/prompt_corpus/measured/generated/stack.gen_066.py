# Task: put the blue block on the red box.
# Plan:
# 1. Detect; read the boxes of the blue block and the red box.
# 2. Target: the red box's box centre in x, y, z at its top; check that the block's footprint is not larger than
#    the box's top.
# 3. Grasp the blue block from above, lift it until its bottom is 5 cm above the red box's top (at least 10 cm).
# 4. Get a place pose at the target on the red box, move there, release, move up.
# 5. Detect again; check that the block's centre is over the box and its bottom near the box's top.


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


detect_objects()
red_box = get_3d_bbox('red_box')
block = get_3d_bbox('blue_block')
target = box_centre(red_box)
target[2] = red_box[5]
block_size = max(block[3] - block[0], block[4] - block[1])
top_size = min(red_box[3] - red_box[0], red_box[4] - red_box[1])
print('red box top at', np.round(target, 3), 'top', round(float(top_size), 3), 'm, block', round(float(block_size), 3), 'm')
if block_size > top_size:
    print('warning: the block is wider than the top of the red box')

open_gripper()
grasp(top_grasp_pose('blue_block'))
close_gripper()
attach_object('blue_block')
# attach_object lifted it 5 cm; lift further so that its bottom is at least 5 cm above the red box's top.
move_in_direction([0, 0, 1], max(0.1, red_box[5] - block[2]))
move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='red_box', position=list(target)))
open_gripper()
detach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)

detect_objects()
red_box = get_3d_bbox('red_box')
block = get_3d_bbox('blue_block')
c = box_centre(block)
on_top = red_box[0] <= c[0] <= red_box[3] and red_box[1] <= c[1] <= red_box[4] and abs(block[2] - red_box[5]) < 0.02
print('blue block at', np.round(c, 3), 'bottom', round(float(block[2]), 3), 'box top', round(float(red_box[5]), 3),
      'on the box:', on_top)
