# class: guard_bypass
# expect: refused
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): nesting: type(type(x).__name__).__name__ and type of the namespace-like things
x = 1
print(type(type(x).__name__).__name__)
print(type(type).__name__ if False else "skip")
