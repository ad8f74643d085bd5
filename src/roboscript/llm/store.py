"""Responses kept on disk, keyed by a hash of the request: replay, recording and caching.

One JSON file per response, ``<key>.json``, holding the request and the response, written atomically, so a store
can be read while another run adds to it and an interrupted run loses nothing it already got.
"""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import asdict
from pathlib import Path

from roboscript.errors import InvalidArgumentError
from roboscript.llm.base import LLM, LLMError, LLMRequest, LLMResponse


class ResponseStore:
    """A directory of recorded responses."""

    def __init__(self, directory: str | os.PathLike):
        self.directory = Path(directory)

    def path(self, key: str) -> Path:
        return self.directory / f"{key}.json"

    def get(self, key: str) -> LLMResponse | None:
        path = self.path(key)
        if not path.exists():
            return None
        try:
            record = json.loads(path.read_text())
            answer = record["response"]
            return LLMResponse(answer["text"], answer["model"], answer["usage"], from_store=True)
        except (json.JSONDecodeError, KeyError, TypeError) as exc:
            raise LLMError(f"the recorded response {path} is damaged ({exc}); delete it to ask again") from exc

    def put(self, key: str, request: LLMRequest, response: LLMResponse) -> None:
        self.directory.mkdir(parents=True, exist_ok=True)
        answer = {"text": response.text, "model": response.model, "usage": response.usage}
        record = {"request": asdict(request), "response": answer}
        fd, tmp = tempfile.mkstemp(dir=self.directory, suffix=".tmp")
        with os.fdopen(fd, "w") as f:
            json.dump(record, f, indent=1, ensure_ascii=False)
        os.replace(tmp, self.path(key))

    def __len__(self) -> int:
        return len(list(self.directory.glob("*.json"))) if self.directory.exists() else 0


class ReplayLLM(LLM):
    """Answers only from a store, for reproducible runs and tests; a request never recorded is an error."""

    def __init__(self, store: ResponseStore, name: str):
        """``name``: the recorded model's name, e.g. ``openai:gpt-4o`` (requests are keyed with it)."""
        self.store, self.name = store, name

    def complete(self, request: LLMRequest) -> LLMResponse:
        key = request.key(self.name)
        response = self.store.get(key)
        if response is None:
            raise LLMError(
                f"no recorded response for this request to {self.name!r} in {self.store.directory} "
                f"(key {key[:12]}): record it first with the model itself (--llm record:DIR=SPEC)"
            )
        return response


class StoredLLM(LLM):
    """Wraps a model with a store: ``mode="cache"`` answers from the store when it can and records what it asks;
    ``mode="record"`` always asks and records."""

    def __init__(self, inner: LLM, store: ResponseStore, mode: str = "cache"):
        if mode not in ("cache", "record"):
            raise InvalidArgumentError(f"mode must be 'cache' or 'record', got {mode!r}")
        self.inner, self.store, self.mode = inner, store, mode
        self.name = inner.name

    def complete(self, request: LLMRequest) -> LLMResponse:
        key = request.key(self.inner.name)
        if self.mode == "cache" and (stored := self.store.get(key)) is not None:
            return stored
        response = self.inner.complete(request)
        self.store.put(key, request, response)
        return response
