# class: format_walk
# expect: contained
# attack: calls .format on numpy's str_ class (np.array(['x']).dtype.type), not on a str, so a run-time template check keyed on str is skipped
u = chr(95) * 2
text_type = np.array(["x"]).dtype.type
template = "{0." + u + "globals" + u + "[os].environ[ROBOSCRIPT_TEST_SECRET]}"
for root in (get_object_name_list, detect_objects):
    try:
        print("secret:", text_type.format(template, root))
    except Exception as exc:
        print("refused:", str(exc)[:80])
for template in (
    "{0." + u + "globals" + u + "[sys].argv} {0." + u + "globals" + u + "[sys].orig_argv}",
    "{0." + u + "globals" + u + "[os].environ}",
    "{0." + u + "globals" + u + "[sys].modules[os].environ}",
):
    try:
        print(text_type.format(template, print))
    except Exception as exc:
        print("refused:", str(exc)[:80])
