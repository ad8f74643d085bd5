# Task: move the white mug into a container with the same colour
#       (the colour of an object is in its name).
# Plan:
# 1. Detect all objects.
# 2. The mug is white_porcelain_mug; the containers are the plates and saucers.
#    Pick the container whose name says 'white': white_ceramic_plate.
# 3. Grasp the mug by its rim from above, lift it.
# 4. Place it into the white container, release it, move up.
detect_objects()
mug = 'white_porcelain_mug'
containers = [n for n in get_object_name_list()
              if any(k in n for k in ['plate', 'saucer', 'bowl', 'basket']) and not n.startswith('cabinet')]
same_colour = [c for c in containers if 'white' in c.split('_')]
target = same_colour[0]

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(mug, preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object(mug)
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(mug, target))
open_gripper()
detach_object(mug)
move_in_direction([0, 0, 1], 0.1)
