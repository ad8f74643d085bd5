# Task: place the white medication bottle in the blue bowl.
# Plan:
# 1. Detect the bottle and the bowl.
# 2. Open the gripper, grasp the bottle top-down at its middle (a narrow cylinder), close the gripper,
#    attach it and lift it.
# 3. Get a place pose inside the blue bowl, move there, open the gripper, detach the bottle, move up.

OBJECT = 'white_medication_bottle'
CONTAINER = 'blue_bowl'
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]


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
    """Put the bottle in the bowl."""
    detect_objects(object_list=[OBJECT, CONTAINER])
    pick(OBJECT)
    place_into(OBJECT, CONTAINER)
    print(f'Done: {OBJECT} is in the {CONTAINER}')


if __name__ == "__main__":
    main()
