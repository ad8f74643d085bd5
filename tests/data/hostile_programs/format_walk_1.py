# class: format_walk
# expect: contained
# attack: a str.format template assembled at run time from "_" * 2 walks a tool stand-in's __globals__ to os.environ and sys.argv
objects = get_object_name_list()
print("objects:", objects)
u = "_" * 2
template = "{0." + u + "globals" + u + "[os].environ[ROBOSCRIPT_TEST_SECRET]}"
try:
    print("secret:", template.format(get_object_pose))
except Exception as exc:
    print("refused:", str(exc)[:80])
for field in ("[os].environ", "[sys].argv", "[sys].orig_argv"):
    try:
        print(("{0." + u + "globals" + u + field + "}").format(detect_objects))
    except Exception as exc:
        print("refused:", str(exc)[:80])
