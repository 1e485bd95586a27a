"""docs/adding_a_map.md followed step by step in a copy of the project (issue 20): the page adds a map,
``geyer-angle2``, and this test does what the page says in a temporary copy of the checkout.

The copy and how commands run in it: tests/checkout.py.

The steps are the page's marked blocks (``<!-- tutorial: MARK -->`` before the fence, which the site
does not show and tests/test_readme.py leaves out, :data:`documents.TUTORIAL`): step 1 writes the
file, step 2 runs the derivation's check, step 3 generates the kernels, step 4
lists the map and runs the Python block (asserting the apex return's status, finiteness, the
Jacobian against central differences), step 5 compares against the exact map (the table printed
must be the one the page shows, so the page's errors are this run's), step 7 removes the module.
The blocks in :data:`NOT_RUN` are not run (minutes each), nor step 7's ``slipmaps generate``: the
sources are then the checkout's own, file for file, whose generated files tests/test_codegen.py
checks; here the files that differ after the ``rm`` must be the ones step 3 wrote.

The SymPy build of step 3 (``slipmaps generate``, 20-55 s of CPU with the machine's load) and the
new map's first compiles dominate; the copy's numba cache starts with the checkout's entries
(tests/checkout.py), so the exact simulator (step 5's reference), whose modules the page leaves
unchanged, loads instead of compiling (it loads while step 3 generates). Marked slow: CI runs it,
``-m "not slow"`` skips it.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from checkout import Checkout, copy_tracked, tracked
from documents import ROOT, tutorial_steps

PAGE = "docs/adding_a_map.md"
STEPS = tutorial_steps(PAGE)
NAME = "geyer-angle2"
#: The marked blocks the test shows but does not run, each mark saying why.
NOT_RUN = {
    "check generated (not run: a second build)",
    "accuracy (not run: minutes)",
    "tests (not run: minutes)",
}
#: What the test does with the others (the order of the page).
RUN = ("write derive/maps/geyer_angle2.py", "check", "generate", "list", "use", "compare", "compare output")
REMOVE = "remove"

pytestmark = pytest.mark.slow


def test_the_page_marks_the_steps_the_test_follows():
    assert set(STEPS) == {*RUN, *NOT_RUN, REMOVE}, list(STEPS)


#: After the page's Python block: what the test asserts about it, from the same process.
_MEASURE = """
import json as _json, math as _math
_exact = slipmaps.apex_return("exact", runner, 1.0, 5.0, 0.35)
_h = 1e-6
_up, _down = (slipmaps.apex_return("geyer-angle2", runner, 1.0, 5.0, 0.35 + s * _h) for s in (1, -1))
print(_json.dumps({
    "status": step.status.name, "height": step.next_apex_height, "speed": step.next_apex_speed,
    "exact": [_exact.next_apex_height, _exact.next_apex_speed],
    "jacobian": jac["next_apex_height", "touchdown_angle"], "finite": bool(_math.isfinite(jac.matrix.sum())),
    "difference": (_up.next_apex_height - _down.next_apex_height) / (2 * _h),
}))
"""


@pytest.fixture(scope="module")
def followed(tmp_path_factory) -> dict:
    base = tmp_path_factory.mktemp("tutorial")
    copy = copy_tracked(base / "checkout")
    here = Checkout(copy, base / "site", base / "numba")
    seeded = here.seed()
    results: dict = {}
    with ThreadPoolExecutor(1) as pool:
        # step 5's reference, the exact simulator, compiles while step 3 generates (the unchanged
        # generated/exact.py keeps its cache entries through the generation)
        warm = pool.submit(here.python, "import slipmaps", _WARM)
        language, code = STEPS[RUN[0]]
        assert language == "python"
        (copy / RUN[0].split()[1]).write_text(code)
        assert STEPS["check"][0] == "python"
        results["derivation"] = here.python(STEPS["check"][1], "print('{}')")
        results["generate"] = here.commands(STEPS["generate"][1])
        warm.result()
        results["list"] = here.commands(STEPS["list"][1])
        results["use"] = here.python(STEPS["use"][1], _MEASURE)
        results["compare"] = here.commands(STEPS["compare"][1])
    remove, regenerate = STEPS[REMOVE][1].splitlines()
    here.commands(remove)
    assert regenerate.split()[:2] == ["slipmaps", "generate"]  # not run: see the module docstring
    results["removed"] = copy
    # numba used the seeded folder: the new map's kernels were cached beside the seeded entries
    results["seeded"] = sorted(f.name for f in seeded.glob("geyer_angle2*.nbi"))
    return results


_WARM = "slipmaps.apex_return('exact', slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35); print('{}')"


def test_generation_writes_the_map(followed):
    written = followed["generate"]
    for rel in (
        "generated/geyer_angle2.py",
        "generated/geyer_angle2_jacobian.py",
        "generated/maps_index.py",
    ):
        assert f"wrote {rel}" in written, written
    assert "wrote generated/geyer.py" not in written  # the helpers' module is unchanged


def test_the_copy_compiled_into_the_seeded_cache(followed):
    """tests/checkout.py seeds the copy's numba cache; the new map's kernels compiled there."""
    assert followed["seeded"], "no geyer_angle2 entry in the seeded cache folder"


def test_the_map_is_in_the_index(followed):
    rows = [line.split() for line in followed["list"].splitlines()]
    assert [NAME, "3.1"] in [r[:2] for r in rows], followed["list"]


def test_its_apex_return_and_jacobian(followed):
    got = followed["use"]
    assert got["status"] == "OK" and math.isfinite(got["height"]) and math.isfinite(got["speed"])
    # the page's comments: 0.905 m, 5.094 m/s, 0.659 m/rad
    assert (round(got["height"], 3), round(got["speed"], 3), round(got["jacobian"], 3)) == (
        0.905,
        5.094,
        0.659,
    )
    assert got["finite"]
    assert got["jacobian"] == pytest.approx(got["difference"], rel=1e-6)


def _relative_errors(table: str) -> dict[str, float]:
    """The rel err column [%] of the compare table's next-apex rows."""
    rows = {}
    for line in table.splitlines():
        if line.startswith("next apex"):
            rows[" ".join(line.split()[:3])] = float(line.split()[-1].rstrip("%"))
    return rows


def test_the_comparison_is_the_pages_and_its_errors_are_measured(followed):
    shown = STEPS["compare output"][1]
    assert shown.strip() in followed["compare"], followed["compare"]
    errors = _relative_errors(shown)
    assert errors == {"next apex height": -1.43, "next apex speed": -1.26}  # the page's prose
    got = followed["use"]
    height, speed = got["exact"]
    assert 100 * (got["height"] / height - 1) == pytest.approx(errors["next apex height"], abs=0.005)
    assert 100 * (got["speed"] / speed - 1) == pytest.approx(errors["next apex speed"], abs=0.005)


def test_removing_it_leaves_only_what_generate_rewrites(followed):
    """After step 7's ``rm``, the files that differ from the checkout's are the ones step 3 wrote and
    the map's generated modules, which step 7's ``slipmaps generate`` rewrites and deletes (from the
    checkout's own sources: test_codegen.py checks that they give the committed files)."""
    removed: Path = followed["removed"]
    wrote = {line.removeprefix("wrote ") for line in followed["generate"].splitlines()}
    differ = {rel for rel in tracked() if (removed / rel).read_bytes() != (ROOT / rel).read_bytes()}
    assert differ <= wrote and "README.md" in differ, sorted(differ - wrote)
    extra = {
        str(p.relative_to(removed))
        for p in removed.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
    } - set(tracked())
    assert extra == {"generated/geyer_angle2.py", "generated/geyer_angle2_jacobian.py"}
