# class: output_flood
# expect: contained
# attack: spams failing tool calls whose error echoes a 1 MB object name, as fast as it can until the time-out: anything on the tools' side that logs or records each call's error in full (a trial recording, a log line) grows by megabytes per call
name = "no_such_thing_" + "z" * 1_000_000
errors = 0
while True:
    try:
        get_object_pose(name)
    except Exception as exc:
        errors += 1
    try:
        get_object_name_list()
    except Exception as exc:
        errors += 1
