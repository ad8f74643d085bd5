# class: guard_bypass
# expect: contained
# attack: builds dunder templates and names the guard cannot see: f-string pieces around a variable, str.translate of a harmless-looking template, keyword names with double underscores
u = "_"
template = f"{{0.{u}{u}globals{u}{u}[os].environ[ROBOSCRIPT_TEST_SECRET]}}"
translated = "{0.QQglobalsQQ[sys].argv}".translate(str.maketrans("Q", "_"))
for t in (template, translated):
    try:
        print(t.format(get_object_center_position))
    except Exception as exc:
        print("refused:", str(exc)[:80])
try:
    print(dict(__builtins__=1, __class__=2))
    print(get_object_pose(object_name="apple", __class__=Pose))
except Exception as exc:
    print("refused:", str(exc)[:80])
