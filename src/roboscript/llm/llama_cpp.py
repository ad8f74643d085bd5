"""A local GGUF model run in-process by llama.cpp (the ``llama`` extra).

Models with a chat template in their GGUF are asked through it; base models without one get the conversation as
plain text ending in an assistant turn that has opened a Python code block, and stop where they close it (the
few-shot answers are single code blocks, so this is the answer's shape; without it a base model runs on).
"""

from __future__ import annotations

import os

from roboscript import extras
from roboscript.llm.base import LLM, LLMError, LLMRequest, LLMResponse


class LlamaCppLLM(LLM):
    """``model_path``: a ``.gguf`` file. ``n_ctx``: context length in tokens."""

    def __init__(self, model_path: str | os.PathLike, n_ctx: int = 8192, n_threads: int | None = None, seed: int = 0):
        path = os.fspath(model_path)
        if not os.path.isfile(path):
            raise LLMError(f"no GGUF model at {path!r}: give the path of a .gguf file")
        try:
            import llama_cpp
        except ImportError as exc:
            raise LLMError(extras.missing_text("llama", "a local GGUF model (llama:PATH.gguf)")) from exc
        try:
            self._llama = llama_cpp.Llama(
                model_path=path, n_ctx=n_ctx, n_threads=n_threads or os.cpu_count(), seed=seed, verbose=False
            )
        except (ValueError, RuntimeError) as exc:
            raise LLMError(f"llama.cpp could not load {path!r}: {exc}") from exc
        self.has_chat_template = bool(self._llama.metadata.get("tokenizer.chat_template"))
        self.n_ctx = n_ctx
        self.name = f"llama:{os.path.basename(path)}"

    def complete(self, request: LLMRequest) -> LLMResponse:
        options = {"temperature": request.temperature, "stop": list(request.stop) or None}
        try:
            if self.has_chat_template:
                out = self._llama.create_chat_completion(
                    messages=list(request.messages), max_tokens=request.max_tokens, **options
                )
                text = out["choices"][0]["message"]["content"] or ""
            else:
                prompt = plain_prompt(request.messages)
                budget = self.n_ctx - len(self._llama.tokenize(prompt.encode())) - 1
                if budget < 16:
                    raise LLMError(f"the prompt does not fit the model's {self.n_ctx}-token context")
                options["stop"] = [*request.stop, *PLAIN_STOPS]
                out = self._llama.create_completion(prompt, max_tokens=min(request.max_tokens, budget), **options)
                code = out["choices"][0]["text"].partition("```")[0]  # a fence closed at once ends the code there
                text = CODE_OPENING + code.rstrip("\n") + "\n```"
        except (ValueError, RuntimeError) as exc:
            raise LLMError(f"llama.cpp failed: {exc}") from exc
        return LLMResponse(text, self.name, dict(out.get("usage") or {}))


CODE_OPENING = "```python\n"
# The code block closed, or a new turn begun (the turn headers of plain_prompt, not any "### " comment).
PLAIN_STOPS = ("\n```", "\n### User", "\n### Instructions", "\n### Assistant")


def plain_prompt(messages) -> str:
    """The conversation as text for a model without a chat template, ending inside the assistant's code block."""
    labels = {"system": "Instructions", "user": "User", "assistant": "Assistant"}
    turns = [f"### {labels[m['role']]}\n{m['content'].strip()}\n" for m in messages]
    return "\n".join(turns) + "\n### Assistant\n" + CODE_OPENING
