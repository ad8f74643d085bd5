# class: guard_bypass
# expect: refused
# attack: (working-tree import support, uncommitted) an import binds a name without a Name node: `from typing import List as RuntimeError` rebinds a builtin base that the class rules take to be the builtin (their rebound check reads Name, arg, def and except bindings only), so `class X(RuntimeError)` derives through typing's __mro_entries__
from typing import Dict as RuntimeError
import math as ValueError
class X(RuntimeError):
    pass
print(repr(X), repr(X()))
try:
    class Y(ValueError):
        pass
    print('Y made', repr(Y))
except Exception as exc:
    print('Y refused:', str(exc)[:100])
