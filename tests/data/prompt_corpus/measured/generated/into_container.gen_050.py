# Task: move the strawberry into the red bowl.
# Plan:
# 1. Detect the objects; read the boxes of the strawberry and the red bowl.
# 2. Compute the target: the bowl's box centre in x, y (the middle of its hollow), z at its rim; check that the
#    strawberry is narrower than the bowl.
# 3. Grasp the strawberry from above (central grasp; adaptive if that fails) and lift it until it clears the rim.
# 4. Get a place pose at the target in the red bowl, move there, open the gripper, detach, move up.
# 5. Detect again and check that the strawberry's centre lies inside the bowl's box.


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


detect_objects()
bowl = get_3d_bbox('red_bowl')
berry = get_3d_bbox('strawberry')
target = box_centre(bowl)
target[2] = bowl[5]
berry_width = max(berry[3] - berry[0], berry[4] - berry[1])
bowl_width = min(bowl[3] - bowl[0], bowl[4] - bowl[1])
print('bowl centre', np.round(target, 3), 'bowl width', round(float(bowl_width), 3),
      'strawberry width', round(float(berry_width), 3))
if berry_width >= bowl_width:
    print('warning: the strawberry is not narrower than the bowl')

open_gripper()
grasp(top_grasp_pose('strawberry'))
close_gripper()
attach_object('strawberry')
# attach_object already lifted it 5 cm; lift further so that its bottom is at least 5 cm above the bowl's rim.
move_in_direction([0, 0, 1], max(0.1, bowl[5] - berry[2]))
move_to_pose(parse_place_pose(object_name='strawberry', receptacle_name='red_bowl', position=list(target)))
open_gripper()
detach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)

detect_objects()
bowl = get_3d_bbox('red_bowl')
c = get_object_center_position('strawberry')
inside = bowl[0] <= c[0] <= bowl[3] and bowl[1] <= c[1] <= bowl[4]
print('strawberry now at', np.round(c, 3), 'inside the bowl box:', inside)
