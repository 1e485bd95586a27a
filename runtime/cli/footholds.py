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

from .robot import _out

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
    p.add_argument("--out", default=None, metavar="DIR", help="the directory to write into (default: docs/)")
    p.add_argument("--quick", action="store_true", help="the small version (needs --out)")
    p.add_argument("--jobs", type=int, default=None, metavar="N", help="processes (default: the cores)")
    p.add_argument("--no-gif", action="store_true", help="do not render the clip")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def run(args: argparse.Namespace) -> int:
    if args.jobs is not None and args.jobs < 1:
        raise ValueError(f"--jobs must be at least 1, got {args.jobs}")
    from ..robot.mj import mujoco

    mujoco()  # the robot's part needs the extra: one line naming it when missing, before any work
    out = _out(args)
    from ..studies.footholds_report import write

    progress = False if args.no_progress else None
    for path in write(out, quick=args.quick, jobs=args.jobs, progress=progress, gif=not args.no_gif):
        print(f"wrote {path}")
    return 0
