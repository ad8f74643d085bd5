"""Phrases in the object library's words: what types a program's name for a thing may mean, and how specifically."""

from __future__ import annotations

import pytest

from roboscript.perception.detection import phrases
from roboscript.perception.detection.phrases import CATEGORY, COLOURED, DESCRIBED, GROUP, NAME, match_phrase


def test_a_type_name_means_that_type_most_and_its_look_alikes_less():
    match = match_phrase("white_ceramic_plate")
    assert match.specificity == {"white_ceramic_plate": NAME}
    white = match_phrase("white plate")  # a type's name, and every white plate
    assert white.specificity["white_plate"] == NAME
    assert white.specificity["white_ceramic_plate"] == COLOURED
    assert "white_saucer" not in white.types and "blue_plate" not in white.types


def test_categories_groups_plurals_and_numbers():
    assert match_phrase("plate").specificity["blue_plate"] == CATEGORY
    assert match_phrase("Plates").types == match_phrase("plate").types
    fruit = match_phrase("fruits")
    assert {"apple", "banana", "pear", "lemon"} <= fruit.types and "baseball" not in fruit.types
    assert set(fruit.specificity.values()) == {GROUP}
    assert match_phrase("red fruit").types == {"apple", "strawberry"}
    assert match_phrase("boxes").types >= {"brown_box", "white_and_pink_box", "cracker_box"}
    assert match_phrase("mug_1").types == match_phrase("mug").types
    bowl = match_phrase("bowl")  # the bowls first, a footed bowl at a pinch
    assert bowl.specificity["red_bowl"] == CATEGORY and bowl.specificity["footed_bowl"] == GROUP


def test_a_described_name_means_its_type_then_what_looks_like_it():
    described = {"white_plate": "white_serving_plate", "mug": "white_and_yellow_mug"}
    assert match_phrase("white_plate", described).specificity["white_serving_plate"] == DESCRIBED
    mug = match_phrase("mug", described).specificity
    assert mug["white_and_yellow_mug"] == DESCRIBED and mug["white_mug"] == COLOURED and "red_mug" not in mug


def test_a_phrase_that_names_nothing_is_none():
    assert match_phrase("unicorn") is None
    assert match_phrase("") is None


def test_groups_must_name_categories_the_library_has(monkeypatch):
    class Resource:
        def __truediv__(self, _):
            return self

        def read_text(self):
            return "fruit: [apple, dragonfruit]\n"

    phrases.phrase_groups.cache_clear()
    monkeypatch.setattr(phrases.resources, "files", lambda _: Resource())
    try:
        with pytest.raises(ValueError, match=r"group 'fruit' names unknown categories \['dragonfruit'\]"):
            phrases.phrase_groups()
    finally:
        monkeypatch.undo()
        phrases.phrase_groups.cache_clear()
