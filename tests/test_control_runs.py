"""Runs, scenarios, the plant, the path, the CLI verb and the evaluation record
(runtime/control/runs.py, scenarios.py, plant.py, motion.py, evaluation.py, report.py,
runtime/cli/run.py).

Every example scenario runs with the ``iterative`` model on the exact plant; the errors are bounded
by the measured ones (in the comments). The evaluation's small version is re-measured against
docs/control.json's ``quick`` record (tests/records.py tolerances) and docs/control.md must be the
rendering of the committed record.
"""

from __future__ import annotations

import ast
import json
import math
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from records import assert_close
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.control import evaluation, report, runs, scenarios
from slipmaps.runtime.control.plant import Plant

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
DOCS = ROOT / "docs"
P = slipmaps.HUMAN_RUNNER
NAMES = ("speed_up", "slow_down", "stop", "turn_around", "stairs", "rough_ground")


@pytest.fixture(scope="module")
def example_runs():
    return {name: slipmaps.run(EXAMPLES / f"{name}.toml") for name in NAMES}


def test_the_examples_are_the_evaluations_scenarios():
    # a sweep's file; the blind-running example (tests/test_swing.py); the stepping stones' example
    # (tests/test_footholds.py)
    others = {"sweep", "blind_running", "stones"}
    robot = {p.stem for p in EXAMPLES.glob("robot_*.toml")}  # the robot's (tests/test_robot_runs.py)
    assert robot, "the robot's examples are gone"
    assert sorted(p.stem for p in EXAMPLES.glob("*.toml") if p.stem not in others | robot) == sorted(NAMES)
    assert evaluation.SCENARIOS == NAMES


@pytest.mark.parametrize("name", NAMES)
def test_every_example_runs_on_the_exact_plant_within_a_hundredth_of_a_millimetre(example_runs, name):
    """Measured largest errors over the six: 1.2e-5 m and 5.5e-5 of the target speed (stop)."""
    r = example_runs[name]
    assert not r.fell, r.status
    assert len(r) == r.scenario.steps
    steps = r.steps
    assert steps and all(s["plan_status"] == "REACHED" for s in steps)
    assert all(s["plant_status"] == "OK" for s in steps)
    dh, dv = r.errors()
    rel = np.abs(dv) / np.maximum(np.abs(r.column("target_speed")), 1.0)
    assert np.max(np.abs(dh)) < 2e-5
    assert np.max(rel) < 1e-4
    assert np.all(np.isfinite(r.column("solve_us")))


def test_the_speed_changes_reach_their_ends(example_runs):
    assert example_runs["speed_up"].column("next_apex_speed")[-1] == pytest.approx(7.0, abs=1e-4)
    assert example_runs["slow_down"].column("next_apex_speed")[-1] == pytest.approx(3.0, abs=1e-4)
    stop = example_runs["stop"]
    assert abs(stop.column("next_apex_speed")[-1]) < 1e-6 and stop.column("next_apex_height")[
        -1
    ] == pytest.approx(1.1, abs=1e-4)
    turn = example_runs["turn_around"].column("next_apex_speed")
    assert turn[-1] == pytest.approx(-3.0, abs=1e-4)
    assert (turn > 0).any() and (turn < 0).any()


def test_the_planner_raises_the_apex_before_a_stair_and_keeps_it_within_a_steps_budget(example_runs):
    stairs = example_runs["stairs"]
    grounds = stairs.column("ground")
    before = np.concatenate([[0.0], grounds[:-1]])
    up = grounds - before > 0
    assert up.any()
    # the apex before each stair up is l0 above the stair (the floor; measured 1.15 m less the
    # iterative model's 3.6e-6 m)
    heights = stairs.column("apex_height")
    assert np.all(heights[up] >= grounds[up] - before[up] + P.l0 - 2e-5)
    speed_up = example_runs["speed_up"]
    nominal, planned = speed_up.column("nominal_speed"), speed_up.column("target_speed")
    assert (planned < nominal - 1e-3).any()  # the ramp is steeper than a step's energy budget
    assert np.all(planned <= nominal + 1e-12)


def test_a_plant_step_is_the_maps_apex_return_except_that_a_reversal_flies_on():
    rng = np.random.default_rng(3)
    n = 60
    h, v = rng.uniform(1.0, 1.3, n), rng.uniform(-6, 6, n)
    th, gr = np.sign(v) * rng.uniform(0.2, 0.5, n), rng.uniform(-0.2, 0.2, n)
    kd = rng.uniform(15_000, 30_000, n)
    steps = Plant("exact", P).step(h, v, th, gr, P.k_c, kd)
    same = reversed_ = 0
    for i in range(n):
        r = slipmaps.apex_return("exact", P.with_(k_d=kd[i]), h[i], v[i], th[i], ground=gr[i])
        if r.ok:
            assert (steps.next_apex_height[i], steps.next_apex_speed[i], steps.step_length[i]) == (
                r.next_apex_height,
                r.next_apex_speed,
                r.step_length,
            )
            same += 1
        elif r.status == slipmaps.Status.LIFTOFF_BACKWARD:
            assert steps.ok[i] and steps.next_apex_speed[i] * v[i] < 0
            reversed_ += 1
        else:
            assert steps.status[i] == r.status
    assert same > 20 and reversed_ > 0  # measured 33 and 13


def test_two_stage_plant_halves_compose_to_the_whole_stance():
    pl = Plant("exact", P)
    args = (np.array([1.0, 1.1]), np.array([5.0, 3.0]), np.array([0.36, 0.3]), np.zeros(2))
    whole = pl.step(*args, P.k_c, 25_000.0)
    halves = pl.decompress(pl.compress(*args, P.k_c), 25_000.0)
    assert np.max(np.abs(halves.next_apex_height - whole.next_apex_height)) < 1e-13  # measured 5e-15


def test_a_run_is_reproducible_and_its_noise_is_seeded():
    sc = scenarios.load(EXAMPLES / "stairs.toml").with_(noise_height=0.002, noise_speed=0.02, seed=7)
    a, b = slipmaps.run(sc), slipmaps.run(sc)
    assert np.array_equal(a.column("measured_speed"), b.column("measured_speed"))
    assert np.array_equal(a.column("next_apex_height"), b.column("next_apex_height"))
    c = slipmaps.run(sc.with_(seed=8))
    assert not np.array_equal(a.column("measured_speed"), c.column("measured_speed"))
    noise = a.column("measured_height") - a.column("apex_height")
    assert 0.0 < np.std(noise) < 0.01


def test_mismatch_and_unknown_ground_cost_accuracy_and_the_bottom_stage_wins_some_back():
    base = scenarios.load(EXAMPLES / "rough_ground.toml")
    exact = slipmaps.run(base)
    heavy = slipmaps.run(base.with_(mismatch_mass=0.1))
    dh0, _ = exact.errors()
    dh1, _ = heavy.errors()
    assert np.max(np.abs(dh1)) > 100 * np.max(np.abs(dh0))  # measured 3.4 cm against 4e-6 m
    blind = base.with_(known=0, start_height=1.2, target_height=(1.2,) * base.steps)
    one = slipmaps.run(blind)
    two = slipmaps.run(blind.with_(two_stage=True))
    assert not two.fell
    assert np.nanmax(np.abs(two.errors()[0])) < 0.2 * np.nanmax(np.abs(one.errors()[0]))


def test_a_fixed_angle_run_has_no_plan_and_falls_on_rough_ground():
    sc = scenarios.load(EXAMPLES / "rough_ground.toml").with_(fixed_angle=0.4111649, known=0)
    r = slipmaps.run(sc)
    assert r.fell and "fell at step" in r.status
    assert {s["plan_status"] for s in r.steps} == {"FIXED"}
    assert r.steps[-1]["plant_status"] != "OK"


def test_the_path_is_continuous_and_lands_the_foot_on_the_terrain(example_runs):
    r = example_runs["stairs"]
    path = r.path()
    assert path.sampled
    assert np.all(np.diff(path.t) >= 0)
    jumps = np.hypot(np.diff(path.x), np.diff(path.y))
    assert jumps.max() < 0.1  # 40 samples per phase: measured 0.06 m
    assert len(path.foot_x) == len(r)
    assert np.allclose(path.foot_y, r.column("ground"))
    legs = np.hypot(path.touchdown_body[:, 0] - path.foot_x, path.touchdown_body[:, 1] - path.foot_y)
    assert np.allclose(legs, P.q_r_td, atol=1e-12)
    x_apex = np.concatenate([[0.0], np.cumsum(r.column("step_length"))])
    assert np.allclose(path.apex[:, 0], x_apex)


@pytest.mark.parametrize(
    ("data", "needle"),
    [
        ({"stepz": 3}, "unknown key stepz; accepted: name"),
        ({"targets": {"speed": {"from": 1, "too": 2}}}, "[targets.speed] too: unknown key"),
        ({"targets": {"speed": "fast"}}, "[targets] speed: must be a number, a list or a ramp"),
        ({"terrain": {"kind": "hills"}}, "[terrain] kind: must be one of flat, steps, stairs, random"),
        ({"terrain": {"kind": "flat", "rise": 0.1}}, "[terrain] rise: is not a key of kind 'flat'"),
        ({"mismatch": {"mass": -1.5}}, "[mismatch] mass: must be a fraction above -1"),
        ({"model": "geyr"}, "model: unknown map 'geyr'"),
        ({"control": {"controls": ["angle"]}}, "[control] controls: has an unknown control 'angle'"),
        ({"control": {"bounds": {"k_d": [1.0]}}}, "[control] bounds['k_d'] must be a pair"),
        ({"params": {"m": -80}}, "[params] m: must be finite and positive, got -80"),
        ({"params": {"k": 0}}, "[params] k: must be finite and positive, got 0"),
        ({"params": {"l0": 0.6, "q_r_td": 0.7}}, "[params] q_r_td: must not exceed the rest length l0=0.6"),
        ({"steps": 0}, "steps: must be a whole number >= 1, got 0"),
        ({"steps": 2.5}, "steps: must be a whole number >= 1, got 2.5"),
        ({"control": {"tol": 0}}, "[control] tol: must be positive, got 0"),
        ({"noise": {"speed": -0.1}}, "[noise] speed: must not be negative, got -0.1"),
        ({"control": {"aim": "up"}}, "[control] aim: must be one of both, height, speed, got 'up'"),
        ({"control": {"decompression": "geyer"}}, "[control] decompression: "),
        (
            {"control": {"policy": "retraction", "retraction_rate": 5.0}},
            "[control] retraction_rate: must lie in [-3.13209, 3.13209] rad/s (|retraction_rate| <= "
            "sqrt(g_f/q_r_td)",
        ),
    ],
)
def test_a_bad_scenario_is_one_line_naming_the_key(data, needle):
    with pytest.raises(ValueError) as err:
        scenarios.from_dict(data, where="s.toml")
    message = str(err.value)
    assert needle in message and "\n" not in message and message.startswith("s.toml: ")
    assert message.count("s.toml") == 1  # the file named once (a [params] error named it twice)


def test_a_scenario_file_round_trips_its_profiles():
    sc = scenarios.load(EXAMPLES / "speed_up.toml")
    assert sc.steps == 16 and len(sc.target_speed) == 16
    assert sc.target_speed[0] == pytest.approx(3.0 + 4.0 / 12) and sc.target_speed[11:] == (7.0,) * 5
    stairs = scenarios.load(EXAMPLES / "stairs.toml")
    assert max(stairs.ground) == pytest.approx(0.6) and stairs.ground[-1] == pytest.approx(0.0, abs=1e-12)
    assert stairs.known == 3


def test_the_cli_runs_a_scenario_prints_its_table_and_writes_the_figure(tmp_path, capsys):
    figure = tmp_path / "out" / "stairs.png"
    assert main(["run", str(EXAMPLES / "stairs.toml"), "--figure", str(figure)]) == 0
    out = capsys.readouterr().out
    assert "stairs up and down: model iterative, plant exact; completed 14 steps" in out
    assert out.count(" REACHED ") == 14 and figure.stat().st_size > 10_000  # a row per step
    assert out.count("plan REACHED: ") == 1  # and the status's meaning once, under the table
    assert main(["run", str(EXAMPLES / "stop.toml"), "--no-figure", "--json", "--steps", "3"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert len(data["steps"]) == 3 and data["fell"] is False


def test_the_cli_runs_every_policy_of_the_declaration(capsys):
    """``--policy`` offers what runtime/control/policies.py declares: Raibert's controller too."""
    argv = [
        "run",
        str(EXAMPLES / "stop.toml"),
        "--no-figure",
        "--json",
        "--steps",
        "2",
        "--policy",
        "raibert",
    ]
    assert main(argv) in (0, 1)
    assert json.loads(capsys.readouterr().out)["scenario"]["policy"] == "raibert"


def test_the_cli_says_when_the_plant_fell(capsys):
    argv = ["run", str(EXAMPLES / "rough_ground.toml"), "--no-figure", "--model", "geyer", "--known", "0"]
    assert main(argv) == 1  # measured: geyer without the ground falls at step 2 (APEX_TOO_LOW)
    assert "fell at step" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("extra", "needle"),
    [
        (["--figure", "{file}/x.png"], "--figure {file}/x.png: cannot create the directory"),
        (["--figure", "{dir}/x.txt"], "--figure {dir}/x.txt: give an image file name ending in .png"),
        (["--gif", "{dir}/x.png"], "--gif {dir}/x.png: give an animation name ending in .gif"),
        (["--steps", "0"], "--steps must be at least 1"),
        (["--model", "nope"], "unknown map 'nope'"),
        (["--option", "nodes=5"], "nodes"),
        (["--out", "{dir}"], "--out: options of --evaluate"),
        (["--quick", "--blind"], "--quick, --blind: options of --evaluate"),
    ],
)
def test_cli_errors_are_one_line_before_any_work(extra, needle, tmp_path, capsys, monkeypatch):
    def no_work(*args, **kwargs):
        raise AssertionError("a run started before the arguments were refused")

    monkeypatch.setattr(runs, "run_batch", no_work)
    file = tmp_path / "c.pdf"
    file.write_text("a file")
    fill = {"file": str(file), "dir": str(tmp_path)}
    assert main(["run", str(EXAMPLES / "stairs.toml"), *(a.format(**fill) for a in extra)]) == 2
    err = capsys.readouterr().err.strip()
    assert needle.format(**fill) in err and "\n" not in err, err
    assert main(["run"]) == 2
    assert "give a scenario file" in capsys.readouterr().err


def test_a_gif_is_written_frame_by_frame_with_a_progress_bar(tmp_path, capsys):
    from PIL import Image

    r = slipmaps.run(
        EXAMPLES / "stop.toml", steps=2, target_height=(1.01, 1.02), target_speed=(4.5, 4.0), ground=(0, 0)
    )
    from slipmaps.runtime.control.figures import animate

    path = animate(r, tmp_path / "stop.gif", fps=10, progress=True)
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames > 5
        frames = im.n_frames
        im.seek(frames // 2)
        middle = np.asarray(im.convert("RGB"))
    # the frames move (the body and the view), and the bar counted every one of them
    with Image.open(path) as im:
        assert not np.array_equal(np.asarray(im.convert("RGB")), middle)
    assert f"{frames}/{frames} frames" in capsys.readouterr().err


def test_control_imports_only_the_layers_below_it_and_nothing_below_imports_it():
    """control uses api, exact, analysis, robot (the MuJoCo robot a plant adapter drives; the robot
    never imports control) and the generated kernels; only control itself, report (the report's
    sections 6-8 read the control evaluation), export (the C solver's bindings read its settings
    record), studies (the robot study runs the controllers), cli and the public API import control."""
    runtime = ROOT / "runtime"
    for path in runtime.rglob("*.py"):
        layer = path.relative_to(runtime).parts[0]
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module:
                mod = "." * node.level + node.module
                names = [mod]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            else:
                continue
            for name in names:
                uses_control = "control" in name.split(".") and ("runtime" in name or name.startswith("."))
                if layer not in ("control", "report", "export", "studies", "cli", "public"):
                    assert not uses_control, f"{path} imports {name}"
                if layer == "control" and name.startswith(".."):
                    assert name.split(".")[2] in ("api", "exact", "analysis", "robot"), (
                        f"{path} imports {name}"
                    )


# --- the evaluation record ------------------------------------------------------------------------


@pytest.fixture(scope="module")
def record():
    return json.loads((DOCS / "control.json").read_text())


def test_the_small_evaluation_is_current(record):
    """control.json's quick record re-measured (regenerate with `slipmaps run --evaluate`)."""
    measured = report.rounded(evaluation.evaluate(EXAMPLES, quick=True, progress=False))
    assert_close(measured, record["quick"], "quick")
    assert measured["target_check"]["steps"] > 0  # the filter below is not empty


def test_the_markdown_renders_the_record(record):
    assert (DOCS / "control.md").read_text() == report.render(record)


def test_the_control_pages_numbers_are_the_records(record):
    """The measured paragraph of docs/control_planning.md (the README's, before the site took it) is
    report.summary of the committed record (rewrapped)."""
    page = " ".join((DOCS / "control_planning.md").read_text().split())
    assert " ".join(report.summary(record).split()) in page


def test_the_recorded_evaluation_meets_its_targets_or_says_so(record):
    verdicts = report.verdicts(record)
    assert len(verdicts) == 4
    text = (DOCS / "control.md").read_text()
    for target, met, measured in verdicts:
        assert f"| {target} | {'yes' if met else '**no**'} | {measured} |" in text
    tc = record["target_check"]
    assert tc["steps"] > 50 and tc["within"] == tc["steps"]  # every step of every scenario
    it = record["rough"]["models"]["iterative"]["known"]
    ds = record["rough"]["d"]
    assert [s for d, s in zip(ds, it["share"], strict=True) if d <= 0.3] == [1.0, 1.0, 1.0]
    assert it["largest_d"] >= 0.3
    assert record["rough"]["runs"] == 1000 and record["rough"]["steps"] == 20
    assert set(record["tracking"]["stairs"]) >= {m.name for m in slipmaps.maps()}
    for figure in ["control_rough.png", *(f"control_{n}.png" for n in NAMES)]:
        assert (DOCS / figure).stat().st_size > 10_000


def test_every_map_has_its_cost_recorded(record):
    cost = record["cost"]["models"]
    assert set(cost) == {m.name for m in slipmaps.maps()}
    for row in cost.values():
        assert row["scalar_us_median"] > 0 and math.isfinite(row["batch_us_per_row"])
        assert row["jacobians_mean"] >= 1.0


def test_the_table_gives_absolute_speed_errors_also_where_the_target_is_a_stop(example_runs):
    """A stop's target speed is 0: the table's speed error is absolute (mm/s), never nan."""
    r = example_runs["stop"]
    assert np.any(r.column("target_speed") == 0.0)
    rows = r.table().splitlines()
    assert "err v mm/s" in rows[0]
    assert not any("nan" in line.split() for line in rows[2 : 2 + len(r)]), rows


def test_a_runs_former_names_of_the_next_apex_read_with_a_warning(example_runs):
    """``next_height``, ``next_speed`` are ``next_apex_height``, ``next_apex_speed`` (the names of
    every result: runtime/api/names.py); the former names read, equal, with a DeprecationWarning."""
    r = example_runs["speed_up"]
    row = r.steps[0]
    assert "next_height" not in row and "next_apex_height" in row and "next_height" not in r.to_pandas()
    with pytest.warns(DeprecationWarning, match="'next_speed' of a run to 'next_apex_speed'"):
        assert np.array_equal(r.column("next_speed"), r.column("next_apex_speed"))
    with pytest.warns(DeprecationWarning, match="'next_height' of a run to 'next_apex_height'"):
        assert row["next_height"] == row["next_apex_height"]
    with pytest.warns(DeprecationWarning, match="next_height"):
        assert np.array_equal(r.batch["next_height"], r.batch.values["next_apex_height"], equal_nan=True)


def test_a_run_to_pandas_has_a_row_per_step_and_the_states_by_coordinate(example_runs):
    r = example_runs["stairs"]
    df = r.to_pandas()
    assert len(df) == len(r) and list(df["step"]) == list(range(len(r)))
    assert {"touchdown_q_r", "liftoff_q_thd", "plan_status", "plant_status", "plant_status_code"} <= set(df)
    assert (df["plant_status"] == "OK").all() and (df["plan_status"] == "REACHED").all()
    assert np.array_equal(df["next_apex_speed"].to_numpy(), r.column("next_apex_speed"))
    assert df["liftoff_q_th"].to_numpy().tolist() == [s["liftoff"][2] for s in r.steps]


# --- a scenario's own leg, its inputs checked up front, honest plan statuses, plain figures ---------

#: The issue's small robot: 30 kg, a 0.6 m leg, 9 kN/m; a speed-up from a 0.65 m apex.
ROBOT = {"m": 30.0, "l0": 0.6, "k": 9000.0}
ROBOT_RUN = {"steps": 4, "start": {"height": 0.65, "speed": 2.5}}
ROBOT_TOML = """steps = 4
start = { height = 0.65, speed = 2.5 }
[targets]
speed = { from = 2.5, to = 3.0, steps = 3 }
[params]
m = 30.0
l0 = 0.6
k = 9000.0
"""


def _robot_scenarios(tmp_path):
    file = tmp_path / "robot.toml"
    file.write_text(ROBOT_TOML)
    ramp = {"speed": {"from": 2.5, "to": 3.0, "steps": 3}}
    loaded = scenarios.load(file)
    target = loaded.target_speed
    return {
        "toml": file,
        "dict": {**ROBOT_RUN, "targets": ramp, "params": ROBOT},
        "Scenario(params=dict)": scenarios.Scenario(
            steps=4, start_height=0.65, start_speed=2.5, target_speed=target, params=ROBOT
        ),
        "HUMAN_RUNNER.with_": scenarios.Scenario(
            steps=4, start_height=0.65, start_speed=2.5, target_speed=target, params=P.with_(**ROBOT)
        ),
    }


def test_a_scenarios_leg_lengths_follow_its_own_l0_in_toml_and_python(tmp_path):
    """`[params] l0 = 0.6` (and its Python forms) kept the human runner's 1 m touchdown and liftoff
    lengths and failed; they follow the scenario's l0 as SlipParams' do, and the run completes
    (measured: every step REACHED, the plant within 3.5e-6 m and 1.4e-5 m/s of the targets)."""
    made = _robot_scenarios(tmp_path)
    for how, sc in made.items():
        r = slipmaps.run(sc)
        p = r.scenario.params
        assert (p.l0, p.q_r_td, p.q_r_lo, p.m, p.k_c, p.k_d) == (0.6, 0.6, 0.6, 30.0, 9000.0, 9000.0), how
        assert not r.fell and len(r) == 4, how
        assert {s["plan_status"] for s in r.steps} == {"REACHED"}, how
        dh, dv = r.errors()
        assert np.abs(dh).max() < 1e-5 and np.abs(dv).max() < 1e-4, how
        assert r.column("target_speed")[-1] == pytest.approx(3.0)
    assert main(["run", str(made["toml"]), "--no-figure"]) == 0
    # a length given stays, and one above the scenario's l0 is refused naming the key, once
    kept = scenarios.from_dict({"params": {**ROBOT, "q_r_td": 0.55}})
    assert (kept.params.q_r_td, kept.params.q_r_lo) == (0.55, 0.6)
    assert P.with_(q_r_td=0.9).with_(l0=0.95).q_r_td == 0.9  # not at the rest length: kept


def _no_run(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("a run started before its inputs were checked")

    monkeypatch.setattr(runs, "_Controller", refuse)


@pytest.mark.parametrize(
    ("overrides", "error", "needle"),
    [
        ({"steps": 2.5}, ValueError, "scenario 'run': steps must be a whole number >= 1, got 2.5"),
        ({"steps": -3}, ValueError, "scenario 'run': steps must be a whole number >= 1, got -3"),
        ({"steps": 0}, ValueError, "scenario 'run': steps must be a whole number >= 1, got 0"),
        ({"steps": True}, ValueError, "steps must be a whole number >= 1, got True"),
        ({"stepz": 3}, TypeError, "unknown scenario field 'stepz' (did you mean steps?); the fields: name,"),
        ({"start_height": -1.0}, ValueError, "start_height must not be negative, got -1.0"),
        ({"start_speed": "5"}, ValueError, "start_speed must be a finite number, got '5'"),
        ({"known": -1}, ValueError, "known must be a whole number >= 0, got -1"),
        ({"model": "bogus"}, ValueError, "model: unknown map 'bogus'; the maps are: geyer"),
        ({"aim": "up"}, ValueError, "aim must be one of both, height, speed, got 'up'"),
        ({"tol": 0.0}, ValueError, "tol must be positive, got 0.0"),
        ({"noise_speed": math.nan}, ValueError, "noise_speed must be a finite number, got nan"),
        ({"mismatch_mass": -1.0}, ValueError, "mismatch_mass must be a fraction above -1"),
        ({"two_stage": 1}, ValueError, "two_stage must be true or false, got 1"),
        ({"fixed_angle": 2.0}, ValueError, "fixed_angle must lie in (-pi/2, pi/2), got 2.0"),
        ({"controls": ("angle",)}, ValueError, "controls has an unknown control 'angle'; the controls are"),
        ({"bounds": {"k_d": (1.0,)}}, ValueError, "scenario 'run': bounds['k_d'] must be a pair"),
        ({"target_speed": (5.0,) * 3}, ValueError, "target_speed has 3 values for 10 steps"),
        ({"params": 3}, ValueError, "params must be a SlipParams or a table of its fields, got 3"),
        ({"params": {"k": 0}}, ValueError, "SlipParams.k must be finite and positive, got 0"),
        ({"policy": "retraction", "retraction_rate": 5.0}, ValueError, "retraction_rate must lie in [-3.1"),
        ({"policy": "retraction", "retraction_rate": 1e9}, ValueError, "sqrt(g_f/q_r_td): the foot's"),
        ({"seeds": [0, 1]}, ValueError, "seeds must be 1 whole numbers >= 0 (one per run), got [0.0, 1.0]"),
        ({"grounds": np.full((1, 10), np.nan)}, ValueError, "grounds must be finite, got nan"),
        ({"scalar": "yes"}, TypeError, "scalar must be True, False or None, got 'yes'"),
    ],
)
def test_run_overrides_are_checked_before_any_work_in_one_line_each(overrides, error, needle, monkeypatch):
    _no_run(monkeypatch)
    for call in (slipmaps.run, slipmaps.run_batch):
        with pytest.raises(error) as err:
            call(**overrides)
        message = str(err.value)
        assert needle in message and "\n" not in message, message


def test_the_retraction_rate_is_checked_against_the_maps_range_wherever_it_enters(tmp_path, capsys):
    """API, TOML and the CLI flag refuse a rate beyond |rate| <= sqrt(g_f/q_r_td) (the flight
    kernels' guard, derive/params.py's row) with the range for the scenario's parameters; a
    scenario with a shorter leg has a wider range (sqrt(9.81/0.6) = 4.04 rad/s)."""
    robot = scenarios.Scenario(params=ROBOT, policy="retraction", retraction_rate=-4.0)  # within
    assert robot.retraction_rate == -4.0
    with pytest.raises(ValueError, match=r"retraction_rate must lie in \[-4\.04351, 4\.04351\] rad/s"):
        robot.with_(retraction_rate=-4.1)
    file = tmp_path / "fast.toml"
    file.write_text('steps = 2\n[control]\npolicy = "retraction"\nretraction_rate = 5.0\n')
    for argv in (["run", str(file)], ["run", str(EXAMPLES / "stairs.toml"), "--retraction-rate", "1e9"]):
        assert main([*argv, "--no-figure"]) == 2
        err = capsys.readouterr().err.strip()
        assert "must lie in [-3.13209, 3.13209] rad/s" in err and "\n" not in err, err
    assert main(["run", str(file), "--no-figure"]) == 2
    assert f"{file}: [control] retraction_rate: must lie in" in capsys.readouterr().err
    assert main(["run", str(EXAMPLES / "stairs.toml"), "--retraction-rate", "-5", "--no-figure"]) == 2
    assert "error: --retraction-rate must lie in [-3.13209" in capsys.readouterr().err


def test_a_binary_scenario_file_is_named(tmp_path, capsys):
    file = tmp_path / "photo.toml"
    file.write_bytes(bytes(range(128, 256)))
    assert main(["run", str(file), "--no-figure"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"slipmaps run: error: {file}: not a TOML file: not UTF-8 text (byte 0)"


def test_a_step_planned_on_the_assumed_flat_ground_says_blind_not_reached():
    """Unknown ground (known = 0): the apex-set policies plan on flat ground, so a step whose true
    ground differs is BLIND (the issue's run said REACHED while the plant missed by up to 166 mm);
    on known ground, or on flat ground unknown, a reached step is REACHED."""
    blind = slipmaps.run(EXAMPLES / "blind_running.toml", steps=4, policy="retraction", retraction_rate=-1.0)
    moved = blind.column("ground") != 0.0
    assert moved.all()  # the filter below is not empty: every touchdown off the flat ground
    assert [s["plan_status"] for s in blind.steps] == ["BLIND"] * 4
    dh, _ = blind.errors()
    assert np.abs(dh).max() > 0.05  # measured 124 mm by step 3: what BLIND warns of
    assert "plan BLIND: the model's next apex on the target on the flat ground the controller assumed" in (
        blind.table()
    )
    flat = slipmaps.run(steps=2, known=0, policy="retraction", retraction_rate=-1.0)
    assert [s["plan_status"] for s in flat.steps] == ["REACHED"] * 2
    known = slipmaps.run(EXAMPLES / "rough_ground.toml", steps=3, policy="retraction", retraction_rate=-1.0)
    assert [s["plan_status"] for s in known.steps] == ["REACHED"] * 3
    assert np.abs(known.errors()[0]).max() < 1e-5  # measured 4e-6 m
    assert set(runs.PLAN_NAMES.values()) - {"-"} == set(runs.PLAN_MEANINGS)


def test_run_figures_label_their_ticks_with_plain_values(tmp_path, monkeypatch):
    """A run that holds 1 m within a few micrometres drew its apex panel as '1e-6 + 9.9999e-1'; every
    axis now labels plain values (api/paths.py's plain_ticks, in the one save_figure)."""
    from slipmaps.runtime.api import paths
    from slipmaps.runtime.control.figures import run_figure

    drawn = []
    save = paths.save_figure

    def spy(fig, path, **kw):
        out = save(fig, path, **kw)
        drawn.append(fig)
        return out

    monkeypatch.setattr(paths, "save_figure", spy)
    r = slipmaps.run(steps=3)
    heights = r.column("next_apex_height")
    assert 0.0 < np.ptp(heights) < 1e-4 and abs(heights.mean() - 1.0) < 1e-4  # what drew the offset
    run_figure(r, tmp_path / "run.png")
    (fig,) = drawn
    texts = [a.get_offset_text().get_text() for ax in fig.axes for a in (ax.xaxis, ax.yaxis)]
    assert len(texts) == 8 and texts == [""] * 8
    labels = [t.get_text() for t in fig.axes[1].yaxis.get_ticklabels() if t.get_text()]
    assert labels and all(abs(float(t.replace("\u2212", "-")) - 1.0) < 1e-3 for t in labels), labels


def test_every_figure_is_saved_through_the_one_helper():
    """Every figure file is written by api/paths.py's save_figure (plain ticks, one error line)."""
    calls = [
        path.relative_to(ROOT).as_posix()
        for path in (ROOT / "runtime").rglob("*.py")
        if ".savefig(" in path.read_text()
    ]
    assert calls == ["runtime/api/paths.py"]


def test_the_step_to_step_correction_removes_a_steady_model_error():
    """A plant 5 % heavier than the model misses every target by 18.1 mm and 35.4 mm/s; with the
    correction of the last three steps the misses fall below 0.1 mm and 0.2 mm/s from the eighth
    step on (measured: 0.02 mm, 0.0 mm/s)."""
    sc = slipmaps.Scenario(steps=12, start_height=1.0, start_speed=5.0, mismatch_mass=0.05, known=1)
    dh0, dv0 = slipmaps.run(sc).errors()
    dh, dv = slipmaps.run(sc.with_(correction=3)).errors()
    assert np.abs(dh0[4:]).min() > 0.015 and np.abs(dv0[4:]).min() > 0.03
    assert np.abs(dh[7:]).max() < 1e-4 and np.abs(dv[7:]).max() < 2e-4


def test_the_correction_leaves_out_steps_whose_ground_changed():
    """The mean residual of the last steps whose touchdown ground changed by at most the gate."""
    from slipmaps.runtime.control.runs import _correction

    values = {
        "ground": np.array([[0.0, 0.0, 0.05, 0.05, 0.05]]),
        "next_apex_height": np.array([[1.01, 1.02, 1.50, 1.04, 0.0]]),
        "predicted_height": np.ones((1, 5)),
        "next_apex_speed": np.array([[5.1, 5.2, 9.0, 5.4, 0.0]]),
        "predicted_speed": np.full((1, 5), 5.0),
    }
    sc = slipmaps.Scenario(steps=5, correction=3, correction_gate=0.01)
    dh, dv = _correction(sc, 4, np.array([0]), values)
    # steps 1..3: step 2's ground rose 5 cm (left out); steps 1 and 3 averaged
    assert dh[0] == pytest.approx(0.03) and dv[0] == pytest.approx(0.3)
    assert _correction(sc.with_(correction=0), 4, np.array([0]), values)[0][0] == 0.0
