# class: pickle_into_trusted
# expect: contained
# attack: re-arms a tool's own exception (UnknownObjectError) with new args and passes it to a tool: unpickling calls its constructor on the tools' side, which joins 4000 shared 1 MB names (4 GB)
try:
    get_object_pose("unicorn")
except Exception as error:
    caught = error
big = "x" * 1_000_000
caught.args = ("apple", [big] * 4000)
try:
    caught.known = [big] * 4000
except Exception:
    pass
try:
    detect_objects([caught])
except Exception as exc:
    print("tool said:", str(exc)[:200])
try:
    get_object_pose(caught)
except Exception as exc:
    print("tool said:", str(exc)[:200])
