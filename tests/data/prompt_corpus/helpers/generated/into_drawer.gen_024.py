# Task: put the rubiks cube into the top drawer; the drawer is closed, so open it first.
# Plan:
# 1. Define helpers: open drawer k by its handle, choose a grasp from the object's name, pick an object, place it into a receptacle.
# 2. The top drawer is cabinet.drawer_0 with cabinet.handle_0: open it, then detect again so the open drawer is measured anew.
# 3. Pick the rubiks cube (a small cube: top-down grasp at its centre).
# 4. Place it into the open top drawer, release it and move up.


def open_drawer(k, distance=0.22):
    handle = 'cabinet.handle_%d' % k
    drawer = 'cabinet.drawer_%d' % k
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')
    # Pull out along the joint axis, no farther than the drawer still opens.
    move_in_direction(joint['joint_axis'], min(distance, joint['joint_upper'] - joint['joint_value']))
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)
    detect_objects()


def grasp_pose_for(name):
    # Mugs and odd shapes: adaptive grasp from above; upright cups and bottles: level grasp; small boxes, blocks, fruit: top-down.
    words = name.split('_')
    if 'mug' in words or 'toy' in words or 'banana' in words:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    if 'cup' in words or 'bottle' in words or 'cleanser' in words:
        return parse_horizontal_grasp_pose(object_name=name)
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def release(name):
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def place_into(name, receptacle):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    release(name)


detect_objects()
open_drawer(0)
pick('rubiks_cube')
place_into('rubiks_cube', 'cabinet.drawer_0')
