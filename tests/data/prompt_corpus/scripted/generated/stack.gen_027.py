# Task: put the wooden block on the brown box.
# Plan:
# 1. Detect the block and the box.
# 2. Open the gripper and grasp the block top-down at its middle; if it is wider than the gripper opens
#    (GraspError), take the adaptive grasp from above instead. Close the gripper, attach it.
# 3. Lift it well clear, higher than the box.
# 4. Get a place pose on top of the brown box, move there, open the gripper, detach the block, move up.

OBJECT = 'wooden_block'
BASE = 'brown_box'
LIFT_HEIGHT_M = 0.15
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]
DOWN = [0, 0, -1]


def grasp_pose_for(name: str) -> Pose:
    """A top-down grasp at the middle, or the adaptive grasp from above where it is too wide."""
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError as error:
        print(f'Central grasp of {name} failed ({error}); using the adaptive grasp')
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=DOWN)


def pick(name: str) -> None:
    """Grasp the object, attach it and lift it."""
    print(f'Picking {name}')
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_onto(name: str, support: str) -> None:
    """Set the held object down on top of the support, release it and move up."""
    print(f'Placing {name} on top of {support}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=support))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Stack the wooden block on the brown box."""
    detect_objects(object_list=[OBJECT, BASE])
    pick(OBJECT)
    place_onto(OBJECT, BASE)
    print(f'Done: {OBJECT} is on the {BASE}')


if __name__ == "__main__":
    main()
