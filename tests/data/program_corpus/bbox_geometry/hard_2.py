# Everything on the table that is not furniture or the basket goes into the basket.
detect_objects()
basket = 'basket_with_fabric_liner'
table_top = get_3d_bbox('table')[5]
for name in get_object_name_list():
    if name in ('table', basket) or name.startswith('cabinet'):
        continue
    if get_3d_bbox(name)[2] > table_top + 0.05:
        continue  # not standing on the table
    open_gripper()
    grasp(parse_central_lift_grasp_pose(name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.15)
    move_to_pose(parse_place_pose(name, receptacle_name=basket))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
