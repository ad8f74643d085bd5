"""The named categories every program outcome falls into."""

from __future__ import annotations

from enum import Enum


class Outcome(str, Enum):
    OK = "ok"
    SYNTAX = "syntax"  # does not parse
    UNKNOWN_FUNCTION = "unknown_function"  # calls a name that is neither a tool, a builtin nor defined
    BAD_ARGUMENTS = "bad_arguments"  # wrong keyword names or arity for a tool or a defined function
    FORBIDDEN_CONSTRUCT = "forbidden_construct"  # imports, dunder access, file access and the like
    RUNTIME_ERROR = "runtime_error"  # raised while running (a tool's error included)
    PLANNING_FAILURE = "planning_failure"  # no IK, no path, blocked motion, lost tracking, no placement
    TIMEOUT = "timeout"  # ran past its time limit
    CHECKS_FAILED = "checks_failed"  # ran to its end, but the task's checks did not all pass
    LLM_ERROR = "llm_error"  # no program: the model could not be asked
    SANDBOX_VIOLATION = "sandbox_violation"  # tried what the sandbox forbids at run time (a system call, the protocol)


STATIC = (Outcome.SYNTAX, Outcome.UNKNOWN_FUNCTION, Outcome.BAD_ARGUMENTS, Outcome.FORBIDDEN_CONSTRUCT)
