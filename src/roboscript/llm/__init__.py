"""LLM backends behind one small interface: OpenAI-compatible HTTP, in-process llama.cpp, recorded responses."""

from roboscript.llm.base import LLM, LLMError, LLMRequest, LLMResponse
from roboscript.llm.spec import make_llm

__all__ = ["LLM", "LLMError", "LLMRequest", "LLMResponse", "make_llm"]
