"""What a generated program may contain: an allow-list of syntax and a deny-list of attribute names.

The guard is static: it reads the program's syntax tree before anything runs. With the restricted builtins of
:mod:`roboscript.codegen.sandbox` it closes the usual ways out of an ``exec`` namespace: imports, dunder and
private attributes (``__class__``, ``__subclasses__``, ``__globals__``), frame and code objects (``gi_frame``,
``f_back``, ``f_globals``), and numpy's file and pointer access (``np.load``, ``arr.tofile``, ``arr.ctypes``).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from roboscript.codegen.checked_calls import uncalled_checked_methods
from roboscript.codegen.program_classes import RESERVED, bindings, class_findings
from roboscript.codegen.program_imports import import_violations

ALLOWED_NODES: tuple[type[ast.AST], ...] = (
    ast.alias,  # only inside an import, which is reported itself
    ast.Module, ast.Expr, ast.Assign, ast.AugAssign, ast.AnnAssign, ast.Pass, ast.Break, ast.Continue,
    ast.If, ast.For, ast.While, ast.Try, ast.ExceptHandler, ast.Raise, ast.Assert, ast.Delete, ast.Global,
    ast.Nonlocal, ast.NamedExpr,
    ast.FunctionDef, ast.ClassDef, ast.Return, ast.Lambda, ast.arguments, ast.arg, ast.keyword,
    ast.Name, ast.Load, ast.Store, ast.Del, ast.Starred, ast.Attribute, ast.Subscript, ast.Slice,
    ast.Constant, ast.List, ast.Tuple, ast.Dict, ast.Set, ast.JoinedStr, ast.FormattedValue,
    ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp, ast.comprehension,
    ast.Call, ast.BoolOp, ast.BinOp, ast.UnaryOp, ast.Compare, ast.IfExp,
    ast.And, ast.Or, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv, ast.Mod, ast.Pow, ast.MatMult,
    ast.UAdd, ast.USub, ast.Not, ast.Invert, ast.BitAnd, ast.BitOr, ast.BitXor, ast.LShift, ast.RShift,
    ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt, ast.GtE, ast.Is, ast.IsNot, ast.In, ast.NotIn,
)  # fmt: skip

# Not reachable through underscores, yet ways out: frames, code objects, generators' internals, numpy's files,
# pointers and pickles, and the names of dangerous modules should one ever be reachable.
FORBIDDEN_ATTRIBUTES = frozenset(
    {
        "gi_frame", "gi_code", "gi_yieldfrom", "cr_frame", "cr_code", "cr_await", "ag_frame", "ag_code",
        "f_back", "f_globals", "f_locals", "f_builtins", "f_code", "f_trace", "tb_frame", "tb_next",
        "co_code", "co_consts", "co_names", "func_globals", "func_code", "mro",
        "load", "loads", "save", "savez", "savez_compressed", "savetxt", "loadtxt", "genfromtxt", "fromfile",
        "tofile", "dump", "dumps", "memmap", "open_memmap", "fromregex", "DataSource", "ctypes", "ctypeslib",
        "lib", "core", "f2py", "distutils", "testing", "os", "sys", "subprocess", "builtins", "importlib",
        "system", "popen", "open", "exec", "eval", "compile", "globals", "locals", "vars", "getattr", "setattr",
        "delattr", "format_map",
        # numpy's raw memory: reinterpreting an array's bytes (as object pointers, too), reading them or their base
        "view", "tobytes", "tostring", "data", "base", "getfield", "setfield", "frombuffer", "fromstring", "cffi",
        "resize",
        "__array_interface__", "byte_bounds",
        # numpy's random generators: the C struct behind one (its state and function pointers), and its lock
        "capsule", "bit_generator", "lock",
    }
)  # fmt: skip

FORBIDDEN_NAMES = frozenset(
    {
        "eval", "exec", "compile", "open", "input", "breakpoint", "help", "globals", "locals", "vars", "dir",
        "getattr", "setattr", "delattr", "hasattr", "type", "object", "super", "memoryview", "classmethod",
        "staticmethod", "property", "exit", "quit", "copyright", "credits", "license", "os", "sys",
        "subprocess", "importlib", "builtins",
    }
)  # fmt: skip

_WHY = {
    ast.With: "with statements are not allowed (there are no files or resources to open)",
    ast.AsyncFunctionDef: "async code is not allowed",
    ast.Await: "async code is not allowed",
    ast.Yield: "generators (yield) are not allowed; return a list",
    ast.YieldFrom: "generators (yield) are not allowed; return a list",
}


@dataclass(frozen=True)
class Violation:
    """Something the program may not contain, with its line."""

    line: int
    message: str
    oversized: bool = False  # past a bound on the program's shape (work on it would be without bound)

    def __str__(self) -> str:
        return f"line {self.line}: {self.message}"


def find_violations(tree: ast.AST) -> list[Violation]:
    """Every forbidden construct in ``tree``, in the order they appear."""
    bound = bindings(tree)
    classes = class_findings(tree, bound)  # what a program's own classes may hold beyond the rules below
    # A builtin's name the program binds is its own variable (for object in objects:): the builtin is not among a
    # program's builtins, so where the binding does not reach, the name is unbound. Not those that are there. The
    # one exception, ``type``, is a builtin that gives a class's name and nothing else (sandbox.type_name), so a
    # program that binds ``type`` and reads it where its binding does not reach gets only that.
    own_names = set(bound) & FORBIDDEN_NAMES - RESERVED
    type_names = _type_names(tree)
    found = [Violation(line, message) for line, message in classes.violations]
    for node in ast.walk(tree):
        line = getattr(node, "lineno", 0)
        if isinstance(node, ast.Import | ast.ImportFrom):
            found += [Violation(line, message) for message in import_violations(node)]
            taken = [alias.name for alias in node.names] if isinstance(node, ast.ImportFrom) else []
            found += [Violation(line, f"the name {n!r} is not allowed") for n in taken if n in FORBIDDEN_ATTRIBUTES]
        elif isinstance(node, ast.Global | ast.Nonlocal) and any(n.startswith("__") for n in node.names):
            found.append(Violation(line, f"the names {', '.join(node.names)} are not all allowed"))
        elif not isinstance(node, ALLOWED_NODES):
            why = _WHY.get(type(node), f"{type(node).__name__} is not allowed in a program")
            found.append(Violation(line, why))
        elif isinstance(node, ast.Name | ast.Attribute) and id(node) in classes.allowed:
            continue
        elif isinstance(node, ast.Attribute) and _forbidden_attribute(node):
            found.append(Violation(line, f"the attribute .{node.attr} is not allowed"))
        elif isinstance(node, ast.Name) and (
            (node.id in READABLE_NAMES and isinstance(node.ctx, ast.Load)) or id(node) in type_names
        ):
            continue
        elif isinstance(node, ast.Name) and (node.id.startswith("__") or node.id in FORBIDDEN_NAMES - own_names):
            found.append(Violation(line, f"the name {node.id!r} is not allowed"))
        elif isinstance(node, _NAMED) and _name_of(node).startswith("__") and id(node) not in classes.allowed:
            # def __f, f(__x=1), except E as __b, class __C; a class's __init__ is allowed
            found.append(Violation(line, f"the name {_name_of(node)!r} is not allowed"))
        elif isinstance(node, ast.ExceptHandler) and node.type is None:
            found.append(Violation(line, "a bare except: is not allowed; name what to catch, e.g. except Exception:"))
        elif isinstance(node, ast.FunctionDef) and node.decorator_list and id(node) not in classes.decorated:
            found.append(Violation(line, "decorators are not allowed"))
        elif isinstance(node, ast.Constant) and _dunder_template(node.value):
            # str.format reads attributes named in its template: "{0.__class__}".format(x)
            found.append(Violation(line, "format strings may not name dunder attributes"))
        elif isinstance(node, ast.arguments) and (count := _parameters(node)) > MAX_PARAMETERS:
            found.append(Violation(line, f"a function of {count} parameters; at most {MAX_PARAMETERS}", True))
        elif isinstance(node, ast.Call) and (count := len(node.args) + len(node.keywords)) > MAX_CALL_ARGUMENTS:
            found.append(Violation(line, f"a call with {count} arguments; at most {MAX_CALL_ARGUMENTS}", True))
        elif isinstance(node, ast.Attribute) and node.attr in ASSIGN_ONLY_ATTRIBUTES and not _loads(node):
            found.append(Violation(line, f"assigning .{node.attr} is not allowed (it reinterprets an array's memory)"))
    found += [
        Violation(line, f"take .{method} only to call it on the spot: x.{method}(...)")
        for line, method in uncalled_checked_methods(tree)
    ]
    return sorted(found, key=lambda v: v.line)


# Dunder names a program may read: a string (a script's `if __name__ == "__main__":`).
READABLE_NAMES = frozenset({"__name__"})

# Dunder attributes a program may read: a string, and nothing to be reached from it (a defensive program's
# messages name the function that failed, ``make_grasp.__name__``).
READABLE_DUNDERS = frozenset({"__name__"})


def _type_names(tree: ast.AST) -> set[int]:
    """The ``type`` names that stand in ``type(x).__name__``, the one use of ``type`` a program has: the class's
    name in a message (``f"{type(e).__name__}: {e}"``); any other use of the name is refused, and at run time
    ``type`` gives nothing but that name (:func:`roboscript.codegen.sandbox.type_name`)."""
    out = set()
    for node in ast.walk(tree):
        call = node.value if isinstance(node, ast.Attribute) and node.attr == "__name__" else None
        if (
            isinstance(call, ast.Call)
            and isinstance(call.func, ast.Name)
            and call.func.id == "type"
            and len(call.args) == 1
            and not isinstance(call.args[0], ast.Starred)
            and not call.keywords
        ):
            out.add(id(call.func))
    return out


def _forbidden_attribute(node: ast.Attribute) -> bool:
    if node.attr in READABLE_DUNDERS and isinstance(node.ctx, ast.Load):
        return False
    return node.attr.startswith("_") or node.attr in FORBIDDEN_ATTRIBUTES


# Bounds on a program's shape: past them, compiling it (CPython's symbol tables copy a function's names into every
# scope nested in it) and binding its calls grow with their product.
MAX_PARAMETERS = 64
MAX_CALL_ARGUMENTS = 256


def _parameters(node: ast.arguments) -> int:
    return len(node.posonlyargs) + len(node.args) + len(node.kwonlyargs) + bool(node.vararg) + bool(node.kwarg)


# Attributes a program may read but not assign: numpy reinterprets an array's memory when they change.
ASSIGN_ONLY_ATTRIBUTES = frozenset({"dtype", "strides"})


def _loads(node: ast.Attribute) -> bool:
    return isinstance(node.ctx, ast.Load)


def _dunder_template(value: object) -> bool:
    return isinstance(value, str) and "{" in value and "__" in value


_NAMED = (ast.FunctionDef, ast.ClassDef, ast.arg, ast.ExceptHandler, ast.keyword)


def _name_of(node: ast.FunctionDef | ast.ClassDef | ast.arg | ast.ExceptHandler | ast.keyword) -> str:
    if isinstance(node, ast.FunctionDef | ast.ClassDef | ast.ExceptHandler):
        return node.name or ""
    return node.arg or ""
