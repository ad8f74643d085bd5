# Task: place the red block on top of the gelatin box.
# Plan:
# 1. Detect the red block and the gelatin box.
# 2. Pick the red block from above at mid height, attach it and lift it clear of the gelatin box.
# 3. Get a place pose on the gelatin box's flat top (stacking), move there, open the gripper, detach the block
#    and move up.


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


detect_objects(object_list=['red_block', 'gelatin_box'])
# Lift so the block's bottom clears the gelatin box's top by at least 5 cm (attach_object already lifted it 5 cm).
clearance = get_3d_bbox('gelatin_box')[5] - get_3d_bbox('red_block')[2]
pick('red_block', lift=max(0.1, clearance + 0.05))
place('red_block', receptacle='gelatin_box')
