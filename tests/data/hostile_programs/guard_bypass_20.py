# class: guard_bypass
# expect: contained
# attack: `from M import name` falls back, when the object M's import returned has no such attribute, on sys.modules[f"{obj.__name__}.{name}"] (CPython's import_from, for circular imports). The program's np is the object `from numpy.linalg import` reads linalg of, and its attributes may be assigned: np.linalg = a function named roboscript, then `from numpy.linalg import codegen` is sys.modules['roboscript.codegen'], the real package; from its modules, real numpy, real typing (and operator.attrgetter, which reads any attribute by a string), the real builtins and __import__
def roboscript():
    pass
np.linalg = roboscript
from numpy.linalg import codegen
print('package:', codegen)
sandbox = codegen.sandbox
print('sandbox module:', sandbox)
real_typing = codegen.program_imports.typing
attrgetter = real_typing.operator.attrgetter
real_builtins = attrgetter('builtins')(sandbox)
print('builtins module:', real_builtins)
imp = attrgetter('__import__')(real_builtins)
print('import:', imp)
opener = attrgetter('open')(real_builtins)
print('open:', opener)
frame = attrgetter('_getframe')(attrgetter('sys')(sandbox))(0)
print('frame:', frame)
print('subclasses of object:', len(attrgetter('__subclasses__')(attrgetter('object')(real_builtins))()))
print('real numpy:', codegen.jail.np, codegen.jail.np.ndarray)
