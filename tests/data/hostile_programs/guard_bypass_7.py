# class: guard_bypass
# expect: contained
# attack: a function with a duplicated parameter name parses (only the compiler's symbol table refuses it), and the trial's static checker turns each definition into an inspect.Signature, which raises ValueError("duplicate parameter name") uncaught in the trial's process: the trial ends as "could not be run" rather than as a syntax error
def place(target, target):
    return target


def grip(name, /, *, name=None):
    return name


place("apple", "footed_bowl")
