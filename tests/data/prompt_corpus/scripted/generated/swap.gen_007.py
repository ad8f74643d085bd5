# Task: exchange the places of the brown box and the red block.
# Plan:
# 1. Detect everything and remember where the box and the block stand before anything moves.
# 2. Move the red block aside onto a free spot of the table (parse_place_pose with 'table' keeps its
#    old place free).
# 3. Move the brown box to where the block stood.
# 4. Move the red block to where the box stood.
# Grasps: top-down at the middle; where an object is wider than the gripper opens (GraspError), the
# adaptive grasp from above instead.

BOX = 'brown_box'
BLOCK = 'red_block'
LIFT_HEIGHT_M = 0.10
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


def release(name: str) -> None:
    """Open the gripper, detach the object and move up."""
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def move_aside(name: str) -> None:
    """Move the object to a free spot of the table away from where it stood."""
    pick(name)
    print(f'Setting {name} aside on the table')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='table'))
    release(name)


def move_to(name: str, position: np.ndarray) -> None:
    """Move the object so that its middle stands above the given position."""
    pick(name)
    print(f'Placing {name} at x={position[0]:.3f}, y={position[1]:.3f}')
    move_to_pose(parse_place_pose(object_name=name, position=list(position)))
    release(name)


def main() -> None:
    """Swap the brown box and the red block."""
    detect_objects()
    box_at = get_object_center_position(BOX)
    block_at = get_object_center_position(BLOCK)
    move_aside(BLOCK)
    move_to(BOX, block_at)
    move_to(BLOCK, box_at)
    print(f'Done: {BOX} and {BLOCK} have swapped places')


if __name__ == "__main__":
    main()
