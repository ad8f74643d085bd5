"""The ``np`` a program gets: maths on arrays of numbers, without files, pointers or raw memory.

An allow-list of numpy's functions, with ``linalg`` and ``random`` trimmed the same way. None of these functions
hands a program an array of Python objects or of raw records: a ``dtype`` argument naming ``object``, a structured
or a void type is refused before the call, and a result holding one is refused after it (``np.array([1, None])``).
Methods of arrays and of random generators can still make object arrays (``a.cumsum(dtype="O")``,
``rng.permutation([1, None])``): they are values, not pointers, once nothing can reinterpret an array's memory.
``np.ndarray`` answers ``isinstance`` but cannot be called (its ``buffer=`` argument reads any memory). The guard
forbids what is left: reinterpreting an array's memory (``.view``, assigning ``.dtype``, ``.getfield``), its bytes
(``.tobytes``, ``.data``), its pointers (``.ctypes``) and resizing it in place (``.resize``, which can leave views
on freed memory); ``.astype`` is checked as it runs (:mod:`roboscript.codegen.checked_calls`).
"""

from __future__ import annotations

import functools
import types
from collections.abc import Callable

import numpy as np

from roboscript.errors import UsageError

NUMPY_NAMES = (
    "array", "asarray", "zeros", "ones", "full", "eye", "arange", "linspace", "empty", "zeros_like", "ones_like",
    "concatenate", "stack", "vstack", "hstack", "column_stack", "reshape", "transpose", "flip", "roll", "tile",
    "repeat", "where", "argmin", "argmax", "argsort", "sort", "unique", "clip", "abs", "absolute", "sign", "sqrt",
    "square", "exp", "log", "log2", "log10", "sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "hypot",
    "degrees", "radians", "deg2rad", "rad2deg", "pi", "e", "inf", "nan", "isnan", "isfinite", "isclose",
    "allclose", "dot", "cross", "outer", "inner", "matmul", "sum", "prod", "mean", "median", "std", "var", "min",
    "max", "minimum", "maximum", "amin", "amax", "floor", "ceil", "round", "around", "rint", "mod", "cumsum",
    "diff", "all", "any", "logical_and", "logical_or", "logical_not", "count_nonzero", "nonzero",
    "float64", "float32", "int64", "int32", "bool_", "newaxis", "interp", "percentile", "trace", "diag",
)  # fmt: skip
LINALG_NAMES = ("norm", "inv", "pinv", "det", "solve", "eig", "svd", "lstsq")
RANDOM_NAMES = ("default_rng", "uniform", "normal", "rand", "randn", "randint", "choice", "seed")
SCALAR_TYPES = frozenset(("float64", "float32", "int64", "int32", "bool_"))


class ObjectArrayError(UsageError, TypeError):
    """A program asked numpy for an array of objects or raw records."""


def program_numpy() -> ProgramModule:
    """A fresh ``np`` namespace for one program."""
    submodules = {
        "ndarray": _ndarray_type(),
        "linalg": _namespace("np.linalg", np.linalg, LINALG_NAMES),
        "random": _namespace("np.random", np.random, RANDOM_NAMES),
    }
    return _namespace("np", np, NUMPY_NAMES, submodules)


def numpy_names() -> frozenset[str]:
    """Every attribute of the program's ``np`` (for the static checker)."""
    return frozenset((*NUMPY_NAMES, "ndarray", "linalg", "random"))


def _namespace(
    name: str, module: types.ModuleType, names: tuple[str, ...], extra: dict[str, object] | None = None
) -> ProgramModule:
    members: dict[str, object] = {"__name__": name, **(extra or {})}
    for member in names:
        if not hasattr(module, member):
            continue
        value = getattr(module, member)
        if module is np.random and member in SEEDED:
            value = _seeded(value, member)
        members[member] = value if member in SCALAR_TYPES or not callable(value) else _checked(value, member)
    return ProgramModule(**members)


class ProgramModule(types.SimpleNamespace):
    """A namespace a program reads and cannot change: made once (its ``__init__`` called again refuses), no
    attribute set or deleted. Nothing numpy honours (``__array_interface__``) can be planted on ``np``, and no
    member replaced by an object of the program's (a function named after a real package, which ``from np.x
    import y`` would look up in ``sys.modules``)."""

    def __init__(self, **members: object):
        if self.__dict__:
            raise TypeError("a program's module cannot be made again")
        for key, value in members.items():
            object.__setattr__(self, key, value)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"{getattr(self, '__name__', 'this module')} cannot be changed: set {name!r} elsewhere")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"{getattr(self, '__name__', 'this module')} cannot be changed")


# Take a seed: numpy also takes a bit generator there, or anything with a ``capsule`` attribute, whose C struct it
# copies (state and function pointers: a freed generator's, refilled with the program's bytes, ran native code).
SEEDED = frozenset(("default_rng", "seed"))


def _seeded(function: Callable, name: str) -> Callable:
    """``function`` taking a seed only: None, an int, or a list of ints."""

    @functools.wraps(function)
    def call(seed=None):
        if not _plain_seed(seed):
            raise TypeError(f"np.random.{name}(): a seed is None, an int or a list of ints, not {type(seed).__name__}")
        return function(seed)

    return call


def _plain_seed(seed: object) -> bool:
    if seed is None or (isinstance(seed, int | np.integer) and not isinstance(seed, bool)):
        return True
    if isinstance(seed, np.ndarray):
        return seed.dtype.kind in "iu"
    return isinstance(seed, list | tuple) and all(isinstance(v, int | np.integer) for v in seed)


def _checked(function: Callable, name: str) -> Callable:
    """``function`` refusing object and record dtypes in its arguments and its result."""

    @functools.wraps(function)
    def call(*args, **kwargs):
        _refuse_dtype_arguments(args, kwargs, f"np.{name}()")
        result = function(*args, **kwargs)
        _refuse_objects(result, name)
        return result

    if isinstance(function, np.ufunc):  # np.maximum.reduce and the like: the ufunc's own methods
        for method in ("reduce", "accumulate", "outer", "reduceat"):
            setattr(call, method, _checked(getattr(function, method), f"{name}.{method}"))
    return call


def _refuse_dtype_arguments(args: tuple, kwargs: dict, call: str) -> None:
    for value in (*args, *kwargs.values()):
        if _names_a_forbidden_dtype(value):
            raise ObjectArrayError(f"{call}: arrays of objects or records are not available; use numbers")


def _names_a_forbidden_dtype(value: object) -> bool:
    if value is object:
        return True
    if isinstance(value, np.dtype):
        return _forbidden(value)
    if isinstance(value, type) and issubclass(value, np.generic):
        return _forbidden(np.dtype(value))
    if isinstance(value, str) and len(value) < 16:  # 'O', 'object', 'V8', ...
        try:
            return _forbidden(np.dtype(value))
        except TypeError:
            return False
    if isinstance(value, list) and value and all(isinstance(v, tuple) for v in value):  # [('a', 'O')]
        try:
            return _forbidden(np.dtype(value))
        except (TypeError, ValueError):
            return False
    return False


def _forbidden(dtype: np.dtype) -> bool:
    return dtype.hasobject or dtype.kind == "V" or dtype.fields is not None


def _refuse_objects(result: object, name: str) -> None:
    parts = result if isinstance(result, tuple) else (result,)
    for part in parts:
        if isinstance(part, np.ndarray | np.generic) and _forbidden(part.dtype):
            raise ObjectArrayError(
                f"np.{name}() would make an array of Python objects (a list that mixes numbers with None, "
                "strings or other things?); arrays must hold numbers"
            )


def checked_astype(owner: object, *args, **kwargs) -> object:
    """``owner.astype(*args, **kwargs)``, refusing object and record dtypes in its arguments and its result,
    whatever ``owner`` is (an array, or a numpy type called with the array first: ``np.float64.astype(x, "V8")``)."""
    _refuse_dtype_arguments(args, kwargs, "astype()")
    result = owner.astype(*args, **kwargs)
    _refuse_objects(result, "ndarray.astype")
    return result


class _ArrayType(type):
    def __instancecheck__(cls, instance: object) -> bool:
        return isinstance(instance, np.ndarray)

    def __subclasscheck__(cls, subclass: type) -> bool:
        return isinstance(subclass, type) and issubclass(subclass, np.ndarray)


def _ndarray_type() -> type:
    def refuse(cls, *args, **kwargs):
        raise TypeError("np.ndarray(...) cannot be called in a program; make arrays with np.array, np.zeros, ...")

    return _ArrayType("ndarray", (), {"__new__": refuse, "__doc__": "isinstance(x, np.ndarray) only."})
