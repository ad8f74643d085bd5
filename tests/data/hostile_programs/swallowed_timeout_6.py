# class: swallowed_timeout
# expect: contained
# attack: after the time-out is swallowed, raises an exception whose message takes seconds to make (str of a large shared list), so the report is built past the limit
try:
    try:
        while True:
            pass
    except ProgramTimeoutThatIsNotDefined:
        pass
except Exception:
    pass
leaf = [0.123456789]
for level in range(23):
    leaf = [leaf, leaf]
raise ValueError(leaf)
