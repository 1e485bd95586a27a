"""The ``slipmaps`` command line.

Subcommands: ``compare`` (the main job: exact vs approximate step, table + plot), ``generate``
(regenerate ``generated/`` and the docs from ``derive/``; ``--check`` fails when they are stale),
``equations`` (run the symbolic check of every registry entry and print its status) and
``accuracy`` (write the accuracy table of the approximate map to docs/).

Built on the standard library's argparse: the interface is a handful of subcommands with float
options, which argparse covers fully, and it keeps the runtime free of extra dependencies.
"""

from __future__ import annotations

import argparse
import json
import sys

from .params import HUMAN_RUNNER, SlipParams

__all__ = ["main", "build_parser"]


def _add_params(p: argparse.ArgumentParser) -> None:
    d = HUMAN_RUNNER
    g = p.add_argument_group("SLIP parameters (SI units; default: the human runner)")
    g.add_argument("--m", type=float, default=d.m, help="body mass [kg] (default %(default)s)")
    g.add_argument("--l0", type=float, default=d.l0, help="rest leg length [m] (default %(default)s)")
    g.add_argument(
        "--k", type=float, default=None, help="leg stiffness, sets k_c = k_d [N/m] (default 20000)"
    )
    g.add_argument("--k-c", type=float, default=None, help="compression stiffness [N/m]")
    g.add_argument("--k-d", type=float, default=None, help="decompression stiffness [N/m]")
    g.add_argument("--g-s", type=float, default=d.g_s, help="gravity in stance [m/s^2] (default %(default)s)")
    g.add_argument("--g-f", type=float, default=d.g_f, help="gravity in flight [m/s^2] (default %(default)s)")
    g.add_argument("--q-r-td", type=float, default=None, help="touchdown leg length [m] (default l0)")
    g.add_argument("--q-r-lo", type=float, default=None, help="liftoff leg length [m] (default l0)")


def _params(args: argparse.Namespace) -> SlipParams:
    k = args.k if args.k is not None else HUMAN_RUNNER.k_c
    return SlipParams(
        m=args.m,
        l0=args.l0,
        k_c=args.k_c if args.k_c is not None else k,
        k_d=args.k_d if args.k_d is not None else k,
        g_s=args.g_s,
        g_f=args.g_f,
        q_r_td=args.q_r_td,
        q_r_lo=args.q_r_lo,
    )


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="slipmaps",
        description="Approximate SLIP stance maps: derived in SymPy, generated as numba kernels, "
        "checked against numerical integration.",
    )
    sub = parser.add_subparsers(dest="command", required=True)

    cmp_ = sub.add_parser(
        "compare",
        help="one step exact vs Geyer et al.'s approximate stance map: table and plot",
        description="One SLIP step from an apex (default: 1.0 m, 5 m/s, touchdown angle 0.35 rad) or "
        "from a touchdown state: exact (solve_ivp) vs Geyer et al.'s approximate stance map.",
    )
    _add_params(cmp_)
    t = cmp_.add_argument_group("touchdown conditions (an apex, or --touchdown)")
    t.add_argument("--apex-height", type=float, default=None, help="apex height [m] (default 1.0)")
    t.add_argument("--apex-speed", type=float, default=None, help="apex speed [m/s] (default 5.0)")
    t.add_argument(
        "--angle", type=float, default=None, help="touchdown leg angle q_th_td [rad] (default 0.35)"
    )
    t.add_argument(
        "--touchdown",
        type=float,
        nargs=4,
        metavar=("Q_R", "Q_RD", "Q_TH", "Q_THD"),
        default=None,
        help="start from this polar touchdown state instead of an apex (e.g. a nonsymmetric one)",
    )
    cmp_.add_argument("--plot", default="slipmaps_compare.png", help="PNG path (default %(default)s)")
    cmp_.add_argument("--no-plot", action="store_true", help="do not write the plot")
    cmp_.add_argument("--json", action="store_true", help="print the numbers as JSON instead of a table")

    gen = sub.add_parser(
        "generate", help="regenerate generated/ and docs from derive/ (needs the [derive] extra)"
    )
    gen.add_argument("--check", action="store_true", help="exit 1 if generated files differ from the sources")

    sub.add_parser(
        "equations", help="check every registered report equation symbolically and print its status"
    )

    acc = sub.add_parser("accuracy", help="write the accuracy table of the approximate map")
    acc.add_argument("--out", default="docs/accuracy.md", help="markdown path (default %(default)s)")
    return parser


def _cmd_compare(args: argparse.Namespace) -> int:
    from .compare import compare, format_table, plot

    params = _params(args)
    touchdown = tuple(args.touchdown) if args.touchdown is not None else None
    c = compare(
        params,
        apex_height=args.apex_height,
        apex_speed=args.apex_speed,
        q_th_td=args.angle,
        touchdown=touchdown,
    )
    path = None if args.no_plot else plot(c, args.plot)
    if args.json:
        data = c.to_dict()
        data["plot"] = path
        print(json.dumps(data, indent=2))
    else:
        print(format_table(c))
        if path:
            print(f"\nplot: {path}")
    return 0


def _derive_module(name: str):
    try:
        import importlib

        return importlib.import_module(f"slipmaps.derive.{name}")
    except ImportError as exc:  # sympy / jinja2 missing
        raise SystemExit(
            f"slipmaps {name}: needs the derive extra (pip install -e '.[derive]'): {exc}"
        ) from None


def _cmd_generate(args: argparse.Namespace) -> int:
    return _derive_module("generate").main(check_only=args.check)


def _cmd_equations(args: argparse.Namespace) -> int:
    registry = _derive_module("registry")
    failed = 0
    for e in registry.entries():
        ok = e.check() if e.check is not None else None
        mark = "-" if ok is None else ("ok" if ok else "FAILED")
        failed += ok is False
        print(f"{e.key:>20}  {e.status:<10}  {mark:<6}  {e.title}")
    print(f"{failed} check(s) failed" if failed else "all checks pass")
    return 1 if failed else 0


def _cmd_accuracy(args: argparse.Namespace) -> int:
    from .accuracy import write

    path = write(args.out)
    print(f"wrote {path}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    handlers = {
        "compare": _cmd_compare,
        "generate": _cmd_generate,
        "equations": _cmd_equations,
        "accuracy": _cmd_accuracy,
    }
    try:
        return handlers[args.command](args)
    except ValueError as exc:
        print(f"slipmaps {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
