"""``slipmaps viability``: the viable set, the viability kernel and the measure on a grid
(:func:`slipmaps.viability`).

The state grid is apex heights at a fixed flight energy (``--energy`` J, with ``--heights MIN MAX N``
[m] or vibly's ``--s MIN MAX N``, s = m g_f h / E), or apex heights x apex speeds (``--speeds MIN MAX
N`` [m/s]); the actions are touchdown angles (``--angles-deg MIN MAX N``, degrees from the vertical,
counterclockwise positive: a forward runner's are positive), optionally k_d (``--k-d-grid MIN MAX N``
[N/m]) and retraction rates (``--retraction-rates MIN MAX N`` [rad/s]). ``--vibly`` is Heim and
Spröwitz's SLIP demo (m 80 kg, k 8200 N/m, l0 1 m, E 1877.08 J, s on 180 points in [0.1, 0.995],
angles -10 ... 70 deg in 161 steps), with ``--outside edge`` it is vibly's algorithm to the bit.
Without a grid: the human runner at the energy of a 1 m, 5 m/s apex, 100 heights from 0.3 l0 to 99.5 %
of the energy's height, angles 0 ... 60 deg in 121 steps.

Prints the sizes, the kernel's extent and where the measure peaks (``--json``: the summary and a row
per state), writes a figure (the viable set as an image, the kernel and the measure beside it;
``--figure PATH``, default ``slipmaps_viability.png``; ``--no-figure``) and with ``--out PATH.npz``
every array. ``--grounds MIN MAX N`` (with ``--speeds`` and ``--k-d-grid``): the ground under the
touchdown is one of these heights [m], unknown at the apex; the kernels and shares of viable
angles with k_d = k_c, k_d chosen at the apex and k_d chosen at the bottom
(:func:`slipmaps.robust_viability`). ``--sweep-out DIR`` computes the steps of a (height, speed)
grid as a resumable sweep into DIR (:func:`slipmaps.viability_sweep`), ``--scheduler local:N`` on a
local Dask cluster, ``--next-state-float32`` holding the next states in half the memory. Paths are
checked before any work, and so is the memory the grid needs. Exit status: 0 done, 2 a user error
(one line on standard error), 130 interrupted.
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

__all__ = ["VIBLY", "add_parser", "run"]

#: Heim and Spröwitz's SLIP demo (vibly's demos/computeQ_slip.py).
VIBLY = {
    "params": {"m": 80.0, "l0": 1.0, "k": 8200.0, "g_s": 9.81, "g_f": 9.81},
    "energy": 1877.08,
    "s": (0.1, 0.995, 180),
    "angles_deg": (-10.0, 70.0, 161),
}


def _grid_arg(text: str) -> float:
    return float(text)


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``viability`` subcommand to the subparsers ``sub``."""
    from .args import add_params

    p = sub.add_parser(
        "viability",
        help="the viable set, the viability kernel and its measure on a grid (Heim and Spröwitz)",
        description="The viable set Q_V (state-action pairs whose next apex is viable), the viability "
        "kernel S_V (apexes with a viable action) and the measure (the share of viable actions) of a "
        "map on a grid, iterated to the fixed point with Heim and Spröwitz's conservative "
        "discretisation. A step fails when the foot would start underground, the body falls (any "
        "status that is not OK) or the next apex speed is not positive.",
        epilog="exit status: 0 done; 2 a user error (one line on standard error); 130 interrupted.",
    )
    add_params(p)
    p.add_argument("--map", default="exact", help="the map (default %(default)s)")
    p.add_argument("--option", action="append", metavar="KEY=VALUE", help="an option of the map")
    p.add_argument("--vibly", action="store_true", help="Heim and Spröwitz's SLIP demo grid and parameters")
    g = p.add_argument_group("grids (MIN MAX N: N points from MIN to MAX)")
    g.add_argument("--energy", type=float, default=None, help="a fixed flight energy [J] (state: height)")
    g.add_argument("--heights", type=_grid_arg, nargs=3, metavar=("MIN", "MAX", "N"), help="apex heights [m]")
    g.add_argument("--s", type=_grid_arg, nargs=3, metavar=("MIN", "MAX", "N"), help="s = m g_f h / E")
    g.add_argument("--speeds", type=_grid_arg, nargs=3, metavar=("MIN", "MAX", "N"), help="apex speeds [m/s]")
    g.add_argument(
        "--angles-deg",
        type=_grid_arg,
        nargs=3,
        metavar=("MIN", "MAX", "N"),
        help="touchdown angles from the vertical [deg]",
    )
    g.add_argument("--k-d-grid", type=_grid_arg, nargs=3, metavar=("MIN", "MAX", "N"), help="k_d [N/m]")
    g.add_argument("--retraction-rates", type=_grid_arg, nargs=3, metavar=("MIN", "MAX", "N"), help="[rad/s]")
    g.add_argument("--ground", type=float, default=0.0, help="touchdown ground height [m] (default 0)")
    g.add_argument(
        "--outside",
        choices=("fail", "edge"),
        default="fail",
        help="a next state beyond the grid: not viable (fail, default) or judged by the edge node "
        "(edge, vibly)",
    )
    r = p.add_argument_group("on an unknown ground (a grid with --speeds and --k-d-grid)")
    r.add_argument(
        "--grounds",
        type=_grid_arg,
        nargs=3,
        metavar=("MIN", "MAX", "N"),
        help="touchdown ground heights [m], unknown at the apex: the kernels with k_d = k_c, k_d chosen "
        "at the apex and k_d chosen at the bottom (slipmaps.robust_viability)",
    )
    w = p.add_argument_group("on the sweep machinery (a grid with --speeds)")
    w.add_argument(
        "--sweep-out",
        default=None,
        metavar="DIR",
        help="compute the steps as a resumable sweep into DIR (slipmaps.viability_sweep)",
    )
    w.add_argument(
        "--scheduler",
        default=None,
        help="where the sweep's chunks run: inprocess (default), local:N (a local Dask cluster) or a "
        "dask scheduler address",
    )
    w.add_argument(
        "--next-state-float32",
        action="store_true",
        help="hold the next states as float32 (half the largest array; the same sets)",
    )
    p.add_argument("--figure", default="slipmaps_viability.png", help="the figure (default %(default)s)")
    p.add_argument("--no-figure", action="store_true", help="do not write the figure")
    p.add_argument("--out", default=None, metavar="PATH.npz", help="write every array (NumPy .npz)")
    p.add_argument("--json", action="store_true", help="print the summary and a row per state as JSON")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def _linspace(flag: str, triple) -> np.ndarray:
    lo, hi, n = triple
    if not (math.isfinite(lo) and math.isfinite(hi)) or n != int(n) or n < 1:
        raise ValueError(
            f"{flag} takes MIN MAX N with N a whole number >= 1, got {' '.join(map(str, triple))}"
        )
    if n > 1 and not hi > lo:
        raise ValueError(f"{flag}: MAX must exceed MIN, got {lo:g} {hi:g}")
    return np.linspace(lo, hi, int(n))


def _study(args: argparse.Namespace) -> tuple[str, object, dict]:
    """The map, the parameters and the keyword arguments of :func:`slipmaps.viability`."""
    from ..api.params import SlipParams
    from .args import map_options, params_of

    if args.vibly:
        from slipmaps.derive import params as table

        flags = ("energy", "heights", "s", "speeds", "angles_deg", "k_d_grid")
        flags += tuple(r["name"] for r in table.PARAMETERS) + tuple(table.ALIASES)
        given = [f for f in flags if getattr(args, f, None) is not None]
        if given:
            flag = "--" + given[0].replace("_", "-")
            raise ValueError(f"--vibly sets the parameters and the grids: give no {flag} with it")
        params = SlipParams(**VIBLY["params"])
        args.energy, args.s, args.angles_deg = VIBLY["energy"], VIBLY["s"], VIBLY["angles_deg"]
    else:
        params = params_of(args)
    kw: dict = {"ground": args.ground, "outside": args.outside}
    if args.speeds is not None and args.energy is not None:
        raise ValueError("give --energy (the state is the height) or --speeds (height and speed), not both")
    if args.s is not None and args.heights is not None:
        raise ValueError("give --heights or --s, not both")
    if args.speeds is not None:
        if args.s is not None:
            raise ValueError("--s needs --energy (s = m g_f h / E)")
        kw["apex_speed"] = _linspace("--speeds", args.speeds)
        heights = args.heights or (0.5 * params.l0, 2.0 * params.l0, 50)
        kw["apex_height"] = _linspace("--heights", heights)
    else:
        energy = args.energy
        if energy is None:
            energy = params.m * (params.g_f * params.l0 + 0.5 * 5.0**2)
        if not (math.isfinite(energy) and energy > 0):
            raise ValueError(f"--energy must be a positive number of joules, got {energy:g}")
        kw["energy"] = energy
        top = energy / (params.m * params.g_f)
        if args.s is not None:
            kw["apex_height"] = _linspace("--s", args.s) * top
        else:
            kw["apex_height"] = _linspace("--heights", args.heights or (0.3 * params.l0, 0.995 * top, 100))
    kw["touchdown_angle"] = np.radians(_linspace("--angles-deg", args.angles_deg or (0.0, 60.0, 121)))
    if args.k_d_grid is not None:
        kw["k_d"] = _linspace("--k-d-grid", args.k_d_grid)
    if args.retraction_rates is not None:
        kw["retraction_rate"] = _linspace("--retraction-rates", args.retraction_rates)
    return args.map, params, kw | map_options(args.map, args.option)


def _table(vs) -> str:
    s = vs.summary()
    lines = [
        f"map {vs.map}; states {' x '.join(f'{n} ({g.size})' for n, g in vs.states.items())}; actions "
        f"{' x '.join(f'{n} ({g.size})' for n, g in vs.actions.items())}"
        + (f"; energy {vs.energy:.6g} J" if vs.energy is not None else ""),
        f"pairs {s['pairs']:,}: failed {s['failed']:,} ({100 * s['failed'] / s['pairs']:.1f} %), viable "
        f"{s['viable_pairs']:,}; steps {vs.seconds['map']:.3g} s, kernel {vs.seconds['kernel']:.3g} s "
        f"({s['rounds']} rounds)",
        f"kernel: {s['kernel_states']} of {s['states']} states",
    ]
    for n, ext in s["kernel_extent"].items():
        lines.append(f"  {n}: " + ("empty" if ext is None else f"{ext[0]:.6g} ... {ext[1]:.6g}"))
    peak = ", ".join(f"{n} {v:.6g}" for n, v in s["measure_peak"].items())
    lines.append(f"measure: max {s['measure_max']:.4g} at {peak}")
    if vs.energy is not None and s["kernel_extent"]["apex_height"] is not None:
        c = vs.params.m * vs.params.g_f / vs.energy
        lo, hi = s["kernel_extent"]["apex_height"]
        lines.append(
            f"  in s = m g y / E: kernel {lo * c:.4g} ... {hi * c:.4g}, measure peak at "
            f"{s['measure_peak']['apex_height'] * c:.4g}"
        )
    return "\n".join(lines)


def _robust_table(rs) -> str:
    from ..analysis.viability_robust import POLICIES

    s = rs.summary()
    lines = [
        f"map {rs.map}; {s['states']} states (apex height x speed), {rs.touchdown_angle.size} angles, "
        f"k_d {', '.join(f'{k:.6g}' for k in rs.k_d)} N/m; ground unknown in "
        f"{', '.join(f'{g:.4g}' for g in rs.ground)} m; steps {rs.seconds['map']:.3g} s, kernels "
        f"{rs.seconds['kernel']:.3g} s",
        "share of viable touchdown angles per state: the mean over the kernel, the largest",
        f"{'policy':<10} {'kernel states':>13} {'mean':>7} {'largest':>8} {'rounds':>6}",
    ]
    for name in POLICIES:
        p = s[name]
        lines.append(
            f"{name:<10} {p['kernel_states']:>13} {p['angles_in_kernel']:>7.4f} {p['angles_max']:>8.4f}"
            f" {p['rounds']:>6}"
        )
    return "\n".join(lines)


def _robust(args, name, params, kw, figure, out, progress) -> int:
    """``--grounds``: :func:`slipmaps.robust_viability`, printed, drawn and written."""
    from ..analysis.viability_robust import robust_viability

    if "apex_speed" not in kw or "k_d" not in kw:
        raise ValueError("--grounds needs a (height, speed) grid and k_d: give --speeds and --k-d-grid")
    if args.sweep_out is not None or "retraction_rate" in kw:
        raise ValueError("--grounds takes no --sweep-out and no --retraction-rates")
    kw = dict(kw)
    kw.pop("ground")
    rs = robust_viability(name, params, ground=_linspace("--grounds", args.grounds), progress=progress, **kw)
    return _emit(rs, _robust_table, args.json, figure, out)


def _emit(study, table, as_json: bool, figure, out) -> int:
    """A study's figure and arrays written where asked, then its JSON or ``table(study)`` printed
    with the paths written."""
    from ..api.paths import writing

    written = []
    if figure:
        written.append(str(study.plot(figure)))
    if out is not None:
        with writing(out):
            np.savez_compressed(out, **study.arrays())
        written.append(str(out))
    if as_json:
        print(json.dumps(study.as_dict() | {"written": written}, indent=1))
    else:
        print(table(study))
        for path in written:
            print(f"wrote {path}")
    return 0


def run(args: argparse.Namespace) -> int:
    from ..analysis.viability import viability
    from ..api.paths import writable_file
    from .args import image_path

    figure = None if args.no_figure else image_path("--figure", args.figure, example="slipmaps_viability")
    out = None
    if args.out is not None:
        out = writable_file("--out", args.out, ("npz",), described="a NumPy archive", example="viability")
    name, params, kw = _study(args)
    progress = False if args.no_progress else None
    if args.scheduler is not None and args.sweep_out is None:
        raise ValueError("--scheduler runs the sweep of --sweep-out DIR: give --sweep-out too")
    if args.next_state_float32 and args.sweep_out is None:
        raise ValueError("--next-state-float32 is the sweep's (--sweep-out DIR): give --sweep-out too")
    if args.grounds is not None:
        return _robust(args, name, params, kw, figure, out, progress)
    if args.sweep_out is not None:
        if "energy" in kw:
            raise ValueError(
                "--sweep-out needs a (height, speed) grid: give --speeds, not --energy or --vibly"
            )
        from ..api.paths import writable_dir
        from ..sweep.viability import viability_sweep

        out_dir = writable_dir("--sweep-out", args.sweep_out)
        dtype = "float32" if args.next_state_float32 else "float64"
        vs = viability_sweep(
            name,
            params,
            out=out_dir,
            scheduler=args.scheduler,
            next_state_dtype=dtype,
            progress=progress,
            **kw,
        )
    else:
        vs = viability(name, params, progress=progress, **kw)
    return _emit(vs, _table, args.json, figure, out)
