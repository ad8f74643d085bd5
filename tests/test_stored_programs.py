"""Stored programs as a policy: matching files and generated-code entries to tasks (no simulation here; the run
through ``roboscript bench`` is in test_bench)."""

import json
from pathlib import Path

import pytest

from roboscript.bench.stored_programs import StoredProgramsError, compose, load_program_store
from roboscript.bench.tasks import load_suite
from roboscript.codegen.checker import check_program

PAPER = load_suite("paper")


def _entry(query: str, code: str = "open_gripper()", functions: dict | None = None) -> dict:
    return {"context": "", "query": query, "src_fs": functions or {}, "code_str": code, "gvars": [], "lvars": []}


def test_entries_match_their_task_by_query_in_any_of_the_originals_forms(tmp_path):
    simple_0 = PAPER["simple_0"].query
    quoted = simple_0.replace("apple,", "'apple',").replace("[table,", "['table',")
    entries = [
        _entry("# " + simple_0 + ".."),  # as the original stores its programs
        _entry(quoted.replace("place the apple", "Place the apple"), code="close_gripper()"),
        _entry("# objects = [table, apple] ; # juggle the apple."),
    ]
    (tmp_path / "a.json").write_text(json.dumps(entries[:1] + entries[2:]))
    (tmp_path / "b.json").write_text(json.dumps(entries[1:2]))
    with pytest.raises(StoredProgramsError, match=r"two stored programs for simple_0: .*a\.json\[0\] and .*b\.json"):
        load_program_store(tmp_path, PAPER)
    (tmp_path / "b.json").unlink()
    store = load_program_store(tmp_path, PAPER)
    assert list(store.programs) == ["simple_0"] and store.programs["simple_0"].source.endswith("a.json[0]")
    assert len(store.unmatched) == 1 and "juggle the apple" in store.unmatched[0]


def test_a_program_is_its_generated_functions_then_its_main_code():
    functions = {"pick": "def pick(name):\n    grasp_it(name)\n", "grasp_it": "def grasp_it(n):\n    pass"}
    program = compose("pick('apple')", functions)
    assert program.index("def pick") < program.index("def grasp_it") < program.index("pick('apple')")
    compile(program, "<stored>", "exec")


def test_a_folder_reports_what_it_cannot_use_and_a_task_without_a_program_is_named(tmp_path):
    (tmp_path / "hard_2.py").write_text("open_gripper()\n")
    (tmp_path / "notes.py").write_text("print('not a task')\n")
    (tmp_path / "run.json").write_text(json.dumps({"policy": "reference"}))  # some other JSON beside them
    store = load_program_store(tmp_path, PAPER)
    assert list(store.programs) == ["hard_2"]
    assert any("notes.py (no task 'notes')" in u for u in store.unmatched)
    assert any("run.json (not in the generated-code format" in u for u in store.unmatched)
    assert store.require(["hard_2"], str(tmp_path))["hard_2"].program == "open_gripper()\n"
    with pytest.raises(StoredProgramsError, match=r"for simple_0 \(programs found for: hard_2\)"):
        store.require(["simple_0", "hard_2"], str(tmp_path))


def test_a_generated_code_file_given_itself_must_be_in_the_format(tmp_path):
    bad = tmp_path / "raw.json"
    bad.write_text(json.dumps([{"query": PAPER["simple_0"].query, "code_str": 42}]))
    with pytest.raises(StoredProgramsError, match=r"raw\.json: \[0\]: 'code_str' must be the program's source, got 42"):
        load_program_store(bad, PAPER)
    with pytest.raises(StoredProgramsError, match="neither a folder"):
        load_program_store(tmp_path / "missing", PAPER)


PROMPT_CORPUS = Path(__file__).parent / "data" / "prompt_corpus"


@pytest.mark.parametrize("path", sorted(PROMPT_CORPUS.glob("*/*/*.py")), ids=lambda p: f"{p.parts[-3]}/{p.stem}")
def test_every_program_written_from_the_prompt_passes_the_static_check(path):
    # They are what an LLM writes: what the checker refuses in them (a defensive program's make_grasp.__name__) is
    # the checker's to allow, or a hole in the prompt.
    assert check_program(path.read_text()) == []
