# class: guard_bypass
# expect: refused
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): SimpleNamespace's dunders on the result: __dict__, __class__, __reduce__
x = 1
print(type(x).__dict__)
