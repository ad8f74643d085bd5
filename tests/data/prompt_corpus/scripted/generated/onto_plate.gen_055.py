# Task: place the lime onto the pink saucer.
# Plan:
# 1. Detect the lime and the pink saucer.
# 2. Open the gripper, grasp the lime top-down at its middle, close the gripper, attach it and lift it.
# 3. Get a place pose on the pink saucer, move there, open the gripper, detach the lime and move up.

OBJECT = 'lime'
SAUCER = 'pink_saucer'
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


def place_onto(name: str, receptacle: str) -> None:
    """Set the held object down on the receptacle, release it and move up."""
    print(f'Placing {name} onto {receptacle}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Put the lime on the pink saucer."""
    detect_objects(object_list=[OBJECT, SAUCER])
    pick(OBJECT)
    place_onto(OBJECT, SAUCER)
    print(f'Done: {OBJECT} is on the {SAUCER}')


if __name__ == "__main__":
    main()
