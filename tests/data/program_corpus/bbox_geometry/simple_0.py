# Geometry from bounding boxes: the apple goes to the middle of the bowl.
detect_objects(['apple', 'footed_bowl'])
bowl = get_3d_bbox('footed_bowl')
apple = get_3d_bbox('apple')
open_gripper()
grasp(parse_central_lift_grasp_pose('apple', description='top'))
close_gripper()
attach_object('apple')
move_in_direction([0, 0, 1], 0.15)
target = [(bowl[0] + bowl[3]) / 2, (bowl[1] + bowl[4]) / 2, bowl[5] + (apple[5] - apple[2]) / 2]
move_to_pose(parse_place_pose('apple', position=target))
open_gripper()
detach_object('apple')
move_in_direction([0, 0, 1], 0.1)
