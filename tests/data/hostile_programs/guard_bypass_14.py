# class: guard_bypass
# expect: refused
# attack: a metaclass other than type through the bases: bases that are not classes (the print lambda, a tool, np, the sealed Pose) make __build_class__ call type(base)(name, bases, namespace); classes named like them exist only in a function that never runs, so the guard takes the names for the program's own
def never():
    class print:
        pass
    class np:
        pass
    class get_object_pose:
        pass
    class Pose:
        pass
    class len:
        pass
results = []
for make in ('print', 'np', 'tool', 'Pose', 'len'):
    try:
        if make == 'print':
            class M(print):
                pass
        elif make == 'np':
            class M(np):
                pass
        elif make == 'tool':
            class M(get_object_pose):
                pass
        elif make == 'Pose':
            class M(Pose):
                pass
        else:
            class M(len):
                pass
        results.append(make + ': made ' + repr(M)[:60])
    except Exception as exc:
        results.append(make + ': ' + str(exc)[:80])
print(results)
