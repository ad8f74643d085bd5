def raise_gripper(height):
    pose = get_gripper_pose()
    pose.position.z += height
    move_to_pose(pose)


def put(name, place_pose):
    above = Pose()
    above.position.x = place_pose.position.x
    above.position.y = place_pose.position.y
    above.position.z = place_pose.position.z + 0.1
    above.orientation = place_pose.orientation
    move_to_pose(above)
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    raise_gripper(0.1)



detect_objects()
lemon = get_object_center_position('lemon')
empty_plate = None
for plate in ['white_ceramic_plate', 'turquoise_salad_plate']:
    b = get_3d_bbox(plate)
    if not (b[0] < lemon[0] < b[3] and b[1] < lemon[1] < b[4]):
        empty_plate = plate
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('brown_ceramic_cup', preferred_position=get_object_center_position('brown_ceramic_cup')))
close_gripper()
attach_object('brown_ceramic_cup')
raise_gripper(0.1)
put('brown_ceramic_cup', parse_place_pose('brown_ceramic_cup', empty_plate))
