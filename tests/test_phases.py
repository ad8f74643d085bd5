"""Exclusive time per phase: inner phases are not counted twice, the rest is what no phase claimed. A test
double of the clock (a counter the test advances) makes the accounting exact."""

import types

import pytest

import roboscript.phases as phases
from roboscript.phases import PHASES, PhaseClock, phase, timed, totals


@pytest.fixture
def clock(monkeypatch):
    now = [100.0]
    monkeypatch.setattr(phases, "time", types.SimpleNamespace(perf_counter=lambda: now[0]))

    def advance(seconds: float) -> None:
        now[0] += seconds

    return advance


def test_time_goes_to_the_innermost_phase_open(clock):
    stopwatch = PhaseClock()
    with phase("planning"):
        clock(2.0)
        with phase("ik"):
            clock(3.0)
            assert totals()["ik"] - stopwatch._start["ik"] == 3.0  # an open phase counts up to now
        clock(1.0)
    clock(0.5)
    spent = stopwatch.read()
    assert spent["ik"] == 3.0 and spent["planning"] == 3.0
    assert spent["rest"] == 0.5 and spent["wall"] == 6.5
    assert sum(spent[p] for p in PHASES) + spent["rest"] == spent["wall"]


def test_a_decorated_function_is_charged_even_when_it_raises(clock):
    @timed("grasp")
    def search():
        clock(1.5)
        raise RuntimeError("no grasp")

    stopwatch = PhaseClock()
    with pytest.raises(RuntimeError):
        search()
    with phase("ik"):  # the stack is clean again: a phase opens and closes as usual
        clock(0.25)
    spent = stopwatch.read()
    assert spent["grasp"] == 1.5 and spent["ik"] == 0.25 and spent["rest"] == 0.0


def test_unknown_phases_are_refused_with_the_known_ones():
    known = "unknown phase 'thinking'; phases: build, llm, program, render"
    with pytest.raises(ValueError, match=known), phase("thinking"):
        pass
    with pytest.raises(ValueError, match="unknown phase"):
        timed("thinking")


def test_a_decorated_call_inside_its_own_phase_keeps_charging_it_and_another_phase_resumes_after(clock):
    @timed("planning")
    def check():
        clock(0.5)

    @timed("ik")
    def solve():
        check()  # charged to planning from within ik
        clock(1.0)

    stopwatch = PhaseClock()
    with phase("planning"):
        for _ in range(4):
            check()
        solve()
        clock(0.25)
    spent = stopwatch.read()
    assert spent["planning"] == 4 * 0.5 + 0.5 + 0.25 and spent["ik"] == 1.0 and spent["rest"] == 0.0
    assert not phases._open  # every phase opened was closed
