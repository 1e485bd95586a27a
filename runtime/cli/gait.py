"""``slipmaps gait``: the periodic gaits (fixed points of the apex-return map) and their eigenvalues.

By default the human runner at apex height 1 m and apex speeds 3-7 m/s, the exact map and every
``--map``: for each speed the touchdown angles whose step returns to the same apex. With
``--energy`` (J) or ``--energy-speed`` (the speed at apex height l0 with that energy) and
``--angle``: the apex heights on the energy level that a fixed touchdown angle returns to
(Seyfarth et al.'s setting). ``--json`` prints the fixed points as JSON; ``--figure PATH`` also
draws the self-stable region (angle of attack against speed) of the maps listed (default: those
of docs/stability.png; the exact one takes about 25 minutes with the ``solve_ivp`` simulator); its
path is checked before any work; ``--no-figure`` draws none (as ``run``'s, it overrides ``--figure``).
Every number of the line searched is checked under its flag before any work.

The table labels its two stability numbers apart (:data:`~.gait.DEFINITIONS`): ``lambda 1-D``, the
eigenvalue of the one-dimensional apex-height map on the energy level, and ``multipliers 2x2``, the
eigenvalues of the 2x2 apex-return Jacobian, (1, lambda) only for a step that conserves the energy
(a note names each map whose points are not). A search whose every step fails prints its status
and message in the row (and in ``--json``), and the command exits 1. Registered in :mod:`.cli` by
:func:`add_parser`.
"""

from __future__ import annotations

import argparse
import json
import textwrap

__all__ = ["add_parser", "run"]

DEFAULT_HEIGHT = 1.0
DEFAULT_SPEEDS = (3.0, 4.0, 5.0, 6.0, 7.0)
#: A map's points get a note under the table when their energy_gradient_error exceeds this: their
#: multipliers are then visibly not (1, lambda) (the exact map's is below 1e-9).
ENERGY_NOTE = 1e-6


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``gait`` subcommand to the subparsers ``sub``."""
    from .args import add_params

    p = sub.add_parser(
        "gait",
        help="periodic gaits: fixed points of the apex-return map and their eigenvalues",
        description="Every fixed point of the apex-return map (a periodic one-step gait) with its "
        "eigenvalue on the energy level (self-stable when its magnitude is below 1) and the Floquet "
        "multipliers, by the exact map and every --map. Default: the human runner at apex height 1 m, "
        "apex speeds 3-7 m/s, the touchdown angle unknown. With --energy or --energy-speed and --angle: "
        "the apex heights unknown. Angles in rad from the vertical (angle of attack from the ground: 90 "
        "deg - angle). "
        "lambda (the eigenvalue) is of the one-dimensional apex-height return map on the energy level; "
        "the multipliers are the eigenvalues of the 2x2 apex-return Jacobian, (1, lambda) only for a "
        "step that conserves the flight energy.",
        epilog="exit status: 0 every search ran (found fixed points or not); 1 a search failed because "
        "the map's steps failed on the whole line (e.g. NOT_CONVERGED: its status and message are "
        "printed in the row, in --json as status and message); 2 a user error (one line on standard "
        "error).",
    )
    add_params(p)
    p.add_argument("--map", action="append", default=None, help="a map beside the exact one (repeatable)")
    p.add_argument("--no-exact", action="store_true", help="leave out the exact map")
    p.add_argument("--option", action="append", metavar="KEY=VALUE", help="an option of every --map")
    g = p.add_argument_group("the line searched")
    g.add_argument("--apex-height", type=float, default=None, help="apex height [m] (default 1.0)")
    g.add_argument(
        "--speed", type=float, nargs="+", default=None, help="apex speeds [m/s] (default 3 4 5 6 7)"
    )
    e = g.add_mutually_exclusive_group()
    e.add_argument("--energy", type=float, default=None, help="apex energy m (g_f h + v^2/2) [J]")
    e.add_argument(
        "--energy-speed", type=float, default=None, help="the energy of this speed [m/s] at apex height l0"
    )
    g.add_argument(
        "--angle", type=float, nargs="+", default=None, help="touchdown angles [rad] (with an energy)"
    )
    p.add_argument("--json", action="store_true", help="print the fixed points as JSON")
    p.add_argument("--figure", default=None, metavar="PATH", help="also draw the self-stable region to PATH")
    p.add_argument("--no-figure", action="store_true", help="draw no figure (overrides --figure)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def _checked(args) -> None:
    """The line's flags checked under their names (one line naming the flag, before any work)."""
    from ..api.validate import leg_angle, non_negative, positive, real

    for flag, check in (
        ("apex_height", non_negative),
        ("speed", real),
        ("energy", positive),
        ("energy_speed", real),
        ("angle", leg_angle),
    ):
        value = getattr(args, flag)
        for x in value if isinstance(value, list) else () if value is None else (value,):
            check(f"--{flag.replace('_', '-')}", x)


def _lines(args, params) -> list[dict]:
    """The keyword arguments of fixed_points for each line the arguments ask for."""
    from ..studies.stability import energy_at_rest_height

    _checked(args)
    energy = args.energy
    if args.energy_speed is not None:
        energy = energy_at_rest_height(params, args.energy_speed)
    if args.angle is not None:
        if energy is None:
            raise ValueError("--angle needs --energy or --energy-speed (the apex height is then the unknown)")
        if args.apex_height is not None or args.speed is not None:
            raise ValueError("--angle searches apex heights: give no --apex-height or --speed with it")
        return [{"energy": energy, "angle": a} for a in args.angle]
    speeds = args.speed or DEFAULT_SPEEDS
    if energy is not None:
        if args.apex_height is not None:
            raise ValueError("give --apex-height or an energy with --speed, not both")
        return [{"energy": energy, "speed": v} for v in speeds]
    h = DEFAULT_HEIGHT if args.apex_height is None else args.apex_height
    return [{"apex_height": h, "speed": v} for v in speeds]


def _label(line: dict) -> str:
    if "angle" in line:
        return f"E {line['energy']:.6g} J, angle {line['angle']:.6g} rad"
    if "apex_height" in line:
        return f"h {line['apex_height']:g} m, v {line['speed']:g} m/s"
    return f"E {line['energy']:.6g} J, v {line['speed']:g} m/s"


def _format(rows: list[tuple[dict, str, tuple]]) -> str:
    """The table, then what its two stability columns are (:data:`~.gait.DEFINITIONS`) and a note
    for each map whose multipliers are not (1, lambda) at its points."""
    from ..analysis.gait import DEFINITIONS

    head = (
        f"{'line':<30} {'map':<16} {'q_th_td [rad]':>14} {'alpha0 [deg]':>12} {'h [m]':>10} {'v [m/s]':>9} "
        f"{'lambda 1-D':>11} {'stable':>6}  {'multipliers 2x2':<24} status"
    )
    out = [head, "-" * len(head)]
    drift: dict[str, float] = {}
    for line, name, points in rows:
        if not points:
            text = "no fixed point" if points.ok else f"no fixed point: {points.message}"
            out.append(f"{_label(line):<30} {name:<16} {text}")
        for p in points:
            mult = ", ".join(f"{z.real:.6g}" + (f"{z.imag:+.3g}j" if z.imag else "") for z in p.multipliers)
            out.append(
                f"{_label(line):<30} {name:<16} {p.touchdown_angle:14.9f} {p.angle_of_attack:12.4f} "
                f"{p.apex_height:10.6f} {p.apex_speed:9.5f} {p.eigenvalue:11.6f} "
                f"{'yes' if p.stable else 'no':>6}  {mult:<24} {p.status.name}"
            )
            if p.ok and p.energy_gradient_error > ENERGY_NOTE:
                drift[name] = max(drift.get(name, 0.0), p.energy_gradient_error)
    width = len(head)
    out.append("")
    for key, label in (("eigenvalue", "lambda 1-D"), ("multipliers", "multipliers 2x2")):
        out.append(textwrap.fill(f"{label}: {DEFINITIONS[key]}", width, subsequent_indent="  "))
    for name, worst in drift.items():
        note = (
            f"note: {name}'s step does not conserve the flight energy (dE'/d(h, v) differs from dE/d(h, v) "
            f"by up to {worst:.2g} relative), so its multipliers are not (1, lambda)"
        )
        out.append(textwrap.fill(note, width, subsequent_indent="  "))
    return "\n".join(out)


def run(args: argparse.Namespace) -> int:
    from ..analysis.gait import DEFINITIONS, fixed_points
    from ..api.index import EXACT, get
    from ..api.params import HUMAN_RUNNER
    from ..studies.stability import region_maps, region_record
    from .args import image_path, map_options, params_of

    params = params_of(args)
    if args.no_figure:
        args.figure = None
    extra = [get(n).name for n in (args.map or [])]
    names = ([] if args.no_exact else [EXACT]) + [n for n in extra if n != EXACT]
    if not names:
        raise ValueError("no map left: --no-exact needs a --map")
    options = {n: map_options(n, args.option) if n in extra else {} for n in names}
    if args.figure and params != HUMAN_RUNNER:
        raise ValueError("--figure draws the human runner's region: give no parameter options with it")
    if args.figure:
        image_path("--figure", args.figure, example="stability")  # before any work
    lines = _lines(args, params)
    show = False if args.no_progress else None
    rows = [
        (line, n, fixed_points(n, params, progress=show, **line, **options[n]))
        for line in lines
        for n in names
    ]
    figure = None
    if args.figure:
        from ..studies.stability_report import figure as draw

        chosen = [n for n in region_maps() if n != EXACT or not args.no_exact] if args.map is None else names
        figure = str(draw({"region": region_record(chosen, show)}, args.figure))
    if args.json:
        data = {
            "params": params.as_dict(),
            "definitions": dict(DEFINITIONS),
            "lines": [{"given": line, "map": n, **pts.as_dict()} for line, n, pts in rows],
            "figure": figure,
        }
        print(json.dumps(data, indent=2))
    else:
        print(_format(rows))
        if figure:
            print(f"\nwrote {figure}")
    return 0 if all(pts.ok for _, _, pts in rows) else 1
