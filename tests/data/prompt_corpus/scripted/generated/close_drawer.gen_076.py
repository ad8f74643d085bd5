# Task: close the open drawer.
# Plan:
# 1. Detect everything. The cabinet has, from the top, drawer_0 (handle_0), drawer_1 (handle_1) and
#    door_0 (handle_2); only the two drawers are candidates.
# 2. Read each drawer's prismatic joint (nearest its handle) and take the one open the most; if none is
#    open, there is nothing to do.
# 3. Open the gripper, grasp that drawer's handle horizontally, close the gripper and attach the drawer.
# 4. Push along -axis by as far as it is open (the axis points out of the cabinet).
# 5. Open the gripper, detach the drawer and back away along +axis.
# 6. Look again and report how far the drawer is still open.

DRAWER_HANDLES = {
    'cabinet.drawer_0': 'cabinet.handle_0',
    'cabinet.drawer_1': 'cabinet.handle_1',
}
OPEN_THRESHOLD_M = 0.01
BACK_OFF_M = 0.05


def drawer_joint(drawer: str) -> dict:
    """The prismatic joint of the drawer, found near its handle."""
    handle_center = get_object_center_position(DRAWER_HANDLES[drawer])
    return get_object_joint_info(object_name=drawer, position=handle_center, type='prismatic')


def find_open_drawer() -> str:
    """Name of the drawer open the most, or None when every drawer is shut."""
    openings = {drawer: drawer_joint(drawer)['joint_value'] for drawer in DRAWER_HANDLES}
    for drawer, value in openings.items():
        print(f'{drawer} is open {value:.3f} m')
    drawer = max(openings, key=openings.get)
    return drawer if openings[drawer] > OPEN_THRESHOLD_M else None


def close_drawer(drawer: str) -> None:
    """Grasp the drawer's handle and push the drawer shut."""
    handle = DRAWER_HANDLES[drawer]
    joint = drawer_joint(drawer)
    axis = np.array(joint['joint_axis'])
    distance = float(joint['joint_value'])
    print(f'Grasping {handle} to push {drawer} shut by {distance:.3f} m')
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(axis, -distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, BACK_OFF_M)


def main() -> None:
    """Close whichever drawer is open."""
    detect_objects()
    drawer = find_open_drawer()
    if drawer is None:
        print('No drawer is open; nothing to close')
        return
    close_drawer(drawer)
    detect_objects([drawer, DRAWER_HANDLES[drawer]])
    print(f'{drawer} is now open {drawer_joint(drawer)["joint_value"]:.3f} m')


if __name__ == "__main__":
    main()
