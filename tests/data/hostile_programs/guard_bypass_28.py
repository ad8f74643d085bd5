# class: guard_bypass
# expect: contained
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): a parameter named type makes `type` an own name anywhere: read bare `type` at module level -> the builtin type_name function
def f(type):
    return type
g = type
print(g, g(3.0).__name__, repr(g([])), g(g).__name__, g(g(1)).__name__)
