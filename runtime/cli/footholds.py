"""``slipmaps footholds``: the footholds study (docs/footholds.md), measured again and rebuilt.

``slipmaps footholds`` hops random stepping-stone courses with the footholds planner at horizons
1, 2 and 3 and with the deadbeat baseline (:mod:`slipmaps.runtime.studies.footholds`: the families
of courses, the `geyer` model, the MuJoCo robot, the replan's time) and writes footholds.json,
footholds.md, its figures and its clip (:mod:`slipmaps.runtime.studies.footholds_report`) into the
checkout's docs/ or ``--out DIR``; ``--quick`` the small version CI runs (``--out`` required: it
never overwrites docs/). ``--jobs N``: processes (default: the machine's cores); ``--no-gif``: no
clip. The robot's part needs MuJoCo (the ``robot`` extra; the ``test`` extra installs it).
"""

from __future__ import annotations

import argparse

from .study import add_study_flags, run_study

__all__ = ["add_parser", "run"]


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``footholds`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "footholds",
        help="the footholds study: stepping stones planned hops ahead (docs/footholds.md)",
        description="Hop random stepping-stone courses with the footholds planner at horizons 1, 2 and 3 "
        "and with the deadbeat step aimed at a stone's centre, on the exact plant (and the MuJoCo robot), "
        "and write footholds.json, footholds.md, its figures and clip into the checkout's docs/ or "
        "--out DIR.",
    )
    add_study_flags(p)
    return p


def run(args: argparse.Namespace) -> int:
    from ..studies.footholds_report import write

    return run_study(args, write)
