"""The scenario file's keys, documented: every key the loader accepts (:data:`.scenarios.KEYS`)
with its type, default, unit and meaning, rendered as the site's scenario reference
(docs/scenarios.md, between its ``scenario-keys`` markers; a test keeps the page, this table and
the loader's keys equal, and the defaults equal to what :func:`.scenarios.from_dict` gives).

Each entry: ``(table, key) -> (type, default, unit, meaning, field)``; ``field`` names the
:class:`~.scenarios.Scenario` field whose default is the entry's (None where the key has no field
of its own: a table, or a terrain key that shapes ``ground``).
"""

from __future__ import annotations

__all__ = ["KEY_DOCS", "reference_markdown"]

_NUM_PROFILE = "number, list or ramp"

#: (table, key) -> (type, default as written in TOML, unit, meaning, Scenario field or None).
KEY_DOCS: dict[tuple[str, str], tuple[str, str, str, str, str | None]] = {
    ("", "name"): ("string", "the file's name", "", "the run's name (titles, tables)", None),
    ("", "description"): ("string", '""', "", "free text", "description"),
    ("", "steps"): ("integer >= 1", "10", "", "steps (apex to apex) to run", "steps"),
    ("", "model"): (
        "map name",
        '"iterative"',
        "",
        "the controller's model: any map of `slipmaps maps`",
        "model",
    ),
    ("", "plant"): (
        'map name, "mujoco" or table',
        '"exact"',
        "",
        "the plant the run happens on: any map, or `mujoco` (the MuJoCo robot: docs/robot.md); as a "
        "table `[plant]`, its `kind` (the name) and its options (instead of `[plant_options]`)",
        "plant",
    ),
    ("", "start"): ("table", "", "", "the first apex: `height`, `speed`", None),
    ("", "targets"): ("table", "", "", "the target of each step's next apex: `height`, `speed`", None),
    ("", "terrain"): ("table", "", "", "the ground of each touchdown: `kind` and its keys, `known`", None),
    ("", "control"): ("table", "", "", "the controller: controls, bounds, two-stage steps, ...", None),
    ("", "params"): (
        "table",
        "the human runner",
        "SI",
        "the controller's SLIP parameters (SlipParams fields; the human runner's where not given, the "
        "leg lengths following l0)",
        None,
    ),
    ("", "mismatch"): ("table", "", "", "how the plant differs from the model: `mass`, `stiffness`", None),
    ("", "noise"): ("table", "", "", "apex measurement noise: `height`, `speed`, `seed`", None),
    ("", "model_options"): (
        "table",
        "{}",
        "",
        "the model map's options (`slipmaps maps NAME`)",
        "model_options",
    ),
    ("", "plant_options"): (
        "table",
        "{}",
        "",
        "the plant map's options, or the robot's parameters and terrain (docs/robot.md)",
        "plant_options",
    ),
    ("start", "height"): ("number >= 0", "1.0", "m", "apex height above the ground under it", "start_height"),
    ("start", "speed"): (
        "number",
        "5.0",
        "m/s",
        "horizontal apex speed, signed (negative: toward -x)",
        "start_speed",
    ),
    ("targets", "height"): (
        _NUM_PROFILE,
        "start height",
        "m",
        "next apex height above that step's touchdown ground; a list per step (the last value held) or a "
        "ramp `{from, to, steps, start}`",
        None,
    ),
    ("targets", "speed"): (_NUM_PROFILE, "start speed", "m/s", "next apex speed, signed; as `height`", None),
    ("terrain", "kind"): ("flat, steps, stairs, random, stones", '"flat"', "", "the terrain's shape", None),
    ("terrain", "heights"): (
        _NUM_PROFILE,
        "",
        "m",
        "kind steps: the ground of each touchdown (absolute)",
        None,
    ),
    ("terrain", "rise"): (
        "number",
        "0.1 (stones: 0.0)",
        "m",
        "kind stairs: height of a stair; kind stones (drawn): each stone's height change, uniform in +-rise",
        None,
    ),
    ("terrain", "before"): ("integer", "2", "", "kind stairs: flat steps before the stairs", None),
    ("terrain", "up"): ("integer", "4", "", "kind stairs: stairs up", None),
    ("terrain", "flat"): ("integer", "2", "", "kind stairs: flat steps on top", None),
    ("terrain", "down"): ("integer", "up", "", "kind stairs: stairs down", None),
    ("terrain", "amplitude"): (
        "number >= 0",
        "0.1",
        "m",
        "kind random: each step's ground change, uniform in +-amplitude",
        None,
    ),
    ("terrain", "seed"): ("integer", "0", "", "kind random, stones (drawn): the ground's seed", None),
    ("terrain", "known"): (
        "integer >= 0",
        "3",
        "steps",
        "touchdown grounds the controller knows ahead (0: unknown, it assumes flat ground)",
        "known",
    ),
    ("terrain", "stones"): (
        "list of [x_a, x_b, height]",
        "drawn",
        "m",
        "kind stones: the stones, each an interval [x_a, x_b] of x at a height (absolute: the start "
        "apex at x = 0 over the ground 0), in order along x, not overlapping (docs/footholds.md); "
        "without it the course is drawn from `count`, `width`, `gap`, `rise`, `seed`",
        None,
    ),
    ("terrain", "count"): ("integer >= 1", "60", "", "kind stones (drawn): the stones", None),
    ("terrain", "width"): (
        "pair [low, high]",
        "[0.3, 0.6]",
        "m",
        "kind stones (drawn): each stone's width, uniform in [low, high]",
        None,
    ),
    ("terrain", "gap"): (
        "pair [low, high]",
        "[0.2, 0.8]",
        "m",
        "kind stones (drawn): each gap between stones, uniform in [low, high]",
        None,
    ),
    ("terrain", "margin"): (
        "number >= 0",
        "0.0",
        "m",
        "kind stones: a foot lands at least this far inside a stone's ends, else it misses (the run "
        "falls there: MISSED)",
        None,
    ),
    ("terrain", "lookahead"): (
        "integer >= 1",
        "10",
        "stones",
        "kind stones: the stones the controller sees ahead",
        "lookahead",
    ),
    ("control", "controls"): (
        "list of names",
        "angle and k_d",
        "",
        "touchdown_angle, k_c, k_d, k; default the angle and k_d (the angle alone for a "
        "constant-stiffness model)",
        "controls",
    ),
    ("control", "bounds"): ("table of [low, high]", "{}", "rad, N/m", "bounds per control", "bounds"),
    ("control", "two_stage"): (
        "boolean",
        "false",
        "",
        "choose k_d again at the measured bottom",
        "two_stage",
    ),
    ("control", "decompression"): (
        "half-map name",
        '"iterative-decompression"',
        "",
        "the model of the decompression a two-stage step plans with",
        "decompression",
    ),
    ("control", "aim"): (
        "both, height, speed",
        '"both"',
        "",
        "which components of the target to reach",
        "aim",
    ),
    ("control", "min_height"): (
        "number > 0",
        "l0",
        "m",
        "the planner's floor of a target apex above the next ground",
        "min_height",
    ),
    ("control", "fixed_angle"): (
        "number, abs < pi/2",
        "none",
        "rad",
        "no controller: this touchdown angle and the nominal stiffness every step",
        "fixed_angle",
    ),
    ("control", "jacobian"): (
        "broyden, newton",
        '"broyden"',
        "",
        "the deadbeat solve's Jacobian updates",
        "jacobian",
    ),
    ("control", "tol"): ("number > 0", "1e-9", "scaled", "the deadbeat solve's tolerance", "tol"),
    ("control", "policy"): (
        "apex, retraction, time-based, raibert, footholds",
        '"apex"',
        "",
        "the swing leg: the angle set at the apex and held; set at the apex and retracting at "
        "`retraction_rate`; or a time-based policy over `grounds` (the controls as functions of the "
        "time since the apex); or Raibert's controller (foot placement and thrust, no map); or "
        "footholds, the stones course's planner (`horizon` hops ahead, docs/footholds.md)",
        "policy",
    ),
    ("control", "retraction_rate"): (
        "number, abs <= sqrt(g_f/q_r_td)",
        "0.0",
        "rad/s",
        "policy retraction (or with fixed_angle): the leg angle after the apex is the angle set plus "
        "this rate times the time (counterclockwise positive)",
        "retraction_rate",
    ),
    ("control", "grounds"): (
        "pair [low, high]",
        "[-0.3 l0, 0.3 l0]",
        "m",
        "policy time-based: the grounds the policy reaches the target on, around the expected one",
        "grounds",
    ),
    ("control", "knots"): (
        "integer >= 2",
        "64",
        "",
        "policy time-based: the grounds of the policy's table",
        "knots",
    ),
    ("control", "raibert"): (
        "table",
        "the tuned gains",
        "s, -, -",
        "policy raibert: its gains `k_v` (foot placement per speed error), `k_h`, `k_i` (height loop)",
        None,
    ),
    ("control", "correction"): (
        "integer >= 0",
        "0",
        "steps",
        "the last steps whose mean prediction residual (next apex minus the model's) shifts the "
        "deadbeat target (0: none)",
        "correction",
    ),
    ("control", "correction_gate"): (
        "number > 0",
        "0.01",
        "m",
        "a step whose ground changed by more than this is left out of the correction",
        "correction_gate",
    ),
    ("control", "model_loss"): (
        "number in [0, 1)",
        "0.0",
        "fraction",
        "the model's loss: the fraction of the apex speed lost per step (`slipmaps.identify` fits it)",
        "model_loss",
    ),
    ("control", "horizon"): (
        "integer >= 0",
        "2",
        "hops",
        "policy footholds: the hops planned ahead at each apex (0: the deadbeat step aimed at the centre "
        "of the stone nearest the neutral foothold, the baseline)",
        "horizon",
    ),
    ("mismatch", "mass"): (
        "number > -1",
        "0.0",
        "fraction",
        "the plant's mass is (1 + mass) times the model's",
        "mismatch_mass",
    ),
    ("mismatch", "stiffness"): (
        "number > -1",
        "0.0",
        "fraction",
        "the plant's springs are (1 + stiffness) times what is commanded",
        "mismatch_stiffness",
    ),
    ("noise", "height"): (
        "number >= 0",
        "0.0",
        "m",
        "standard deviation of the apex height measurement",
        "noise_height",
    ),
    ("noise", "speed"): (
        "number >= 0",
        "0.0",
        "m/s",
        "standard deviation of the apex speed measurement",
        "noise_speed",
    ),
    ("noise", "seed"): (
        "integer",
        "0",
        "",
        "the noise's seed (run i of a batch draws from the pair (seed, i))",
        "seed",
    ),
}


def _params_rows() -> list[tuple[str, str, str, str, str]]:
    from ..api.params import FIELDS, HUMAN_RUNNER, PARAMETERS

    docs = {p["name"]: p for p in PARAMETERS}
    rows = []
    for f in FIELDS:
        rest = docs[f]["default"]  # "l0" for a leg length: it follows the rest length
        kinds = {"leg_length": f"number in (0, {rest}]", "non_negative": "number >= 0"}
        kind = kinds.get(docs[f]["domain"], "number > 0")
        default = rest if isinstance(rest, str) else repr(getattr(HUMAN_RUNNER, f))
        rows.append((f"`{f}`", kind, default, docs[f]["unit"], docs[f]["doc"]))
    rows.append(("`k`", "number > 0", "", "N/m", "both stiffnesses, k_c = k_d = k"))
    return rows


def reference_markdown() -> str:
    """The reference as Markdown: a table per TOML table, its keys in this table's order (the
    loader's: a test keeps them equal), then ``[params]``, SlipParams' fields. (This module does not
    import the loader, which reads :data:`KEY_DOCS`.)"""
    tables: dict[str, list[str]] = {}
    for table, key in KEY_DOCS:
        tables.setdefault(table, []).append(key)
    out = []
    for table, keys in [*tables.items(), ("params", [])]:
        out.append(f"### {'Top level' if not table else f'[{table}]'}")
        out.append("")
        out.append("| key | type | default | unit | meaning |")
        out.append("|---|---|---|---|---|")
        if table == "params":
            rows = _params_rows()
        else:
            rows = [(f"`{k}`", *KEY_DOCS[table, k][:4]) for k in keys]
        out.extend("| " + " | ".join(r) + " |" for r in rows)
        out.append("")
    return "\n".join(out).rstrip() + "\n"
