# class: guard_bypass
# expect: contained
# attack: guard_bypass_2's import_from fallback by other names: np.random set to a class named numpy, then `from numpy.random import linalg` and `from numpy.random import random` are the real numpy.linalg and numpy.random modules (sys.modules['numpy.linalg'], ['numpy.random']); from the real numpy.random, real numpy (mtrand.np: ndarray, lib, ctypeslib) and operator.attrgetter (mtrand.operator), which reads any attribute; no function definition with an odd name needed
class numpy:
    pass
np.random = numpy
from numpy.random import linalg
from numpy.random import random
print('real linalg:', linalg)
print('real random:', random, random.mtrand)
real_numpy = random.mtrand.np
print('real numpy:', real_numpy, real_numpy.ndarray)
getter = random.mtrand.operator.attrgetter
print('via attrgetter:', getter('_core.multiarray')(real_numpy), getter('__globals__')(getter('seed')(random)) is not None)
