"""The controllers a run can use: a scenario's ``[control] policy`` and ``slipmaps run --policy``.

Plain data, so that the command line lists them without importing the control code.
"""

from __future__ import annotations

__all__ = ["POLICIES"]

#: Each policy's name and what it does (runtime/control/scenarios.py: the scenario keys each takes).
POLICIES: dict[str, str] = {
    "apex": "the touchdown angle set at the apex and held",
    "retraction": "the leg retracting at the retraction rate from the angle set at the apex",
    "time-based": "the controls as functions of the time since the apex",
    "raibert": "Raibert's controller: foot placement and thrust, no model",
    "footholds": "stepping stones planned hops ahead (a stones course)",
}
