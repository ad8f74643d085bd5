"""The one place an LLM writes a program: for a query, and again for the same query from what went wrong when the
last one ran (a repair round)."""

from __future__ import annotations

from collections.abc import Sequence

from roboscript.codegen.agent import CodeAgent, Generation
from roboscript.codegen.checker import check_program
from roboscript.codegen.sandbox import ExecutionResult
from roboscript.llm.base import LLM
from roboscript.phases import phase


class ProgramAuthor:
    """Writes the program for ``query`` with ``llm`` at once (raising :class:`~roboscript.llm.LLMError` where the
    LLM cannot be asked); ``base_xy``, where the robot's base stands, goes into the rules where known."""

    def __init__(self, llm: LLM, query: str, base_xy: Sequence[float] | None = None):
        self.query = query
        self.agent = CodeAgent(llm, base_xy=base_xy)
        with phase("llm"):
            self.generation: Generation = self.agent.write_program(query)

    @property
    def program(self) -> str:
        return self.generation.program

    def repair(self, result: ExecutionResult) -> None:
        """Asks for the program again, told what went wrong in ``result`` (:func:`error_report`)."""
        with phase("llm"):
            self.agent.repair(self.query, self.generation, error_report(self.generation.program, result))


def error_report(program: str, result: ExecutionResult) -> list[str]:
    """What the LLM is told about a failed attempt: every checker finding, or the error and the output before it."""
    findings = check_program(program)
    if findings:
        return [f"{f.outcome.value}: {f.message} (line {f.line})" for f in findings]
    lines = [f"{result.outcome.value}: {result.error}"]
    printed = result.output.strip().splitlines()[-10:]
    if printed:
        lines.append("the program printed, last lines:\n" + "\n".join(printed))
    lines.append("the world was reset to how it was before the program ran")
    return lines
