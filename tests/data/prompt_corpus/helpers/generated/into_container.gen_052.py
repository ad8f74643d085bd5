# Task: place the toy car in the basket.
# Plan:
# 1. Detect the toy car and the basket (the basket stays where it is).
# 2. Pick the toy car from above (gripped across its length, not along it), attach it and lift it well clear
#    (15 cm) so it can pass over the basket's rim.
# 3. Get a place pose inside the basket, move there, open the gripper, detach the car and move up.


def pick(name, lift=0.1):
    # Grasp `name` from above, attach it and lift it; a second try with the adaptive grasp if the first held nothing.
    for attempt in range(2):
        open_gripper()
        if attempt == 0:
            try:
                pose = parse_central_lift_grasp_pose(object_name=name, description='center')
            except GraspError:
                pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        else:
            pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        grasp(pose)
        close_gripper()
        try:
            attach_object(name)
        except GraspError:
            if attempt == 1:
                raise
            open_gripper()
            move_in_direction([0, 0, 1], 0.1)
            detect_objects([name])
            continue
        move_in_direction([0, 0, 1], lift)
        return


def place(name, receptacle=None, position=None):
    # Set the held `name` down in/on `receptacle` or at `position`, let go and move up.
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


detect_objects(object_list=['toy_car', 'basket'])
pick('toy_car', lift=0.15)
place('toy_car', receptacle='basket')
