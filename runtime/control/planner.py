"""The planner over a horizon of known ground: the intermediate apex targets that keep the coming
steps reachable.

One step can change the flight energy only by what k_d within its bounds adds or removes at the
bottom, (k_d - k_c)(l0 - q_r_b)^2 / 2 (report eq 97), and a step up needs the apex high enough above
the next ground. With the ground of the next K touchdowns known, the planner chooses the next
apex's target so that the energy plan stays feasible, per unit mass, relative to the ground under
the current apex:

* the energies: e_0 = g h + v^2/2 now, e_k = g (G_k + H_k) + V_k^2/2 at apex k (G_k the ground of
  touchdown k, (H_k, V_k) the nominal target of step k);
* what a step can do: e_k - e_(k-1) in [lo, hi], from the energy authority A = dE'/dk_d of the
  latest deadbeat solve (J per N/m) times the k_d range about the nominal k_c, times
  :data:`MARGIN` (so that the planned target stays reachable by the model);
* the floors: apex k at least ``min_height`` above the ground of touchdown k+1 at its nominal speed
  (the ground beyond the horizon taken as the last known one);
* backward, the lowest energy L_k from which the floors ahead can still be met (L_K = floor_K,
  L_k = max(floor_k, L_(k+1) - hi)); forward, the next energy e_1 nearest the nominal within
  [e_0 + lo, e_0 + hi] and at least L_1 (best effort, e_0 + hi, when even that is short).

The next target is then the point of the energy level e_1 nearest the nominal target in the scaled
norm ((H - H_1)/l0)^2 + ((V - V_1)^2 / (g l0)) (the deadbeat's own scaling), the height at least its
floor; a hop in place (V_1 = 0) puts all of it into the height. With the nominal target feasible the
planner returns it unchanged. Vectorised over runs (numpy).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["MARGIN", "plan_targets", "split_energy"]

#: The share of a step's energy range the planner uses (the authority is an estimate from the
#: latest solve, at its touchdown angle).
MARGIN = 0.9


def split_energy(e, ground, height, speed, floor, g: float, l0: float):
    """The point (H, V) on the energy level g (ground + H) + V^2/2 = e nearest (height, speed) in the
    scaled norm, with H >= floor (arrays broadcast). Returns (H, V)."""
    e, ground, height, speed, floor = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (e, ground, height, speed, floor))
    )
    x0 = height / l0
    y0 = speed / math.sqrt(g * l0)
    c = (e / g - ground) / l0  # x + y^2/2 = c
    # x = x0 + lam, y = y0 / (1 - lam): f(lam) = x0 + lam + y0^2 / (2 (1 - lam)^2) - c, increasing on
    # lam < 1, from -inf; bisection between a point below the root and 1
    lo = np.minimum(0.0, c - x0 - 0.5 * y0 * y0) - 1.0
    hi = np.full_like(lo, 1.0 - 1e-12)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        f = x0 + mid + 0.5 * y0 * y0 / (1.0 - mid) ** 2 - c
        below = f < 0.0
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    lam = 0.5 * (lo + hi)  # < 1: the speed keeps its sign
    x = x0 + lam
    y = np.where(y0 == 0.0, 0.0, y0 / (1.0 - lam))
    x = np.where(y0 == 0.0, c, x)
    # the floor: keep the height there and take the speed from the energy (zero at worst)
    xf = floor / l0
    low = x < xf
    rest = np.maximum(c - xf, 0.0)
    y = np.where(low, np.sign(y0) * np.sqrt(2.0 * rest), y)
    x = np.where(low, np.minimum(xf, c), x)
    return x * l0, y * math.sqrt(g * l0)


def plan_targets(
    height,
    speed,
    grounds,
    target_height,
    target_speed,
    authority,
    k_c: float,
    k_d_bounds: tuple[float, float],
    *,
    mass: float,
    g: float,
    l0: float,
    min_height: float,
):
    """The next apex targets of R runs (module docstring).

    ``height``, ``speed``: the current apex (R,); ``grounds`` (R, K): the known touchdown grounds
    of the next K steps relative to the ground under the current apex; ``target_height``,
    ``target_speed`` (R, K): the nominal targets of those steps; ``authority`` (R,): dE'/dk_d [J
    per N/m] (NaN: the model cannot change the energy, the planner only keeps the floor). Returns
    (H, V) of the next apex, (R,) each."""
    h, v = np.asarray(height, dtype=float), np.asarray(speed, dtype=float)
    G = np.asarray(grounds, dtype=float)
    Ht, Vt = np.asarray(target_height, dtype=float), np.asarray(target_speed, dtype=float)
    R, K = G.shape
    a = np.asarray(authority, dtype=float) / mass  # J/kg per N/m
    able = np.isfinite(a)
    a = np.where(able, a, 0.0)
    lo = MARGIN * (k_d_bounds[0] - k_c) * a
    hi = MARGIN * (k_d_bounds[1] - k_c) * a
    e0 = g * h + 0.5 * v * v
    nominal = g * (G + Ht) + 0.5 * Vt * Vt  # (R, K)
    beyond = np.concatenate([G[:, 1:], G[:, -1:]], axis=1)  # the ground of touchdown k+1
    floors = g * (beyond + min_height) + 0.5 * Vt * Vt
    L = floors[:, -1].copy()
    for k in range(K - 2, -1, -1):
        L = np.maximum(floors[:, k], L - hi)
    e1 = np.clip(nominal[:, 0], e0 + lo, e0 + hi)
    e1 = np.minimum(np.maximum(e1, L), e0 + hi)
    e1 = np.where(able, e1, e0)  # no energy control: the energy stays
    floor = beyond[:, 0] - G[:, 0] + min_height
    H, V = split_energy(e1, G[:, 0], Ht[:, 0], Vt[:, 0], floor, g, l0)
    keep = (e1 == nominal[:, 0]) & (Ht[:, 0] >= floor)  # the nominal target is feasible: unchanged
    return np.where(keep, Ht[:, 0], H), np.where(keep, Vt[:, 0], V)
