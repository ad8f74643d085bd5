# class: guard_bypass
# expect: contained
# attack: no attribute needed: the program raises the tools' failure class itself for its own bug (an index past a list's end), and the outcome is planning_failure, not runtime_error
names = ['apple']
try:
    second = names[1]
except IndexError as exc:
    raise GraspError('no grasp fits the ' + str(exc))
