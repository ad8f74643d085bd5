# Open the drawer: approach its handle head-on, against the drawer front's normal, pull along the joint axis.
detect_objects()
handle_position = get_object_center_position('cabinet.handle_1')
normal = get_plane_normal('cabinet.drawer_1', handle_position)
joint = get_object_joint_info('cabinet', handle_position, type='prismatic')
axis = np.array(joint['joint_axis'])
if np.dot(axis, normal) < 0:
    axis = -axis  # pull out of the cabinet, the way its front faces
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1', approach_direction=-normal))
close_gripper()
attach_object('cabinet.drawer_1')
move_in_direction(axis, 0.2)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(normal, 0.1)

for box in [n for n in get_object_name_list() if n.endswith('box')]:
    grasp(parse_adaptive_shape_grasp_pose(box, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(box)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(box, 'cabinet.drawer_1'))
    open_gripper()
    detach_object(box)
    move_in_direction([0, 0, 1], 0.1)
