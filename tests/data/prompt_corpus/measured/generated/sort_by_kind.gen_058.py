# Task: sort the objects on the table by kind: put the fruits on the red plate.
# Plan:
# 1. Kinds are known only from names: the fruits are the names with a fruit word (here the plum and the
#    strawberry); the medication bottle, the golf ball and the white-and-pink box are not fruits and stay, as do
#    the basket, the plate and the bowl.
# 2. Skip any fruit already over the plate (centre within the plate's box).
# 3. Compute a spot on the plate for each: its centre for one, else spots a quarter of the plate's size from
#    the centre, so the fruits do not land on each other.
# 4. For each: re-detect, grasp from above (central; adaptive if that fails), lift, place at its spot on the red
#    plate, release, move up.
# 5. Detect again and print which fruits lie over the plate.

STAYS = ('basket', 'plate', 'saucer', 'bowl')
FRUITS = ('apple', 'banana', 'lemon', 'lime', 'orange', 'peach', 'pear', 'plum', 'strawberry', 'grape', 'mango',
          'kiwi', 'cherry', 'apricot')


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


def spots_on(box, n):
    c = box_centre(box)
    c[2] = box[5]
    if n <= 1:
        return [c]
    qx, qy = (box[3] - box[0]) / 4, (box[4] - box[1]) / 4
    if n == 2:
        offsets = [(0.0, qy), (0.0, -qy)]
    else:
        offsets = [(qx, qy), (qx, -qy), (-qx, qy), (-qx, -qy)]
    spots = [c + np.array([dx, dy, 0.0]) for dx, dy in offsets]
    return [spots[i % len(spots)] for i in range(n)]


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def over(c, box):
    return box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4]


detect_objects()
plate = get_3d_bbox('red_plate')
fruits = [n for n in get_object_name_list()
          if n != 'table' and not n.startswith('cabinet') and not any(word in n for word in STAYS)
          and any(word in FRUITS for word in n.split('_'))]
to_move = [n for n in fruits if not over(get_object_center_position(n), plate)]
print('fruits:', fruits, '; to move:', to_move)
spots = spots_on(plate, len(to_move))

for name, spot in zip(to_move, spots):
    detect_objects()
    open_gripper()
    grasp(top_grasp_pose(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='red_plate', position=list(spot)))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    print('put', name, 'on the red plate near', np.round(spot, 3))

detect_objects()
plate = get_3d_bbox('red_plate')
for name in fruits:
    print(name, 'over the red plate:', over(get_object_center_position(name), plate))
