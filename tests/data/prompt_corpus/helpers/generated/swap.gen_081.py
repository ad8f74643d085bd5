# Task: swap the positions of the pear and the blue block.
# Plan:
# 1. Detect everything and remember where the pear and the blue block stand (centres of their boxes) before
#    anything moves.
# 2. Move the pear aside to a free spot of the table (parse_place_pose with 'table' keeps its old place free).
# 3. Move the blue block to where the pear stood.
# 4. Move the pear to where the blue block stood.
# Each move: grasp from above at mid height, attach, lift, place, release, detach, move up.


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


def move_object(name, receptacle=None, position=None):
    pick(name)
    place(name, receptacle=receptacle, position=position)


detect_objects()
pear_at = get_object_center_position('pear')
block_at = get_object_center_position('blue_block')

move_object('pear', receptacle='table')          # aside, so that its place is free
move_object('blue_block', position=pear_at)
move_object('pear', position=block_at)
