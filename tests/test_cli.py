"""The command line: `slipmaps compare` (the README's main job), `generate --check`, errors."""

from __future__ import annotations

import json
import math

import pytest
from slipmaps.runtime.cli import main
from slipmaps.runtime.compare import compare
from slipmaps.runtime.params import HUMAN_RUNNER

QUANTITIES = (
    "stance time t_s",
    "bottom time t_b",
    "bottom leg length q_r_b",
    "bottom leg angle q_th_b",
    "liftoff leg rate q_rd_lo",
    "liftoff leg angle q_th_lo",
    "liftoff angle rate q_thd_lo",
    "next apex height",
    "next apex speed",
)


def test_compare_default_prints_table_and_writes_plot(tmp_path, capsys):
    png = tmp_path / "cmp.png"
    assert main(["compare", "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    for q in QUANTITIES:
        assert q in out
    assert "abs err" in out and "rel err" in out
    assert png.stat().st_size > 10_000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_json_matches_python_api(capsys):
    assert main(["compare", "--json", "--no-plot", "--apex-speed", "4.5", "--angle", "0.3"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["exact_status"] == "OK" and data["approx_status"] == "OK"
    ref = compare(HUMAN_RUNNER, apex_speed=4.5, q_th_td=0.3)
    assert [r["quantity"] for r in data["rows"]] == list(QUANTITIES)
    for row, r in zip(data["rows"], ref.rows, strict=True):
        assert row["exact"] == r.exact and row["approx"] == r.approx
        assert row["abs_error"] == pytest.approx(r.approx - r.exact, rel=0, abs=0)


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
    assert lo_angle["exact"] != pytest.approx(-0.3, abs=0.02)  # not a mirror of touchdown


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["--k-c", "20000", "--k-d", "25000"], "k_c"),  # Geyer's map needs a constant stiffness
        (["--m", "-80"], "-80"),
        (["--angle", "2.0"], "2.0"),
        (["--apex-height", "0.5"], "touchdown"),  # apex below the touchdown height
    ],
)
def test_compare_invalid_input_is_a_clear_error(argv, needle, capsys):
    assert main(["compare", "--no-plot", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("slipmaps compare: error:") and needle in err


def test_generate_check_passes_on_a_current_tree(capsys):
    assert main(["generate", "--check"]) == 0
    assert "current" in capsys.readouterr().out


def test_rel_error_of_zero_exact_is_nan():
    from slipmaps.runtime.compare import Row

    assert math.isnan(Row("x", "m", 0.0, 1.0).rel_error)
