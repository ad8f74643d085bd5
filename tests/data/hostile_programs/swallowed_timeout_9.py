# class: swallowed_timeout
# expect: contained
# attack: an exception class whose __str__ never returns: the program's own error is raised before its time is up, and the sandbox formatting it (describe_exception) runs into the time limit inside the program's __str__, which also catches every Exception on the way
class Stuck(RuntimeError):
    def __str__(self):
        n = 0
        while True:
            try:
                n += 1
            except Exception:
                pass
        return 'never'
raise Stuck('x')
