"""The static checker: every call is bound to a tool's signature or to a function the program defines, before
anything runs. Findings carry their line and category; unknown names come with the closest known ones."""

from __future__ import annotations

import ast
import builtins
import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from roboscript.api.program_errors import PROGRAM_ERRORS
from roboscript.api.signature import ALIASES
from roboscript.codegen.guard import find_violations
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.program_numpy import ProgramModule
from roboscript.codegen.sandbox import MAX_PROGRAM, PROGRAM_BUILTINS, parse_program, safe_numpy, shortened
from roboscript.errors import did_you_mean


@dataclass(frozen=True)
class Finding:
    line: int
    outcome: Outcome
    message: str

    def __str__(self) -> str:
        return f"line {self.line}: {self.message}"


@dataclass(frozen=True)
class CallSite:
    """A call of a name the program neither defines nor gets: what the function-generating agent is asked for."""

    name: str
    line: int
    source: str  # the statement the call is in


def tool_signatures() -> dict[str, inspect.Signature]:
    """The tool API's signatures (without ``self``), and ``Pose``'s constructor."""
    from roboscript.api import Pose, ToolAPI

    signatures = {}
    for name in ToolAPI.TOOL_NAMES:
        signatures[name] = _plain(inspect.signature(getattr(ToolAPI, name)), drop_first=True)
    signatures["Pose"] = _plain(inspect.signature(Pose))
    return signatures


def _plain(signature: inspect.Signature, drop_first: bool = False) -> inspect.Signature:
    """Without annotations, so that messages show ``f(a, b=1)`` as a program would write it."""
    params = list(signature.parameters.values())[1 if drop_first else 0 :]
    params = [p.replace(annotation=inspect.Parameter.empty) for p in params]
    return signature.replace(parameters=params, return_annotation=inspect.Signature.empty)


def check_program(program: str, tools: Mapping[str, inspect.Signature] | None = None) -> list[Finding]:
    """Every problem found without running ``program``; empty when it may run. Bounded work whatever the program:
    its size is bounded first, the guard bounds its functions' parameters and its calls' arguments."""
    tools = tool_signatures() if tools is None else tools
    if len(program) > MAX_PROGRAM:
        message = f"the program is {len(program)} characters long; at most {MAX_PROGRAM} (programs are short)"
        return [Finding(0, Outcome.SYNTAX, message)]
    try:
        tree = parse_program(program)
    except SyntaxError as exc:
        return [Finding(exc.lineno or 0, Outcome.SYNTAX, f"SyntaxError: {_short(exc.msg)}")]
    try:
        violations = find_violations(tree)
    except (ValueError, TypeError, RecursionError, MemoryError) as exc:  # a tree too odd to walk is no program
        return [Finding(0, Outcome.SYNTAX, f"SyntaxError: the program cannot be checked: {type(exc).__name__}")]
    findings = [Finding(v.line, Outcome.FORBIDDEN_CONSTRUCT, v.message) for v in violations]
    if any(v.oversized for v in violations):  # binding its calls would be work without bound
        return _capped(sorted(set(findings), key=_order))
    try:
        findings += _call_findings(tree, tools)
    except (ValueError, TypeError, RecursionError) as exc:  # def f(a, a): parses, but no signature has it
        findings.append(Finding(0, Outcome.SYNTAX, f"SyntaxError: {_short(str(exc))}"))
    except Exception as exc:  # hostile text must not crash the trial's process: it is refused, not run
        findings.append(Finding(0, Outcome.SYNTAX, f"SyntaxError: the program cannot be checked: {type(exc).__name__}"))
    return _capped(sorted({Finding(f.line, f.outcome, _short(f.message)) for f in findings}, key=_order))


def _order(finding: Finding) -> tuple[int, str]:
    return finding.line, finding.message


def _capped(found: list[Finding]) -> list[Finding]:
    """The first :data:`MAX_FINDINGS`, and one that says how many more there were."""
    if len(found) <= MAX_FINDINGS:
        return found
    left = found[MAX_FINDINGS]
    return [*found[:MAX_FINDINGS], Finding(left.line, left.outcome, f"... and {len(found) - MAX_FINDINGS} more")]


MAX_FINDING = 500  # characters of one finding's message
MAX_FINDINGS = 50  # findings reported at most: the first ones say what is wrong, the rest only grow the report


def _short(text: str) -> str:
    return shortened(text, MAX_FINDING)


def _call_findings(tree: ast.Module, tools: Mapping[str, inspect.Signature]) -> list[Finding]:
    findings: list[Finding] = []
    defined = _defined_functions(tree)
    known = _callable_names(tree, tools)
    numpy = safe_numpy()
    unknown: dict[str, str] = {}  # each unknown name's message, made once
    for call in (n for n in ast.walk(tree) if isinstance(n, ast.Call)):
        if len(findings) >= MAX_FINDINGS:
            break
        func = call.func
        if isinstance(func, ast.Name):
            name = func.id
            if name in defined:  # a program's own function may take a tool's name (its own move_in_direction)
                findings += _bind(call, name, defined[name], aliases=False)
            elif name in tools:
                findings += _bind(call, name, tools[name], aliases=True)
            elif name not in known:
                if name not in unknown:
                    unknown[name] = _unknown(name, set(tools) | set(defined) | PROGRAM_BUILTINS)
                findings.append(Finding(call.lineno, Outcome.UNKNOWN_FUNCTION, unknown[name]))
        elif isinstance(func, ast.Attribute) and (path := _numpy_path(func)) is not None:
            target = numpy
            for part in path[1:]:
                # Only the program's own namespaces are looked into, by their members: a getattr walk past them ran
                # numpy's properties in this, the trial's, process (np.random.rand.__wrapped__.__self__..., one of
                # which raised ImportError here), and the guard reports what starts with an underscore anyway.
                if not isinstance(target, ProgramModule) or part.startswith("_"):
                    break
                parent, target = target, vars(target).get(part)
                if target is None:
                    names = [n for n in vars(parent) if not n.startswith("_")]
                    message = f"np.{'.'.join(path[1:])} is not available to programs" + _closest(part, names)
                    findings.append(Finding(call.lineno, Outcome.UNKNOWN_FUNCTION, message))
                    break
    return findings


def undefined_calls(program: str, tools: Mapping[str, inspect.Signature] | None = None) -> list[CallSite]:
    """Calls of names that are neither tools, builtins, defined nor assigned: one per name, first call first."""
    tools = tool_signatures() if tools is None else tools
    tree = parse_program(program)
    known = _callable_names(tree, tools)
    lines = program.splitlines()
    sites: dict[str, CallSite] = {}
    for call in sorted((n for n in ast.walk(tree) if isinstance(n, ast.Call)), key=lambda n: n.lineno):
        if isinstance(call.func, ast.Name) and call.func.id not in known and call.func.id not in sites:
            sites[call.func.id] = CallSite(call.func.id, call.lineno, lines[call.lineno - 1].strip())
    return list(sites.values())


def _callable_names(tree: ast.AST, tools: Mapping[str, inspect.Signature]) -> set[str]:
    """Names a program may call: tools, builtins, the errors it may raise, its own functions, and names it assigns
    (a lambda, an alias)."""
    defined = set(_defined_functions(tree))
    # super: the guard lets a program call it only as super().__init__(...), in a class's method
    return set(tools) | PROGRAM_BUILTINS | {"super"} | set(PROGRAM_ERRORS) | defined | _assigned_names(tree)


def _bind(call: ast.Call, name: str, signature: inspect.Signature, aliases: bool) -> list[Finding]:
    if any(isinstance(a, ast.Starred) for a in call.args) or any(k.arg is None for k in call.keywords):
        return []  # *args / **kwargs: cannot be bound statically
    keywords = {}
    takes_any = any(p.kind is inspect.Parameter.VAR_KEYWORD for p in signature.parameters.values())
    for keyword in call.keywords:
        key = keyword.arg
        if aliases and key not in signature.parameters:
            key = ALIASES.get(key, key)
        if key not in signature.parameters and not takes_any:
            valid = ", ".join(signature.parameters)
            message = f"{name}() has no argument {keyword.arg!r}; its arguments are ({valid})"
            return [Finding(call.lineno, Outcome.BAD_ARGUMENTS, message + _closest(keyword.arg, signature.parameters))]
        keywords[key] = None
    try:
        signature.bind(*([None] * len(call.args)), **keywords)
    except TypeError as exc:
        return [Finding(call.lineno, Outcome.BAD_ARGUMENTS, f"{name}{signature}: {exc}")]
    return []


def _defined_functions(tree: ast.AST) -> dict[str, inspect.Signature]:
    """What the program defines that a bare name calls: its functions, and its classes with their ``__init__``'s
    parameters after ``self`` (a class without one takes anything: its base decides). A method is called on an
    object, never by a bare name: a method named as a tool does not hide the tool."""
    methods = {id(item) for node in ast.walk(tree) if isinstance(node, ast.ClassDef) for item in node.body}
    functions = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef) and id(node) not in methods:
            functions[node.name] = _signature_of(node.args)
        elif isinstance(node, ast.ClassDef):
            functions[node.name] = _constructor_of(node)
    return functions


def _constructor_of(node: ast.ClassDef) -> inspect.Signature:
    for item in node.body:
        if isinstance(item, ast.FunctionDef) and item.name == "__init__":
            signature = _signature_of(item.args)
            return signature.replace(parameters=list(signature.parameters.values())[1:])
    P = inspect.Parameter
    return inspect.Signature([P("args", P.VAR_POSITIONAL), P("kwargs", P.VAR_KEYWORD)])


def _signature_of(args: ast.arguments) -> inspect.Signature:
    P = inspect.Parameter
    params = []
    positional = args.posonlyargs + args.args
    defaults = [P.empty] * (len(positional) - len(args.defaults)) + list(args.defaults)
    for i, (arg, default) in enumerate(zip(positional, defaults, strict=True)):
        kind = P.POSITIONAL_ONLY if i < len(args.posonlyargs) else P.POSITIONAL_OR_KEYWORD
        params.append(P(arg.arg, kind, default=None if default is not P.empty else P.empty))
    if args.vararg:
        params.append(P(args.vararg.arg, P.VAR_POSITIONAL))
    for arg, default in zip(args.kwonlyargs, args.kw_defaults, strict=True):
        params.append(P(arg.arg, P.KEYWORD_ONLY, default=P.empty if default is None else None))
    if args.kwarg:
        params.append(P(args.kwarg.arg, P.VAR_KEYWORD))
    return inspect.Signature(params)


def _assigned_names(tree: ast.AST) -> set[str]:
    """Names bound by assignment, loops, comprehensions, arguments and exception handlers (callable values such as
    lambdas or functions kept in variables are legitimate to call)."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, ast.arg):
            names.add(node.arg)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            names.add(node.name)
        elif isinstance(node, ast.alias):  # import numpy as np, from math import sqrt
            names.add(node.asname or node.name.partition(".")[0])
    return names


def _numpy_path(node: ast.Attribute) -> list[str] | None:
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name) and node.id == "np":
        return ["np", *reversed(parts)]
    return None


def _unknown(name: str, known: set[str]) -> str:
    if hasattr(builtins, name):
        return f"{name}() is not available to programs"
    return f"unknown function {name}(): it is not a tool and the program does not define it" + _closest(name, known)


def _closest(name: str, candidates) -> str:
    close = did_you_mean(name, candidates, cutoff=0.6)
    return f" ({close})" if close else ""


Checker = Callable[[str], list[Finding]]
