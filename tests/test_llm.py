"""LLM backends against a real HTTP server on loopback: answers, retries that give up, timeouts, the store."""

from __future__ import annotations

import pytest

from chat_server import ScriptedChatServer
from roboscript.llm import LLMError, LLMRequest, make_llm
from roboscript.llm.openai_compatible import OpenAICompatibleLLM
from roboscript.llm.store import ReplayLLM, ResponseStore, StoredLLM

MESSAGES = ({"role": "system", "content": "be brief"}, {"role": "user", "content": "hello"})


def test_a_completion_goes_through_the_openai_client():
    with ScriptedChatServer([{"text": "hi there"}]) as server:
        llm = make_llm(f"openai:scripted-model@{server.url}")
        response = llm.complete(LLMRequest(MESSAGES, temperature=0.2, max_tokens=64))
    assert response.text == "hi there" and response.model == "scripted-model"
    assert response.usage["total_tokens"] == 15
    (request,) = server.requests
    assert request["model"] == "scripted-model" and request["messages"] == list(MESSAGES)
    assert request["temperature"] == 0.2 and request["max_tokens"] == 64


def test_429_and_500_are_retried_then_answered():
    with ScriptedChatServer([{"status": 429}, {"status": 500}, {"text": "done"}]) as server:
        llm = OpenAICompatibleLLM("m", base_url=server.url, max_retries=3)
        assert llm.complete(LLMRequest(MESSAGES)).text == "done"
    assert len(server.requests) == 3


def test_retries_give_up_and_say_why():
    with ScriptedChatServer([{"status": 500}]) as server:
        llm = OpenAICompatibleLLM("m", base_url=server.url, max_retries=2)
        with pytest.raises(LLMError, match="answered HTTP 500 after 2 retries"):
            llm.complete(LLMRequest(MESSAGES))
    assert len(server.requests) == 3


def test_a_server_that_does_not_answer_times_out():
    """The reply comes only after 60 s: a client that waited for it would get "late" and fail the match."""
    with ScriptedChatServer([{"delay": 60.0, "text": "late"}]) as server:
        llm = OpenAICompatibleLLM("m", base_url=server.url, timeout=0.3, max_retries=1)
        with pytest.raises(LLMError, match=r"did not answer within 0\.3 s"):
            llm.complete(LLMRequest(MESSAGES))
    assert len(server.requests) == 2


def test_an_unreachable_endpoint_is_reported():
    llm = OpenAICompatibleLLM("m", base_url="http://127.0.0.1:9/v1", timeout=1.0, max_retries=0)
    with pytest.raises(LLMError, match=r"cannot reach http://127\.0\.0\.1:9/v1"):
        llm.complete(LLMRequest(MESSAGES))


def test_record_then_replay_without_the_server(tmp_path):
    with ScriptedChatServer([{"text": "first"}, {"text": "second"}]) as server:
        recorder = make_llm(f"record:{tmp_path}=openai:m@{server.url}")
        assert recorder.complete(LLMRequest(MESSAGES)).text == "first"
        cached = StoredLLM(OpenAICompatibleLLM("m", base_url=server.url), ResponseStore(tmp_path), mode="cache")
        again = cached.complete(LLMRequest(MESSAGES))
    assert again.text == "first" and again.from_store and len(server.requests) == 1
    replay = ReplayLLM(ResponseStore(tmp_path), "openai:m")
    assert replay.complete(LLMRequest(MESSAGES)).text == "first"
    with pytest.raises(LLMError, match="no recorded response"):
        replay.complete(LLMRequest(MESSAGES, temperature=0.7))


def test_bad_specs_and_requests_say_what_is_valid(monkeypatch):
    monkeypatch.delenv("ROBOSCRIPT_LLM", raising=False)
    monkeypatch.delenv("ROBOSCRIPT_LLM_MODEL", raising=False)
    with pytest.raises(LLMError, match="no LLM configured"):
        make_llm(None)
    with pytest.raises(LLMError, match="unknown LLM kind 'gpt'"):
        make_llm("gpt:4")
    with pytest.raises(LLMError, match=r"use replay:DIR=NAME"):
        make_llm("replay:/tmp")
    with pytest.raises(LLMError, match="no GGUF model at"):
        make_llm("llama:/nonexistent/model.gguf")
    with pytest.raises(ValueError, match="role 'robot'"):
        LLMRequest(({"role": "robot", "content": "x"},))


def test_the_environment_configures_the_llm_in_one_order(monkeypatch):
    from roboscript.llm.openai_compatible import OpenAICompatibleLLM
    from roboscript.llm.spec import configured_spec

    monkeypatch.delenv("ROBOSCRIPT_LLM", raising=False)
    monkeypatch.delenv("ROBOSCRIPT_LLM_MODEL", raising=False)
    assert configured_spec() is None
    monkeypatch.setenv("ROBOSCRIPT_LLM_MODEL", "served-model")
    monkeypatch.setenv("ROBOSCRIPT_LLM_BASE_URL", "http://127.0.0.1:9/v1")
    assert configured_spec() == "openai:served-model"
    llm = make_llm(None)
    assert isinstance(llm, OpenAICompatibleLLM) and llm.model == "served-model"
    assert llm.base_url.rstrip("/") == "http://127.0.0.1:9/v1"  # the client keeps a trailing slash
    monkeypatch.setenv("ROBOSCRIPT_LLM", "replay:/tmp/r=openai:x")
    assert configured_spec() == "replay:/tmp/r=openai:x"  # ROBOSCRIPT_LLM comes first
