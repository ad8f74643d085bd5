# Task: open the cabinet door and put the strawberry in the cupboard behind it
# Plan:
# 1. The cabinet has one door (cabinet.door_0) and one drawer (cabinet.drawer_0); handles are numbered by row
#    from the top, so the door's handle is cabinet.handle_0 if the door is above the drawer, else cabinet.handle_1.
# 2. Open the door: grasp its handle horizontally, attach the door, turn it about its hinge well past 40 degrees,
#    release the handle and back the hand out.
# 3. Look again now that the door has moved.
# 4. Grasp the strawberry level with a horizontal grasp (needed to carry it into the compartment), lift it a little.
# 5. Place it into the compartment behind the open door, release it and back the hand out the way it came.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


def back_out(distance):
    # Move the hand straight back against its approach direction.
    back = -np.array(quaternion_z_axis(get_gripper_pose()))
    move_in_direction(back, distance)


def door_handle_name(door, drawer):
    # Rows count from the top: the higher part has handle_0, the lower one handle_1.
    if get_object_center_position(door)[2] > get_object_center_position(drawer)[2]:
        return 'cabinet.handle_0'
    return 'cabinet.handle_1'


def open_door(door, handle, target_angle=70):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
    angle = min(target_angle, joint['joint_upper'] - joint['joint_value'])
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                          joint_position=joint['joint_position'], n=20, angle=angle)
    follow_path(path)
    open_gripper()
    detach_object(door)
    back_out(0.1)


def pick_level(name):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.05)


def place_behind_door(name, door):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=door))
    open_gripper()
    detach_object(name)
    back_out(0.1)


detect_objects()
door = 'cabinet.door_0'
handle = door_handle_name(door, 'cabinet.drawer_0')
open_door(door, handle)
detect_objects()
pick_level('strawberry')
place_behind_door('strawberry', door)
