# class: unbounded_trusted_work
# expect: contained
# attack: a 60-million-character object name: the unknown-name error runs difflib over it (an index list of 60 million ints) and echoes it whole in a message that travels back
name = "apple" + "pear" * 15_000_000
try:
    get_object_pose(name)
except Exception as exc:
    print("refused:", len(str(exc)))
try:
    attach_object(name)
except Exception as exc:
    print("refused:", len(str(exc)))
