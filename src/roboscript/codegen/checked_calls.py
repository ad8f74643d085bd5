"""Method calls a program makes that are checked while it runs: ``x.format(...)`` and ``x.astype(...)``.

The guard cannot know what ``x`` will be, so such a call is rewritten into a helper's call with ``x`` first
(``__checked_format__(x, ...)``): a template's fields are read before formatting
(:mod:`roboscript.codegen.format_check`), an array's new dtype may not hold objects or records
(:mod:`roboscript.codegen.program_numpy`).
The helpers' names begin with underscores, which no program may write; the method taken without being called on
the spot (``f = str.format``) is refused by the guard, as it would escape the check.
"""

from __future__ import annotations

import ast
from collections.abc import Callable

from roboscript.codegen.format_check import checked_format
from roboscript.codegen.program_numpy import checked_astype

CHECKED_METHODS: dict[str, str] = {"format": "__checked_format__", "astype": "__checked_astype__"}


def helpers() -> dict[str, Callable]:
    """The helpers by the names rewritten calls use: they belong in a program's builtins."""
    return {CHECKED_METHODS["format"]: checked_format, CHECKED_METHODS["astype"]: checked_astype}


class _Rewriter(ast.NodeTransformer):
    def visit_Call(self, node: ast.Call) -> ast.AST:
        self.generic_visit(node)
        func = node.func
        if isinstance(func, ast.Attribute) and func.attr in CHECKED_METHODS and isinstance(func.ctx, ast.Load):
            helper = ast.copy_location(ast.Name(CHECKED_METHODS[func.attr], ast.Load()), func)
            return ast.copy_location(ast.Call(helper, [func.value, *node.args], node.keywords), node)
        return node


def rewrite_checked_calls(tree: ast.Module) -> ast.Module:
    """``tree`` with its checked method calls routed through the helpers (changed in place, and returned)."""
    return ast.fix_missing_locations(_Rewriter().visit(tree))


def uncalled_checked_methods(tree: ast.AST) -> list[tuple[int, str]]:
    """Where a checked method is taken without being called on the spot: (line, method)."""
    called = {id(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
    return [
        (node.lineno, node.attr)
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute) and node.attr in CHECKED_METHODS and id(node) not in called
    ]
