"""The pipeline of the studies of ``slipmaps accuracy`` (runtime/studies/study.py, runner.py): one
writer for every study (measure -> JSON -> Markdown -> PNG, deterministic), the studies and their
file names, the maps each study runs derived from the roles in the index, and the studies' modules
importing one way (no circle, no private name of another module).

Nothing here measures a map: the studies' records are re-measured by tests/test_accuracy.py,
tests/test_stiffness.py and tests/test_gait.py.
"""

from __future__ import annotations

import ast
import json
import math
from pathlib import Path

import pytest
from slipmaps.runtime.api import index
from slipmaps.runtime.studies import accuracy, convergence, runner, stability, stiffness, study

STUDIES_DIR = Path(study.__file__).resolve().parent


class Toy(study.Study):
    """A study of two numbers, one of them not measured (NaN)."""

    name = "toy"

    def __init__(self):
        self.measured = 0

    def measure(self, show_progress=None) -> dict:
        self.measured += 1
        return {"values": [1.0 / 3.0, math.nan], "label": "third"}

    def markdown(self, record: dict, figure_name: str) -> str:
        return f"# {record['label']}\n\n{record['values']!r} ![]({figure_name})\n"

    def figure(self, record: dict, path: Path) -> Path:
        path.write_bytes(b"\x89PNG\r\n\x1a\n")
        return path


def test_one_writer_measures_once_and_writes_json_markdown_figure(tmp_path):
    toy = Toy()
    written = study.write(toy, tmp_path / "toy.md")
    assert written == [tmp_path / "toy.md", tmp_path / "toy.json", tmp_path / "toy.png"]
    assert toy.measured == 1
    record = json.loads((tmp_path / "toy.json").read_text())
    assert record == {"version": study.VERSION, "values": [0.333333, None], "label": "third"}
    # the report is rendered from the record as written: 6 digits, NaN as null
    assert (tmp_path / "toy.md").read_text() == "# third\n\n[0.333333, None] ![](toy.png)\n"
    assert study.from_json((tmp_path / "toy.json").read_text()) == {
        "values": [0.333333, None],
        "label": "third",
    }


def test_the_same_inputs_give_byte_identical_json_and_markdown(tmp_path):
    first, second = tmp_path / "a" / "toy.md", tmp_path / "b" / "toy.md"
    for md in (first, second):
        md.parent.mkdir()
        study.write(Toy(), md)
    for suffix in (".json", ".md"):
        assert first.with_suffix(suffix).read_bytes() == second.with_suffix(suffix).read_bytes()


def test_slipmaps_accuracy_writes_every_study_in_order():
    names = ["accuracy", "convergence", "stiffness", "stability", "reproductions"]
    assert [cls.name for cls in runner.STUDIES] == names
    assert [s.name for s in runner.studies()] == names


def test_a_study_with_nothing_to_measure_is_left_out():
    """Geyer et al.'s map alone has no pass count and needs k_c == k_d: no convergence, no stiffness
    study; the converging iterative map has both; the reproductions name their maps: all maps only."""
    assert [s.name for s in runner.studies(["geyer"])] == ["accuracy", "stability"]
    assert [s.name for s in runner.studies(["iterative"])] == [
        "accuracy",
        "convergence",
        "stiffness",
        "stability",
    ]


def test_chosen_maps_are_measured_with_the_baseline():
    baseline = accuracy.baseline()
    assert baseline in accuracy.maps_with("baseline") and index.get(baseline)
    assert runner.chosen_maps(None) is None
    assert runner.chosen_maps(["iterative"]) == [baseline, "iterative"]
    assert runner.chosen_maps([baseline]) == [baseline]
    with pytest.raises(ValueError, match="unknown map 'nope'"):
        runner.chosen_maps(["nope"])


def test_report_paths():
    by_name = {s.name: s for s in runner.studies(["iterative"])}
    docs = Path("docs/accuracy.md")
    assert [runner.report_path(docs, s) for s in by_name.values()] == [
        docs,
        Path("docs/convergence.md"),
        Path("docs/stiffness.md"),
        Path("docs/stability.md"),
    ]
    one = Path("out/accuracy_iterative.md")
    assert runner.report_path(one, by_name["stability"], plain_names=False) == Path(
        "out/stability_accuracy_iterative.md"
    )
    assert runner.report_path(one, by_name["accuracy"], plain_names=False) == one


def test_run_names_chosen_maps_reports_by_the_out_stem_or_plainly(tmp_path, monkeypatch):
    """runner.run: chosen maps' reports are ``<study>_<stem>.md`` beside ``out``, or ``<study>.md``
    with ``plain_names=True`` (``slipmaps report --quick``); the writer is a recorder (no measuring)."""
    calls = []
    monkeypatch.setattr(runner, "write", lambda s, path, show=None: calls.append(Path(path).name) or [path])
    runner.run(tmp_path / "one.md", ["iterative"])
    runner.run(tmp_path / "accuracy.md", ["iterative"], plain_names=True)
    names = ["convergence", "stiffness", "stability"]
    assert calls == ["one.md", *[f"{n}_one.md" for n in names], "accuracy.md", *[f"{n}.md" for n in names]]


# ----------------------------------------------------------------------------------------------
# The maps each study runs come from the roles in the index
# ----------------------------------------------------------------------------------------------
def test_every_declared_role_is_read_by_a_study():
    """Roles of the maps and their options in the index; the studies read no list of names."""
    map_roles = {r for m in index.maps() for r in m.roles}
    option_roles = {r for m in (*index.maps(), *index.halves()) for o in m.options for r in o.roles}
    assert map_roles == {"baseline", "accuracy-figure", "yu-target", "region", "default"}
    assert option_roles == {
        "accuracy-variants",
        "accuracy-passes",
        "accuracy-readings",
        "convergence-passes",
        "convergence-series",
        "stiffness-variants",
        "tolerance",
    }


def test_region_and_convergence_and_stiffness_maps_follow_the_roles():
    region = accuracy.maps_with("region")
    assert region and stability.region_maps() == [index.EXACT, *region]
    passes = [m.name for m in index.maps() if any("convergence-passes" in o.roles for o in m.options)]
    assert passes and convergence.study_maps() == passes
    assert {v.map for v in stiffness.variants()} == {
        m.name for m in index.maps() if m.name != index.EXACT and "k_d" in m.params
    }


def test_accuracy_variants_follow_the_option_roles():
    """Each map at its defaults, and every non-default value of an accuracy-variants option once."""
    variants = accuracy.variants()
    names = [m.name for m in index.maps() if m.name != index.EXACT]
    assert [v.map for v in variants if v.default] == names
    labels = {v.label for v in variants}
    checked = 0
    for m in (index.get(name) for name in names):
        for o in accuracy.options_with(m, "accuracy-variants"):
            for value in accuracy.other_values(o):
                assert f"{m.name} [{o.name}={value}]" in labels
                checked += 1
    assert checked >= 20


# ----------------------------------------------------------------------------------------------
# Imports run one way
# ----------------------------------------------------------------------------------------------
def _relative_imports() -> dict[str, list[tuple[str, str]]]:
    """Per module of runtime/studies/: (module, name) of each ``from .module import name``."""
    out = {}
    for path in sorted(STUDIES_DIR.glob("*.py")):
        found = []
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                for alias in node.names:
                    found.append((node.module or alias.name, alias.name))
        out[path.stem] = found
    return out


def test_study_modules_import_no_private_name_and_no_circle():
    imports = _relative_imports()
    assert len(imports) >= 10
    private = [(m, src, name) for m, found in imports.items() for src, name in found if name.startswith("_")]
    assert not private
    graph = {m: {src.split(".")[0] for src, _ in found} & set(imports) for m, found in imports.items()}
    assert any(graph.values())
    done: set[str] = set()

    def visit(m: str, path: tuple[str, ...]) -> None:
        assert m not in path, f"import circle: {' -> '.join((*path, m))}"
        if m not in done:
            for dep in sorted(graph[m]):
                visit(dep, (*path, m))
            done.add(m)

    for m in sorted(graph):
        visit(m, ())
    # the measurements never import their reports
    for measurement in ("accuracy", "stiffness", "stability"):
        assert f"{measurement}_report" not in graph[measurement]
