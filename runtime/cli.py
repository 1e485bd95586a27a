"""The ``slipmaps`` command line (also ``python -m slipmaps`` and ``python -m slipmaps.runtime``).

Subcommands:

- ``maps [--json]``: the maps of the index (name, title, report section, equations, requirements,
  options), then the half-stance maps;
- ``compare [--map NAME] [--against NAME] [--option KEY=VALUE ...]``: the main job, one step by two
  maps from the same touchdown (default Geyer et al. against the exact simulator): table + plot; a
  half-stance map is compared with the same half of --against (from its bottom for a decompression
  half);
- ``accuracy [--map NAME|all]``: every map against the exact simulator on the accuracy grids,
  written to docs/accuracy.md (+ .json, .png), with the convergence study of the iterative maps
  (docs/convergence.md) and the variable-stiffness study over k_d/k_c (docs/stiffness.md);
- ``equations [--json]``: run the symbolic check of every registered report equation;
- ``generate [--check]``: regenerate generated/ and the docs from derive/ (``--check``: exit 1 when
  stale).

A user error (bad value, unknown map or option, a map that refuses the parameters) is one line on
standard error and exit code 2, never a traceback. The map names and options come from the
generated index.
"""

from __future__ import annotations

import argparse
import json
import sys

from . import sweep_cli
from .params import HUMAN_RUNNER, SlipParams

#: The reference of ``compare`` (``"exact"`` in the index; spelled here so that building the parser,
#: and so ``slipmaps generate``, never needs the generated index).
EXACT = "exact"

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
    """The parameters as given; SlipParams itself refuses --k together with --k-c/--k-d. An unset
    stiffness is the human runner's."""
    if args.k_c is None and args.k_d is None:
        stiff = {"k": HUMAN_RUNNER.k_c if args.k is None else args.k}
    else:
        stiff = {
            "k_c": HUMAN_RUNNER.k_c if args.k_c is None else args.k_c,
            "k_d": HUMAN_RUNNER.k_d if args.k_d is None else args.k_d,
        }
        if args.k is not None:
            stiff["k"] = args.k
    return SlipParams(
        m=args.m, l0=args.l0, **stiff, g_s=args.g_s, g_f=args.g_f, q_r_td=args.q_r_td, q_r_lo=args.q_r_lo
    )


def _options(name: str, pairs: list[str] | None) -> dict:
    """``KEY=VALUE`` strings -> options of map ``name``, typed from the index."""
    from .index import lookup

    info = lookup(name)
    out = {}
    for pair in pairs or ():
        key, sep, value = pair.partition("=")
        if not sep:
            raise ValueError(f"--option takes KEY=VALUE, got {pair!r}")
        opt = info.option(key.strip())
        value = value.strip()
        try:
            out[opt.name] = (
                value if opt.kind == "choice" else (int(value) if opt.kind == "int" else float(value))
            )
        except ValueError:
            raise ValueError(
                f"map {name!r} option {opt.name!r} must be a {opt.kind}, got {value!r}"
            ) from None
    return out


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="slipmaps",
        description="Approximate SLIP stance maps: derived in SymPy, generated as numba kernels, "
        "checked against numerical integration.",
    )
    sub = parser.add_subparsers(dest="command", required=True)

    mp = sub.add_parser("maps", help="list the maps (name, title, report section, equations, options)")
    mp.add_argument("--json", action="store_true", help="print the index as JSON")

    cmp_ = sub.add_parser(
        "compare",
        help="one step by two maps from the same touchdown: table and plot",
        description="One SLIP step from an apex (default: 1.0 m, 5 m/s, touchdown angle 0.35 rad) or from "
        "a touchdown state, by --map and by --against (default: Geyer et al.'s map, or geyer-vs when "
        "k_c != k_d, against the exact simulator).",
    )
    _add_params(cmp_)
    cmp_.add_argument(
        "--map",
        default=None,
        help="the map to compare (default geyer; geyer-vs when k_c != k_d; see `slipmaps maps`)",
    )
    cmp_.add_argument("--against", default=EXACT, help="the reference map (default %(default)s)")
    cmp_.add_argument(
        "--option", action="append", metavar="KEY=VALUE", help="an option of --map (repeatable)"
    )
    cmp_.add_argument("--against-option", action="append", metavar="KEY=VALUE", help="an option of --against")
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

    eq = sub.add_parser(
        "equations", help="check every registered report equation symbolically and print its status"
    )
    eq.add_argument("--json", action="store_true", help="one JSON object per equation")

    acc = sub.add_parser("accuracy", help="every map against the exact simulator on the accuracy grids")
    acc.add_argument(
        "--map",
        default="all",
        help="a map name, or 'all' (default): all maps, written to docs/accuracy.md (and beside it "
        "docs/convergence.md, docs/stiffness.md)",
    )
    acc.add_argument("--out", default=None, help="markdown path (default docs/accuracy.md for all maps)")
    acc.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    sweep_cli.add_parser(sub)
    return parser


def _cmd_maps(args: argparse.Namespace) -> int:
    from .index import HalfInfo, halves, maps

    rows = maps() + halves()
    if args.json:
        print(json.dumps([m.as_dict() for m in rows], indent=2))
        return 0
    w = max(len(m.name) for m in rows) + 1
    for m in rows:
        print(f"{m.name:<{w}} {m.section:<6} {m.title}")
        if isinstance(m, HalfInfo):
            where = f"half of {m.whole}: {m.start} -> {m.end} (slipmaps.half_stance)"
        else:
            where = f"requires {', '.join(m.requires) or 'nothing'}"
        print(f"{'':<{w}} equations {', '.join(m.equations)}; {where}")
        for o in m.options:
            kind = "|".join(o.choices) if o.kind == "choice" else o.kind
            print(f"{'':<{w}} --option {o.name}=<{kind}> (default {o.default}): {o.doc}")
    return 0


def _cmd_compare(args: argparse.Namespace) -> int:
    from .compare import compare, default_map, format_table, plot

    params = _params(args)
    name = args.map or default_map(params)
    c = compare(
        params,
        map=name,
        against=args.against,
        apex_height=args.apex_height,
        apex_speed=args.apex_speed,
        touchdown_angle=args.angle,
        touchdown=tuple(args.touchdown) if args.touchdown is not None else None,
        options=_options(name, args.option),
        against_options=_options(args.against, args.against_option),
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
    import importlib

    try:
        return importlib.import_module(f"slipmaps.derive.{name}")
    except ImportError as exc:  # sympy / jinja2 missing
        raise ValueError(f"needs the derive extra (pip install -e '.[derive]'): {exc}") from None


def _cmd_generate(args: argparse.Namespace) -> int:
    return _derive_module("generate").main(check_only=args.check)


def _cmd_equations(args: argparse.Namespace) -> int:
    return _derive_module("equations").main(json_output=args.json)


def _cmd_accuracy(args: argparse.Namespace) -> int:
    from .accuracy_report import write
    from .index import get

    names = None if args.map == "all" else [get(args.map).name]
    if names == [EXACT]:
        raise ValueError("accuracy compares maps against the exact simulator; choose an approximate map")
    out = args.out or ("docs/accuracy.md" if names is None else f"accuracy_{args.map}.md")
    for path in write(out, names, show_progress=False if args.no_progress else None):
        print(f"wrote {path}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    handlers = {
        "maps": _cmd_maps,
        "compare": _cmd_compare,
        "generate": _cmd_generate,
        "equations": _cmd_equations,
        "accuracy": _cmd_accuracy,
        "sweep": sweep_cli.run,
    }
    try:
        return handlers[args.command](args)
    except (ValueError, TypeError) as exc:
        print(f"slipmaps {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
