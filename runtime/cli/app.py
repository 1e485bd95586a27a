"""The ``slipmaps`` command line (also ``python -m slipmaps`` and ``python -m slipmaps.runtime``).

Subcommands (``slipmaps --version`` prints the installed version):

- ``maps [--json]``: the maps of the index (name, title, report section, equations, requirements,
  options), then the half-stance maps;
- ``compare [--map NAME] [--against NAME] [--option KEY=VALUE ...]``: the main job, one step by two
  maps from the same touchdown (default Geyer et al. against the exact simulator): table + plot; a
  half-stance map is compared with the same half of --against (from its bottom for a decompression
  half). The default step scales with the leg: apex height 1.0 l0 (``--apex-height-l0``), speed by
  the Froude number 1.596 (``--froude``), touchdown angle 0.35 rad sqrt(25.5 / kappa) with kappa =
  k_c l0 / (m g_s), i.e. 1.0 m, 5 m/s and 0.35 rad for the human runner; ``--apex-height`` [m],
  ``--apex-speed`` [m/s] and ``--angle`` [rad] give absolute values. With ``--touchdown`` the
  touchdown leg length q_r_td is the state's q_r (a different ``--q-r-td`` is refused). Exit status:
  0 when both sides ran (status OK), 1 when a side failed physically (no touchdown, a fall, no
  flight phase...: its status and message under the table, ``n/a`` in its cells), 2 for a user error;
- ``accuracy [--map NAME|all] [--out DIR]``: every map against the exact simulator on the accuracy
  grids, written as accuracy.md (+ .json, .png) with the convergence study of the iterative maps
  (convergence.md), the variable-stiffness study over k_d/k_c (stiffness.md) and the periodic
  gaits' fixed points and stability (stability.md) and, for all maps, published claims checked by
  code (reproductions.md): into the checkout's docs/ when slipmaps runs from a source checkout,
  else into ``--out DIR`` (required there);
- ``gait [--map NAME ...] [--json] [--figure PATH]``: periodic gaits, the fixed points of the
  apex-return map and their eigenvalues (runtime/cli/gait.py);
- ``equations [--json]``: run the symbolic check of every registered report equation (``--json``:
  one JSON array, an object per equation);
- ``generate [--check]``: regenerate generated/ and the docs from derive/ (``--check``: exit 1 when
  stale); a source checkout only;
- ``run SCENARIO.toml`` / ``run --evaluate``: a multi-step controlled run, or the control evaluation
  (runtime/cli/run.py);
- ``report [--render-only | --quick] [--out DIR]``: every study and the control evaluation measured
  again, then the report's sections 6-8 (docs/sections.md) rebuilt from their records
  (runtime/cli/report.py);
- ``viability [--vibly | --energy J --heights MIN MAX N | --speeds ...] [--json] [--out PATH.npz]``:
  the viable set, the viability kernel and its measure on a grid, with a figure
  (runtime/cli/viability.py);
- ``warmup [MAPS]``: compile the kernels into numba's disk cache ahead, on every core, with a
  progress bar (runtime/cli/warmup.py).

A user error (bad value, unknown map or option, a map that refuses the parameters, a path to write
that cannot be written) is one line on standard error and exit code 2, never a traceback; it names
the flag as typed. Every path a command writes (``compare --plot``, ``gait --figure``, ``sweep
--out``, ``accuracy --out``, ``run --figure/--gif``) is checked by one helper (:mod:`.paths`: a
probe file created and removed) before any work. A reader that closes standard output early
(``slipmaps maps | head -1``) ends any command quietly with exit status :data:`BROKEN_PIPE`;
Ctrl-C ends any command with one line and :data:`INTERRUPTED` (130). An OSError while writing is
one line naming the path and the reason, exit 2 (``paths.writing``). On a terminal, numba compiling
a kernel on its first use (an empty or stale cache) is one line on standard error with its seconds
(:func:`~slipmaps.runtime.api.notices.compile_notices`; none with ``--no-progress`` or when
standard error is piped). The map names and options come from the generated index.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from ..api.notices import compile_notices
from ..api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from ..api.paths import writable_dir, writable_file
from ..api.progress import Stages
from ..api.validate import leg_angle, non_negative, polar_state, positive
from . import damping_viability as damping_viability_cli
from . import footholds as footholds_cli
from . import report as report_cli
from . import robot as robot_cli
from . import run as run_cli
from . import sweep as sweep_cli
from . import viability as viability_cli
from . import warmup as warmup_cli
from .args import add_params, image_path, map_options, params_of, stiffness_note
from .defaults import (
    APEX_FROUDE,
    APEX_HEIGHT_L0,
    TOUCHDOWN_ANGLE,
    apex_height_of,
    apex_speed_of,
    default_touchdown_angle,
    stiffness_number,
)

__all__ = ["main", "build_parser", "BROKEN_PIPE", "INTERRUPTED"]

#: The exit status when standard output's reader closed the pipe early (128 + SIGPIPE, the status
#: of a process that the signal ended): no traceback, nothing on standard error.
BROKEN_PIPE = 141

#: The exit status of a command ended by Ctrl-C (128 + SIGINT): one line on standard error.
INTERRUPTED = 130


def _step(args: argparse.Namespace, params: SlipParams) -> dict:
    """The step's keywords of :func:`~.compare.compare`, validated under the flags' names: the apex
    (absolute, or relative to the leg) or the touchdown state; None keeps a default."""
    height = speed = None
    if args.apex_height is not None:
        height = non_negative("--apex-height", args.apex_height)
    if args.apex_height_l0 is not None:
        height = apex_height_of(params, positive("--apex-height-l0", args.apex_height_l0))
    if args.apex_speed is not None:
        speed = non_negative("--apex-speed", args.apex_speed)
    if args.froude is not None:
        speed = apex_speed_of(params, non_negative("--froude", args.froude))
    angle = None if args.angle is None else leg_angle("--angle", args.angle)
    td = None if args.touchdown is None else polar_state(params, args.touchdown, what="--touchdown")
    return {"apex_height": height, "apex_speed": speed, "touchdown_angle": angle, "touchdown": td}


def _version() -> str:
    """The installed distribution's version (``unknown`` when slipmaps runs uninstalled)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("slipmaps")
    except PackageNotFoundError:
        return "unknown (not installed)"


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="slipmaps",
        description="Approximate SLIP stance maps: derived in SymPy, generated as numba kernels, "
        "checked against numerical integration.",
    )
    parser.add_argument("--version", action="version", version=f"slipmaps {_version()}")
    sub = parser.add_subparsers(dest="command", required=True)

    mp = sub.add_parser(
        "maps",
        help="list the maps (name, title, report section, equations, options)",
        description="List every map of the index (name, report section, title, equations, requirements, "
        "options with their defaults), then the half-stance maps.",
    )
    mp.add_argument("--json", action="store_true", help="print the index as JSON")

    cmp_ = sub.add_parser(
        "compare",
        help="one step by two maps from the same touchdown: table and plot",
        description="One SLIP step from an apex (default: 1.0 l0 high at Froude number "
        f"{APEX_FROUDE:.4g}, touchdown angle scaled by the leg's stiffness; 1.0 m, 5 m/s and "
        f"{TOUCHDOWN_ANGLE:g} rad for the human runner) or from a touchdown state, by --map and by "
        "--against (default: Geyer et al.'s map, or geyer-vs when k_c != k_d, against the exact simulator).",
        epilog="exit status: 0 both sides ran (status OK); 1 a side failed physically (no touchdown, a fall, "
        "no flight phase...: n/a in its cells, its status and message under the table); 2 a user error "
        "(one line on standard error).",
    )
    add_params(cmp_)
    cmp_.add_argument(
        "--map",
        default=None,
        help="the map to compare (default geyer; geyer-vs when k_c != k_d; see `slipmaps maps`)",
    )
    cmp_.add_argument(
        "--against", default=None, help="the reference map (default: the exact map, the ground truth)"
    )
    cmp_.add_argument(
        "--option", action="append", metavar="KEY=VALUE", help="an option of --map (repeatable)"
    )
    cmp_.add_argument("--against-option", action="append", metavar="KEY=VALUE", help="an option of --against")
    t = cmp_.add_argument_group(
        "touchdown conditions (an apex, or --touchdown)",
        "The defaults scale with the leg (the human runner's: 1.0 m, 5 m/s, 0.35 rad): --apex-height-l0 "
        "and --froude are relative to l0, --apex-height [m], --apex-speed [m/s] and --angle [rad] "
        "absolute (give one of each pair).",
    )
    height = t.add_mutually_exclusive_group()
    height.add_argument(
        "--apex-height",
        type=float,
        default=None,
        help="apex height [m], absolute (default: see --apex-height-l0)",
    )
    height.add_argument(
        "--apex-height-l0",
        type=float,
        default=None,
        metavar="H",
        help=f"apex height in units of l0 (default {APEX_HEIGHT_L0}: 1.0 m for the human runner, "
        "0.25 m for a 0.25 m leg)",
    )
    speed = t.add_mutually_exclusive_group()
    speed.add_argument(
        "--apex-speed", type=float, default=None, help="apex speed [m/s], absolute (default: see --froude)"
    )
    speed.add_argument(
        "--froude",
        type=float,
        default=None,
        metavar="FR",
        help=f"apex speed as the Froude number v/sqrt(g_f l0) (default {APEX_FROUDE:.4g}: 5 m/s for the "
        "human runner, 2.5 m/s for a 0.25 m leg)",
    )
    t.add_argument(
        "--angle",
        type=float,
        default=None,
        help=f"touchdown leg angle q_th_td [rad], absolute (default {TOUCHDOWN_ANGLE:g} "
        f"sqrt({stiffness_number(HUMAN_RUNNER):.3g}/kappa), kappa = k_c l0/(m g_s) the dimensionless "
        f"stiffness: {TOUCHDOWN_ANGLE:g} rad for the human runner, "
        f"{default_touchdown_angle(ROBOT_HOPPER):.3g} rad for the robot hopper)",
    )
    t.add_argument(
        "--touchdown",
        type=float,
        nargs=4,
        metavar=("Q_R", "Q_RD", "Q_TH", "Q_THD"),
        default=None,
        help="start from this polar touchdown state instead of an apex (e.g. a nonsymmetric one); "
        "its Q_R is the touchdown leg length q_r_td",
    )
    cmp_.add_argument(
        "--plot",
        default="slipmaps_compare.png",
        help="image path, .png/.pdf/.svg (default %(default)s; a missing directory is created)",
    )
    cmp_.add_argument("--no-plot", action="store_true", help="do not write the plot")
    cmp_.add_argument("--json", action="store_true", help="print the numbers as JSON instead of a table")

    gen = sub.add_parser(
        "generate",
        help="regenerate generated/ and docs from derive/ (needs the [derive] extra)",
        description="Render generated/ (the numba kernels and the map index), docs/equations.md, "
        "docs/maps.md and the README tables from the SymPy derivations in derive/. Works on a source "
        "checkout (pip install -e '.[derive]'); writes only files whose content changes.",
    )
    gen.add_argument("--check", action="store_true", help="exit 1 if generated files differ from the sources")
    gen.add_argument(
        "--target",
        choices=("numba", "c"),
        default="numba",
        help="numba (default): generated/ and the docs; c: the analytic maps and the deadbeat solver as a "
        "C99 library (slipmaps.h, slipmaps.c, ...) in DIR (docs/c_export.md)",
    )
    gen.add_argument("dir", nargs="?", type=Path, help="the output directory of --target c")

    eq = sub.add_parser(
        "equations",
        help="check every registered report equation symbolically and print its status",
        description="Run the SymPy check of every equation of the report registered in derive/equations "
        "and print its status (verified, corrected, definition) with a note; exit 1 if a check fails. "
        "Needs the [derive] extra.",
    )
    eq.add_argument(
        "--json",
        action="store_true",
        help="print the equations as one JSON array (an object per equation) instead of the table",
    )

    acc = sub.add_parser(
        "accuracy",
        help="every map against the exact simulator on the accuracy grids",
        description="Measure every map (or one) against the exact simulator on the accuracy grids and "
        "write accuracy.md (+ .json, .png), convergence.md, stiffness.md, stability.md and, for all maps, "
        "reproductions.md (+ .json, .png): "
        "into the "
        "checkout's docs/ when slipmaps runs from a source checkout, else into --out DIR.",
    )
    acc.add_argument(
        "--map",
        default="all",
        help="a map name, or 'all' (default): all maps, written as accuracy.md (and beside it "
        "convergence.md, stiffness.md, stability.md, reproductions.md); one map: accuracy_<map>.md",
    )
    acc.add_argument(
        "--out",
        default=None,
        metavar="DIR",
        help="the directory to write into (or a .md path for the accuracy report); default: the "
        "checkout's docs/, required when slipmaps does not run from a source checkout",
    )
    acc.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")

    from .gait import add_parser as add_gait

    add_gait(sub)
    sweep_cli.add_parser(sub)
    run_cli.add_parser(sub)
    report_cli.add_parser(sub)
    robot_cli.add_parser(sub)
    footholds_cli.add_parser(sub)
    damping_viability_cli.add_parser(sub)
    viability_cli.add_parser(sub)
    warmup_cli.add_parser(sub)
    return parser


def _percent(x: float) -> str:
    p = 100.0 * x
    return f"{p:.2g} %" if p < 10.0 else f"{p:.0f} %"


def _front_column(name: str) -> tuple[str, list[str]]:
    """``slipmaps maps``'s cost-accuracy column for a map at its defaults (``front``, ``dominated``
    or ``-``: not measured) and its line (runtime/api/pareto.json, benchmarks/bench_pareto.py)."""
    from ..api.front import at_defaults, front

    v = at_defaults(name)
    if v is None:
        return "-", []
    text = (
        f"cost-accuracy: {v.ns_per_apex_return:,.0f} ns per apex return, next-apex error mean "
        f"{_percent(v.mean_error)}, max {_percent(v.max_error)}, {v.failures} failures"
    )
    if v.dominated_by is None:
        return "front", [text + "; on the front (no variant measured dominates it)"]
    by = front()[v.dominated_by]
    return "dominated", [
        text + f"; dominated by {by.label} ({by.command}: {by.ns_per_apex_return:,.0f} ns, mean "
        f"{_percent(by.mean_error)}, max {_percent(by.max_error)}, {by.failures} failures)"
    ]


def _cmd_maps(args: argparse.Namespace) -> int:
    from ..api.front import at_defaults, measurement
    from ..api.index import HalfInfo, halves, maps

    rows = maps() + halves()
    if args.json:
        out = []
        for m in rows:
            d = m.as_dict()
            v = at_defaults(m.name)
            d["dominated_by"] = None if v is None else v.dominated_by
            d["on_front"] = None if v is None else v.dominated_by is None
            out.append(d)
        print(json.dumps(out, indent=2))
        return 0
    w = max(len(m.name) for m in rows) + 1
    meta = measurement()
    print(
        f"{'map':<{w}} {'sec':<6} {'front':<9} title  (front: the map at its defaults on the measured "
        f"cost-accuracy front, or dominated; {meta['measured_by']}, {meta['date']})"
    )
    for m in rows:
        column, lines = _front_column(m.name)
        print(f"{m.name:<{w}} {m.section:<6} {column:<9} {m.title}")
        if isinstance(m, HalfInfo):
            where = f"half of {m.whole}: {m.start} -> {m.end} (slipmaps.half_stance)"
        else:
            where = f"requires {', '.join(m.requires) or 'nothing'}"
        print(f"{'':<{w}} equations {', '.join(m.equations)}; {where}")
        for o in m.options:
            kind = "|".join(o.choices) if o.kind == "choice" else o.kind
            print(f"{'':<{w}} --option {o.name}=<{kind}> (default {o.default}): {o.doc}")
        for line in lines:
            print(f"{'':<{w}} {line}")
    return 0


def _cmd_compare(args: argparse.Namespace) -> int:
    """0 when both sides ran, 1 when a side failed physically (its status under the table)."""
    params = params_of(args)
    step = _step(args, params)  # bad values and plot paths are refused before any work
    path = None if args.no_plot else image_path("--plot", args.plot)
    note = stiffness_note(args, params)
    if note:
        print(f"slipmaps compare: note: {note}", file=sys.stderr)
    from ..api.index import EXACT
    from .compare import compare, default_map, format_table, plot

    name = args.map or default_map(params)
    against = args.against or EXACT
    c = compare(
        params,
        map=name,
        against=against,
        **step,
        options=map_options(name, args.option),
        against_options=map_options(against, args.against_option),
    )
    if not args.json:  # the table first, flushed: the reader has the numbers while the plot is drawn
        print(format_table(c), flush=True)
    if path:
        try:
            plot(c, path)
        except OSError as exc:
            raise ValueError(f"--plot {path}: {exc.strerror or exc}") from None
    if args.json:
        data = c.to_dict()
        data["plot"] = path
        print(json.dumps(data, indent=2))
    elif path:
        print(f"\nplot: {path}")
    return 0 if c.ok else 1


def _derive_module(name: str):
    import importlib

    try:
        return importlib.import_module(f"slipmaps.derive.{name}")
    except ImportError as exc:  # sympy / jinja2 missing
        raise ValueError(f"needs the derive extra (pip install -e '.[derive]'): {exc}") from None


def _cmd_generate(args: argparse.Namespace) -> int:
    if args.target == "c":
        if args.dir is None or args.check:
            raise ValueError(
                "--target c writes a C library into a directory: slipmaps generate --target c DIR"
            )
        writable_dir("DIR", args.dir)
        stages = Stages(3, "slipmaps generate")  # derive (12 s), translate (20 s), write
        for path in _derive_module("ctarget").write(args.dir, stage=stages, show=None):
            print(f"wrote {path}")
        stages.done()
        return 0
    if args.dir is not None:
        raise ValueError(f"{args.dir}: an output directory is for --target c (generated/ has its place)")
    return _derive_module("generate").main(check_only=args.check)


def _cmd_equations(args: argparse.Namespace) -> int:
    return _derive_module("equations").main(json_output=args.json)


def _accuracy_out(args: argparse.Namespace) -> Path:
    """The accuracy report's markdown path: ``--out`` (a directory, or a .md path; checked, and its
    directory created, before any work), else the checkout's docs/; ValueError when there is
    neither (never a relative docs/) or when ``--out`` cannot be written."""
    from ..studies.checkout import docs_dir

    name = "accuracy.md" if args.map == "all" else f"accuracy_{args.map}.md"
    if args.out is not None:
        out = Path(args.out)
        if out.suffix == ".md":
            return writable_file("--out", args.out, ("md",), described="a markdown file")
        return writable_dir("--out", args.out) / name
    docs = docs_dir()
    if docs is None:
        raise ValueError(
            "slipmaps does not run from a source checkout, so there is no docs/ to update: "
            "give --out DIR (the directory for accuracy.md, convergence.md, stiffness.md)"
        )
    return docs / name


def _cmd_accuracy(args: argparse.Namespace) -> int:
    from ..api.index import get
    from ..studies.runner import run

    names = None if args.map == "all" else [get(args.map).name]
    if names is not None and get(names[0]).ground_truth:
        raise ValueError("accuracy compares maps against the exact simulator; choose an approximate map")
    out = _accuracy_out(args)  # before any work
    for path in run(out, names, show_progress=False if args.no_progress else None):
        print(f"wrote {path}")
    return 0


def _cmd_gait(args: argparse.Namespace) -> int:
    from .gait import run

    return run(args)


def main(argv: list[str] | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``) and return its exit status: a user
    error is one line on standard error and 2; a reader that closes standard output early
    (``slipmaps maps | head -1``) ends every command quietly with :data:`BROKEN_PIPE`."""
    try:
        return _run(argv)
    except BrokenPipeError:
        # The reader stopped early: nothing more to say to it. Python flushes stdout again at
        # exit; pointing it at devnull keeps that flush quiet (the recipe of Python's signal docs).
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return BROKEN_PIPE


def _run(argv: list[str] | None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit:  # --help, --version or a usage error: their output is written now
        sys.stdout.flush()
        raise
    handlers = {
        "maps": _cmd_maps,
        "compare": _cmd_compare,
        "generate": _cmd_generate,
        "equations": _cmd_equations,
        "accuracy": _cmd_accuracy,
        "gait": _cmd_gait,
        "sweep": sweep_cli.run,
        "run": run_cli.run,
        "report": report_cli.run,
        "robot": robot_cli.run,
        "footholds": footholds_cli.run,
        "damping-viability": damping_viability_cli.run,
        "viability": viability_cli.run,
        "warmup": warmup_cli.run,
    }
    try:
        # numba compiling a kernel on first use (tens of seconds on an empty cache) is a line on a
        # terminal's standard error, for every command (runtime/api/progress.py)
        with compile_notices(enabled=False if getattr(args, "no_progress", False) else None):
            code = handlers[args.command](args)
    except (ValueError, TypeError, ImportError) as exc:  # ImportError: an optional extra is missing
        print(f"slipmaps {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        raise
    except OSError as exc:  # a write no command guarded: still one line naming the path
        where = exc.filename if exc.filename is not None else "a file"
        print(f"slipmaps {args.command}: error: cannot write {where}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"slipmaps {args.command}: interrupted", file=sys.stderr)
        return INTERRUPTED
    sys.stdout.flush()  # a closed pipe shows here, inside main, not at the interpreter's exit
    return code


if __name__ == "__main__":
    sys.exit(main())
