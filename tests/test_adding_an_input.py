"""docs/adding_an_input.md followed step by step in a copy of the project (issue 29 item 6): the page
adds an apex-return input, ``sole``, by editing its row in derive/params.py and the descent in
derive/model/flight.py, and this test does what the page says in a temporary copy of the checkout
(tests/checkout.py).

The steps are the page's marked blocks: the two diffs are applied with ``patch -p1``, then
``slipmaps generate`` runs, then the page's Python block and what this test measures beside it in
the same process: the sole's step is the step onto ground that much higher (every output but
``foot_y``, within a few ulps: the two inputs enter the same sum) in ``geyer``, ``iterative`` and
the exact map, the ``solve_ivp`` reference takes it by name, the Jacobians' ``sole`` column is
their ``ground`` column, and a negative sole is refused. Finally, the files of the copy that differ
from the checkout's are the two the page edits and the ones ``slipmaps generate`` wrote: no other
hand-written file changed.

One SymPy build (``slipmaps generate``, about a minute of CPU) and the kernels' first compiles in
the copy (about a minute) dominate. Marked slow: CI runs it, ``-m "not slow"`` skips it.
"""

from __future__ import annotations

import shutil
import subprocess

import pytest
from checkout import Checkout, copy_tracked, tracked
from documents import ROOT, tutorial_steps

PAGE = "docs/adding_an_input.md"
STEPS = tutorial_steps(PAGE)
EDITS = ("edit derive/params.py", "edit derive/model/flight.py")

pytestmark = pytest.mark.slow


def test_the_page_marks_the_steps_the_test_follows():
    assert set(STEPS) == {*EDITS, "generate", "use"}, list(STEPS)
    for mark in EDITS:
        language, diff = STEPS[mark]
        assert language == "diff"
        assert diff.splitlines()[:2] == [f"--- a/{mark.split()[1]}", f"+++ b/{mark.split()[1]}"]


#: After the page's Python block: what the test asserts about it, from the same process.
_MEASURE = """
import json as _json
import numpy as _np
from slipmaps.runtime.exact.reference import simulate_step as _step
_out = {"printed": [soled.next_apex_height, higher.next_apex_height]}
_out["printed"] += [jac["next_apex_height", "sole"], jac["next_apex_height", "ground"]]
for _name in ("geyer", "iterative", "exact"):
    _a = slipmaps.apex_return(_name, runner, 1.05, 4.0, 0.3, sole=0.03)
    _b = slipmaps.apex_return(_name, runner, 1.05, 4.0, 0.3, ground=0.03)
    _ja = slipmaps.apex_return_jacobian(_name, runner, 1.05, 4.0, 0.3, sole=0.03)
    _jb = slipmaps.apex_return_jacobian(_name, runner, 1.05, 4.0, 0.3, ground=0.03)
    _rows = [i for i, o in enumerate(_ja.outputs) if o != "foot_y"]
    _out[_name] = {
        "ok": bool(_a.ok and _b.ok and _ja.ok and _jb.ok),
        "values": max(
            abs(x - _b.values[o]) / max(abs(_b.values[o]), 1e-300)
            for o, x in _a.values.items()
            if o != "foot_y"
        ),
        "foot_y": [_a.foot_y, _b.foot_y],
        "column": float(_np.max(_np.abs(_ja.matrix[_rows, _ja.inputs.index("sole")]
                                        - _jb.matrix[_rows, _jb.inputs.index("ground")]))),
        "inputs": list(_ja.inputs),
        "apex": [_a.next_apex_height, _a.next_apex_speed],
    }
_r = _step(runner, 1.05, 4.0, 0.3, sole=0.03)
_out["reference"] = [_r.status.name, *_r.next_apex]
try:
    slipmaps.apex_return("geyer", runner, 1.05, 4.0, 0.3, sole=-0.01)
    _out["negative"] = "accepted"
except ValueError as _e:
    _out["negative"] = str(_e)
print(_json.dumps(_out))
"""


@pytest.fixture(scope="module")
def followed(tmp_path_factory) -> dict:
    if shutil.which("patch") is None:
        pytest.skip("no patch command")
    base = tmp_path_factory.mktemp("input-tutorial")
    copy = copy_tracked(base / "checkout")
    here = Checkout(copy, base / "site", base / "numba")
    seeded = here.seed()
    before = {f.name: f.stat().st_mtime_ns for f in seeded.glob("*.nbi")}
    for mark in EDITS:
        done = subprocess.run(
            ["patch", "-p1", "--forward", "--no-backup-if-mismatch"],
            cwd=copy,
            input=STEPS[mark][1] + "\n",
            capture_output=True,
            text=True,
        )
        assert done.returncode == 0, (mark, done.stdout, done.stderr)
    results = {"generate": here.commands(STEPS["generate"][1])}
    results["use"] = here.python(STEPS["use"][1], _MEASURE)
    results["copy"] = copy
    # numba used the seeded folder: the copy's compiles rewrote indexes there
    results["rewritten"] = sorted(
        f.name for f in seeded.glob("*.nbi") if before.get(f.name) != f.stat().st_mtime_ns
    )
    return results


def test_the_input_is_every_maps_and_its_jacobians_column(followed):
    got = followed["use"]
    soled, higher, d_sole, d_ground = got["printed"]
    assert soled == pytest.approx(higher, rel=1e-14) and d_sole == pytest.approx(d_ground, rel=1e-12)
    for name in ("geyer", "iterative", "exact"):
        row = got[name]
        assert row["ok"], name
        assert "sole" in row["inputs"] and "ground" in row["inputs"], row["inputs"]
        # the same sum, ground + sole, in another order: equal to round-off (geyer: bit for bit)
        assert row["values"] <= 1e-14, (name, row["values"])
        assert row["column"] <= 1e-12, (name, row["column"])
        assert row["foot_y"][0] == pytest.approx(-1.05) and row["foot_y"][1] == pytest.approx(0.03 - 1.05)
    status, height, speed = got["reference"]
    assert status == "OK"
    assert [height, speed] == pytest.approx(got["exact"]["apex"], rel=1e-9)


def test_a_negative_sole_is_refused_by_its_domain(followed):
    message = followed["use"]["negative"]
    assert message.startswith("sole") and "-0.01" in message, message


def test_the_copy_compiled_into_the_seeded_cache(followed):
    """tests/checkout.py seeds the copy's numba cache; the rewritten modules' kernels compiled there."""
    assert any(name.startswith("geyer.") for name in followed["rewritten"]), followed["rewritten"]


def test_only_the_two_edited_files_and_the_generated_ones_differ(followed):
    copy = followed["copy"]
    wrote = {
        line.removeprefix("wrote ") for line in followed["generate"].splitlines() if line.startswith("wrote ")
    }
    assert "generated/flight.py" in wrote and "generated/maps_index.py" in wrote, sorted(wrote)
    differ = {rel for rel in tracked() if (copy / rel).read_bytes() != (ROOT / rel).read_bytes()}
    assert differ - wrote == {"derive/params.py", "derive/model/flight.py"}, sorted(differ - wrote)
