# class: guard_bypass
# expect: contained
# attack: the name type, allowed only as type(x).__name__ (an adversarial review of that allowance): build a template from a type name and format it (checked at run time)
x = 1
tpl = "{0." + type(x).__name__[:0] + "_" * 2 + "class" + "_" * 2 + "}"
try:
    print(tpl.format(x))
except Exception as e:
    print(type(e).__name__, e)
