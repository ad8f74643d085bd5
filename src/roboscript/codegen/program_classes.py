"""A program's own classes, as an LLM writes them: what the guard lets through, and how they run.

A plain class with methods (``class Robot:`` keeping what it holds in ``self.held``), an exception of its own
(``class GraspFailed(RuntimeError): pass``), ``__init__`` calling ``super().__init__(message)``, ``@staticmethod``
and ``@property``, private state in ``self._held``. What would let a class hook the interpreter or reach past the
guard stays out: metaclasses and class keywords, bases other than ``object``, the exceptions a program may raise
and its own classes, other decorators, dunder methods other than :data:`CLASS_DUNDERS`.

``self._x`` is renamed ``self.private_x`` before the program runs: a method called with another object as ``self``
(``Robot.pick(np)``) then reads no private attribute of anything but the program's own instances.
"""

from __future__ import annotations

import ast
import builtins
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field

CLASS_DUNDERS = frozenset({"__init__", "__repr__", "__str__"})
METHOD_DECORATORS = frozenset({"staticmethod", "classmethod", "property"})
# Builtin classes a program's class may extend (its exceptions); its own classes, too.
BUILTIN_BASES = frozenset(
    {
        "object", "Exception", "ArithmeticError", "AssertionError", "IndexError", "KeyError", "LookupError",
        "RuntimeError", "StopIteration", "TypeError", "ValueError", "ZeroDivisionError", "NotImplementedError",
    }
)  # fmt: skip
PRIVATE_PREFIX = "private_"
# Builtins a program's class statements need: a program may name them only where the guard allows, never bind them.
RESERVED = frozenset({"__build_class__", "super", *METHOD_DECORATORS})


def class_builtins() -> dict[str, object]:
    """What running a class statement needs beyond a program's builtins: ``__build_class__`` checking bases as
    the class is made (:func:`class_builder`), ``super`` and the method decorators. The guard lets a program
    name these only in ``super().__init__(...)`` and as a method's decorator, and bind none of them."""
    plain = {name: getattr(builtins, name) for name in RESERVED - {"__build_class__"}}
    return {"__build_class__": class_builder(), **plain}


def class_builder() -> Callable[..., type]:
    """``__build_class__`` for one program: a base must be ``object``, one of :data:`BUILTIN_BASES`, or a class
    this program made, whatever its name was bound to when the guard read it (a name can be shadowed where the
    guard cannot follow it); no class keywords."""
    allowed = tuple(getattr(builtins, name) for name in sorted(BUILTIN_BASES))
    made: list[weakref.ref] = []

    def build_class(func: Callable, name: str, *bases: object, **keywords: object) -> type:
        if keywords:
            raise TypeError(f"class {name}: class keywords are not allowed")
        for base in bases:
            if not any(base is a for a in allowed) and not any(base is ref() for ref in made):
                raise TypeError(
                    f"class {name} may extend only object, an exception such as RuntimeError, or a class the "
                    f"program defines, not a {type(base).__name__}"
                )
        cls = builtins.__build_class__(func, name, *bases)
        made.append(weakref.ref(cls))
        return cls

    return build_class


@dataclass
class ClassFindings:
    """What the general rules would refuse that a class may hold, by node id: names and attributes, and dunder
    methods (``allowed``), methods whose decorators are all allowed (``decorated``); and what a class holds that
    it may not (``violations``: line and message)."""

    allowed: set[int] = field(default_factory=set)
    decorated: set[int] = field(default_factory=set)
    violations: list[tuple[int, str]] = field(default_factory=list)


def class_findings(tree: ast.Module, bound: dict[str, tuple[int, int]]) -> ClassFindings:
    """What the program's classes may and may not hold (:class:`ClassFindings`); ``bound``: its
    :func:`bindings`."""
    found = ClassFindings()
    for name in sorted(RESERVED & bound.keys()):
        found.violations.append((bound[name][0], f"the name {name!r} is reserved: a program may not bind it"))
    # The bases the guard can vouch for: classes the module defines once, at its top, and binds no other way; the
    # builtin ones the program does not bind (object is dropped from bases before the program runs, bound or not).
    own = {
        node.name for node in tree.body if isinstance(node, ast.ClassDef) and bound[node.name][1] == 1
    }
    allowed_bases = own | BUILTIN_BASES - {n for n in BUILTIN_BASES - {'object'} if n in bound}
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef):
            _check_class(node, allowed_bases, found)
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    _check_method(item, found)
        elif _is_private_of_self(node):
            found.allowed.add(id(node))
    return found


def _check_class(node: ast.ClassDef, allowed_bases: set[str], found: ClassFindings) -> None:
    line = node.lineno
    if node.keywords:
        found.violations.append((line, f"class {node.name}: class keywords (metaclass=...) are not allowed"))
    if node.decorator_list:
        found.violations.append((line, f"class {node.name}: decorators on a class are not allowed"))
    for base in node.bases:
        name = base.id if isinstance(base, ast.Name) else None
        if name is None or name not in allowed_bases:
            got = repr(name) if name is not None else f"an expression ({type(base).__name__})"
            found.violations.append(
                (line, f"class {node.name} may extend only object, an exception such as RuntimeError, or a class "
                       f"the program defines at its top, got {got}")
            )
        elif name == "object":
            found.allowed.add(id(base))


def _check_method(node: ast.FunctionDef, found: ClassFindings) -> None:
    if node.name.startswith("__"):
        if node.name in CLASS_DUNDERS:
            found.allowed.add(id(node))
        else:
            allowed = ", ".join(sorted(CLASS_DUNDERS))
            found.violations.append((node.lineno, f"the method {node.name} is not allowed; of the dunder methods "
                                                  f"a class may define {allowed}"))
    decorators = [d for d in node.decorator_list if isinstance(d, ast.Name) and d.id in METHOD_DECORATORS]
    if decorators and len(decorators) == len(node.decorator_list):
        found.decorated.add(id(node))
        found.allowed |= {id(d) for d in decorators}
    for call in _own_nodes(node):
        if isinstance(call, ast.Call) and _is_super_init(call.func):
            found.allowed |= {id(call.func), id(call.func.value.func)}


def _own_nodes(method: ast.FunctionDef) -> list[ast.AST]:
    """The nodes of a method's body, not those of functions, lambdas or classes inside it (there ``super()`` has
    no class to go by)."""
    out, stack = [], list(method.body)
    while stack:
        node = stack.pop()
        out.append(node)
        if not isinstance(node, ast.FunctionDef | ast.Lambda | ast.ClassDef):
            stack.extend(ast.iter_child_nodes(node))
    return out


def _is_super_init(node: ast.AST) -> bool:
    """``super().__init__``, read to be called."""
    return (
        isinstance(node, ast.Attribute)
        and node.attr == "__init__"
        and isinstance(node.ctx, ast.Load)
        and isinstance(node.value, ast.Call)
        and isinstance(node.value.func, ast.Name)
        and node.value.func.id == "super"
        and not node.value.args
        and not node.value.keywords
    )


def _is_private_of_self(node: ast.AST) -> bool:
    """``self._x``: one leading underscore, on the name ``self``."""
    return (
        isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "self"
        and node.attr.startswith("_")
        and not node.attr.startswith("__")
    )


def bindings(tree: ast.AST) -> dict[str, tuple[int, int]]:
    """Every name the program binds, however (assignment, loop, argument, function, class, handler, import): the
    line of its first binding and how many there are."""
    found: dict[str, tuple[int, int]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store | ast.Del):
            names = [node.id]
        elif isinstance(node, ast.arg):
            names = [node.arg]
        elif isinstance(node, ast.FunctionDef | ast.ClassDef | ast.ExceptHandler) and node.name:
            names = [node.name]
        elif isinstance(node, ast.alias):
            names = [node.asname or node.name.partition(".")[0]]
        elif isinstance(node, ast.Global | ast.Nonlocal):
            names = list(node.names)
        else:
            continue
        for name in names:
            line, count = found.get(name, (getattr(node, "lineno", 0), 0))
            found[name] = (line, count + 1)
    return found


class _Rewriter(ast.NodeTransformer):
    def visit_ClassDef(self, node: ast.ClassDef) -> ast.AST:
        self.generic_visit(node)
        node.bases = [b for b in node.bases if not (isinstance(b, ast.Name) and b.id == "object")]
        return node

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        self.generic_visit(node)
        if _is_private_of_self(node):
            node.attr = PRIVATE_PREFIX + node.attr[1:]
        return node


def rewrite_classes(tree: ast.Module) -> ast.Module:
    """``tree`` ready to run: ``object`` dropped from bases (a program's builtins have no ``object``), ``self._x``
    renamed (changed in place, and returned)."""
    return ast.fix_missing_locations(_Rewriter().visit(tree))
