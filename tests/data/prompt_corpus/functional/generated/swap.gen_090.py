# Task: exchange the places of the rubiks cube and the plum.
# Plan:
# 1. Detect the scene and remember where both objects stand before anything moves.
# 2. Move the rubiks cube aside to a free spot of the table (parse_place_pose with 'table' keeps its old
#    place free).
# 3. Move the plum to where the cube stood.
# 4. Move the cube to where the plum stood.

FIRST = 'rubiks_cube'
SECOND = 'plum'


def grasp_pose_for(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place(name, pose, retreat=0.1):
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


def move_aside(name):
    pick(name)
    place(name, parse_place_pose(object_name=name, receptacle_name='table'))


def move_to(name, position):
    pick(name)
    place(name, parse_place_pose(object_name=name, position=list(position)))


def main():
    detect_objects()
    first_at = get_object_center_position(FIRST)
    second_at = get_object_center_position(SECOND)
    move_aside(FIRST)
    move_to(SECOND, first_at)
    move_to(FIRST, second_at)


main()
