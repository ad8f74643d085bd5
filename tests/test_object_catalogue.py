"""The object catalogue is a data file: every type checked on load, and a wrong entry named with what is valid."""

from pathlib import Path

import pytest

from roboscript.objects import get_object_type, object_types
from roboscript.objects.library import CatalogueFileError, read_catalogue

APPLE = """- name: apple
  category: apple
  color: red
  shape: round
  design: {kind: sphere, radius: 0.038}
  density: 850
  description: a red apple, 7.6 cm
  round: true
"""


def _catalogue(tmp_path: Path, text: str) -> str:
    path = tmp_path / "catalogue.yaml"
    path.write_text(text)
    return str(path)


def test_the_packaged_catalogue_builds_every_type_with_its_parts_and_its_interior():
    types = object_types()
    assert len(types) >= 70
    mug = get_object_type("white_mug")
    assert mug.container and mug.interior is not None and mug.interior[1][2] > mug.interior[0][2]
    assert mug.size[2] == pytest.approx(0.095, abs=0.01)
    assert get_object_type("medication_bottle").parts[-1].rgba == get_object_type("white_mug").rgba  # a white cap


def test_an_entry_of_the_catalogue_reads_as_the_recipe_it_names(tmp_path):
    apple = read_catalogue(_catalogue(tmp_path, APPLE))["apple"]
    assert apple.round and apple.size == pytest.approx([0.076, 0.076, 0.076])
    assert apple.density == 850


@pytest.mark.parametrize(
    ("change", "says"),
    [
        (("kind: sphere", "kind: sphear"), r"design kind 'sphear' is not one of .*sphere"),
        (("radius: 0.038", "diameter: 0.076"), r"design 'sphere' takes radius; unknown: diameter; missing: radius"),
        (("color: red", "color: reddish"), r"colour 'reddish' is not one of red"),
        (("shape: round", "shape: roundish"), r"shape 'roundish' is not one of round"),
        (("density: 850", "density: heavy"), r"field 'density' must be a finite number"),
        (("round: true", "rounded: true"), r"unknown field 'rounded' \(did you mean 'round'\?\)"),
    ],
)
def test_a_wrong_entry_is_named_with_what_is_wrong_and_what_would_be_valid(tmp_path, change, says):
    path = _catalogue(tmp_path, APPLE.replace(*change))
    with pytest.raises(CatalogueFileError, match=r"object catalogue file .*: catalogue\[0\] 'apple': " + says):
        read_catalogue(path)


def test_a_type_listed_twice_is_refused(tmp_path):
    with pytest.raises(CatalogueFileError, match=r"catalogue\[1\] 'apple': 'apple' is listed twice"):
        read_catalogue(_catalogue(tmp_path, APPLE + APPLE))
