"""The bounded store of costly things a process keeps (compiled worlds and robots, renderers)."""

import pytest

from roboscript.kept import Kept


def test_the_least_recently_used_is_given_up_first_and_a_kept_value_is_not_made_again():
    dropped, made = [], []
    kept = Kept(2, give_up=dropped.append)

    def make(value):
        made.append(value)
        return value

    assert kept.get("a", lambda: make("A")) == "A"
    kept.get("b", lambda: make("B"))
    assert kept.get("a", lambda: make("A again")) == "A"  # kept: not made again, and now the most recent
    kept.get("c", lambda: make("C"))
    assert made == ["A", "B", "C"] and dropped == ["B"] and len(kept) == 2
    kept.clear()
    assert sorted(dropped) == ["A", "B", "C"] and len(kept) == 0


def test_a_store_keeps_at_least_one():
    with pytest.raises(ValueError, match="at least one value, got size 0"):
        Kept(0)
