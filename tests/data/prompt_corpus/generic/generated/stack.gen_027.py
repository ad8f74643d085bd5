# Task: put the wooden block on the brown box
# Plan:
# 1. Detect everything; a dict maps the object to move to the object it goes on top of.
# 2. Pick the block (top-down when narrow enough, else adaptive from above) and lift it so that its
#    bottom clears the box's top by about 5 cm (at least 10 cm up).
# 3. Place it on top of the box (stacking on a flat top), release it and move up.
def grasp_pose_for(name):
    box = get_3d_bbox(name)
    narrow = min(box[3] - box[0], box[4] - box[1]) < 0.07
    if narrow and 'mug' not in name and 'cup' not in name:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put(name, receptacle=None, position=None, retreat=0.1):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


detect_objects()
on_top_of = {'wooden_block': 'brown_box'}
for name, support in on_top_of.items():
    clearance = get_3d_bbox(support)[5] - get_3d_bbox(name)[2] + 0.05
    pick(name, lift=max(0.1, clearance))
    put(name, receptacle=support)
