# query: objects = [table, white_plate, blue_bowl, apple, lemon, tennis_ball, toy_car] ; # fruits onto the plate, toys into the bowl
# Plan:
# 1. Decide for each object where it goes: fruits (apple, lemon) to the plate, toys (tennis ball, toy car) to the bowl.
# 2. Move them one at a time with a helper.
detect_objects()
destination = {'apple': 'white_plate', 'lemon': 'white_plate', 'tennis_ball': 'blue_bowl', 'toy_car': 'blue_bowl'}


def pick_and_place(name, receptacle):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


for name, receptacle in destination.items():
    pick_and_place(name, receptacle)
