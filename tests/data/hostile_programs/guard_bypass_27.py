# class: guard_bypass
# expect: contained
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): declare `global type` in a never-called function: `type` becomes an "own name", so bare `type` reads the builtin type_name
def never():
    global type
t = type
ns = t(1)
print(t, t.__name__, ns, ns.__name__)
ns.anything = 5
print(ns)
