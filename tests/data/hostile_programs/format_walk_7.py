# class: format_walk
# expect: contained
# attack: templates that are not plain str when formatted: numpy's str_ scalars taken out of arrays (and their class's format called with one), a template reached through a nested spec built at run time, index fields ("{0[__class__]}") where the walk is spelled with brackets, and f-string specs computed while the program runs
u = "_" * 2
walk = "{0." + u + "globals" + u + "[os].environ[ROBOSCRIPT_TEST_SECRET]}"
texts = np.array([walk, "{0:{1." + u + "class" + u + "}}", "{0[" + u + "class" + u + "]}"])
for template in texts:
    for call in (
        lambda: template.format(get_object_pose, get_object_pose),
        lambda: texts.dtype.type.format(template, print, print),
        lambda: str(template).format(np.linalg.norm, np.linalg.norm),
    ):
        try:
            print("formatted:", call()[:80])
        except Exception as exc:
            print("refused:", str(exc)[:80])
spec = ">" + "1" * 3
print(f"{'x':{spec}}"[:5])
try:
    print(f"{get_object_pose!r:{walk}}")
except Exception as exc:
    print("refused:", str(exc)[:80])
print("%(name)s" % {"name": walk})
