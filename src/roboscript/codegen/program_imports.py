"""The imports a program may write though it needs none: ``import numpy as np``, ``import math``, ``from typing
import List``, ``import time``. LLMs write them out of habit, told or not, and a program is no less correct for them.

``numpy`` is the program's own ``np`` (:mod:`roboscript.codegen.program_numpy`), ``math`` its functions and
constants, ``typing`` the names type hints use (hints that mean nothing: :class:`TypeHint`), ``time`` its clocks
and ``sleep`` (a program waiting for something to settle: the wait counts against its time limit), ``random`` its
draws; no module object is handed over. Any other import, a relative one or ``import *`` is refused by the guard,
with what would be accepted.
"""

from __future__ import annotations

import ast
import math
import random
import time
from collections.abc import Callable

from roboscript.codegen.program_numpy import ProgramModule, program_numpy

TYPING_NAMES = (
    "Any", "Callable", "Dict", "FrozenSet", "Iterable", "Iterator", "List", "Mapping", "Optional", "Sequence", "Set",
    "Tuple", "Union",
)  # fmt: skip
TIME_NAMES = ("sleep", "time", "monotonic", "perf_counter")
RANDOM_NAMES = ("random", "uniform", "randint", "randrange", "choice", "choices", "shuffle", "sample", "gauss", "seed")
IMPORTABLE = ("numpy", "math", "typing", "time", "random")
SUBMODULES = ("numpy.linalg", "numpy.random")  # the only dotted names a program may import


def _members(name: str, module: object, names: tuple[str, ...]) -> ProgramModule:
    # Named so that no key of sys.modules starts with it: `from M import x`, x missing, looks up
    # sys.modules[M.__name__ + ".x"] (`from typing import io` gave the real typing.io).
    return ProgramModule(__name__=f"<{name}>", **{n: getattr(module, n) for n in names})


class TypeHint:
    """What ``typing``'s names are to a program: type hints that evaluate and mean nothing, ``List[int]`` and
    ``Optional[Pose]`` included. The real aliases pass attribute assignment on to the classes behind them
    (``Mapping.get = f`` replaced ``collections.abc.Mapping.get`` in the program's process)."""

    __slots__ = ("name",)

    def __init__(self, name: str):
        object.__setattr__(self, "name", name)

    def __getitem__(self, arguments: object) -> TypeHint:
        return self

    def __or__(self, other: object) -> TypeHint:
        return self

    __ror__ = __or__

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"typing.{self.name} cannot be changed")

    def __repr__(self) -> str:
        return f"typing.{self.name}"


def program_importer(np: ProgramModule | None = None) -> Callable[..., ProgramModule]:
    """The ``__import__`` of a program's builtins: ``numpy`` (and its submodules ``linalg`` and ``random``) gives
    ``np``; ``math``, ``typing``, ``time`` and ``random`` namespaces of the names listed; anything else an
    ``ImportError``."""
    np = np if np is not None else program_numpy()
    # Every module by its full name, fixed now: what the importer hands out never depends on what a program did
    # to a namespace since (it cannot change them either: ProgramModule).
    modules = {
        "numpy": np,
        "numpy.linalg": np.linalg,
        "numpy.random": np.random,
        "math": _members("math", math, tuple(n for n in dir(math) if not n.startswith("_"))),
        "typing": ProgramModule(__name__="<typing>", **{n: TypeHint(n) for n in TYPING_NAMES}),
        "time": _members("time", time, TIME_NAMES),
        "random": _members("random", random.Random(), RANDOM_NAMES),  # a generator of the program's own
    }

    def importer(name, globals=None, locals=None, fromlist=(), level=0):  # the builtin __import__'s signature
        if level != 0 or not _importable(str(name)):
            raise ImportError(f"a program may import only {', '.join(IMPORTABLE)}; {name!r} is not among them")
        # import numpy.linalg binds numpy; from numpy.linalg import norm takes norm from the submodule
        return modules[str(name)] if fromlist else modules[str(name).partition(".")[0]]

    return importer


def import_violations(node: ast.Import | ast.ImportFrom) -> list[str]:
    """Why an import statement may not stand (empty if it may)."""
    accepted = f"a program may import only {', '.join(IMPORTABLE)} (np and Pose are already there; everything else "
    accepted += "is a tool)"
    if isinstance(node, ast.ImportFrom):
        if node.level:
            return [f"relative imports are not allowed: {accepted}"]
        modules = [node.module or ""]
        if any(alias.name == "*" for alias in node.names):
            return [f"'from {node.module} import *' is not allowed: name what you use"]
    else:
        modules = [alias.name for alias in node.names]
    found = [f"import of {module!r} is not allowed: {accepted}" for module in modules if not _importable(module)]
    names = [n for alias in node.names for n in (alias.asname, alias.name if isinstance(node, ast.ImportFrom) else "")]
    found += [f"the name {n!r} is not allowed" for n in names if n and n.startswith("_")]
    return found


def _importable(module: str) -> bool:
    return module in IMPORTABLE or module in SUBMODULES
