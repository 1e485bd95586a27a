"""The command line: `slipmaps maps`, `compare` (the README's main job) for every map, `equations
--json`, `generate --check`, and one-line errors (exit 2, no traceback)."""

from __future__ import annotations

import json
import math

import pytest
from slipmaps.generated import maps_index
from slipmaps.generated.status import Status
from slipmaps.runtime.api import index
from slipmaps.runtime.api.params import HUMAN_RUNNER
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.cli.compare import Row, compare
from slipmaps.runtime.studies.quantities import QUANTITIES

GENERATED = [row["name"] for row in maps_index.MAPS]


def test_maps_lists_every_map_of_the_index(capsys):
    assert main(["maps"]) == 0
    out = capsys.readouterr().out
    for name in [*GENERATED, "exact"]:
        assert name in out


def test_maps_json_has_the_documented_fields(capsys):
    assert main(["maps", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    halves = [row["name"] for row in maps_index.HALVES]
    assert [r["name"] for r in rows] == [*GENERATED, "exact", *halves]
    for r in rows:
        assert {"name", "title", "section", "equations", "requires", "options"} <= set(r)
        numbered = [e for e in r["equations"] if str(e).isdigit()]
        assert numbered and all(isinstance(e, int) for e in numbered), r["name"]
    sections = {r["name"]: r["section"] for r in rows}
    assert sections["geyer"] == "3.1"
    assert [sections[f"gravity-type{i}"] for i in range(6)] == ["4.1", "4.2", "4.3", "4.4", "4.5", "4.6"]


def test_compare_default_prints_table_and_writes_plot(tmp_path, capsys):
    png = tmp_path / "cmp.png"
    assert main(["compare", "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    for q in QUANTITIES:
        assert q.label in out
    assert "abs err" in out and "rel err" in out
    assert png.stat().st_size > 10_000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_prints_its_table_before_drawing_the_plot(tmp_path, capsys, monkeypatch):
    # a first run compiles the plot's kernels after the table: the reader has the numbers first
    from slipmaps.runtime.cli import compare as compare_module

    printed = []
    monkeypatch.setattr(compare_module, "plot", lambda c, path: printed.append(capsys.readouterr().out))
    png = tmp_path / "p.png"
    assert main(["compare", "--against", "geyer", "--plot", str(png)]) == 0
    assert len(printed) == 1 and "next apex speed" in printed[0]
    assert capsys.readouterr().out.strip() == f"plot: {png}"


def test_compare_runs_the_exact_step_through_its_solve_ivp_backend():
    # one step of a map with a solve_ivp backend (its stance and its plotted curve) runs through it
    # unless a method was chosen: a first run on an empty cache compiles no exact kernel; the
    # backend's step and curve are the compiled simulator's to round-off (measured: 3.6e-15 on the
    # curve, 1.1e-15 on the table's values at the default step, relative above 1)
    from slipmaps.runtime.api.maps import stance, trajectory
    from slipmaps.runtime.cli.compare import one_step_options

    exact = index.get("exact")
    assert one_step_options(exact, {"rtol": 1e-9}) == {"rtol": 1e-9, "method": "scipy"}
    assert one_step_options(exact, {"method": "compiled"}) == {"method": "compiled"}
    assert one_step_options(index.get("geyer"), {}) == {}
    c = compare(HUMAN_RUNNER)
    assert c.against.options == {"method": "scipy"} and c.map.options == {}
    asked = compare(HUMAN_RUNNER, against_options={"method": "compiled"})
    assert asked.against.options == {"method": "compiled"}
    rows = [(r.reference, s.reference) for r, s in zip(c.rows, asked.rows, strict=True)]
    assert rows and all(abs(a - b) <= 1e-12 * max(1.0, abs(b)) for a, b in rows)
    td = c.touchdown
    assert stance("exact", HUMAN_RUNNER, td, method="scipy").ok
    t, curve, status = trajectory("exact", HUMAN_RUNNER, td, **c.against.options)
    _, compiled, compiled_status = trajectory("exact", HUMAN_RUNNER, td, t=t)
    assert status == compiled_status == Status.OK and t.size == 200
    assert abs(curve - compiled).max() < 1e-12


def test_compare_plots_a_map_with_event_states_only(tmp_path, capsys):
    # `iterative` has no state-at-time kernel: its touchdown, bottom and liftoff are marked
    png = tmp_path / "it.png"
    argv = ["compare", "--map", "iterative", "--k-c", "20000", "--k-d", "25000", "--plot", str(png)]
    assert main(argv) == 0
    assert "next apex speed" in capsys.readouterr().out
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_json_matches_python_api(capsys):
    assert main(["compare", "--json", "--no-plot", "--apex-speed", "4.5", "--angle", "0.3"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["exact_status"] == "OK" and data["approx_status"] == "OK"
    assert data["map"] == "geyer" and data["against"] == "exact"
    ref = compare(HUMAN_RUNNER, apex_speed=4.5, touchdown_angle=0.3)
    assert [r["quantity"] for r in data["rows"]] == [q.label for q in QUANTITIES]
    for row, r in zip(data["rows"], ref.rows, strict=True):
        assert row["reference"] == r.reference and row["value"] == r.value
        assert row["abs_error"] == r.value - r.reference


@pytest.mark.parametrize("name", GENERATED)
def test_compare_runs_for_every_map(name, capsys):
    assert main(["compare", "--map", name, "--json", "--no-plot"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["map"] == name and data["map_status"] == "OK" and data["against_status"] == "OK"
    speed = next(r for r in data["rows"] if r["quantity"] == "next apex speed")
    # Every map predicts the default step's next apex speed within 2 % (measured: Geyer 1.45 %, the
    # gravity corrections 0.1-0.4 %), except the report's printed iteration, which makes no accuracy
    # claim (measured: 4.4 %).
    if not index.get(name).as_printed:
        assert abs(speed["rel_error"]) < 0.02


def test_compare_with_options_and_against_another_map(capsys):
    argv = ["compare", "--map", "gravity-type2", "--option", "reading=report", "--option", "iterations=1"]
    argv += ["--option", "tol=0", "--against", "geyer", "--json", "--no-plot"]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["map_options"] == {"reading": "report", "iterations": 1, "tol": 0.0}
    assert data["against"] == "geyer" and data["against_status"] == "OK"


def test_compare_nonsymmetric_touchdown_state(capsys):
    # A touchdown state off the symmetric gait (leg shorter than l0, faster leg swing): one flag away.
    argv = [
        "compare",
        "--json",
        "--no-plot",
        "--q-r-td",
        "0.98",
        "--touchdown",
        "0.98",
        "-2.0",
        "0.3",
        "-5.0",
    ]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["touchdown"] == {"q_r": 0.98, "q_rd": -2.0, "q_th": 0.3, "q_thd": -5.0}
    assert data["exact_status"] == "OK" and data["approx_status"] == "OK"
    lo_angle = next(r for r in data["rows"] if r["quantity"] == "liftoff leg angle q_th_lo")
    assert lo_angle["reference"] != pytest.approx(-0.3, abs=0.02)  # not a mirror of touchdown


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["--map", "geyer", "--k-c", "20000", "--k-d", "25000"], "constant leg stiffness"),  # names it
        (["--m", "-80"], "--m must be finite and positive, got -80"),
        (["--angle", "2.0"], "--angle must lie in (-pi/2, pi/2)"),
        (["--map", "gravity-type2", "--option", "reading=sideways"], "'mean', 'report'"),
        (["--map", "gravity-type2", "--option", "nonsense=1"], "its options: reading"),
        (["--map", "gravity-type2", "--option", "iterations=2.5"], "iterations"),
        (["--map", "geyer", "--option", "x"], "KEY=VALUE"),
    ],
)
def test_compare_invalid_input_is_a_clear_error(argv, needle, capsys):
    assert main(["compare", "--no-plot", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("slipmaps compare: error:") and needle in err
    assert "Traceback" not in err and err.count("\n") == 1


def test_compare_variable_stiffness_names_the_maps_that_accept_it(capsys):
    assert main(["compare", "--no-plot", "--map", "geyer", "--k-c", "20000", "--k-d", "25000"]) == 2
    err = capsys.readouterr().err
    accepting = [m.name for m in index.maps() if "constant_stiffness" not in m.requires]
    assert accepting and all(name in err for name in accepting)


def test_compare_variable_stiffness_defaults_to_the_simple_variable_stiffness_map(capsys):
    """k_c != k_d with no --map: Geyer et al.'s map would refuse, so its split form geyer-vs runs."""
    assert main(["compare", "--no-plot", "--k-c", "20000", "--k-d", "25000"]) == 0
    out = capsys.readouterr().out
    assert "map:       geyer-vs" in out and "k_d=25000" in out


def test_compare_exact_against_exact_has_zero_error(capsys):
    assert main(["compare", "--map", "exact", "--json", "--no-plot"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert all(r["abs_error"] == 0.0 for r in rows)


def test_equations_json_classifies_every_equation(capsys):
    assert main(["equations", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    numbers = {str(r["number"]) for r in rows}
    assert {str(n) for n in range(1, 78)} <= numbers
    assert {r["status"] for r in rows} <= {"verified", "corrected", "definition"}
    assert all({"number", "status", "note"} <= set(r) for r in rows)


def test_rel_error_of_zero_reference_is_nan():
    assert math.isnan(Row("x", "m", 0.0, 1.0).rel_error)


def test_generate_does_not_need_the_generated_index():
    """`slipmaps generate` rebuilds generated/: it must start when generated/maps_index.py is stale,
    broken or missing (here: made unimportable). The command line and the derivations import
    without it; test_api checks that the derivations load nothing from the runtime."""
    import subprocess
    import sys

    code = (
        "import sys; sys.modules['slipmaps.generated.maps_index'] = None\n"
        "from slipmaps.runtime.cli.app import build_parser\n"
        "args = build_parser().parse_args(['generate', '--check'])\n"
        "import slipmaps.derive.generate\n"
        "print(args.command)\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    assert run.stdout.strip() == "generate"


@pytest.mark.parametrize(
    ("name", "end"), [("iterative-compression", "bottom"), ("iterative-decompression", "liftoff")]
)
def test_compare_a_half_map_against_the_same_half(name, end, tmp_path, capsys):
    """The half from the exact touchdown (compression) or the exact bottom (decompression) against
    the exact simulator's same half (measured: below 2e-6 relative at the default step)."""
    assert main(["compare", "--map", name, "--k-c", "20000", "--k-d", "25000", "--json", "--no-plot"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["map"] == name and data["map_status"] == "OK" and data["against_status"] == "OK"
    rows = {r["quantity"]: r for r in data["rows"]}
    assert set(rows) == {
        "half time",
        "end leg length q_r",
        "end leg rate q_rd",
        "end leg angle q_th",
        "end angle rate q_thd",
    }
    assert all(abs(r["abs_error"]) < 2e-6 * max(1.0, abs(r["reference"])) for r in rows.values()), rows
    png = tmp_path / "half.png"
    assert main(["compare", "--map", name, "--plot", str(png)]) == 0
    header = capsys.readouterr().out.split("quantity")[0]
    assert ("bottom:" in header) == (end == "liftoff")  # the decompression half starts at the bottom
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_maps_lists_the_half_maps(capsys):
    assert main(["maps"]) == 0
    out = capsys.readouterr().out
    assert "iterative-compression" in out and "half of iterative: touchdown -> bottom" in out


def test_compare_a_decompression_half_without_a_reference_bottom_says_it_did_not_run(capsys):
    argv = ["compare", "--map", "iterative-decompression", "--angle", "1.4", "--json", "--no-plot"]
    assert main(argv) == 1  # the reference fell: a side failed physically
    data = json.loads(capsys.readouterr().out)
    assert data["against_status"] == data["map_status"] == "FALL"
    assert data["map_message"].startswith("not run: ")
    assert all(r["value"] is None for r in data["rows"])


def test_generate_target_c_reports_its_stages_and_its_kernels(tmp_path, capsys, monkeypatch):
    """`slipmaps generate --target c` took 17 s in silence (issue 52): each of its stages is a line
    on standard error (deriving 12 s, translating the 208 kernels 20 s: a bar on a terminal,
    writing), the paths written on standard output."""
    from slipmaps.derive import ctarget, generate

    kernels = []

    def build(modules, show=False):
        kernels.append(show)
        return {"slipmaps.h": "/* h */\n", "slipmaps.c": "/* c */\n"}

    monkeypatch.setattr(generate, "modules", lambda: ())
    monkeypatch.setattr(ctarget, "build", build)
    assert main(["generate", "--target", "c", str(tmp_path)]) == 0
    captured = capsys.readouterr()
    assert captured.err.splitlines() == [
        "slipmaps generate: [1/3] deriving the kernel modules from derive/ (SymPy)",
        "slipmaps generate: [2/3] translating the kernels to C",
        f"slipmaps generate: [3/3] writing the C library into {tmp_path}",
    ]
    assert kernels == [None]  # the bar: on a terminal only
    assert captured.out.splitlines() == [
        f"wrote {tmp_path / 'slipmaps.h'}",
        f"wrote {tmp_path / 'slipmaps.c'}",
    ]
