"""``slipmaps sweep``: the command line of :mod:`.sweep` (registered by :mod:`.app`).

A TOML file (``examples/sweep.toml``) and/or flags; a flag replaces the file's value, ``--axis`` and
``--fixed`` the file's entry of that quantity. A quantity given twice on the command line (two
``--axis``, or ``--axis`` and ``--fixed`` of it) contradicts itself and is refused, as the file
(an axis listed twice, a quantity both in ``[fixed]`` and ``[axes]``) and :class:`~.sweep_spec.Sweep`
refuse it. The output directory is checked (:mod:`.paths`) before any chunk runs. Errors are one
line and exit 2 (``cli.main``); an interrupted sweep (Ctrl-C) keeps its chunks, says so and exits
130.
"""

from __future__ import annotations

import argparse
import json
import sys
import textwrap
from pathlib import Path

from ..api.paths import writable_dir
from ..sweep.axes import CHUNK_ROWS_EXACT, CHUNK_ROWS_GENERATED, KINDS, quantities

__all__ = ["add_parser", "run"]


def _epilog() -> str:
    params = ", ".join(n for n, q in quantities("apex_return").items() if q.role == "param")
    kinds = "; ".join(f"{k}: {', '.join(q.name for q in v)}" for k, v in KINDS.items())
    text = textwrap.fill(
        "axis SPEC: LOW:HIGH:NUM (a grid; LOW:HIGH:NUM:log spaces it logarithmically), LOW:HIGH (a "
        f"random sample: uniform), or V1,V2,... (values). Quantities (SI units): the inputs ({kinds}) "
        f"and the parameters {params} (k_d_over_k_c: k_d = k_c * ratio). Parameters not given are the "
        "human runner's (m 80 kg, l0 1 m, k 20 kN/m).",
        width=100,
    )
    return f"""\
examples::

  slipmaps sweep --map geyer --fixed apex_height=1.0 --axis apex_speed=3:7:41 \\
      --axis touchdown_angle=0.25:0.45:21 --out sweep_geyer
  slipmaps sweep examples/sweep.toml --scheduler local:2
  slipmaps sweep --map exact --random 2000 --seed 1 --fixed apex_height=1 \\
      --axis apex_speed=3:7 --axis touchdown_angle=0.2:0.45 --format parquet --out sweep_exact

{text}

output: OUT/manifest.json (definition, units), OUT/chunks/part-NNNNN.csv|parquet, with --combine
OUT/sweep.csv|parquet; columns: the inputs, the swept parameters, the map's outputs (the next
apex as next_apex_height, next_apex_speed), status and status_name. Interrupted? Run the same
command again: it resumes from the chunks written (a different sweep into the same OUT is refused).
"""


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "sweep",
        help="a map over a grid or a random sample of apexes and parameters, written to CSV/Parquet",
        description="Run any map (or exact) over a grid or a random sample of apex height, speed, "
        "touchdown angle, stiffness ratio and SLIP parameters, chunk by chunk into a directory "
        "(resumable), in this process or on a Dask cluster.",
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("config", nargs="?", help="a sweep TOML file (see examples/sweep.toml)")
    p.add_argument("--map", help="the map (see `slipmaps maps`; 'exact' for the simulator)")
    p.add_argument("--kind", choices=tuple(KINDS), help="apex_return (default) or stance")
    p.add_argument("--axis", action="append", metavar="NAME=SPEC", help="a swept quantity (repeatable)")
    p.add_argument("--fixed", action="append", metavar="NAME=VALUE", help="a fixed quantity (repeatable)")
    p.add_argument("--option", action="append", metavar="KEY=VALUE", help="a map option (repeatable)")
    p.add_argument("--random", type=int, metavar="N", help="a random sample of N rows instead of a grid")
    p.add_argument("--seed", type=int, help="the random sample's seed (default 0)")
    p.add_argument(
        "--chunk-rows",
        type=int,
        help=f"rows per chunk file (default {CHUNK_ROWS_GENERATED}; exact: {CHUNK_ROWS_EXACT})",
    )
    p.add_argument("--format", choices=("csv", "parquet"), help="file format (default csv)")
    p.add_argument("--out", help="output directory (resumed when it holds this sweep)")
    p.add_argument(
        "--scheduler",
        help="inprocess (default), local:N (a local Dask cluster of N workers) or a Dask scheduler "
        "address (tcp://host:8786)",
    )
    p.add_argument("--combine", action="store_true", default=None, help="also write OUT/sweep.<format>")
    p.add_argument("--max-chunks", type=int, help="compute at most this many chunks now (resume later)")
    p.add_argument(
        "--yes",
        action="store_true",
        help=f"run a sweep over {LARGE_ROWS:.0e} rows or beyond the free disk (refused without it)",
    )
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    return p


def _pairs(flag: str, items: list[str] | None) -> dict[str, str]:
    """``NAME=VALUE`` strings of a repeatable flag, by name; a name given twice is refused (two
    values for one quantity contradict each other)."""
    out = {}
    for item in items or ():
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise ValueError(f"{flag} takes NAME=VALUE, got {item!r}")
        name = key.strip()
        if name in out:
            raise ValueError(
                f"{flag} {name} given twice ({name}={out[name]} and {name}={value.strip()}): "
                "give each quantity once"
            )
        out[name] = value.strip()
    return out


def _float(flag: str, name: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{flag} {name}: {text!r} is not a number") from None


def _definition(args: argparse.Namespace) -> tuple[dict, dict]:
    """(the definition's keys, the run settings) from the TOML file and the flags."""
    from ..sweep.run import split_keys
    from ..sweep.spec import axes_by_name, read_toml

    data = dict(read_toml(args.config)) if args.config else {}
    split_keys(data, args.config or "sweep")  # an unknown key of the file, listing every known one
    axes = dict(axes_by_name(data.get("axes", {})))
    fixed = dict(data.get("fixed", {}))
    flag_axes, flag_fixed = _pairs("--axis", args.axis), _pairs("--fixed", args.fixed)
    both = [name for name in flag_axes if name in flag_fixed]
    if both:
        raise ValueError(
            f"{', '.join(both)}: given both --axis and --fixed; a quantity is either swept or fixed"
        )
    for name, spec in flag_axes.items():
        fixed.pop(name, None)
        axes[name] = spec
    for name, text in flag_fixed.items():
        axes.pop(name, None)
        fixed[name] = _float("--fixed", name, text)
    data.update(axes=axes, fixed=fixed)
    for key in ("map", "kind", "seed", "chunk_rows", "out", "format", "scheduler", "combine"):
        if getattr(args, key) is not None:
            data[key] = getattr(args, key)
    if args.random is not None:
        data.update(mode="random", samples=args.random)
    if args.option:
        from .args import map_options

        if "map" not in data:
            raise ValueError("--option needs --map (or map in the TOML file)")
        data["options"] = {**data.get("options", {}), **map_options(data["map"], args.option)}
    return split_keys(data, args.config or "sweep")


#: A sweep over at least this many rows runs only with ``--yes`` (a plausible typo of a grid).
LARGE_ROWS = 10**8

#: Bytes a row's value takes in a file, about: a float64 printed in full and its comma (CSV), the
#: float64 itself (Parquet, before compression).
BYTES_PER_VALUE = {"csv": 24, "parquet": 8}


def check_size(definition, out, fmt: str) -> int:
    """The estimated bytes of the sweep's files; ValueError with the estimate when the sweep has
    :data:`LARGE_ROWS` rows or more, or when the estimate exceeds the free disk under ``out``."""
    import shutil

    rows = definition.rows
    size = rows * len(definition.columns) * BYTES_PER_VALUE.get(fmt, 24)
    folder = Path(out)
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    free = shutil.disk_usage(folder).free
    if rows >= LARGE_ROWS or size > free:
        raise ValueError(
            f"the sweep has {rows:,} rows, about {size / 1e9:,.3g} GB of {fmt} ({free / 1e9:,.3g} GB free "
            f"under {folder}): check the axes, or give --yes to run it"
        )
    return size


def run(args: argparse.Namespace) -> int:
    from ..sweep.run import sweep
    from ..sweep.schedulers import check_scheduler
    from ..sweep.spec import Sweep

    data, settings = _definition(args)
    definition = Sweep.from_dict(data)
    if "out" not in settings:
        raise ValueError("give an output directory: --out DIR (or out in the TOML file)")
    writable_dir("--out" if args.out is not None else f"out (in {args.config})", settings["out"])
    if settings.get("scheduler") is not None:  # its form, before anything is tried
        check_scheduler(
            settings["scheduler"],
            "--scheduler" if args.scheduler is not None else f"scheduler (in {args.config})",
        )
    if not args.yes:
        check_size(definition, settings["out"], settings.get("format") or "csv")
    try:
        summary = sweep(
            definition,
            settings["out"],
            format=settings.get("format"),
            scheduler=settings.get("scheduler"),
            combine=settings.get("combine"),
            progress=False if args.no_progress else None,
            max_chunks=args.max_chunks,
        )
    except KeyboardInterrupt:
        print(
            f"slipmaps sweep: interrupted; the chunks written in {settings['out']} are kept: "
            "run the same command again to resume",
            file=sys.stderr,
        )
        return 130
    print(json.dumps(summary.as_dict(), indent=2) if args.json else summary.format())
    return 0
