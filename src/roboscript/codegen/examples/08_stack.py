# query: objects = [table, red_box, yellow_box] ; # put the red box on top of the yellow box
# Plan:
# 1. Grasp the red box from above, lift it higher than the yellow box.
# 2. Place it onto the yellow box ('on' placement uses the receptacle's top) and release it.
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='red_box', description='center'))
close_gripper()
attach_object('red_box')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='red_box', receptacle_name='yellow_box'))
open_gripper()
detach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
