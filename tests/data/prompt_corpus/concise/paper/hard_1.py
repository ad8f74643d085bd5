# Task: exchange the positions of the apple and the banana on the table.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the apple to a free spot 20 cm towards the robot, so that its place is free.
# 3. Move the banana to where the apple was, then the apple to where the banana was.
detect_objects()
apple_at = get_object_center_position('apple')
banana_at = get_object_center_position('banana')


def move_object(name, position):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


move_object('apple', [apple_at[0] - 0.2, apple_at[1], apple_at[2]])
move_object('banana', apple_at)
move_object('apple', banana_at)
