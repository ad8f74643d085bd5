# class: output_flood
# expect: contained
# attack: makes a tool print in the trial's process, whose stdout is the command's: attach_object without a grasp makes the tools believe the apple is held, open_gripper then owes a retreat, and an upward move longer than the arm can reach prints "[retreat] backed off ... out of reach" from ToolAPI._own_retreat; repeated, each round adds a line in front of roboscript exec --json's one JSON document
rounds = 0
while rounds < 200:
    try:
        attach_object("apple")
        open_gripper()
        move_in_direction([0, 0, 1], 1.5)
        move_in_direction([0, 0, -1], 0.25)
        detach_object("apple")
        rounds += 1
    except Exception as exc:
        print(rounds, str(exc)[:200])
        break
print("rounds", rounds)
