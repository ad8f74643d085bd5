# class: guard_bypass
# expect: contained
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): with the leaked type_name: what can a SimpleNamespace instance give without dunders? slice/eq/repr/isinstance/np
def never():
    global type
t = type
ns = t(0)
ns.shape = (2,)
print(repr(ns), ns == t(1), ns == t(2.0), isinstance(ns, int), t(t).__name__)
s = slice(ns, t, ns)
print(s.start is ns, s.stop)
try:
    print(np.array(ns))
except Exception as e:
    print(type(e).__name__, e)
try:
    print(np.asarray([ns, 1]))
except Exception as e:
    print(type(e).__name__, e)
try:
    print(t(value=ns, extra=1))
except Exception as e:
    print(type(e).__name__, e)
