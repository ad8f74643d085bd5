"""Any OpenAI-compatible chat endpoint (OpenAI, Gemini's compatible endpoint, vLLM, Ollama, llama.cpp server).

Retries are the official client's: exponential backoff with jitter on connection errors, timeouts, 408, 409, 429
and 5xx, honouring ``Retry-After``, up to ``max_retries``; then the error is raised as :class:`LLMError`.
"""

from __future__ import annotations

import os

from roboscript.llm.base import LLM, LLMError, LLMRequest, LLMResponse

BASE_URL_ENV = "ROBOSCRIPT_LLM_BASE_URL"
API_KEY_ENV = "ROBOSCRIPT_LLM_API_KEY"
MODEL_ENV = "ROBOSCRIPT_LLM_MODEL"


class OpenAICompatibleLLM(LLM):
    """Chat completions through the ``openai`` client.

    ``base_url``, ``api_key`` and ``model`` default to ``ROBOSCRIPT_LLM_BASE_URL``, ``ROBOSCRIPT_LLM_API_KEY``
    (else ``OPENAI_API_KEY``) and ``ROBOSCRIPT_LLM_MODEL``. ``timeout`` bounds each attempt, in seconds.
    """

    def __init__(
        self,
        model: str | None = None,
        base_url: str | None = None,
        api_key: str | None = None,
        timeout: float = 120.0,
        max_retries: int = 3,
    ):
        try:
            import openai
        except ImportError as exc:  # pragma: no cover - openai is a core dependency
            raise LLMError("the openai package is needed for OpenAI-compatible endpoints: pip install openai") from exc
        self.model = model or os.environ.get(MODEL_ENV)
        if not self.model:
            raise LLMError(f"no model given: pass one (openai:MODEL) or set {MODEL_ENV}")
        base_url = base_url or os.environ.get(BASE_URL_ENV) or None
        api_key = api_key or os.environ.get(API_KEY_ENV) or os.environ.get("OPENAI_API_KEY")
        if not api_key:
            if base_url is None:
                raise LLMError(f"no API key: set {API_KEY_ENV} or OPENAI_API_KEY, or give a local endpoint's URL")
            api_key = "none"  # local servers accept any key
        if timeout <= 0 or max_retries < 0:
            raise LLMError(f"timeout must be > 0 s and max_retries >= 0, got {timeout} and {max_retries}")
        self._openai = openai
        self._client = openai.OpenAI(base_url=base_url, api_key=api_key, timeout=timeout, max_retries=max_retries)
        self.base_url = str(self._client.base_url)
        self.name = f"openai:{self.model}"

    def complete(self, request: LLMRequest) -> LLMResponse:
        openai = self._openai
        try:
            completion = self._client.chat.completions.create(
                model=self.model,
                messages=list(request.messages),
                temperature=request.temperature,
                max_tokens=request.max_tokens,
                stop=list(request.stop) or None,
            )
        except openai.APITimeoutError as exc:
            raise LLMError(
                f"{self.base_url} did not answer within {self._client.timeout} s, "
                f"{self._client.max_retries} retries included"
            ) from exc
        except openai.APIConnectionError as exc:
            raise LLMError(f"cannot reach {self.base_url}: {exc}") from exc
        except openai.APIStatusError as exc:
            raise LLMError(
                f"{self.base_url} answered HTTP {exc.status_code} after {self._client.max_retries} retries: "
                f"{_short(exc.message)}"
            ) from exc
        except openai.OpenAIError as exc:
            raise LLMError(f"{self.base_url}: {exc}") from exc
        if not completion.choices or completion.choices[0].message.content is None:
            raise LLMError(f"{self.base_url} returned no completion text for model {self.model!r}")
        usage = completion.usage.model_dump() if completion.usage is not None else {}
        return LLMResponse(completion.choices[0].message.content, completion.model or self.model, usage)


def _short(text: str, limit: int = 300) -> str:
    return text if len(text) <= limit else text[:limit] + "..."
