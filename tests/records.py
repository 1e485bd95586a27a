"""A re-measured report record (docs/*.json) against the committed one: shared by the tests of the
generated reports (tests/test_accuracy.py, tests/test_stiffness.py).

The records have 6 significant digits and the integrations are deterministic, so the numbers must
match to 2e-5 relative (the slack only covers the last digit of a different libm). Values below
1e-9 are compared to 1e-9 absolute: in SI units (the accuracy record) and as fractions (errors
relative to l0, to an exact value or to the compression, the stiffness record) that is at the exact
simulator's own precision (its integration agrees with an outside reference to 2e-11 relative),
where a reformulation of a kernel moves them by round-off. A recorded fraction of 1e-11 can thus
grow to 1e-9 unnoticed here; tests/test_stiffness.py bounds the one such row ((153) with the exact
bottom p_th) separately.
"""

from __future__ import annotations

import math

REL = 2e-5
ABS = 1e-9


def assert_close(measured, recorded, path: str) -> None:
    """Same structure, same keys, equal strings and integers, floats within REL / ABS."""
    if isinstance(measured, dict):
        assert set(measured) == set(recorded), f"{path}: keys differ: {sorted(set(measured) ^ set(recorded))}"
        for k in measured:
            assert_close(measured[k], recorded[k], f"{path}.{k}")
    elif isinstance(measured, list):
        assert len(measured) == len(recorded), f"{path}: lengths differ"
        for i, (x, y) in enumerate(zip(measured, recorded, strict=True)):
            assert_close(x, y, f"{path}[{i}]")
    elif isinstance(measured, float) and isinstance(recorded, float):
        assert math.isclose(measured, recorded, rel_tol=REL, abs_tol=ABS), (
            f"{path}: measured {measured!r}, recorded {recorded!r}"
        )
    else:
        assert measured == recorded, f"{path}: measured {measured!r}, recorded {recorded!r}"
