"""What crosses between a program's process and the tools: data only, in JSON, checked and bounded both ways.

Nothing from a program is unpickled or evaluated: a value is numbers, strings, booleans, None, lists, tuples,
dicts with string keys, numeric arrays (bool, integer and float dtypes, of bounded size and rank), and the API's
pose types (:class:`~roboscript.api.pose.Pose`, ``Point``, ``Quaternion``). Everything else is refused with an
error that says what may be passed. Encoding counts what it has produced and stops at its budget, so a value
that shares its parts (``[[big] * 1000] * 1000``) is refused after a bounded amount of work instead of growing;
decoding rebuilds at most what the bytes spell out, and JSON has no references.
"""

from __future__ import annotations

import base64
import json
import math

import numpy as np

from roboscript.api.pose import Point, Pose, Quaternion
from roboscript.errors import UsageError

MAX_DEPTH = 24  # nesting of lists, tuples and dicts
MAX_INT = 2**63  # a whole number's magnitude; larger ones are no tool's argument
MAX_ARRAY_RANK = 8
ARRAY_DTYPES = frozenset(
    ("bool", "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64", "float16", "float32", "float64")
)  # fmt: skip
TAG = "$"  # a JSON object is always a tagged value, never a bare dict


class WireError(UsageError, TypeError):
    """A value that cannot cross to or from the tools: its kind, its size or its form."""


class TooMuchData(WireError):
    """A value larger than the bytes it may take."""


def to_tree(value: object, budget: int) -> object:
    """``value`` as a JSON-ready tree; :class:`WireError` if it is not data or would take about more than
    ``budget`` bytes (counted as it is visited, so shared parts cannot multiply the work unseen)."""
    return _to_wire(value, 0, _Budget(budget))


def from_tree(tree: object) -> object:
    """The value a tree (parsed JSON) stands for; :class:`WireError` if it is not one :func:`to_tree` makes."""
    return _from_wire(tree, 0)


def encode(value: object, budget: int) -> bytes:
    """``value`` as JSON bytes; :class:`WireError` if it is not data or would take more than ``budget`` bytes."""
    data = json.dumps(to_tree(value, budget), separators=(",", ":"), allow_nan=True).encode()
    if len(data) > budget:
        raise TooMuchData(f"{len(data)} bytes of data; at most {budget}")
    return data


def decode(data: bytes, budget: int) -> object:
    """The value ``data`` encodes; :class:`WireError` if it is larger than ``budget`` or not a valid encoding."""
    if len(data) > budget:
        raise WireError(f"{len(data)} bytes of data; at most {budget}")
    try:
        tree = json.loads(data)
    except (ValueError, RecursionError, UnicodeDecodeError) as exc:
        raise WireError(f"not a valid encoding: {type(exc).__name__}: {str(exc)[:200]}") from None
    return from_tree(tree)


def describe(value: object) -> str:
    """A value's kind as a program's author would name it."""
    if callable(value):
        return f"a function ({type(value).__name__})"
    return f"a {type(value).__name__}"


# --- encoding --------------------------------------------------------------------------------------------------


class _Budget:
    """Bytes (roughly) that the encoding may still produce; spent as values are visited."""

    def __init__(self, limit: int):
        self.limit = self.left = limit

    def spend(self, amount: int) -> None:
        self.left -= amount
        if self.left < 0:
            raise TooMuchData(f"more than {self.limit} bytes of data")


WHAT_MAY_PASS = "numbers, strings, booleans, None, lists, tuples, dicts with string keys, arrays of numbers, poses"


def _to_wire(value: object, depth: int, budget: _Budget) -> object:
    if depth > MAX_DEPTH:
        raise WireError(f"data nested deeper than {MAX_DEPTH} levels")
    budget.spend(8)
    if value is None or isinstance(value, bool):
        return value
    if isinstance(value, int | np.integer):
        number = int(value)
        if abs(number) > MAX_INT:
            raise WireError(f"a whole number larger than 2**63 ({_digits(number)} digits)")
        return number
    if isinstance(value, float | np.floating):
        return float(value)
    if isinstance(value, str):
        budget.spend(len(value))
        return value
    if isinstance(value, list):
        return [_to_wire(item, depth + 1, budget) for item in value]
    if isinstance(value, tuple):
        return {TAG: "tuple", "v": [_to_wire(item, depth + 1, budget) for item in value]}
    if isinstance(value, set | frozenset):  # a set of names is a list of them to every tool
        return [_to_wire(item, depth + 1, budget) for item in sorted(value, key=repr)]
    if type(value) is dict:
        for key in value:
            if not isinstance(key, str):
                raise WireError(f"a dict with a key of type {type(key).__name__}; keys must be strings")
        return {TAG: "dict", "v": {key: _to_wire(item, depth + 1, budget) for key, item in value.items()}}
    if isinstance(value, np.ndarray):
        return _array_to_wire(value, budget)
    if isinstance(value, Pose):
        return {TAG: "pose", "v": [*map(float, value.position_array()), *map(float, value.quaternion_array())]}
    if isinstance(value, Point):
        return {TAG: "point", "v": [float(value.x), float(value.y), float(value.z)]}
    if isinstance(value, Quaternion):
        return {TAG: "quaternion", "v": [float(value.x), float(value.y), float(value.z), float(value.w)]}
    raise WireError(f"{describe(value)} cannot be passed; only data: {WHAT_MAY_PASS}")


def _array_to_wire(array: np.ndarray, budget: _Budget) -> dict:
    dtype = array.dtype
    if dtype.name not in ARRAY_DTYPES or dtype.fields is not None:
        kinds = ", ".join(sorted(ARRAY_DTYPES))
        raise WireError(f"an array of dtype {dtype.name!r}; arrays must hold numbers ({kinds})")
    if array.ndim > MAX_ARRAY_RANK:
        raise WireError(f"an array of {array.ndim} dimensions; at most {MAX_ARRAY_RANK}")
    budget.spend(array.size * dtype.itemsize * 4 // 3 + 64)
    raw = np.ascontiguousarray(array, dtype=dtype.newbyteorder("<")).tobytes()
    return {TAG: "array", "dtype": dtype.name, "shape": list(array.shape), "v": base64.b64encode(raw).decode()}


def _digits(number: int) -> int:
    return max(1, int(abs(number).bit_length() * math.log10(2)))


# --- decoding --------------------------------------------------------------------------------------------------


def _from_wire(tree: object, depth: int) -> object:
    if depth > MAX_DEPTH:
        raise WireError(f"data nested deeper than {MAX_DEPTH} levels")
    if tree is None or isinstance(tree, bool | float | str):
        return tree
    if isinstance(tree, int):
        if abs(tree) > MAX_INT:
            raise WireError("a whole number larger than 2**63")
        return tree
    if isinstance(tree, list):
        return [_from_wire(item, depth + 1) for item in tree]
    if not isinstance(tree, dict):
        raise WireError(f"unexpected JSON value of type {type(tree).__name__}")
    tag = tree.get(TAG)
    if tag == "tuple" and set(tree) == {TAG, "v"} and isinstance(tree["v"], list):
        return tuple(_from_wire(item, depth + 1) for item in tree["v"])
    if tag == "dict" and set(tree) == {TAG, "v"} and isinstance(tree["v"], dict):
        return {key: _from_wire(item, depth + 1) for key, item in tree["v"].items()}
    if tag == "array" and set(tree) == {TAG, "dtype", "shape", "v"}:
        return _array_from_wire(tree)
    if tag in _POSE_TYPES and set(tree) == {TAG, "v"}:
        cls, size = _POSE_TYPES[tag]
        numbers = _finite_numbers(tree["v"], size, tag)
        if cls is Pose:
            return Pose(numbers[:3], numbers[3:])
        return cls(*numbers)
    raise WireError(f"unknown tagged value {str(tag)[:40]!r}")


_POSE_TYPES: dict[str, tuple[type, int]] = {"pose": (Pose, 7), "point": (Point, 3), "quaternion": (Quaternion, 4)}


def _finite_numbers(numbers: object, size: int, tag: str) -> list[float]:
    """A pose type's numbers: ``size`` finite floats (what a pose holds; anything else was not made by one)."""
    if not (isinstance(numbers, list) and len(numbers) == size):
        raise WireError(f"a {tag} must be {size} numbers")
    values = []
    for number in numbers:
        if isinstance(number, bool) or not isinstance(number, int | float):
            raise WireError(f"a {tag} must be {size} numbers")
        try:
            value = float(number)
        except OverflowError:
            raise WireError(f"a {tag}'s number is too large") from None
        if not math.isfinite(value):
            raise WireError(f"a {tag}'s numbers must be finite")
        values.append(value)
    return values


def _array_from_wire(tree: dict) -> np.ndarray:
    dtype, shape, text = tree["dtype"], tree["shape"], tree["v"]
    if dtype not in ARRAY_DTYPES:
        raise WireError(f"an array of dtype {str(dtype)[:40]!r}; arrays must hold numbers")
    valid_shape = isinstance(shape, list) and len(shape) <= MAX_ARRAY_RANK
    if not valid_shape or not all(isinstance(n, int) and not isinstance(n, bool) and n >= 0 for n in shape):
        raise WireError(f"an array's shape must be at most {MAX_ARRAY_RANK} sizes")
    if not isinstance(text, str):
        raise WireError("an array's data must be base64 text")
    try:
        raw = base64.b64decode(text, validate=True)
    except ValueError:
        raise WireError("an array's data is not valid base64") from None
    kind = np.dtype(dtype).newbyteorder("<")
    if math.prod(shape) * kind.itemsize != len(raw):
        raise WireError(f"an array of shape {tuple(shape)} and dtype {dtype} cannot hold {len(raw)} bytes")
    return np.frombuffer(raw, dtype=kind).astype(dtype).reshape(shape)
