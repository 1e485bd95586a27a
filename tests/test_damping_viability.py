"""Heim et al.'s damping study (runtime/studies/damping_viability.py): the bird's gait, the viable set
with a damped leg on a reduced grid, the committed record and its table in docs/damping.md, the
command's user errors. CI runs ``slipmaps damping-viability --quick`` itself."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from slipmaps.runtime.studies.damping_viability import (
    BIRD,
    FULL,
    GROUNDS,
    HEIM_DAMPING,
    QUICK,
    cell_measure,
    measure,
    nominal_gait,
    params,
    ratios,
    table,
)

DOCS = Path(__file__).resolve().parent.parent / "docs"


def test_the_birds_fitted_stiffness_makes_its_apex_periodic_without_damping():
    gait = nominal_gait(params(), top=0.5)
    assert gait.found and gait.at_bird
    # the deadbeat step keeps k_d = k_c and the bird's angle (measured: 0 N/m and 0 rad apart)
    assert gait.k_d == pytest.approx(BIRD["k"], rel=1e-9)
    assert gait.touchdown_angle == pytest.approx(BIRD["touchdown_angle"], abs=1e-8)


def test_the_sweep_is_heims_damping_values_as_ratios():
    rows = ratios(params())
    assert [r["d_over_k"] for r in rows] == [0.0, *HEIM_DAMPING]
    assert len(HEIM_DAMPING) == 21 and HEIM_DAMPING[-1] == 0.19
    p = params()
    # c = (d/k) k; ratio = c / (2 sqrt(k m)): their largest, 0.19 s, is 2.36 (overdamped)
    assert rows[-1]["c"] == pytest.approx(0.19 * p.k_c)
    assert rows[-1]["ratio"] == pytest.approx(0.19 * p.k_c / (2 * math.sqrt(p.k_c * p.m)))
    assert 2.3 < rows[-1]["ratio"] < 2.4


def test_cell_measure_is_the_mean_over_the_cells_nodes_inside_the_grid():
    m = np.arange(12.0).reshape(3, 4)
    h, v = np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 2.0, 3.0])
    assert cell_measure(m, h, v, 0.5, 1.5) == np.mean([m[0, 1], m[0, 2], m[1, 1], m[1, 2]])
    assert cell_measure(m, h, v, 5.0, 1.5) == np.mean([m[2, 1], m[2, 2]])  # above the grid: the edge nodes


def test_a_little_damping_enlarges_the_viable_set_on_the_reduced_grid():
    p = params()
    c = 0.001 * p.k_c  # Heim et al.'s smallest damping value, d/k = 0.001 s: ratio 0.0124
    record = measure(QUICK, [{"c": 0.0}, {"c": c}], progress=False)
    undamped, damped = record["rows"]
    assert undamped["gait"]["at_bird"] and damped["gait"]["at_bird"]
    # measured: k_d / k_c 1 and 1.106 (the damped gait needs k_d > k_c to put the energy back)
    assert undamped["k_d_over_k_c"] == pytest.approx(1.0)
    assert 1.0 < damped["k_d_over_k_c"] < 1.2
    # measured (QUICK grid, 11,970 pairs): viable share 0.0099 without damping (25 kernel states
    # left after 62 rounds: an energy-conserving step on a (height, speed) grid) and 0.132 with it
    # (260 states, 3 rounds)
    assert 0 < undamped["viable_share"] < damped["viable_share"]
    assert undamped["rounds"] > 10 > damped["rounds"]
    assert damped["kernel_states"] > undamped["kernel_states"] > 0
    # their figure's measure after one step: on level ground (0 of GROUNDS) the periodic gait returns
    # to its apex, so S_M there is the measure at the gait's apex (0.233 with damping, measured)
    level = GROUNDS.index(0.0)
    for row in (undamped, damped):
        assert row["post_step"][level] == row["measure_at_gait"]
    assert damped["post_step"][level] > 0
    # measured: no ground leaves the undamped bird in the eroded kernel; the damped one keeps
    # -7 ... +1.5 cm (their largest step up, 2.75 cm, puts its foot underground at the apex)
    assert undamped["post_step_grounds"] is None
    assert damped["post_step_grounds"] == [-0.07, 0.015]


def test_the_committed_record_is_the_full_grid_and_its_table_is_in_the_docs():
    record = json.loads((DOCS / "damping_viability.json").read_text())
    assert record["grid"]["heights"] == list(FULL.heights) and record["grid"]["pairs"] == 91 * 101 * 90
    assert [r["d_over_k"] for r in record["rows"]] == [0.0, *HEIM_DAMPING]
    assert table(record) in (DOCS / "damping.md").read_text()
    assert (DOCS / "damping_viability.png").stat().st_size > 0


@pytest.mark.parametrize(
    ("flags", "words"),
    [
        (["--quick"], "--quick writes a reduced study: give --out DIR"),
        (["--out", "/dev/null/x"], "--out"),
    ],
)
def test_the_commands_bad_flags_are_one_line(flags, words, capsys):
    from slipmaps.runtime.cli import main

    assert main(["damping-viability", *flags]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1
