"""``slipmaps damping-viability``: Heim et al.'s damping study (docs/damping.md), measured again.

``slipmaps damping-viability`` computes the viable set of Heim et al.'s guinea fowl on their
(apex height, speed) x angle grid for no damping and each of their 21 damping values, k_d chosen
per damping so that the nominal gait is periodic (:mod:`slipmaps.runtime.studies.damping_viability`),
and writes damping_viability.json and .png into the checkout's docs/ or ``--out DIR``; ``--quick``
the small version CI runs (a coarser grid, every 4th damping value; ``--out`` required: it never
overwrites docs/).
"""

from __future__ import annotations

import argparse

from .study import add_study_flags, run_study

__all__ = ["add_parser", "run"]


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``damping-viability`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "damping-viability",
        help="Heim et al.'s damping study: the viable set against the leg's damping ratio (docs/damping.md)",
        description="Compute the viable set of Heim et al.'s guinea fowl (apex height 0.05-0.5 m x speed "
        "0-10 m/s x touchdown angle 0-89 deg, the exact map) for each of their damping values as a "
        "parallel leg damper, k_d chosen so that the nominal gait is periodic, and write "
        "damping_viability.json and .png into the checkout's docs/ or --out DIR.",
    )
    add_study_flags(p, robot=False)
    return p


def run(args: argparse.Namespace) -> int:
    from ..studies.damping_viability import write

    return run_study(args, write, robot=False)
