# Task: put the blue mug into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Open it: grasp the handle horizontally, attach the drawer, pull along its prismatic joint's axis,
#    release and back away.
# 3. Look again so that the open drawer is measured anew.
# 4. Pick the blue mug with the adaptive grasp from above (its rim), lift it.
# 5. Place it into the open drawer, release it and move up.
def open_drawer(k, distance=0.22):
    drawer = 'cabinet.drawer_%d' % k
    handle = 'cabinet.handle_%d' % k
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')
    move_in_direction(joint['joint_axis'], min(distance, joint['joint_upper'] - joint['joint_value']))
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


def pick(name):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def place_into(name, receptacle):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


detect_objects()
open_drawer(1)
detect_objects()
pick('blue_mug')
place_into('blue_mug', 'cabinet.drawer_1')
