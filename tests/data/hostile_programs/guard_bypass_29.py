# class: guard_bypass
# expect: contained
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): `except ... as type` and `import math as type` make `type` own; then pass the leaked function around
try:
    raise ValueError("x")
except ValueError as type:
    pass
import math as type
def k():
    return type
print(k())
