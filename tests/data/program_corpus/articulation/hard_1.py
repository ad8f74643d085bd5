# Swap the apple and the banana, using the table as the spot in between.
detect_objects()
apple_at = get_object_pose('apple').position
banana_at = get_object_pose('banana').position


def carry(name, pose_of_place):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(name, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(pose_of_place(name))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


carry('apple', lambda n: parse_place_pose(n, 'table'))
carry('banana', lambda n: parse_place_pose(n, position=[apple_at.x, apple_at.y, apple_at.z]))
carry('apple', lambda n: parse_place_pose(n, position=[banana_at.x, banana_at.y, banana_at.z]))
