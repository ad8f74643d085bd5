# class: swallowed_timeout
# expect: contained
# attack: a finally clause that continues the loop swallows each time-out exception; after two it ends on its own, so the run reports success after running past its limit
swallowed = 0
while swallowed < 2:
    try:
        total = 0
        while True:
            total += 1
    finally:
        swallowed += 1
        continue
print("finished normally after", swallowed, "time-outs")
