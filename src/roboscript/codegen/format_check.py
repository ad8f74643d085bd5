"""``str.format`` with templates a program builds at run time: fields may not read attributes.

A format field walks attributes (``"{0.__class__}"``), so a template is a way past the guard's ban on dunder
attributes when it is assembled while the program runs. Every ``x.format(...)`` call is routed through
:func:`checked_format` (:mod:`roboscript.codegen.checked_calls`), which reads the template's fields first.
``format_map`` is forbidden outright.
"""

from __future__ import annotations

import string

from roboscript.errors import UsageError


class FormatTemplateError(UsageError, ValueError):
    """A format template whose fields read attributes."""


def checked_format(owner: object, *args, **kwargs) -> object:
    """``owner.format(*args, **kwargs)``, for a str template only after its fields were checked."""
    if isinstance(owner, str):
        _check_template(owner)
        return owner.format(*args, **kwargs)
    if isinstance(owner, type) and issubclass(owner, str):  # str.format(template, ...), np.str_.format(...)
        if not args or not isinstance(args[0], str):
            raise TypeError("str.format() needs a template string first")
        _check_template(args[0])
        return str.format(*args, **kwargs)
    if isinstance(owner, type):
        raise FormatTemplateError(f"{owner.__name__}.format cannot be called with a template; use template.format()")
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
