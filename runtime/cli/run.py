"""``slipmaps run``: a multi-step run of a scenario (a TOML file: ``examples/*.toml``), or the control
evaluation.

``slipmaps run SCENARIO.toml`` runs the scenario (the controller plans each step with its model map,
the plant steps: :func:`slipmaps.run`), prints a row per step (apex, target, controls, plan status,
next apex and its error against the target, plant status, step length, the controller's time) and
writes a figure (the body path over the terrain, the leg at each touchdown and liftoff, the
targets; ``--figure PATH``, default ``slipmaps_run.png``, ``--no-figure``) and with ``--gif PATH``
an animation (matplotlib's Pillow writer). ``--model``, ``--plant``, ``--steps``, ``--known``,
``--two-stage``, ``--option`` / ``--plant-option`` override the file. ``--json`` prints the run's
records as JSON.

``slipmaps run --evaluate`` writes the control evaluation (docs/control.md, .json and figures: every
map as the controller's model on the exact plant; :mod:`slipmaps.runtime.control.evaluation`) into
the checkout's docs/ or ``--out DIR``; ``--quick`` the small version the tests re-run.

Every path written is checked before any work (a probe file created and removed; one line naming the
flag, exit 2), and so is the run's memory (``--steps`` beyond the machine's memory is refused with
the estimate). Ctrl-C prints the steps already run, then one line, exit 130. Exit status: 0 the run
completed (or the evaluation was written), 1 the plant fell (a step failed: its status in the last
row), 2 a user error, 130 interrupted.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from ..control.policies import POLICIES

__all__ = ["add_parser", "run"]


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``run`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "run",
        help="a multi-step run of a scenario (deadbeat control on a model map, the exact plant)",
        description="Run a scenario (a TOML file, as in examples/): every step the controller measures "
        "the apex, "
        "plans the touchdown angle and the leg stiffness with its model map (deadbeat: the next apex on "
        "the target) and the plant (the exact simulator by default) steps. Prints a row per step and "
        "writes a figure (and --gif an animation). --evaluate writes the control evaluation "
        "(docs/control.md) instead.",
        epilog="exit status: 0 the run completed (or the evaluation was written); 1 the plant fell (a step "
        "failed: its status in the last row); 2 a user error (one line on standard error).",
    )
    p.add_argument("scenario", nargs="?", default=None, help="a scenario TOML file (one of examples/)")
    p.add_argument("--model", default=None, help="the controller's model map (overrides the file)")
    p.add_argument("--plant", default=None, help="the plant map (overrides the file; default exact)")
    p.add_argument("--steps", type=int, default=None, help="number of steps (overrides the file)")
    p.add_argument(
        "--known", type=int, default=None, help="touchdown grounds known ahead (0: unknown, flat assumed)"
    )
    p.add_argument("--two-stage", action="store_true", help="choose k_d again at the bottom")
    p.add_argument(
        "--policy",
        default=None,
        choices=tuple(POLICIES),
        help="the controller (overrides the file): "
        + "; ".join(f"{name}: {what}" for name, what in POLICIES.items()),
    )
    p.add_argument(
        "--retraction-rate",
        type=float,
        default=None,
        metavar="RAD_PER_S",
        help="the swing leg's rate after the apex (policy retraction; negative: retracting; within "
        "+-sqrt(g_f/q_r_td), 3.13 rad/s for a 1 m leg)",
    )
    p.add_argument("--option", action="append", metavar="KEY=VALUE", help="an option of the model map")
    p.add_argument("--plant-option", action="append", metavar="KEY=VALUE", help="an option of the plant")
    p.add_argument(
        "--figure",
        default="slipmaps_run.png",
        help="image path of the run's figure (default %(default)s; a missing directory is created)",
    )
    p.add_argument("--no-figure", action="store_true", help="do not write the figure")
    p.add_argument("--gif", default=None, metavar="PATH", help="also write an animation (a .gif)")
    p.add_argument("--json", action="store_true", help="print the run's records as JSON")
    e = p.add_argument_group("evaluation")
    e.add_argument("--evaluate", action="store_true", help="write the control evaluation instead of a run")
    e.add_argument(
        "--out",
        default=None,
        metavar="DIR",
        help="the evaluation's directory (default: the checkout's docs/)",
    )
    e.add_argument("--quick", action="store_true", help="the small evaluation the tests re-run")
    e.add_argument(
        "--blind",
        action="store_true",
        help="re-measure only the blind-running part (swing-leg policies on unknown ground) into the "
        "committed control.json and re-render control.md",
    )
    e.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def _evaluate(args: argparse.Namespace) -> int:
    from ..api.paths import writable_dir
    from ..studies.checkout import checkout_root, docs_dir

    if args.scenario is not None:
        raise ValueError("--evaluate runs its own scenarios: give no scenario file with it")
    root = checkout_root()
    if root is None or not (root / "examples").is_dir():
        raise ValueError(
            "--evaluate runs the scenarios of a source checkout's examples/: run it from a checkout"
        )
    if args.out is not None:
        out = writable_dir("--out", args.out)
    else:
        out = docs_dir()
        if out is None:
            raise ValueError(
                "slipmaps does not run from a source checkout, so there is no docs/ to update: give --out DIR"
            )
    from ..control.report import write

    parts = ("blind",) if args.blind else None
    progress = False if args.no_progress else None
    for path in write(out, root / "examples", quick=args.quick, progress=progress, parts=parts):
        print(f"wrote {path}")
    return 0


def _overrides(args: argparse.Namespace, sc) -> dict:
    from .args import map_options

    out = {}
    if args.model is not None:
        out["model"] = args.model
    if args.plant is not None:
        out["plant"] = args.plant
    if args.steps is not None:
        if args.steps < 1:
            raise ValueError(f"--steps must be at least 1, got {args.steps}")
        from ..control.runs import check_memory

        try:
            check_memory(1, args.steps)  # before the scenario's profiles grow to --steps
        except ValueError as exc:
            raise ValueError(f"--steps {args.steps}: {exc}") from None
        out["steps"] = args.steps
    if args.known is not None:
        if args.known < 0:
            raise ValueError(f"--known must not be negative, got {args.known}")
        out["known"] = args.known
    if args.two_stage:
        out["two_stage"] = True
    if args.policy is not None:
        out["policy"] = args.policy
    if args.retraction_rate is not None:
        from ..api.validate import within_limit

        # the maps' range for the scenario's parameters (derive/params.py's row), named by the flag
        rate = args.retraction_rate
        out["retraction_rate"] = within_limit("--retraction-rate", "retraction_rate", rate, sc.params)
        out.setdefault("policy", "retraction" if sc.fixed_angle is None else sc.policy)
    if args.option:
        out["model_options"] = map_options(out.get("model", sc.model), args.option)
    if args.plant_option:
        out["plant_options"] = map_options(out.get("plant", sc.plant), args.plant_option)
    return out


#: Frames per second of a robot's animation (``--gif`` with ``plant = "mujoco"``).
GIF_FPS = 20.0


def _animation(result, path) -> Path:
    """The run's animation: the robot rendered by MuJoCo (a drawing without GL) from its logged
    trajectory on the robot plant, else the SLIP's path drawn by matplotlib."""
    plant = result.batch.plant
    if hasattr(plant, "hoppers"):  # the robot plant
        from ..robot.render import frames, write_gif

        images, _ = frames(plant.hoppers[result.index], width=480, height=360)
        return write_gif(images, path, plant.settings.log_rate)
    from ..control.figures import animate

    return animate(result, path)


def run(args: argparse.Namespace) -> int:
    from ..api.paths import writable_file
    from .args import image_path

    if args.evaluate:
        return _evaluate(args)
    given = [f for f, on in (("--out", args.out), ("--quick", args.quick), ("--blind", args.blind)) if on]
    if given:
        raise ValueError(f"{', '.join(given)}: options of --evaluate (a run writes --figure, --gif, --json)")
    if args.scenario is None:
        raise ValueError("give a scenario file (e.g. examples/speed_up.toml), or --evaluate")
    figure = None if args.no_figure else image_path("--figure", args.figure, example="slipmaps_run")
    gif = None
    if args.gif is not None:
        gif = str(writable_file("--gif", args.gif, ("gif",), described="an animation", example="run"))
    from ..control.runs import scenario_of

    sc = scenario_of(Path(args.scenario), {})
    overrides = _overrides(args, sc)
    if "steps" in overrides:
        from ..control.scenarios import resized

        sc = resized(sc, overrides.pop("steps"))
    sc = sc.with_(**overrides)
    from ..control.plant import ROBOT
    from ..control.runs import check
    from ..control.runs import run as run_scenario

    if gif and sc.plant == ROBOT and not sc.plant_options.get("log_rate"):
        sc = sc.with_(plant_options={**sc.plant_options, "log_rate": GIF_FPS})  # the robot logs its frames
    check(sc)  # the maps and their options, before any work
    if sys.stderr.isatty():  # the first steps wait for the kernels: say so rather than sit silent
        print(
            f"slipmaps run: {sc.name}: {sc.steps} steps; the maps' kernels load first (numba compiles them "
            "on a first run, about a minute, and caches them)",
            file=sys.stderr,
        )

    from ..control.runs import RunInterrupted

    try:
        result = run_scenario(sc)
    except RunInterrupted as stop:
        partial = stop.batch.run(0)
        if len(partial):
            print(partial.table())
        print(f"slipmaps run: interrupted after {len(partial)} step(s); nothing written", file=sys.stderr)
        return 130
    written = []
    if figure:
        from ..control.figures import run_figure

        written.append(str(run_figure(result, figure)))
    if gif:
        written.append(str(_animation(result, gif)))
    if args.json:
        data = result.as_dict()
        data["written"] = written
        print(json.dumps(data, indent=2))
    else:
        print(result.table())
        for path in written:
            print(f"wrote {path}")
    return 1 if result.fell else 0
