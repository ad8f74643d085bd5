# class: unbounded_trusted_work
# expect: contained
# attack: a path of two poses, one of them 10000 km away (finite, so every check passes): cartesian_path on the tools' side interpolates the whole straight line into 5 mm steps before it solves the first IK, a list of 2*10**9 Transforms that grows by some 30 MB a second until the time limit (2.5 GB after a minute, ~10 GB at the default 300 s) or TRIAL_MEMORY; the frame that asks for it is 300 bytes, and move_in_direction's 1.5 m cap does not apply to poses
grip = get_gripper_pose()
far = Pose([1e7, 0.0, 0.3], [0, 1, 0, 0])
for call in (lambda: follow_path([grip, far]), lambda: follow_path([far, grip, far]), lambda: move_to_pose(far), lambda: grasp(far)):
    try:
        call()
        print("returned")
    except Exception as exc:
        print("refused:", str(exc)[:200])
