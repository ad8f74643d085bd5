"""The interface every LLM backend implements: a chat request in, one text completion out."""

from __future__ import annotations

import hashlib
import json
from abc import ABC, abstractmethod
from dataclasses import asdict, dataclass, field

from roboscript.errors import InvalidArgumentError, RoboScriptError


class LLMError(RoboScriptError, RuntimeError):
    """The model could not be asked or did not answer (after any retries); the message says why."""


@dataclass(frozen=True)
class LLMRequest:
    """A chat completion request: ``messages`` are ``{"role": "system"|"user"|"assistant", "content": str}``."""

    messages: tuple[dict, ...]
    temperature: float = 0.0
    max_tokens: int = 2048
    stop: tuple[str, ...] = ()

    def __post_init__(self):
        for i, message in enumerate(self.messages):
            if not isinstance(message, dict) or set(message) != {"role", "content"}:
                raise InvalidArgumentError(
                    f"message {i} must be a dict with exactly 'role' and 'content', got {message!r}"
                )
            if message["role"] not in ("system", "user", "assistant"):
                raise InvalidArgumentError(
                    f"message {i} has role {message['role']!r}; use 'system', 'user' or 'assistant'"
                )
            if not isinstance(message["content"], str):
                raise InvalidArgumentError(
                    f"message {i} content must be a string, got {type(message['content']).__name__}"
                )
        if self.max_tokens < 1:
            raise InvalidArgumentError(f"max_tokens must be at least 1, got {self.max_tokens}")

    def key(self, model: str) -> str:
        """A stable hash of the request and the model it is for (for the response store)."""
        payload = json.dumps({"model": model, **asdict(self)}, sort_keys=True, ensure_ascii=False)
        return hashlib.sha256(payload.encode()).hexdigest()


@dataclass(frozen=True)
class LLMResponse:
    """The completion text, the model that wrote it, and token counts where the backend reports them."""

    text: str
    model: str
    usage: dict = field(default_factory=dict)
    from_store: bool = False


class LLM(ABC):
    """A chat model. ``name`` identifies it in records (e.g. ``openai:gpt-4o``)."""

    name: str = "llm"

    @abstractmethod
    def complete(self, request: LLMRequest) -> LLMResponse:
        """One completion for ``request``; raises :class:`LLMError` when there is none."""

    def chat(self, messages: list[dict], **options) -> LLMResponse:
        return self.complete(LLMRequest(tuple(messages), **options))
