"""Viability on an unknown ground: k_d chosen at the apex (one stage) or at the bottom (two stages).

On known, flat ground a k_d chosen at the bottom is no better than one chosen at the apex: k_d
acts only after the bottom, and the bottom state is a function of the apex and the touchdown angle
(the compression runs with k_c), so every k_d the runner could pick at the bottom it could have
picked at the apex (with a single ground height the two policies below give the same sets: tested).
The choice at the bottom matters when something is learned between the apex and the bottom: the
ground's height, which the runner meets at touchdown. :func:`robust_viability` studies it.

- The state is the apex (height above the ground under it, speed) and the actions the touchdown
  angle and k_d, as in :func:`slipmaps.viability`; the touchdown ground is one of the heights
  ``ground`` [m] (H, relative to the ground under the apex: positive a step up), unknown at the
  apex. The next apex height is the apex map's, above the new ground, so after every step the state
  is again a height above the ground under the apex, on the same grid.
- The transition map is one batch per ground height over state x angle x k_d (the k_d grid with
  k_c added): ``failed`` and ``next_state`` over state x angle x k_d x ground.
- Three policies, each iterated to its fixed point with the conservative cell rule of
  :func:`.viability_kernel.viable_set` (``choose`` reduces the ground and, for two stages, k_d):

  * ``constant``: k_d = k_c; Q_V(s, a) = for every h in H the step is viable.
  * ``one-stage``: angle and k_d chosen at the apex, the ground unknown;
    Q_V(s, a, k_d) = for every h the step is viable.
  * ``two-stage``: the angle chosen at the apex, k_d at the bottom once the ground is known;
    Q_V(s, a) = for every h some k_d makes the step viable.

  Each Q_V holds the one before it (k_c is one of the k_d; "some k_d for every h" holds "one k_d
  for every h"), so the kernels nest: constant within one stage within two stages.
- Per state: ``measure`` (the share of the policy's action tuples in Q_V) and ``angles`` (the share
  of touchdown angles that are viable with some choice of k_d: the measure compared across the
  policies).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from ..api.params import SlipParams
from .viability import checked, grid, grid_span
from .viability_kernel import cells, steps_into, viable_set
from .viability_map import Grids, check_memory, transition

__all__ = ["POLICIES", "Policy", "RobustSet", "robust_viability"]

#: The policies, each holding the one before it.
POLICIES = ("constant", "one-stage", "two-stage")


def _constant(ok: np.ndarray) -> np.ndarray:  # (S, angle, ground) -> (S, angle)
    return ok.all(axis=-1)


def _one_stage(ok: np.ndarray) -> np.ndarray:  # (S, angle, k_d, ground) -> (S, angle, k_d)
    return ok.all(axis=-1)


def _two_stage(ok: np.ndarray) -> np.ndarray:  # (S, angle, k_d, ground) -> (S, angle)
    return ok.any(axis=-2).all(axis=-1)


@dataclass(frozen=True, eq=False)
class Policy:
    """One policy's sets: ``viable`` (Q_V over state x angle, with one stage state x angle x k_d),
    ``kernel`` (S_V), ``measure`` (the share of the policy's action tuples in Q_V), ``angles`` (the
    share of touchdown angles viable with some k_d) and the ``rounds`` of the fixed point."""

    name: str
    viable: np.ndarray
    kernel: np.ndarray
    measure: np.ndarray
    angles: np.ndarray
    rounds: int

    def summary(self) -> dict:
        inside = self.kernel
        return {
            "kernel_states": int(inside.sum()),
            "viable_pairs": int(self.viable.sum()),
            "viable_state_angles": int(np.round(self.angles.sum() * self.viable.shape[2])),
            "angles_in_kernel": float(self.angles[inside].mean()) if inside.any() else 0.0,
            "angles_max": float(self.angles.max()),
            "measure_in_kernel": float(self.measure[inside].mean()) if inside.any() else 0.0,
            "rounds": self.rounds,
        }


@dataclass(frozen=True, eq=False)
class RobustSet:
    """A study of :func:`robust_viability`: ``failed`` (bool), ``status`` (int8) and ``next_state``
    (trailing axis (h', v'), h' above the new ground; NaN where failed) over apex height x apex speed
    x touchdown angle x k_d x ground, the grids, and ``policies`` by name (:data:`POLICIES`)."""

    map: str
    params: SlipParams
    options: dict
    states: dict[str, np.ndarray]
    touchdown_angle: np.ndarray
    k_d: np.ndarray
    ground: np.ndarray
    outside: str
    failed: np.ndarray
    status: np.ndarray
    next_state: np.ndarray
    cell: np.ndarray
    policies: dict[str, Policy]
    seconds: dict[str, float] = field(default_factory=dict)

    def choices(self, policy: str = "two-stage") -> np.ndarray:
        """The steps (bool over state x angle x k_d x ground) that do not fail and land in a cell
        of ``policy``'s kernel: the k_d a runner on that kernel may choose at the bottom once the
        ground is known."""
        return steps_into(self.policies[policy].kernel, self.failed, self.cell, self.outside)

    def summary(self) -> dict:
        return {
            "states": int(self.failed[..., 0, 0, 0].size),
            "steps": int(self.failed.size),
            "ground": self.ground.tolist(),
            "k_d": self.k_d.tolist(),
            **{name: p.summary() for name, p in self.policies.items()},
        }

    def as_dict(self) -> dict:
        return {
            "map": self.map,
            "params": self.params.as_dict(),
            "options": dict(self.options),
            "outside": self.outside,
            "states": {n: grid_span(g) for n, g in self.states.items()},
            "touchdown_angle": grid_span(self.touchdown_angle),
            "summary": self.summary(),
            "seconds": dict(self.seconds),
        }

    def arrays(self) -> dict[str, np.ndarray]:
        """Every array by name (``np.savez``): the grids, ``failed``, ``status``, ``next_state`` and
        per policy ``<policy>_viable``, ``_kernel``, ``_measure``, ``_angles``."""
        out = {f"state_{n}": g for n, g in self.states.items()}
        out |= {"action_touchdown_angle": self.touchdown_angle, "action_k_d": self.k_d, "ground": self.ground}
        out |= {"failed": self.failed, "status": self.status, "next_state": self.next_state}
        for name, p in self.policies.items():
            key = name.replace("-", "_")
            for what in ("viable", "kernel", "measure", "angles"):
                out[f"{key}_{what}"] = getattr(p, what)
        return out

    def plot(self, path):
        """Write the figure to ``path`` (returns it): per policy the share of viable touchdown
        angles over apex height and speed, the kernel's outline on it."""
        from .viability_robust_figure import figure

        return figure(self, path)


def robust_viability(
    name: str,
    params: SlipParams,
    *,
    apex_height,
    apex_speed,
    touchdown_angle,
    k_d,
    ground,
    outside: str = "fail",
    progress: bool | None = None,
    **options,
) -> RobustSet:
    """The viable sets of map ``name`` on an unknown ground (module docstring): the apex
    ``apex_height`` [m] (above the ground under the apex) x ``apex_speed`` [m/s], the actions
    ``touchdown_angle`` [rad, from the vertical, counterclockwise positive] and ``k_d`` [N/m] (k_c
    added when the grid lacks it), the touchdown ground one of ``ground`` [m, relative to the
    ground under the apex], all 1-D increasing grids; ``outside`` and ``options`` as in
    :func:`slipmaps.viability`. Returns a :class:`RobustSet` with the policies constant,
    one-stage and two-stage."""
    k_d = np.union1d(grid("k_d", k_d, positive=True), [params.k_c])
    grounds = grid("ground", ground)
    grids, call = checked(
        name, params, apex_height, touchdown_angle, apex_speed, None, k_d, None, outside, options
    )
    check_memory(Grids(grids.states, {**grids.actions, "ground": grounds}, None))
    start = time.perf_counter()
    maps = [
        transition(name, params, grids, ground=float(h), progress=progress, options=options) for h in grounds
    ]
    failed = np.stack([m.failed for m in maps], axis=-1)
    status = np.stack([m.status for m in maps], axis=-1)
    nxt = np.stack([m.next_state for m in maps], axis=-2)
    del maps
    seconds = {"map": time.perf_counter() - start}
    start = time.perf_counter()
    cell = cells(nxt, failed, list(grids.states.values()))
    j = int(np.flatnonzero(k_d == params.k_c)[0])
    policies = {}
    for policy, f, c, choose in (
        ("constant", failed[:, :, :, j], cell[:, :, :, j], _constant),
        ("one-stage", failed, cell, _one_stage),
        ("two-stage", failed, cell, _two_stage),
    ):
        k = viable_set(f, c, 2, outside, choose)
        angles = k.viable.any(axis=-1).mean(axis=-1) if k.viable.ndim == 4 else k.measure
        policies[policy] = Policy(policy, k.viable, k.kernel, k.measure, angles, k.rounds)
    seconds["kernel"] = time.perf_counter() - start
    return RobustSet(
        call.info.name,
        params,
        dict(call.options),
        grids.states,
        grids.actions["touchdown_angle"],
        k_d,
        grounds,
        outside,
        failed,
        status,
        nxt,
        cell,
        policies,
        seconds,
    )
