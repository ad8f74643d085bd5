# class: guard_bypass
# expect: refused
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): __class__ of the result
x = 1
print(type(x).__class__)
