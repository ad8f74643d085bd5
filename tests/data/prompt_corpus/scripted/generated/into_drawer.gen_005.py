# Task: put the toy car into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. Detect everything. The cabinet has three drawers; the second from the top is cabinet.drawer_1,
#    with cabinet.handle_1.
# 2. Open the gripper, grasp handle_1 horizontally, close the gripper and attach the drawer.
# 3. Read its prismatic joint near the handle and pull along +axis as far as it opens.
# 4. Open the gripper, detach the drawer and back away along +axis.
# 5. Look again at the drawer, which moved.
# 6. Grasp the toy car top-down at its middle (across its length), close, attach and lift it.
# 7. Place it into the open drawer, open the gripper, detach it and move up.

DRAWER = 'cabinet.drawer_1'
HANDLE = 'cabinet.handle_1'
OBJECT = 'toy_car'
BACK_OFF_M = 0.05
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.08
UP = [0, 0, 1]


def drawer_joint() -> dict:
    """The drawer's prismatic joint, found near its handle."""
    handle_center = get_object_center_position(HANDLE)
    return get_object_joint_info(object_name=DRAWER, position=handle_center, type='prismatic')


def open_drawer() -> None:
    """Grasp the handle and pull the drawer out as far as it opens."""
    joint = drawer_joint()
    axis = np.array(joint['joint_axis'])
    distance = float(joint['joint_upper']) - float(joint['joint_value'])
    print(f'Pulling {DRAWER} open by {distance:.3f} m')
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=HANDLE))
    close_gripper()
    attach_object(DRAWER)
    move_in_direction(axis, distance)
    open_gripper()
    detach_object(DRAWER)
    move_in_direction(axis, BACK_OFF_M)
    detect_objects([DRAWER, HANDLE])


def pick(name: str) -> None:
    """Grasp the object from above at its middle, attach it and lift it."""
    print(f'Picking {name}')
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_into(name: str, receptacle: str) -> None:
    """Set the held object down in the receptacle, release it and move up."""
    print(f'Placing {name} into {receptacle}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Open the second drawer and put the toy car into it."""
    detect_objects()
    open_drawer()
    pick(OBJECT)
    place_into(OBJECT, DRAWER)
    print(f'Done: {OBJECT} is in {DRAWER}')


if __name__ == "__main__":
    main()
