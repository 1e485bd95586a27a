"""``slipmaps robot``: the robot study (docs/robot.md), measured again and rebuilt.

``slipmaps robot`` runs slipmaps' controllers and Raibert's on the MuJoCo robot
(:mod:`slipmaps.runtime.studies.robot`: Raibert's gain search, the identification, steady running,
speed and height changes, unknown ramps, measurement noise, cost) and writes robot.json, robot.md,
its figures and its clip (:mod:`slipmaps.runtime.studies.robot_report`) into the checkout's docs/
or ``--out DIR``; ``--quick`` the small version CI runs (``--out`` required: it never overwrites
docs/). ``--jobs N``: processes (default: the machine's cores); ``--no-gif``: no clip. Needs the
``robot`` extra (MuJoCo).
"""

from __future__ import annotations

import argparse
from pathlib import Path

__all__ = ["add_parser", "run"]


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``robot`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "robot",
        help="the robot study: slipmaps' controllers against Raibert's on the MuJoCo robot (docs/robot.md)",
        description="Run slipmaps' controllers and Raibert's on the MuJoCo monoped (Raibert's gain search, "
        "the identification of the model, steady running, speed and height changes, unknown ramps, noise, "
        "cost) and write robot.json, robot.md, its figures and clip into the checkout's docs/ or --out DIR. "
        "Needs the robot extra: pip install 'slipmaps[robot]'.",
    )
    p.add_argument("--out", default=None, metavar="DIR", help="the directory to write into (default: docs/)")
    p.add_argument("--quick", action="store_true", help="the small version (needs --out)")
    p.add_argument("--jobs", type=int, default=None, metavar="N", help="processes (default: the cores)")
    p.add_argument("--no-gif", action="store_true", help="do not render the clip")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def _out(args: argparse.Namespace) -> Path:
    from .args import docs_out

    return docs_out(args.out, args.quick)


def run(args: argparse.Namespace) -> int:
    if args.jobs is not None and args.jobs < 1:
        raise ValueError(f"--jobs must be at least 1, got {args.jobs}")
    from ..robot.mj import mujoco

    mujoco()  # the extra, before any work (one line naming it when missing)
    out = _out(args)
    from ..studies.robot_report import write

    progress = False if args.no_progress else None
    for path in write(out, quick=args.quick, jobs=args.jobs, progress=progress, gif=not args.no_gif):
        print(f"wrote {path}")
    return 0
