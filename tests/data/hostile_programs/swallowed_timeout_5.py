# class: swallowed_timeout
# expect: contained
# attack: spins at the recursion limit, so the timer's Python handler cannot even be called (no frame left for it): the signal becomes a RecursionError that the program catches, twice, then it ends normally


def spin_at_limit(depth, state):
    try:
        return spin_at_limit(depth + 1, state)
    except Exception:
        if state["bottom"]:
            raise
        state["bottom"] = True
        while True:
            pass


swallowed = 0
while swallowed < 2:
    try:
        spin_at_limit(0, {"bottom": False})
    except Exception:
        swallowed += 1
print("ended normally after", swallowed, "signals turned into recursion errors")
