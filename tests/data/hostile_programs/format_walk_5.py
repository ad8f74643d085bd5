# class: format_walk
# expect: contained
# attack: a tool's exception is formatted with a template (built by str.replace) that follows its traceback into the stand-in's frame globals, and a nested format spec carries a second walk
try:
    get_object_pose("unicorn")
except Exception as error:
    template = "{0.XXtracebackXX.tb_next.tb_frame.f_globals[os].environ[ROBOSCRIPT_TEST_SECRET]}".replace("XX", "_" * 2)
    try:
        print(template.format(error))
    except Exception as exc:
        print("refused:", str(exc)[:80])
    spec = "{0:{1.XXtracebackXX.tb_next.tb_frame.f_globals[sys].argv}}".replace("XX", "_" * 2)
    try:
        print(spec.format("x", error))
    except Exception as exc:
        print("refused:", str(exc)[:80])
    flipped = "}]TERCES_TSET_TPIRCSOBOR[norivne.]so[slabolg_YY.0{".replace("YY", "_" * 2)[::-1]
    try:
        print(flipped.format(get_object_pose))
    except Exception as exc:
        print("refused:", str(exc)[:80])
