"""Tool call binding: keyword aliases of the original system and argument errors that say what is valid."""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable

from roboscript.errors import UsageError, did_you_mean

# Keyword names that programs written for the original system use, and the names they stand for here.
ALIASES: dict[str, str] = {"obj_name": "object_name", "direction": "axis", "category_list": "object_list"}


class ToolCallError(UsageError, TypeError):
    """A tool was called with arguments that do not fit its signature."""


def tool(function: Callable) -> Callable:
    """Wraps a tool method so that aliases are accepted and a bad call names the tool's real signature."""
    signature = inspect.signature(function)
    params = [p for p in signature.parameters.values() if p.name != "self"]
    usage = f"{function.__name__}({', '.join(_describe(p) for p in params)})"

    @functools.wraps(function)
    def wrapper(self, *args, **kwargs):
        renamed = {}
        for key, value in kwargs.items():
            target = ALIASES.get(key, key) if key not in signature.parameters else key
            if target not in signature.parameters or target == "self":
                close = did_you_mean(key, [p.name for p in params], n=1, cutoff=0.6)
                hint = f" ({close})" if close else ""
                raise ToolCallError(
                    f"{function.__name__}() got an unexpected keyword argument {key!r}{hint}; use {usage}"
                )
            if target in renamed:
                raise ToolCallError(
                    f"{function.__name__}() got {target!r} twice (as {key!r} and {target!r}); use {usage}"
                )
            renamed[target] = value
        try:
            bound = signature.bind(self, *args, **renamed)
        except TypeError as exc:
            raise ToolCallError(f"{function.__name__}(): {exc}; use {usage}") from None
        return function(*bound.args, **bound.kwargs)

    wrapper.usage = usage  # type: ignore[attr-defined]
    wrapper.is_tool = True  # type: ignore[attr-defined]
    return wrapper


def _describe(p: inspect.Parameter) -> str:
    return p.name if p.default is inspect.Parameter.empty else f"{p.name}={p.default!r}"
