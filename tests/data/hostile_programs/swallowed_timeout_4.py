# class: swallowed_timeout
# expect: contained
# attack: a return inside finally in a recursive function: each time-out ends one busy loop and the finally starts the next one a level deeper, then the program returns normally


def stubborn(depth):
    try:
        count = 0
        while True:
            count += 1
    finally:
        if depth < 1:
            return stubborn(depth + 1)
        return depth


levels = stubborn(0)
print("survived", levels, "time-outs")
