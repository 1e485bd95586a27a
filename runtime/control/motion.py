"""The continuous path of a run: the body through every flight and stance, the foot of every stance,
the terrain, for the figures and the animation.

From a run's records (:class:`~.runs.Run`): apex n at x_n (x_0 = 0; x_(n+1) = x_n + step_length)
and height G_(n-1) + h_n (the ground under it plus the apex height; G_(-1) = 0); the ballistic
descent (g_f) for t_descent to the touchdown, the foot at x_n + foot_x on the touchdown ground G_n;
the stance sampled from the plant's trajectory (``slipmaps.trajectory`` with the stiffness the
plant ran with) where the plant has one, else piecewise linear in the polar state through the
touchdown, bottom and liftoff states (``iterative``: event states only); the ballistic ascent for
t_ascent. The terrain is flat between feet, each edge halfway between two consecutive feet (a stones
course: its stones, :meth:`~.stones.Course.polyline`). The swing
leg's angle along the flights (``leg``): over a descent the run's record of it (``RunBatch.swing``,
interpolated), over an ascent the angle the next descent starts with (held).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..api.index import get
from ..api.maps import trajectory
from .plant import ROBOT

__all__ = ["Path", "path"]


@dataclass(frozen=True)
class Path:
    """A run's path: ``t``, ``x``, ``y`` of the body and ``stance`` (True in a stance) along it;
    per step the foot (``foot_x``, ``foot_y``), the touchdown and liftoff times (``t_touchdown``,
    ``t_liftoff``) and body positions (``touchdown_body``, ``liftoff_body``: (n, 2)); the apexes
    (``apex``: (n + 1, 2)) and the planned targets (``target``: (n, 2), at the next apex's x); the
    terrain as a polyline (``terrain``: (k, 2)); ``sampled``: False when the stance is interpolated
    between its event states (a plant without a trajectory); ``leg``: the swing leg's angle along
    the path (NaN in a stance)."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    stance: np.ndarray
    foot_x: np.ndarray
    foot_y: np.ndarray
    t_touchdown: np.ndarray
    t_liftoff: np.ndarray
    touchdown_body: np.ndarray
    liftoff_body: np.ndarray
    apex: np.ndarray
    target: np.ndarray
    terrain: np.ndarray
    sampled: bool
    leg: np.ndarray


def _polar_to_body(q_r, q_th):
    return -q_r * np.sin(q_th), q_r * np.cos(q_th)


def _stance_states(run, n: int, samples: int, plant_params, stiff: float, sampled: bool):
    b = run.batch
    i = run.index
    td = b.states["touchdown"][i, n]
    t_s = b.values["t_stance"][i, n]
    times = np.linspace(0.0, t_s, samples)
    if sampled:
        k_c = b.values["k_c"][i, n] * stiff
        k_d = b.values["k_d"][i, n] * stiff
        params = plant_params.with_(k_c=k_c, k_d=k_d)
        options = dict(run.scenario.plant_options)
        name = run.scenario.plant
        if "constant_stiffness" in get(name).requires:
            params = plant_params.with_(k=k_c)
        _, states, _ = trajectory(name, params, td, times, **options)
        return times, states
    bottom = b.states["bottom"][i, n]
    lo = b.states["liftoff"][i, n]
    t_b = b.values["t_bottom"][i, n]
    knots_t = np.array([0.0, t_b, t_s])
    knots = np.array([td, bottom, lo])
    states = np.stack([np.interp(times, knots_t, knots[:, j]) for j in range(4)], axis=1)
    return times, states


def path(run, samples: int = 40) -> Path:
    """The path of ``run`` (module docstring), ``samples`` points per flight and per stance."""
    sc = run.scenario
    b = run.batch
    i = run.index
    g = sc.params.g_f
    plant_params = sc.params.with_(m=sc.params.m * (1.0 + sc.mismatch_mass))
    stiff = 1.0 + sc.mismatch_stiffness
    sampled = sc.plant != ROBOT and get(sc.plant).has_trajectory  # the robot: its event states
    n_steps = len(run)
    ok = b.codes["plant_status"][i] == 0
    T, X, Y, ST, LEG = [], [], [], [], []
    swing = b.swing[i] if b.swing is not None else None

    def swing_at(k, tt, t_d):
        """The leg's angle at times ``tt`` of descent ``k`` (of duration ``t_d``)."""
        if swing is None or k >= n_steps or not np.isfinite(swing[k]).all():
            th = b.values["touchdown_angle"][i, min(k, n_steps - 1)]
            return np.full(tt.shape, th)
        grid = np.linspace(0.0, t_d, swing.shape[1]) if t_d > 0 else np.zeros(swing.shape[1])
        return np.interp(tt, grid, swing[k]) if t_d > 0 else np.full(tt.shape, swing[k][0])

    feet_x, feet_y, t_td, t_lo, td_body, lo_body, apexes, targets = [], [], [], [], [], [], [], []
    x_apex, t_now = 0.0, 0.0
    ground_prev = 0.0
    for n in range(n_steps):
        h = b.values["apex_height"][i, n]
        v = b.values["apex_speed"][i, n]
        y_apex = ground_prev + h
        apexes.append((x_apex, y_apex))
        if not ok[n]:
            break
        G = b.values["ground"][i, n]
        t_d = b.values["t_descent"][i, n]
        tt = np.linspace(0.0, t_d, samples)
        T.append(t_now + tt)
        X.append(x_apex + v * tt)
        Y.append(y_apex - 0.5 * g * tt * tt)
        ST.append(np.zeros(samples, dtype=bool))
        LEG.append(swing_at(n, tt, t_d))
        t_now += t_d
        foot = x_apex + b.values["foot_x"][i, n]
        feet_x.append(foot)
        feet_y.append(G)
        t_td.append(t_now)
        times, states = _stance_states(run, n, samples, plant_params, stiff, sampled)
        bx, by = _polar_to_body(states[:, 0], states[:, 2])
        T.append(t_now + times)
        X.append(foot + bx)
        Y.append(G + by)
        ST.append(np.ones(samples, dtype=bool))
        LEG.append(np.full(samples, np.nan))
        td_body.append((foot + bx[0], G + by[0]))
        lo = b.states["liftoff"][i, n]
        lbx, lby = _polar_to_body(lo[0], lo[2])
        lo_body.append((foot + lbx, G + lby))
        t_now += times[-1]
        t_lo.append(t_now)
        xd = -math.sin(lo[2]) * lo[1] - lo[0] * math.cos(lo[2]) * lo[3]
        yd = math.cos(lo[2]) * lo[1] - lo[0] * math.sin(lo[2]) * lo[3]
        t_a = b.values["t_ascent"][i, n]
        tt = np.linspace(0.0, t_a, samples)
        T.append(t_now + tt)
        X.append(foot + lbx + xd * tt)
        Y.append(G + lby + yd * tt - 0.5 * g * tt * tt)
        ST.append(np.zeros(samples, dtype=bool))
        nxt = n + 1 if n + 1 < n_steps and ok[n + 1] else n
        LEG.append(np.full(samples, swing_at(nxt, np.zeros(1), 0.0)[0]))
        t_now += t_a
        x_apex = x_apex + b.values["step_length"][i, n]
        targets.append((x_apex, G + b.values["target_height"][i, n]))
        ground_prev = G
    if ok[: max(n_steps, 1)].all() and n_steps:
        apexes.append((x_apex, ground_prev + b.values["next_apex_height"][i, n_steps - 1]))
    xs = np.concatenate(X) if X else np.zeros(1)
    terrain = _terrain(np.array(feet_x), np.array(feet_y), float(xs.min()), float(xs.max()))
    if sc.stones is not None:  # a stones course: its stones, the gaps as pits
        terrain = sc.stones.polyline()
    return Path(
        t=np.concatenate(T) if T else np.zeros(0),
        x=xs if X else np.zeros(0),
        y=np.concatenate(Y) if Y else np.zeros(0),
        stance=np.concatenate(ST) if ST else np.zeros(0, dtype=bool),
        foot_x=np.array(feet_x),
        foot_y=np.array(feet_y),
        t_touchdown=np.array(t_td),
        t_liftoff=np.array(t_lo),
        touchdown_body=np.array(td_body).reshape(-1, 2),
        liftoff_body=np.array(lo_body).reshape(-1, 2),
        apex=np.array(apexes).reshape(-1, 2),
        target=np.array(targets).reshape(-1, 2),
        terrain=terrain,
        sampled=sampled,
        leg=np.concatenate(LEG) if LEG else np.zeros(0),
    )


def _terrain(feet_x: np.ndarray, feet_y: np.ndarray, x_min: float, x_max: float) -> np.ndarray:
    """The ground as a polyline in the order the run crosses it: level 0 under the start apex (at
    x = 0), each foot's level about it, the edges halfway between consecutive feet (the first
    halfway between the start apex and the first foot)."""
    pad = 0.5
    if feet_x.size == 0:
        return np.array([[x_min - pad, 0.0], [x_max + pad, 0.0]])
    direction = 1.0 if feet_x[-1] >= 0.0 else -1.0
    prev_x, prev_y = 0.0, 0.0
    pts = [(min(x_min, 0.0) - pad if direction > 0 else max(x_max, 0.0) + pad, 0.0)]
    for fx, fy in zip(feet_x, feet_y, strict=True):
        edge = 0.5 * (prev_x + fx)
        if fy != prev_y:
            pts += [(edge, prev_y), (edge, fy)]
        prev_x, prev_y = fx, fy
    pts.append((max(x_max, prev_x) + pad if direction > 0 else min(x_min, prev_x) - pad, prev_y))
    return np.array(pts)
