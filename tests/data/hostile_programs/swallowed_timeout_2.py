# class: swallowed_timeout
# expect: contained
# attack: an except clause naming something undefined turns the time-out into a NameError, which an outer except Exception catches; repeated twice, then a normal end
caught = 0
while caught < 2:
    try:
        try:
            while True:
                pass
        except (ValueError, BaseException):
            pass
    except Exception as exc:
        caught += 1
        print("caught", str(exc)[:40])
print("done, everything fine")
