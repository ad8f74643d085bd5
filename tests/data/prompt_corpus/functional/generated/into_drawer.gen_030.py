# Task: open the second drawer of the cabinet and put the yellow box into it.
# Plan:
# 1. The cabinet has three drawers counted from the top: the second is cabinet.drawer_1, its handle
#    cabinet.handle_1.
# 2. Read the drawer's prismatic joint near its handle; the travel left is joint_upper - joint_value.
# 3. Grasp the handle horizontally, close the gripper, attach the drawer, pull along the joint axis by the
#    travel left; release and back away along the axis.
# 4. Detect again, since the drawer moved.
# 5. Pick the yellow box from above, lift it.
# 6. Place it into the open drawer, release, move up.

DRAWER = 'cabinet.drawer_1'
HANDLE = 'cabinet.handle_1'
ITEM = 'yellow_box'


def drawer_joint(handle):
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def travel_left(joint):
    return joint['joint_upper'] - joint['joint_value']


def grasp_pose_for(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def open_drawer(drawer, handle):
    joint = drawer_joint(handle)
    distance = travel_left(joint)
    if distance <= 0.005:
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(joint['joint_axis'], distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place(name, pose, retreat=0.08):
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


def main():
    detect_objects()
    open_drawer(DRAWER, HANDLE)
    detect_objects()
    pick(ITEM)
    place(ITEM, parse_place_pose(object_name=ITEM, receptacle_name=DRAWER))


main()
