# class: guard_bypass
# expect: contained
# attack: except ... as __builtins__ / __checked_format__ / __warningregistry__ binds dunder globals (the handler's name is not a Name node), then defines and calls functions inside the handler
results = []
try:
    raise ValueError("x")
except ValueError as __builtins__:
    def inner():
        return len([1, 2])
    try:
        results.append(inner())
    except Exception as exc:
        results.append(str(exc)[:60])
try:
    raise KeyError("y")
except KeyError as __checked_format__:
    try:
        results.append("{}".format(1))
    except Exception as exc:
        results.append(str(exc)[:60])
try:
    raise ValueError("z")
except ValueError as __warningregistry__:
    results.append(np.log(np.zeros(1)))
print(results)
print(get_object_name_list())
