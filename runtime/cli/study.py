"""What the study commands share (``slipmaps robot``, ``slipmaps footholds``, ``slipmaps
damping-viability``): their flags and their run (where they write:
:func:`~slipmaps.runtime.cli.args.docs_out`).

A study command measures its study again and rebuilds its page, record, figures and clip into the
checkout's docs/ or ``--out DIR``; ``--quick`` the small version CI runs (``--out`` required: it
never overwrites docs/); ``--jobs N`` processes (default: the machine's cores); ``--no-gif`` no
clip; ``--no-progress`` no progress bar. The robot and footholds studies run the MuJoCo robot, so the
extra is checked first (one line naming it when missing); a study without the robot
(``robot=False``) has neither ``--jobs`` nor ``--no-gif``.
"""

from __future__ import annotations

import argparse

from .args import docs_out

__all__ = ["add_study_flags", "run_study"]


def add_study_flags(p: argparse.ArgumentParser, robot: bool = True) -> None:
    """The study commands' flags (module docstring); ``robot``: with ``--jobs`` and ``--no-gif``."""
    p.add_argument("--out", default=None, metavar="DIR", help="the directory to write into (default: docs/)")
    p.add_argument("--quick", action="store_true", help="the small version (needs --out)")
    if robot:
        p.add_argument("--jobs", type=int, default=None, metavar="N", help="processes (default: the cores)")
        p.add_argument("--no-gif", action="store_true", help="do not render the clip")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")


def run_study(args: argparse.Namespace, write, robot: bool = True) -> int:
    """Run a study command: its flags checked, the robot's extra (``robot``), then ``write(out,
    quick=, progress=)`` (the study's writer; with the robot also ``jobs=``, ``gif=``), each path
    written printed."""
    media = {}
    if robot:
        if args.jobs is not None and args.jobs < 1:
            raise ValueError(f"--jobs must be at least 1, got {args.jobs}")
        from ..robot.mj import mujoco

        mujoco()  # the extra, before any work (one line naming it when missing)
        media = {"jobs": args.jobs, "gif": not args.no_gif}
    out = docs_out(args.out, args.quick)
    progress = False if args.no_progress else None
    for path in write(out, quick=args.quick, progress=progress, **media):
        print(f"wrote {path}")
    return 0
