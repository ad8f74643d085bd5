"""The main agent writes a program for a task query; the function-generating sub-agent writes every function the
program calls but neither gets nor defines, recursively (with a depth bound, and each name asked for once)."""

from __future__ import annotations

import ast
import contextlib
from collections.abc import Sequence
from dataclasses import dataclass, field

from roboscript.codegen.checker import undefined_calls
from roboscript.codegen.extract import extract_code
from roboscript.codegen.prompt import Example, function_messages, program_messages, repair_messages
from roboscript.llm.base import LLM, LLMRequest


@dataclass
class Generation:
    """A generated program with everything that went into it (for the trial's record)."""

    program: str
    exchanges: list[dict] = field(default_factory=list)  # {"purpose", "messages", "response"}
    helpers: list[str] = field(default_factory=list)  # names the sub-agent defined
    unresolved: list[str] = field(default_factory=list)  # names it could not define (depth bound, no definition)
    repairs: int = 0  # rounds of repair used


MAX_DEFINED = 12  # names the sub-agent is asked to define for one program at most


class CodeAgent:
    """Writes programs with ``llm``. ``max_depth``: how many levels of helpers the sub-agent may generate;
    ``base_xy``: where the robot's base stands, told in the rules where known (:func:`system_prompt`)."""

    def __init__(
        self,
        llm: LLM,
        examples: list[Example] | None = None,
        max_depth: int = 3,
        max_tokens: int = 2048,
        base_xy: Sequence[float] | None = None,
    ):
        self.llm, self.examples, self.max_depth, self.max_tokens = llm, examples, max_depth, max_tokens
        self.base_xy = None if base_xy is None else (float(base_xy[0]), float(base_xy[1]))

    def write_program(self, query: str) -> Generation:
        messages = program_messages(query, self.examples, self.base_xy)
        text = self._ask(messages)
        generation = Generation(extract_code(text), [{"purpose": "program", "messages": messages, "response": text}])
        self.define_missing(generation)
        return generation

    def repair(self, query: str, generation: Generation, errors: list[str]) -> None:
        """One repair round: the program and what went wrong with it go back to the LLM; its answer (with any
        helpers it calls) replaces the program."""
        messages = repair_messages(query, generation.program, errors, self.examples, self.base_xy)
        text = self._ask(messages)
        generation.exchanges.append({"purpose": "repair", "messages": messages, "response": text})
        generation.program = extract_code(text)
        generation.repairs += 1
        self.define_missing(generation)

    def define_missing(self, generation: Generation) -> None:
        """Adds definitions for called-but-undefined names, breadth first, up to ``max_depth`` levels and
        :data:`MAX_DEFINED` names in all (a model whose every answer calls new names would otherwise be asked
        without end: K + K^2 + K^3 requests)."""
        asked: set[str] = set()
        for _ in range(self.max_depth):
            try:
                missing = [site for site in undefined_calls(generation.program) if site.name not in asked]
            except SyntaxError:
                return  # the checker will report it
            if not missing:
                return
            for site in missing:
                if len(asked) >= MAX_DEFINED:
                    break
                asked.add(site.name)
                messages = function_messages(site.name, site.source, generation.program)
                text = self._ask(messages)
                exchange = {"purpose": f"function {site.name}", "messages": messages, "response": text}
                generation.exchanges.append(exchange)
                definitions = _function_definitions(extract_code(text), site.name)
                if definitions is None:
                    generation.unresolved.append(site.name)
                    continue
                generation.program = definitions + "\n\n" + generation.program
                generation.helpers.append(site.name)
        with contextlib.suppress(SyntaxError):
            generation.unresolved += [s.name for s in undefined_calls(generation.program) if s.name not in asked]

    def _ask(self, messages: list[dict]) -> str:
        return self.llm.complete(LLMRequest(tuple(messages), max_tokens=self.max_tokens)).text


def _function_definitions(code: str, name: str) -> str | None:
    """The function definitions in ``code`` if one of them defines ``name``; other statements are dropped (a model
    may add example calls)."""
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return None
    functions = [node for node in tree.body if isinstance(node, ast.FunctionDef)]
    if not any(f.name == name for f in functions):
        return None
    return "\n\n".join(ast.get_source_segment(code, f) for f in functions) + "\n"
