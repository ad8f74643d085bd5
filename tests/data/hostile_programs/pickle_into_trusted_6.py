# class: pickle_into_trusted
# expect: contained
# attack: keyword names no Python call spelled out can have (a space, a digit first, an empty name, a lone surrogate, 'self') passed with ** to tools: the program's encoder sends any string key, the tools' side takes a key that is not an identifier for a forged frame and stops the process as a sandbox violation, so a program can decide to end as sandbox_violation (or a careless one ends so) without breaking anything
pose = get_gripper_pose()
for keywords in ({"self": pose}, {"object name": "apple"}, {"1st": "apple"}, {"": "apple"}, {chr(0xD800): "apple"}):
    try:
        print(get_object_pose(**keywords))
    except Exception as exc:
        print("refused:", str(exc)[:100])
print("still running")
