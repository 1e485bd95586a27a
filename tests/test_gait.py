"""Periodic gaits (runtime/analysis/gait.py, `slipmaps gait`) and the stability docs (docs/stability.md).

The fixed points are checked against their definition (the step returns to the same apex), against
brentq, and their eigenvalue against a finite-difference slope of the one-dimensional return map.
The record's fixed-point grids are re-measured once per module (15 lines, each about 0.3-0.5 s with
the solve_ivp simulator, the approximate maps in milliseconds), the region at a few cells.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
import slipmaps
from records import assert_close
from scipy.optimize import brentq
from slipmaps.runtime.analysis import gait
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.studies import stability
from slipmaps.runtime.studies.report_format import rounded
from slipmaps.runtime.studies.stability_report import grid_rows, region_facts, render_markdown

DOCS = Path(__file__).resolve().parent.parent / "docs"
P = slipmaps.HUMAN_RUNNER
#: Seyfarth et al.'s energy: 5 m/s at apex height 1 m.
ENERGY = stability.energy_at_rest_height(P, 5.0)


@pytest.fixture(scope="module")
def record() -> dict:
    return stability.from_json((DOCS / "stability.json").read_text())


@pytest.fixture(scope="module")
def grids(record) -> list[dict]:
    names = list(record["grids"][0]["lines"][0]["maps"])
    return [stability.measure_grid(g, names) for g in stability.GRIDS]


@pytest.fixture(scope="module")
def runner_5ms() -> dict[str, gait.FixedPoint]:
    """The one fixed point of each map at apex height 1 m and 5 m/s."""
    out = {}
    for name in ("exact", "geyer", "gravity-type5", "iterative"):
        (out[name],) = slipmaps.fixed_points(name, P, apex_height=1.0, speed=5.0)
    return out


def test_fixed_points_return_to_themselves(grids):
    """Every completed fixed point of every map on the record's grids: |h' - h| <= 1e-12 m (measured
    at most 9e-14 m: Newton stops at 1e-13 m or a 1e-10 step). The exact step conserves the energy,
    so v' = v too: |v' - v| <= 1e-9 m/s (measured 2.6e-11, the simulator's energy drift)."""
    n = n_exact = 0
    for g in grids:
        for line in g["lines"]:
            for points in [line["exact"], *line["maps"].values()]:
                for p in points:
                    if p["status"] == "OK":
                        assert abs(p["residual"]) <= 1e-12, (g["name"], line["given"], p)
                        n += 1
            exact = [p for p in line["exact"] if p["status"] == "OK"]
            assert all(abs(p["speed_residual"]) <= 1e-9 for p in exact)
            n_exact += len(exact)
    assert n >= 100 and n_exact >= 10, (n, n_exact)


@pytest.mark.parametrize("name", ["exact", "geyer", "gravity-type5", "iterative"])
def test_newton_equals_brentq(name, runner_5ms):
    """Measured: the safeguarded Newton root and brentq's (xtol 1e-15) differ by at most 3.2e-14 rad."""
    p = runner_5ms[name]

    def gap(a: float) -> float:
        return slipmaps.apex_return(name, P, 1.0, 5.0, a).next_apex_height - 1.0

    root = brentq(gap, p.touchdown_angle - 0.01, p.touchdown_angle + 0.01, xtol=1e-15, rtol=1e-15)
    assert abs(p.touchdown_angle - root) <= 1e-12


def _slope(name: str, p: gait.FixedPoint, d: float = 1e-5) -> float:
    """The central-difference slope of h -> h'(h, v_E(h)) on p's energy level at p."""
    e = p.energy / P.m

    def h_next(h: float) -> float:
        v = math.sqrt(2.0 * (e - P.g_f * h))
        return slipmaps.apex_return(name, P, h, v, p.touchdown_angle).next_apex_height

    return (h_next(p.apex_height + d) - h_next(p.apex_height - d)) / (2.0 * d)


@pytest.mark.parametrize("name", ["exact", "geyer", "gravity-type5", "iterative"])
def test_eigenvalue_is_the_slope_of_the_energy_level_return_map(name, runner_5ms):
    """lambda = dh'/dh - dh'/dv g_f/v against a central difference of the 1-D map (step 1e-5 m):
    measured within 4.4e-8 (the slope's truncation error) at 5 m/s; bound 1e-6."""
    p = runner_5ms[name]
    assert abs(p.eigenvalue - _slope(name, p)) <= 1e-6


def test_seyfarth_line_has_a_stable_and_an_unstable_gait():
    """At Seyfarth et al.'s energy and alpha0 = 68 deg the exact map has two fixed points: h = 0.9403
    m with lambda = -0.1613 (stable) and h = 1.3377 m with lambda = 1.687 (measured); their eigenvalues
    match the 1-D slope to 1.7e-9; at 66 deg the level has none."""
    low, high = slipmaps.fixed_points("exact", P, energy=ENERGY, angle=math.radians(22.0))
    assert low.stable and not high.stable
    assert low.apex_height == pytest.approx(0.94027, abs=1e-5)
    assert high.apex_height == pytest.approx(1.33769, abs=1e-5)
    for p in (low, high):
        assert p.energy == pytest.approx(ENERGY, rel=1e-14)
        assert abs(p.eigenvalue - _slope("exact", p)) <= 1e-6
    assert slipmaps.fixed_points("exact", P, energy=ENERGY, angle=math.radians(24.0)) == ()


def test_exact_floquet_multipliers_are_one_and_the_eigenvalue(grids):
    """An energy-conserving step has the multiplier 1 (measured |mu - 1| <= 9.5e-10 with the 1e-5
    central differences) and the other is lambda (measured within 2.5e-10); bound 1e-8."""
    n = 0
    for g in grids:
        for line in g["lines"]:
            for p in line["exact"]:
                if p["status"] == "OK":
                    assert p["energy_multiplier_deviation"] <= 1e-8, (g["name"], line["given"])
                    re, im = p["multiplier"]
                    assert abs(complex(re, im) - p["eigenvalue"]) <= 1e-8, (g["name"], line["given"])
                    n += 1
    assert n >= 10, n


def test_stability_record_is_current(grids, record):
    """docs/stability.json's fixed points re-measured (regenerate with `slipmaps accuracy`)."""
    assert_close(grids, record["grids"], "grids")


#: Region cells re-measured: (map, v0 [m/s], alpha0 [deg]); the region itself takes minutes.
REGION_CELLS = (
    ("exact", 5.0, 68.0),
    ("exact", 3.0, 76.0),
    ("geyer", 5.0, 68.0),
    ("gravity-type5", 7.0, 62.0),
)


@pytest.mark.parametrize(("name", "v0", "aoa"), REGION_CELLS)
def test_region_record_cells_are_current(record, name, v0, aoa):
    """A self-stable cell of each region map and an unstable one of the exact map, re-measured."""
    region = record["region"]
    i = region["speeds"].index(v0)
    j = region["angles_of_attack_deg"].index(aoa)
    cell = stability.measure_region(name, speeds=(v0,), aoas=(aoa,))
    assert cell["classes"][0] == region["maps"][name]["classes"][i][j]
    measured = rounded(cell["min_abs_eigenvalue"][0][0])
    assert_close(measured, region["maps"][name]["min_abs_eigenvalue"][i][j], "cell")


def test_stability_markdown_renders_the_record(record):
    assert (DOCS / "stability.md").read_text() == render_markdown(record)


def test_accuracy_docs_link_the_stability_docs():
    assert "docs/stability.md" in (DOCS / "accuracy.md").read_text()


def test_exact_region_has_a_minimum_speed_and_68_deg_stable_at_5ms(record):
    """The comparison with Seyfarth et al.: no self-stable cell at 3 m/s (Seyfarth, Geyer and Herr
    2003, Fig. 4), 68 deg at 5 m/s self-stable, a slowest self-stable speed above 3 m/s."""
    region = record["region"]
    facts = region_facts(region, "exact")
    assert 3.0 < facts["slowest_stable_speed"] < 5.0
    assert "S" not in region["maps"]["exact"]["classes"][region["speeds"].index(3.0)]
    i, j = region["speeds"].index(5.0), region["angles_of_attack_deg"].index(68.0)
    assert region["maps"]["exact"]["classes"][i][j] == "S"


def test_iterative_map_fixed_points_match_the_exact_ones(record):
    """The converging iterative map's fixed points on every grid: same count, same stability (measured:
    eigenvalues within 1e-5 and 4e-5 on the human runner's grids, 2.2e-3 on the robot hopper's)."""
    for g in record["grids"]:
        row = next(r for r in grid_rows(g) if r["map"] == "iterative")
        assert row["missing"] == row["extra"] == row["failed"] == row["stability_differs"] == 0, g["name"]
        assert row["eigenvalue"] < 1e-2, g["name"]


# ----------------------------------------------------------------------------------------------
# The Jacobian used by the search
# ----------------------------------------------------------------------------------------------
def test_newton_uses_the_public_jacobian(monkeypatch):
    """The search takes its slopes from slipmaps.apex_return_jacobian (analytic derivatives)."""
    calls = []
    real = gait.apex_jacobian

    def spy(name, params, h, v, th, **options):
        calls.append(name)
        return real(name, params, h, v, th, **options)

    monkeypatch.setattr(gait, "apex_jacobian", spy)
    (p,) = slipmaps.fixed_points("geyer", P, apex_height=1.0, speed=5.0)
    assert p.ok and calls and set(calls) == {"geyer"}


# ----------------------------------------------------------------------------------------------
# Errors
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("params", "kwargs", "match"),
    [
        (P.with_(k_d=21_000.0), {"apex_height": 1.0, "speed": 5.0}, r"k_c == k_d.*no periodic gait"),
        (P.with_(g_s=9.0), {"apex_height": 1.0, "speed": 5.0}, r"g_s == g_f"),
        (P.with_(q_r_td=0.95), {"apex_height": 1.0, "speed": 5.0}, r"q_r_td == q_r_lo"),
        (P, {"apex_height": 1.0}, "takes apex_height and speed, energy and speed, or energy and angle"),
        (P, {"apex_height": 1.0, "angle": 0.3}, "got angle, apex_height"),
        (P, {"energy": ENERGY, "angle": -0.3}, "angle must be positive"),
        (P, {"energy": 10.0, "speed": 5.0}, "below the kinetic energy"),
        (P, {"apex_height": 1.0, "speed": 5.0, "scan": 1}, "scan must be an integer >= 2"),
        (P, {"apex_height": 1.0, "speed": 5.0, "iterations": 3}, "has no option 'iterations'"),
    ],
)
def test_fixed_points_errors(params, kwargs, match):
    with pytest.raises(ValueError, match=match):
        slipmaps.fixed_points("geyer", params, **kwargs)


def test_unknown_map_is_a_value_error():
    with pytest.raises(ValueError, match="unknown map 'nope'"):
        slipmaps.fixed_points("nope", P, apex_height=1.0, speed=5.0)


# ----------------------------------------------------------------------------------------------
# CLI
# ----------------------------------------------------------------------------------------------
def test_gait_prints_the_human_runners_gaits(capsys):
    assert main(["gait", "--map", "geyer", "--speed", "3", "5"]) == 0
    out = capsys.readouterr().out.splitlines()
    rows = {(r.split()[6], r.split()[4]): r for r in out if r.startswith("h 1 m")}
    assert len(rows) >= 4, out
    assert "0.411164928" in rows[("exact", "5")] and rows[("exact", "5")].split()[-4] == "yes"
    assert rows[("exact", "3")].split()[-4] == "no"
    assert ("geyer", "5") in rows


def test_gait_json_matches_the_api(capsys):
    argv = ["gait", "--no-exact", "--map", "gravity-type5", "--energy-speed", "5", "--angle", "0.3839724354"]
    argv.append("--json")
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    (line,) = data["lines"]
    assert line["map"] == "gravity-type5"
    api = slipmaps.fixed_points("gravity-type5", P, energy=ENERGY, angle=0.3839724354)
    assert [p["apex_height"] for p in line["fixed_points"]] == [p.apex_height for p in api]
    assert [p["stable"] for p in line["fixed_points"]] == [True, False]


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["gait", "--k-d", "21000"], "k_c == k_d"),
        (["gait", "--angle", "0.3"], "--angle needs --energy"),
        (["gait", "--no-exact"], "--no-exact needs a --map"),
        (["gait", "--map", "nope"], "unknown map 'nope'"),
        (["gait", "--map", "geyer", "--m", "70", "--figure", "x.png"], "human runner"),
    ],
)
def test_gait_errors_are_one_line_exit_2(capsys, argv, match):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert match in err and len(err.strip().splitlines()) == 1


# ----------------------------------------------------------------------------------------------
# Tracker issue 16: the eigenvalue and the multipliers told apart; a search that fails says so
# ----------------------------------------------------------------------------------------------
#: Bounds of the documented measurements on docs/stability.json's grids (gait.py's docstring, the
#: page docs/control_planning.md): the largest |first multiplier - 1| and |second multiplier - lambda|
#: per map.
CLOSED_FORM = ("geyer", "geyer-vs", "iterative-report", *(f"gravity-type{i}" for i in range(6)))


def _worst(record: dict) -> dict[str, tuple[float, float]]:
    worst: dict[str, tuple[float, float]] = {}
    for g in record["grids"]:
        for line in g["lines"]:
            for name, points in [("exact", line["exact"]), *line["maps"].items()]:
                for p in points:
                    if p["status"] == "OK":
                        gap = abs(complex(*p["multiplier"]) - p["eigenvalue"])
                        one, two = worst.get(name, (0.0, 0.0))
                        worst[name] = (max(one, p["energy_multiplier_deviation"]), max(two, gap))
    return worst


def test_the_multipliers_are_one_and_lambda_only_where_the_step_conserves_the_energy(record):
    """Measured (docs/stability.json): the first multiplier is 1 within 6.1e-11 (exact), 9.3e-14
    (the closed-form maps), 8.9e-4 (iterative); the second is lambda to the record's 6 digits for the
    gravity corrections and iterative-report, within 0.016 for iterative, but up to 0.30 away for
    Geyer et al.'s map and geyer-vs, whose step does not conserve the energy."""
    worst = _worst(record)
    assert worst["exact"][0] < 1e-10 and worst["exact"][1] < 1e-5
    for name in CLOSED_FORM:
        assert worst[name][0] < 1e-13, name
    for name in ("iterative-report", *(f"gravity-type{i}" for i in range(6))):
        assert worst[name][1] < 1e-5, name
    assert worst["iterative"][0] < 1e-3 and worst["iterative"][1] < 0.02
    for name in ("geyer", "geyer-vs"):
        assert 0.25 < worst[name][1] < 0.35, name


def test_energy_gradient_error_says_which_steps_conserve_the_energy(runner_5ms):
    """At 1 m, 5 m/s: Geyer et al.'s dE'/dh is 8.60 m/s^2 per kg against g_f = 9.81 (error 0.12), so
    its multipliers (1, 0.788) are not (1, lambda = 0.856); the exact map and type 5 conserve it."""
    geyer = runner_5ms["geyer"]
    assert geyer.energy_gradient_error == pytest.approx(1.0 - 8.6039 / 9.81, abs=1e-4)
    assert abs(geyer.multipliers[0] - 1.0) < 1e-12 and abs(geyer.multipliers[1] - geyer.eigenvalue) > 0.05
    for name, bound in (("exact", 1e-8), ("gravity-type5", 1e-9), ("iterative", 1e-3)):
        p = runner_5ms[name]
        assert p.energy_gradient_error < bound, name
        assert abs(p.multipliers[1] - p.eigenvalue) < 10 * bound, name
    assert gait.DEFINITIONS.keys() >= {"eigenvalue", "multipliers", "energy_gradient_error"}
    assert set(gait.DEFINITIONS) <= set(geyer.as_dict())


def test_geyers_unit_multiplier_is_its_curve_of_fixed_points(runner_5ms):
    """Why Geyer et al.'s map has a unit multiplier without conserving the energy: at the gait's
    touchdown angle every nearby apex height has a speed whose step returns to the same apex (both
    h and v, to round-off), a curve of fixed points crossing the energy levels."""
    th = runner_5ms["geyer"].touchdown_angle
    energies = []
    for h in (0.98, 1.02, 1.05):

        def gap(v: float, h: float = h) -> float:
            return slipmaps.apex_return("geyer", P, h, v, th).next_apex_height - h

        v = brentq(gap, 4.5, 5.5, xtol=1e-15, rtol=1e-15)
        step = slipmaps.apex_return("geyer", P, h, v, th)
        assert abs(step.next_apex_height - h) < 1e-12 and abs(step.next_apex_speed - v) < 1e-12, h
        energies.append(gait.energy_of(P, h, v))
    assert max(energies) - min(energies) > 1.0  # [J]: not one energy level


def test_a_search_says_how_it_went():
    """fixed_points returns a FixedPoints tuple: status OK with the scan's status counts when the
    scan could search, the map's failure when every step failed, APEX_TOO_LOW when the energy
    reaches no touchdown."""
    import pickle

    found = slipmaps.fixed_points("geyer", P, apex_height=1.0, speed=5.0)
    assert isinstance(found, gait.FixedPoints) and isinstance(found, tuple) and len(found) == 1
    assert found.ok and sum(found.scan.values()) == gait.SCAN and found.scan["OK"] > 0
    # a success says what it found first, then how much of the scan left the map's domain
    assert found.message.startswith("found 1 fixed point"), found.message
    assert ("failed" not in found.message) and (found.scan["OK"] == gait.SCAN or "angles" in found.message)
    again = pickle.loads(pickle.dumps(found))
    assert again == found and again.scan == found.scan and again.status == found.status
    failed = slipmaps.fixed_points("gravity-type2", P, apex_height=1.0, speed=5.0, iterations=1)
    assert failed == () and not failed.ok and failed.status == slipmaps.Status.NOT_CONVERGED
    assert failed.message.startswith(f"every step of the scan failed ({gait.SCAN} steps: NOT_CONVERGED ")
    assert "OK" not in failed.scan and sum(failed.scan.values()) == gait.SCAN
    low = slipmaps.fixed_points("geyer", P, energy=100.0, angle=0.3)
    assert low == () and low.status == slipmaps.Status.APEX_TOO_LOW and "touchdown height" in low.message
    assert failed.as_dict()["status"] == "NOT_CONVERGED" and failed.as_dict()["fixed_points"] == []
