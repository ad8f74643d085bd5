# class: format_walk
# expect: contained
# attack: .format taken without a call (map, sorted key, a stored bound method) so a rewrite of x.format(...) calls never sees it
u = "_" * 2
template = "{0." + u + "globals" + u + "[os].environ[ROBOSCRIPT_TEST_SECRET]}"
walk = template.format
print(list(map(template.format, [get_object_name_list])))
print(sorted([get_object_pose], key=template.format))
print(walk(detect_objects))
print(max([open_gripper], key=template.format))
