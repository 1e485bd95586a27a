"""The MuJoCo robot as a run's plant (runtime/control/robot_plant.py): every policy runs on it
unchanged, Raibert's controller runs on both plants, scenarios and the command line take it."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from slipmaps.runtime.robot.mj import headless_gl  # noqa: E402

headless_gl()  # MUJOCO_GL=egl before MuJoCo's import: its frames render headless
mujoco = pytest.importorskip("mujoco")

import slipmaps  # noqa: E402
from slipmaps.runtime.cli import main  # noqa: E402
from slipmaps.runtime.control import scenarios  # noqa: E402
from slipmaps.runtime.control.robot_plant import COLUMNS  # noqa: E402
from slipmaps.runtime.control.runs import run_batch  # noqa: E402
from slipmaps.runtime.robot.params import RobotParams  # noqa: E402

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
ROBOT = RobotParams().slip_params()


def _robot(steps: int = 8, **changes) -> slipmaps.Scenario:
    return slipmaps.Scenario(steps=steps, start_height=1.1, start_speed=4.0, plant="mujoco", **changes)


def test_a_robot_scenario_plans_with_the_robots_nominal_slip():
    sc = _robot()
    assert sc.params == ROBOT and sc.params.m == pytest.approx(30.3)
    assert slipmaps.Scenario(plant="exact").params == slipmaps.HUMAN_RUNNER


@pytest.mark.parametrize(
    "policy",
    [
        {"policy": "apex"},
        {"policy": "retraction", "retraction_rate": -1.0},
        {"policy": "time-based", "grounds": (-0.1, 0.1), "knots": 16},
        {"policy": "apex", "two_stage": True},
        {"policy": "raibert"},
    ],
    ids=["apex", "retraction", "time-based", "two-stage", "raibert"],
)
def test_every_policy_runs_the_robot_and_records_its_columns(policy):
    """Eight hops on flat ground at 4 m/s: no fall, the robot's own columns recorded, the ground it
    met 0; the deadbeat policies' next apex within 0.15 m/s and 1.5 cm of the target (measured:
    0.07-0.12 m/s and 1.4-12 mm with the robot's nominal SLIP as the model: a plant that loses
    energy at every hop); Raibert's in its own test."""
    run = slipmaps.run(_robot(**policy))
    assert not run.fell and len(run) == 8
    for c in COLUMNS:
        assert np.isfinite(run.column(c)).all(), c
    assert (run.column("skid") > 0.005).all() and (run.column("energy_start") > 300.0).all()
    assert np.array_equal(run.column("ground"), np.zeros(8))
    if policy["policy"] != "raibert":
        dh, dv = run.errors()
        assert np.abs(dv).max() < 0.15 and np.abs(dh).max() < 0.015


def test_a_two_stage_step_chooses_k_d_at_the_robots_bottom():
    run = slipmaps.run(_robot(two_stage=True))
    assert (np.asarray(run.batch.codes["bottom_status"][0][: len(run)]) >= 0).all()
    assert np.isfinite(run.column("bottom_us")).all()


def test_raibert_runs_on_both_plants():
    """The same policy and gains on the exact SLIP and on the robot: both complete, Raibert's plan
    status FEEDBACK, its k_d above k_c on the robot (the thrust that makes up the losses), the speed
    after the fourth hop within 10 % of the target (measured: 1.6 % on the SLIP, 3.8 % on the
    robot)."""
    for plant in ("exact", "mujoco"):
        run = slipmaps.run(_robot(steps=10, policy="raibert").with_(plant=plant))
        assert not run.fell, plant
        assert set(run.column("plan_status").tolist()) == {-3}
        assert run.steps[0]["plan_status"] == "FEEDBACK"
        _, dv = run.errors()
        assert np.abs(dv[4:]).max() < 0.4
    assert np.median(run.column("k_d")) > ROBOT.k_c


def test_the_robot_meets_its_terrain_unknown_to_the_controller():
    """Ramps the controller does not know: the ground recorded is the terrain's under the foot, not
    the scenario's level of the step, and the robot's apex is above it."""
    levels = np.random.default_rng(1).uniform(-0.05, 0.05, (1, 8))
    sc = _robot(known=0, target_height=(1.15,) * 8).with_(start_height=1.15)
    batch = run_batch(sc, levels)
    run = batch.run(0)
    assert not run.fell
    ground = run.column("ground")
    assert np.abs(ground).max() > 0.01 and not np.allclose(ground, levels[0])
    terrain = batch.plant.hoppers[0].terrain
    feet = np.cumsum(np.r_[0.0, run.column("step_length")[:-1]]) + run.column("foot_x")
    assert np.allclose(terrain.height_at(feet), ground, atol=2e-3)  # the foot's contact point


def test_a_robot_in_a_toml_scenario_and_its_bad_options():
    sc = scenarios.from_dict({"plant": {"kind": "mujoco", "body_mass": 25.0, "terrain": "boxes"}})
    assert sc.plant == "mujoco" and sc.plant_options == {"body_mass": 25.0, "terrain": "boxes"}
    assert sc.params.m == pytest.approx(25.3)
    with pytest.raises(ValueError) as err:
        scenarios.from_dict({"plant": {"kind": "mujoco", "body_mass": -1.0, "foot_radius": 0.0, "wings": 2}})
    lines = str(err.value).splitlines()
    assert len(lines) == 3, lines  # one line per bad value
    assert any("'wings' is not an option of the robot" in x for x in lines)
    assert any("body_mass" in x for x in lines) and any("foot_radius" in x for x in lines)
    with pytest.raises(ValueError, match="mismatch_mass is for a map plant"):
        _robot(mismatch_mass=0.1)
    with pytest.raises(ValueError, match="or 'mujoco', the MuJoCo robot"):
        scenarios.from_dict({"plant": "robot"})


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("robot_*.toml")))
def test_the_robot_examples_run_from_the_command_line(name, tmp_path, capsys):
    assert main(["run", str(EXAMPLES / name), "--plant", "mujoco", "--steps", "4", "--no-figure"]) == 0
    assert "plant mujoco; completed 4 steps" in capsys.readouterr().out


def test_the_command_line_renders_the_robot(tmp_path, capsys):
    """``--gif`` on the robot: MuJoCo's frames of the logged run (or a drawing without GL)."""
    from PIL import Image

    gif = tmp_path / "robot.gif"
    code = main(
        ["run", str(EXAMPLES / "robot_raibert.toml"), "--steps", "2", "--no-figure", "--gif", str(gif)]
    )
    assert code == 0
    with Image.open(gif) as im:
        assert im.n_frames > 10 and im.size == (480, 360)
    assert f"wrote {gif}" in capsys.readouterr().out


def test_identification_on_robot_hops_predicts_better_than_the_nominal_slip():
    """Three excited runs of 14 hops, three quarters fitted: the identified iterative map predicts
    the held-out next apexes better than the nominal SLIP (measured: 11 -> 3 mm, 3.0 -> 0.2 %)."""
    from slipmaps.runtime.studies.robot import _scenario, excitation

    runs = [run_batch(_scenario(len(H), V[0], heights=H, speeds=V)) for H, V in excitation(3, 14)]
    got = slipmaps.identify(runs, map="iterative", fit=("k", "l0", "loss"))
    before, after = got.errors_nominal["held_out"], got.errors_fitted["held_out"]
    assert after["count"] == before["count"] >= 8
    assert after["height_mean"] < 0.5 * before["height_mean"]
    assert after["speed_rel_mean"] < 0.3 * before["speed_rel_mean"] and after["speed_rel_mean"] < 0.005
    assert 0.0 < got.loss < 0.06 and math.isfinite(got.k_factor)


def test_without_mujoco_the_command_line_names_the_extra(monkeypatch, capsys):
    """A robot scenario where MuJoCo is not installed: one line naming the extra, exit 2."""
    import importlib

    from slipmaps.runtime.robot import mj

    real = importlib.import_module

    def missing(name, *args):
        if name == "mujoco":
            raise ImportError("No module named 'mujoco'")
        return real(name, *args)

    monkeypatch.setattr(mj.importlib, "import_module", missing)
    assert main(["run", str(EXAMPLES / "robot_raibert.toml"), "--steps", "2", "--no-figure"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [
        "slipmaps run: error: the robot (slipmaps.runtime.robot) needs MuJoCo: pip install 'slipmaps[robot]'"
    ]
