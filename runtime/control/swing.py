"""Swing-leg policies: the controls as functions of the time since the apex, computed from a map, so
that whatever the ground the foot meets in a range, the next apex is the target (deadbeat without
knowing the ground: Wu and Geyer 2013's time-based control, here from any map of the project).

From an apex (height ``apex_height`` [m] above the ground under it, signed ``apex_speed`` [m/s]) and
a target next apex (``target_height`` above the touchdown ground, ``target_speed``),
:func:`swing_policy` solves the deadbeat step (:class:`~.deadbeat.Deadbeat`, one batch) for ``n``
grounds evenly spaced in ``grounds = (low, high)`` [m] (relative to the ground under the apex, a
step up positive). Each ground's controls touch down at their own time: a leg held at angle
theta_i from the apex meets ground g_i at t_i = sqrt(2 (h - g_i - q_r_td cos theta_i) / g_f), and the
stance depends on the touchdown state alone (a massless leg), so a leg whose angle passes through
theta_i at t_i reaches the target on ground g_i whatever it did before. The policy is the table
(t_i, theta_i, k_c_i, k_d_i) in increasing time, interpolated by cubic Hermite polynomials with
three-point slopes (:mod:`.swing_tables`; an error of third order in the knot spacing, measured by
:meth:`SwingPolicy.representation_error`); before the first knot and after the last the end values
are held. k_c and k_d are read at the touchdown instant, like the angle.

Per ground (``status``, plan statuses of :class:`~.deadbeat.PlanStatus`): REACHED; UNREACHABLE (the
table holds the controls of the closest reachable next apex, ``next_apex_height``/``next_apex_speed``
say which); MAP_FAILED (the map fails at every control tried: no knot, e.g. a ground too high to reach
from this apex). A knot whose touchdown time is not later than that of a higher ground is left out
of the table (``used`` False): a leg's angle is one function of time, so the grounds must touch down
in order of height. With ``controls=("touchdown_angle",)`` the stiffness is the nominal
(``params.k_c``, ``params.k_d``) and the one target is the speed (``slipmaps.deadbeat``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..api.names import RUN_RENAMED, Renamed
from ..api.params import SlipParams
from ..api.validate import real
from . import compiled, swing_tables
from .deadbeat import PLAN_STATUS, Deadbeat, controller

__all__ = ["SwingPolicy", "PolicyTables", "swing_policy", "policy_tables", "DEFAULT_KNOTS"]

#: Grounds of a policy by default (knots of its table).
DEFAULT_KNOTS = 64
#: The controls a policy's table holds, in this order.
_TABLE = ("touchdown_angle", "k_c", "k_d")


@dataclass
class PolicyTables:
    """Policies of many apexes at once (rows), as the runs use them: per row and ground (rows x
    ``n``) the grounds ``grounds``, plan ``status`` codes, touchdown times ``t``, controls
    ``touchdown_angle``, ``k_c``, ``k_d`` and the model's next apex ``next_apex_height``,
    ``next_apex_speed``;
    ``used`` (the knot is in the table); the tables themselves: ``knots`` (rows x n, the used knots'
    indices into the grounds in increasing time, -1 padded), ``counts`` (rows), and per control the
    knot times ``T`` and values and slopes (``runtime/control/swing_tables.py``)."""

    grounds: np.ndarray
    status: np.ndarray
    map_status: np.ndarray
    t: np.ndarray
    touchdown_angle: np.ndarray
    k_c: np.ndarray
    k_d: np.ndarray
    next_apex_height: np.ndarray
    next_apex_speed: np.ndarray
    used: np.ndarray
    knots: np.ndarray
    counts: np.ndarray
    T: np.ndarray
    values: dict[str, np.ndarray]
    slopes: dict[str, np.ndarray]
    q_r_td: float
    g_f: float

    @property
    def rows(self) -> int:
        return self.grounds.shape[0]

    def touchdown(self, apex_height, ground) -> dict[str, np.ndarray]:
        """Per row, the touchdown of the policy's leg from the true ``apex_height`` onto the true
        ``ground`` (relative to the apex's; arrays of ``rows``, or of any length for tables of one
        row): ``t`` [s], the controls at that instant (``touchdown_angle``, ``k_c``, ``k_d``),
        ``where`` (``swing_tables.IN_RANGE``, ...) and ``status``, the plan code of the step:
        REACHED when both knots around the touchdown reached the target, UNREACHABLE when one did
        not, ``OUT_OF_RANGE`` (3) outside the table."""
        h, gr = np.broadcast_arrays(np.asarray(apex_height, dtype=float), np.asarray(ground, dtype=float))
        h, gr = np.ascontiguousarray(np.atleast_1d(h)), np.ascontiguousarray(np.atleast_1d(gr))
        n = h.shape[0]
        t, angle = np.empty(n), np.empty(n)
        where, knot = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
        A, MA = self.values["touchdown_angle"], self.slopes["touchdown_angle"]
        args = (self.T, A, MA, self.counts, t, angle, where, knot)
        swing_tables.touchdown_rows(h, gr, self.g_f, self.q_r_td, *args)
        out = {"t": t, "touchdown_angle": angle, "where": where}
        stiffness = self.controls_at(np.where(np.isfinite(t), t, 0.0))
        out["k_c"], out["k_d"] = stiffness["k_c"], stiffness["k_d"]
        out["status"] = self._step_status(where, knot)
        return out

    def controls_at(self, t) -> dict[str, np.ndarray]:
        """The controls at times ``t`` [s] after the apex: one time per row (or any number of times
        for tables of one row)."""
        x = np.ascontiguousarray(np.atleast_1d(np.asarray(t, dtype=float)))
        out = {}
        for name in _TABLE:
            out[name] = np.empty(x.shape[0])
            swing_tables.evaluate_rows(
                self.T, self.values[name], self.slopes[name], self.counts, x, out[name]
            )
        return out

    def _step_status(self, where, knot) -> np.ndarray:
        """The plan code of each touchdown from the knots around it (its table row, or the one row)."""
        out = np.full(where.shape[0], OUT_OF_RANGE, dtype=np.int64)
        i = np.flatnonzero(where == swing_tables.IN_RANGE)
        r = np.minimum(i, self.rows - 1)
        lo = self.knots[r, knot[i]]
        hi = self.knots[r, knot[i] + 1]
        both = (self.status[r, lo] == compiled.REACHED) & (self.status[r, hi] == compiled.REACHED)
        out[i] = np.where(both, compiled.REACHED, compiled.UNREACHABLE)
        return out


#: The plan code of a step whose touchdown lies outside its policy's table (the end values held).
OUT_OF_RANGE = 3


def _ground_grid(grounds, n: int) -> np.ndarray:
    try:
        low, high = grounds
    except (TypeError, ValueError):
        raise ValueError(f"grounds must be a pair (low, high) [m], got {grounds!r}") from None
    low, high = real("grounds low", low), real("grounds high", high)
    if not low < high:
        raise ValueError(f"grounds must have low < high, got ({low!r}, {high!r})")
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise ValueError(f"n must be an integer >= 2 (grounds of the table), got {n!r}")
    return np.linspace(high, low, n)  # the highest ground first: the earliest touchdown


def policy_tables(
    ctl: Deadbeat, apex_height, apex_speed, target_height, target_speed, grounds
) -> PolicyTables:
    """The policies of many apexes (arrays of one length, or scalars) over ``grounds`` (rows x n, or
    one row for all; each row from the highest ground to the lowest): one batch deadbeat on the
    controller ``ctl`` (module docstring)."""
    h = np.atleast_1d(np.asarray(apex_height, dtype=float))
    v = np.atleast_1d(np.asarray(apex_speed, dtype=float))
    H = None if target_height is None else np.atleast_1d(np.asarray(target_height, dtype=float))
    V = None if target_speed is None else np.atleast_1d(np.asarray(target_speed, dtype=float))
    sizes = [x.shape[0] for x in (h, v, H, V) if x is not None]
    G = np.atleast_2d(np.asarray(grounds, dtype=float))
    rows = max([*sizes, G.shape[0]])
    n = G.shape[1]
    G = np.broadcast_to(G, (rows, n))

    def col(x):
        return None if x is None else np.broadcast_to(x[:, None] if x.shape[0] > 1 else x, (rows, n))

    hh, vv = col(h), col(v)
    b = ctl.plan_batch(hh, vv, col(H), col(V), ground=G)
    p = ctl.params
    status = np.asarray(b["status"])
    theta = np.asarray(b["touchdown_angle"])
    drop = hh - G - p.q_r_td * np.cos(theta)
    ok = (status != compiled.MAP_FAILED) & (drop > 0.0)
    t = np.where(ok, np.sqrt(np.where(ok, 2.0 * drop / p.g_f, 0.0)), math.nan)
    # grounds from the highest: a knot is used when its touchdown is later than every earlier one's
    # (a dropped knot's time is below that maximum, so the maximum over the usable knots is the
    # maximum over the used ones)
    earlier = np.maximum.accumulate(np.where(ok, t, -math.inf), axis=1)
    earlier = np.concatenate([np.full((rows, 1), -math.inf), earlier[:, :-1]], axis=1)
    used = ok & (t > earlier)
    counts = used.sum(axis=1)
    order = np.argsort(~used, axis=1, kind="stable")  # the used knots first, in ground order
    knots = np.where(np.arange(n)[None, :] < counts[:, None], order, -1)
    take = np.where(knots >= 0, knots, 0)
    front = np.arange(n)[None, :] < counts[:, None]
    T = np.where(front, np.take_along_axis(t, take, axis=1), math.nan)
    source = {"touchdown_angle": theta, "k_c": np.asarray(b["k_c"]), "k_d": np.asarray(b["k_d"])}
    values = {c: np.where(front, np.take_along_axis(source[c], take, axis=1), math.nan) for c in _TABLE}
    slopes = {}
    for c in _TABLE:
        slopes[c] = swing_tables.empty_slopes(T)
        swing_tables.slopes_rows(T, values[c], counts, slopes[c])
    out = PolicyTables(
        grounds=np.array(G),
        status=status,
        map_status=np.asarray(b["map_status"]),
        t=t,
        touchdown_angle=theta,
        k_c=source["k_c"],
        k_d=source["k_d"],
        next_apex_height=np.asarray(b["next_apex_height"]),
        next_apex_speed=np.asarray(b["next_apex_speed"]),
        used=used,
        knots=knots,
        counts=counts,
        T=T,
        values=values,
        slopes=slopes,
        q_r_td=p.q_r_td,
        g_f=p.g_f,
    )
    return out


class SwingPolicy:
    """One apex's swing-leg policy (module docstring). Per ground of the table (arrays of ``n``):
    ``grounds``, ``status`` (plan statuses by name), ``t_touchdown``, ``touchdown_angle``, ``k_c``,
    ``k_d``, ``next_apex_height``, ``next_apex_speed`` (the model's next apex; the former names
    ``next_height``, ``next_speed`` still read, with a DeprecationWarning), ``used``.
    ``controls_at(t)``: the controls at times after the apex; ``touchdown(ground)``: where a ground
    is met and with what; ``representation_error()``: what the interpolation adds;
    ``to_pandas()``, ``as_dict()``, ``plot(path)``."""

    def __init__(self, ctl: Deadbeat, tables: PolicyTables, apex, target):
        self._ctl, self._tables = ctl, tables
        self.model = ctl.name
        self.controls = ctl.controls
        self.params: SlipParams = ctl.params
        self.apex_height, self.apex_speed = apex
        self.target_height, self.target_speed = target

    # per ground
    @property
    def grounds(self) -> np.ndarray:
        return self._tables.grounds[0]

    @property
    def codes(self) -> np.ndarray:
        return self._tables.status[0]

    @property
    def status(self) -> np.ndarray:
        return np.array([PLAN_STATUS[int(c)].value for c in self.codes], dtype=object)

    @property
    def used(self) -> np.ndarray:
        return self._tables.used[0]

    @property
    def t_touchdown(self) -> np.ndarray:
        return self._tables.t[0]

    @property
    def touchdown_angle(self) -> np.ndarray:
        return self._tables.touchdown_angle[0]

    @property
    def k_c(self) -> np.ndarray:
        return self._tables.k_c[0]

    @property
    def k_d(self) -> np.ndarray:
        return self._tables.k_d[0]

    @property
    def next_apex_height(self) -> np.ndarray:
        return self._tables.next_apex_height[0]

    @property
    def next_apex_speed(self) -> np.ndarray:
        return self._tables.next_apex_speed[0]

    next_height = Renamed(RUN_RENAMED["next_height"], "a swing policy")
    next_speed = Renamed(RUN_RENAMED["next_speed"], "a swing policy")

    @property
    def reached(self) -> np.ndarray:
        return self.codes == compiled.REACHED

    # the policy
    def controls_at(self, t) -> dict[str, np.ndarray]:
        """The controls at times ``t`` [s] after the apex (an array): the table interpolated (module
        docstring)."""
        shape = np.shape(t)
        return {k: v.reshape(shape) for k, v in self._tables.controls_at(np.ravel(t)).items()}

    def touchdown(self, ground, apex_height=None) -> dict[str, np.ndarray]:
        """Where the policy's leg meets ``ground`` (an array, relative to the apex's ground) from
        ``apex_height`` (default the policy's): ``t`` [s], the controls at that instant,
        ``status`` (plan codes; ``OUT_OF_RANGE`` (3) outside the table)."""
        h = self.apex_height if apex_height is None else apex_height
        shape = np.broadcast_shapes(np.shape(ground), np.shape(h))
        hh, gg = (np.ravel(np.broadcast_to(x, shape)) for x in (h, ground))
        return {k: v.reshape(shape) for k, v in self._tables.touchdown(hh, gg).items()}

    def representation_error(self, per_interval: int = 4, plant: str | None = None) -> dict[str, float]:
        """What the table's interpolation adds to the next apex's error: on ``per_interval`` grounds
        inside each interval between two used knots that both reached the target, the touchdown of
        the interpolated policy and the next apex of the model (``plant``: another map) at its
        controls, against the target: the largest height error [m] and speed error [m/s], and the
        grounds measured (``samples``)."""
        from .plant import Plant

        g = self.grounds
        knots = np.flatnonzero(self.used)
        good = [
            (g[a], g[b])
            for a, b in zip(knots[:-1], knots[1:], strict=True)
            if self.reached[a] and self.reached[b]
        ]
        if not good:
            return {"height": math.nan, "speed": math.nan, "samples": 0}
        frac = (np.arange(per_interval) + 1.0) / (per_interval + 1.0)
        grounds = np.concatenate([hi + (lo - hi) * frac for hi, lo in good])
        td = self.touchdown(grounds)
        p = self.params
        if "k" in self._ctl.wrt:
            p = p.with_(k=p.k_c)
        sim = Plant(plant or self.model, p, **({} if plant else dict(self._ctl.options)))
        steps = sim.step(
            self.apex_height, self.apex_speed, td["touchdown_angle"], grounds, td["k_c"], td["k_d"]
        )
        dh = (
            np.abs(steps.next_apex_height - self.target_height)
            if self.target_height is not None
            else np.zeros(1)
        )
        dv = (
            np.abs(steps.next_apex_speed - self.target_speed)
            if self.target_speed is not None
            else np.zeros(1)
        )
        if "touchdown_angle" in self.controls and len(self.controls) == 1:
            dh = np.zeros(1)  # one control: the speed is the target (the height follows)
        return {"height": float(np.max(dh)), "speed": float(np.max(dv)), "samples": int(grounds.size)}

    def columns(self) -> dict[str, np.ndarray]:
        return {
            "ground": self.grounds,
            "status": self.status,
            "used": self.used,
            "t_touchdown": self.t_touchdown,
            "touchdown_angle": self.touchdown_angle,
            "k_c": self.k_c,
            "k_d": self.k_d,
            "next_apex_height": self.next_apex_height,
            "next_apex_speed": self.next_apex_speed,
        }

    def to_pandas(self):
        """A pandas DataFrame, a row per ground of the table."""
        from ..api.frames import to_pandas

        return to_pandas(self.columns())

    def as_dict(self) -> dict:
        """JSON-ready (None for NaN)."""

        def f(x):
            return [float(v) if isinstance(v, float | np.floating) and math.isfinite(v) else None for v in x]

        cols = self.columns()
        out = {k: f(v) for k, v in cols.items() if k not in ("status", "used")}
        out["status"] = [str(s) for s in cols["status"]]
        out["used"] = [bool(u) for u in cols["used"]]
        return {
            "model": self.model,
            "controls": list(self.controls),
            "apex_height": self.apex_height,
            "apex_speed": self.apex_speed,
            "target_height": self.target_height,
            "target_speed": self.target_speed,
        } | out

    def plot(self, path):
        """A figure of the policy (the controls against the time since the apex, the knots marked by
        status) written to ``path``; returns the path."""
        from .figures import policy_figure

        return policy_figure(self, path)

    def __repr__(self) -> str:
        counts = dict(zip(*np.unique(self.status, return_counts=True), strict=True))
        return (
            f"SwingPolicy(model={self.model!r}, controls={self.controls}, grounds={self.grounds[-1]:.4g}.."
            f"{self.grounds[0]:.4g} m, knots={int(self.used.sum())}, status={counts})"
        )


def swing_policy(
    model: str,
    params: SlipParams,
    apex_height,
    apex_speed,
    target_height,
    target_speed,
    *,
    grounds=(-0.1, 0.1),
    controls=("touchdown_angle",),
    n: int = DEFAULT_KNOTS,
    bounds=None,
    **map_options,
) -> SwingPolicy:
    """The swing-leg policy of one apex (module docstring): the controls ``controls``
    (``("touchdown_angle",)``, or ``("touchdown_angle", "k_c", "k_d")``, any set ``slipmaps.deadbeat``
    takes) as functions of the time since the apex, from ``n`` deadbeat solves of map ``model`` over
    the grounds ``grounds = (low, high)`` [m] relative to the ground under the apex; ``bounds`` and
    ``map_options`` as ``slipmaps.deadbeat`` takes them."""
    ctl = controller(model, params, controls, bounds, {"budget": False, **map_options})
    h = real("apex_height", apex_height)
    v = real("apex_speed", apex_speed)
    H = None if target_height is None else real("target_height", target_height)
    V = None if target_speed is None else real("target_speed", target_speed)
    G = _ground_grid(grounds, n)
    tables = policy_tables(ctl, h, v, H, V, G[None, :])
    return SwingPolicy(ctl, tables, (h, v), (H, V))
