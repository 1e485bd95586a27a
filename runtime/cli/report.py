"""``slipmaps report``: the report's sections 6-8 (docs/sections.md), measured again and rebuilt.

``slipmaps report`` runs every study of ``slipmaps accuracy`` (accuracy, convergence, stiffness,
stability, reproductions), then the control evaluation (``slipmaps run --evaluate``), then writes
docs/sections.md and its figure from the records (:mod:`slipmaps.runtime.report.sections`): into
the checkout's docs/ or ``--out DIR``. It takes about ten minutes once the kernels are compiled.
Standard error shows which stage runs, of how many (:class:`~slipmaps.runtime.api.progress.Stages`:
one line per stage, on a terminal with the time so far), and on a terminal each stage's progress
bar (``--no-progress``: none).

- ``--render-only``: no measurement; the page from the records already in docs/ (or ``--out``),
  as the site's build does (seconds).
- ``--quick``: the reduced version CI runs: the studies of three maps (``geyer``,
  ``gravity-type5``, ``iterative``) and the control evaluation's small version, into ``--out DIR``
  (required: a reduced run never overwrites docs/), the page rendered with what it measured
  (numbers and claims of maps it did not measure read "not measured in this run").

Needs Jinja2, which renders the page (the ``derive``, ``docs`` and ``test`` extras have it).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..api.progress import Stages

__all__ = ["QUICK_MAPS", "add_parser", "run"]

#: The maps of ``--quick`` (with the baseline map, which the studies add).
QUICK_MAPS = ("gravity-type5", "iterative")


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``report`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "report",
        help="measure every study again and rebuild the report's sections 6-8 (docs/sections.md)",
        description="Run every study (accuracy, convergence, stiffness, stability, reproductions) and the "
        "control evaluation, then write the report's sections 6-8 (sections.md and its figure) from their "
        "records: into the checkout's docs/ or --out DIR. --render-only: only the page, from the records "
        "there; --quick: the reduced version (three maps, the small control evaluation) into --out DIR.",
    )
    p.add_argument("--out", default=None, metavar="DIR", help="the directory of the records and the page")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--render-only", action="store_true", help="no measurement: the page from the records")
    mode.add_argument("--quick", action="store_true", help="the reduced version (needs --out)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def _out(args: argparse.Namespace) -> Path:
    from .args import docs_out

    return docs_out(args.out, args.quick)


def run(args: argparse.Namespace) -> int:
    """Run ``slipmaps report`` (module docstring); prints the paths it wrote. Exit 1 with one line
    when the records do not support a claim of the page or lack one it needs (strict render)."""
    from ..report import sections

    try:
        return _run(args)
    except (sections.ClaimFailed, sections.MissingData) as exc:
        print(f"slipmaps report: {exc}", file=sys.stderr)
        return 1


def _run(args: argparse.Namespace) -> int:
    from ..report import sections
    from ..studies.checkout import checkout_root

    out = _out(args)  # before any work
    show = False if args.no_progress else None
    written: list[Path] = []
    if args.render_only:
        for path in sections.write(out, draw=True):
            print(f"wrote {path}")
        return 0
    root = checkout_root()
    if root is None:
        raise ValueError("report runs the control scenarios of a checkout's examples/: run it from one")
    from ..control.report import write as write_control
    from ..studies.runner import run as run_studies
    from ..studies.runner import studies

    maps = list(QUICK_MAPS) if args.quick else None  # chosen: with the baseline map
    stage = Stages(len(studies(maps)) + 2, "slipmaps report")  # the studies, the control evaluation, the page
    written += run_studies(  # the page reads <study>.json
        out / "accuracy.md", maps, show, plain_names=True, on_study=lambda s: stage(f"the {s.name} study")
    )
    stage("the control evaluation")
    written += write_control(out, root / "examples", quick=args.quick, progress=show)
    stage("sections 6-8")
    records = sections.load(out)
    if args.quick:
        import json

        records["control"] = json.loads((out / "control_quick.json").read_text(encoding="utf-8"))
    written += sections.write(out, records=records, strict=not args.quick)
    stage.done()
    for path in written:
        print(f"wrote {path}")
    return 0
