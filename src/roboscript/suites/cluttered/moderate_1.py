# Task: move the white mug into a container with the same color.
# Plan:
# 1. Detect the objects. The containers are the plates and bowls; the one with the mug's colour is the
#    white plate.
# 2. Grasp the white mug with the adaptive grasp (it is wide and has a handle), preferring a top-down approach.
# 3. Close the gripper, attach the mug, lift it.
# 4. Place it on the white plate, release it, move up.
detect_objects()
containers = [name for name in get_object_name_list() if ('plate' in name or 'bowl' in name)]
target = [name for name in containers if name.startswith('white')][0]
open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose(object_name='white_mug', preferred_approach_direction=[0, 0, -1])
grasp(grasp_pose)
close_gripper()
attach_object('white_mug')
move_in_direction(direction=[0, 0, 1], distance=0.1)
place_pose = parse_place_pose(object_name='white_mug', receptacle_name=target)
move_to_pose(place_pose)
open_gripper()
detach_object('white_mug')
move_in_direction(direction=[0, 0, 1], distance=0.1)
