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

from .study import add_study_flags, run_study

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
    add_study_flags(p)
    return p


def run(args: argparse.Namespace) -> int:
    from ..studies.robot_report import write

    return run_study(args, write)
