# Task: sort the objects on the table by kind: put the fruits on the red plate.
# Plan:
# 1. Detect everything.
# 2. The fruits are the objects whose name has a fruit word in it; here plum and strawberry (the
#    medication bottle, golf ball and box are not fruits; the basket, plate and bowl stay where they are).
# 3. For each fruit: grasp it top-down at its middle, close the gripper, attach it and lift it.
# 4. Place it on the red plate, open the gripper, detach it and move up.

PLATE = 'red_plate'
FRUIT_WORDS = (
    'apple', 'apricot', 'banana', 'cherry', 'grape', 'kiwi', 'lemon', 'lime', 'mango', 'orange',
    'peach', 'pear', 'plum', 'strawberry',
)
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]


def is_fruit(name: str) -> bool:
    """True where a word of the name is a fruit (``green_apple``, ``plum``)."""
    return any(word in FRUIT_WORDS for word in name.split('_'))


def fruits_on_table() -> list:
    """Names of the fruits among the known objects."""
    return [name for name in get_object_name_list() if is_fruit(name)]


def pick(name: str) -> None:
    """Grasp the object from above at its middle, attach it and lift it."""
    print(f'Picking {name}')
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_onto(name: str, receptacle: str) -> None:
    """Set the held object down on the receptacle, release it and move up."""
    print(f'Placing {name} onto {receptacle}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Put every fruit on the red plate."""
    detect_objects()
    fruits = fruits_on_table()
    print(f'Fruits: {fruits}')
    for name in fruits:
        pick(name)
        place_onto(name, PLATE)
    print(f'Done: {len(fruits)} fruits put on the {PLATE}')


if __name__ == "__main__":
    main()
