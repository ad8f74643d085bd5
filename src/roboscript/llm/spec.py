"""LLM specs as given on the command line: ``openai:MODEL[@BASE_URL]``, ``llama:PATH.gguf``, ``replay:DIR=NAME``,
``record:DIR=SPEC`` and ``cache:DIR=SPEC``."""

from __future__ import annotations

import os

from roboscript.llm.base import LLM, LLMError

FORMS = (
    "openai:MODEL[@BASE_URL]",
    "llama:PATH.gguf",
    "replay:DIR=NAME (NAME as recorded, e.g. openai:gpt-4o)",
    "record:DIR=SPEC",
    "cache:DIR=SPEC",
)


def configured_spec() -> str | None:
    """The LLM the environment configures: ``ROBOSCRIPT_LLM``, else an OpenAI-compatible endpoint serving
    ``ROBOSCRIPT_LLM_MODEL`` (at ``ROBOSCRIPT_LLM_BASE_URL``); None if neither is set."""
    from roboscript.llm.openai_compatible import MODEL_ENV

    if os.environ.get("ROBOSCRIPT_LLM"):
        return os.environ["ROBOSCRIPT_LLM"]
    if os.environ.get(MODEL_ENV):
        return f"openai:{os.environ[MODEL_ENV]}"
    return None


def short_name(spec: str) -> str:
    """The model a spec names, short enough for a folder or a plot's label: ``openai:gpt-4o@http://host/v1`` is
    ``gpt-4o``, ``llama:/models/qwen2.5-coder-7b.gguf`` is ``qwen2.5-coder-7b``; a stored LLM is the one it stores."""
    kind, _, rest = spec.partition(":")
    if kind == "openai":
        return rest.partition("@")[0] or spec
    if kind == "llama":
        return os.path.splitext(os.path.basename(rest))[0] or spec
    if kind in ("replay", "record", "cache") and "=" in rest:
        return short_name(rest.partition("=")[2])
    return spec


def make_llm(spec: str | None = None) -> LLM:
    """The LLM a spec names; with none, the one ``ROBOSCRIPT_LLM`` names, else an OpenAI-compatible endpoint
    configured by ``ROBOSCRIPT_LLM_MODEL`` (and ``ROBOSCRIPT_LLM_BASE_URL``). Raises :class:`LLMError`."""
    from roboscript.llm.openai_compatible import MODEL_ENV, OpenAICompatibleLLM

    spec = spec or configured_spec()
    if not spec:
        raise LLMError(f"no LLM configured: pass --llm ({' | '.join(FORMS)}) or set ROBOSCRIPT_LLM or {MODEL_ENV}")
    kind, sep, rest = spec.partition(":")
    if not sep or not rest:
        raise LLMError(f"bad LLM spec {spec!r}; use one of: {', '.join(FORMS)}")
    if kind == "openai":
        model, _, url = rest.partition("@")
        return OpenAICompatibleLLM(model=model, base_url=url or None)
    if kind == "llama":
        from roboscript.llm.llama_cpp import LlamaCppLLM

        return LlamaCppLLM(rest)
    if kind in ("replay", "record", "cache"):
        from roboscript.llm.store import ReplayLLM, ResponseStore, StoredLLM

        directory, eq, inner = rest.partition("=")
        if not eq or not directory or not inner:
            raise LLMError(f"bad LLM spec {spec!r}; use {kind}:DIR={'NAME' if kind == 'replay' else 'SPEC'}")
        store = ResponseStore(directory)
        if kind == "replay":
            return ReplayLLM(store, inner)
        return StoredLLM(make_llm(inner), store, mode=kind)
    raise LLMError(f"unknown LLM kind {kind!r} in {spec!r}; use one of: {', '.join(FORMS)}")
