"""``str.format`` with templates a program builds at run time: fields may not read attributes.

A format field walks attributes (``"{0.__class__}"``), so a template is a way past the guard's ban on dunder
attributes when it is assembled while the program runs. The guard rewrites every ``x.format(...)`` call into
:func:`checked_format`, which reads the template's fields first, and refuses ``.format`` taken without a call
(``f = str.format``). ``format_map`` is forbidden outright.
"""

from __future__ import annotations

import ast
import string

from roboscript.errors import UsageError

FORMAT_HELPER = "__checked_format__"  # the rewritten calls' name: a program cannot name it (leading underscores)


class FormatTemplateError(UsageError, ValueError):
    """A format template whose fields read attributes."""


def checked_format(owner: object, *args, **kwargs) -> object:
    """``owner.format(*args, **kwargs)``, for a str template only after its fields were checked."""
    if isinstance(owner, str):
        _check_template(owner)
        return owner.format(*args, **kwargs)
    if owner is str:  # str.format(template, ...)
        if not args or not isinstance(args[0], str):
            raise TypeError("str.format() needs a template string first")
        _check_template(args[0])
        return str.format(*args, **kwargs)
    return owner.format(*args, **kwargs)


def _check_template(template: str, depth: int = 0) -> None:
    if depth > 2:
        raise FormatTemplateError("format specifications are nested too deeply")
    try:
        fields = list(string.Formatter().parse(template))
    except ValueError as exc:
        raise FormatTemplateError(f"not a valid format template: {exc}") from None
    for _, field, spec, _ in fields:
        if field and "." in field:
            raise FormatTemplateError(
                f"format fields may not read attributes ({{{field[:40]}}}); format the value itself, e.g. f'{{x}}'"
            )
        if spec and "{" in spec:
            _check_template(spec, depth + 1)


class FormatCallRewriter(ast.NodeTransformer):
    """Turns ``x.format(a, b=c)`` into ``__checked_format__(x, a, b=c)``."""

    def visit_Call(self, node: ast.Call) -> ast.AST:
        self.generic_visit(node)
        func = node.func
        if isinstance(func, ast.Attribute) and func.attr == "format" and isinstance(func.ctx, ast.Load):
            helper = ast.copy_location(ast.Name(FORMAT_HELPER, ast.Load()), func)
            return ast.copy_location(ast.Call(helper, [func.value, *node.args], node.keywords), node)
        return node


def uncalled_format_lines(tree: ast.AST) -> list[int]:
    """Lines where ``.format`` is taken without being called on the spot."""
    called = {id(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
    return [
        node.lineno
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute) and node.attr == "format" and id(node) not in called
    ]


def rewrite_format_calls(tree: ast.Module) -> ast.Module:
    """``tree`` with its format calls checked at run time (changed in place, and returned)."""
    return ast.fix_missing_locations(FormatCallRewriter().visit(tree))
