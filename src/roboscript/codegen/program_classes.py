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
from collections import Counter
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


def class_builtins() -> dict[str, object]:
    """What running a class statement needs beyond a program's builtins; the guard lets a program name none of
    these but as a method's decorator or in ``super().__init__(...)``."""
    names = ("__build_class__", "super", *sorted(METHOD_DECORATORS))
    return {name: getattr(builtins, name) for name in names}


@dataclass
class ClassFindings:
    """What the general rules would refuse that a class may hold, by node id: names and attributes, and dunder
    methods (``allowed``), methods whose decorators are all allowed (``decorated``); and what a class holds that
    it may not (``violations``: line and message)."""

    allowed: set[int] = field(default_factory=set)
    decorated: set[int] = field(default_factory=set)
    violations: list[tuple[int, str]] = field(default_factory=list)


def class_findings(tree: ast.AST) -> ClassFindings:
    """What the program's classes may and may not hold (:class:`ClassFindings`)."""
    found = ClassFindings()
    classes = [node for node in ast.walk(tree) if isinstance(node, ast.ClassDef)]
    own = {node.name for node in classes}
    rebound = _rebound(tree, own)
    for node in classes:
        _check_class(node, own, rebound, found)
        for item in node.body:
            if isinstance(item, ast.FunctionDef):
                _check_method(item, found)
    for node in ast.walk(tree):
        if _is_super_init(node):
            found.allowed |= {id(node.value.func), id(node)}
        elif _is_private_of_self(node):
            found.allowed.add(id(node))
    return found


def _check_class(node: ast.ClassDef, own: set[str], rebound: set[str], found: ClassFindings) -> None:
    line = node.lineno
    if node.keywords:
        found.violations.append((line, f"class {node.name}: class keywords (metaclass=...) are not allowed"))
    if node.decorator_list:
        found.violations.append((line, f"class {node.name}: decorators on a class are not allowed"))
    for base in node.bases:
        name = base.id if isinstance(base, ast.Name) else None
        if name is None or name not in own | BUILTIN_BASES or name in rebound:
            found.violations.append(
                (line, f"class {node.name} may extend only object, an exception such as RuntimeError, or a class "
                       f"the program defines, got {ast.unparse(base)}")
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


def _is_super_init(node: ast.AST) -> bool:
    """``super().__init__`` (the attribute, to be called)."""
    return (
        isinstance(node, ast.Attribute)
        and node.attr == "__init__"
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


def _rebound(tree: ast.AST, own: set[str]) -> set[str]:
    """Names a base may not be, though they look like one: a program's class defined twice or bound otherwise too,
    a builtin base bound by the program (a base must be the class its name promises)."""
    classes = Counter(node.name for node in ast.walk(tree) if isinstance(node, ast.ClassDef))
    other = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store | ast.Del):
            other.add(node.id)
        elif isinstance(node, ast.arg):
            other.add(node.arg)
        elif isinstance(node, ast.FunctionDef | ast.ExceptHandler) and node.name:
            other.add(node.name)
    twice = {name for name in own if classes[name] > 1}
    return twice | (other & own) | (BUILTIN_BASES & (other | set(classes)))


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
