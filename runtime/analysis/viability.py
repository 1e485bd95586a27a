"""Viability: from which apexes the runner can avoid a fall forever, and with how many actions.

Heim and Spröwitz ("Beyond basins of attraction: quantifying robustness of natural dynamics", IEEE
T-RO 2019; their code sheim/vibly) define it in state-action space on a grid: the viable set Q_V (the
state-action pairs whose next state is viable), the viability kernel S_V (the states with at least
one viable action) and the measure of robustness of a state (the share of its actions in Q_V).
:func:`viability` computes them with any map of slipmaps::

    import numpy as np, slipmaps

    p = slipmaps.SlipParams(m=80.0, l0=1.0, k=8200.0)
    vs = slipmaps.viability("exact", p, apex_height=np.linspace(0.3, 2.3, 100),
                            touchdown_angle=np.radians(np.linspace(-10, 70, 161)), energy=1877.08)
    vs.kernel, vs.measure          # over the apex heights
    vs.plot("viability.png")

- The states: ``apex_height`` [m] at a fixed flight ``energy`` E = m (g_f h + v^2/2) [J] (the step
  must conserve it: k_c = k_d, the default leg lengths, g_s = g_f, c = 0), or ``apex_height`` x
  ``apex_speed`` [m/s] (any map and parameters).
- The actions: ``touchdown_angle`` [rad, from the vertical, counterclockwise positive: a forward
  runner's is positive], optionally ``k_d`` [N/m] (the decompression stiffness chosen per step, k_c
  the parameters'; the state is then (height, speed): k_c != k_d changes the energy) and
  ``retraction_rate`` [rad/s].
- A step fails (vibly's failure set) when the foot would start underground (no touchdown), the body
  falls (any status of the step that is not OK: a fall, no flight after the stance, a liftoff moving
  backward, a map that does not converge), or the next apex speed is not positive (no longer running
  forward) (:mod:`.viability_map`).
- The discretisation is conservative, as Heim and Spröwitz's: a next state counts as viable only if
  every grid node of its cell is in the kernel estimate, and beyond the grid it is not viable
  (``outside="edge"``: judged by the edge node, as vibly does); the kernel estimate is iterated to its
  fixed point (:mod:`.viability_kernel`).

The transition map is batches of the public apex-return API (one per k_d and chunk of states), so the
exact map on vibly's SLIP demo grid (28,980 pairs) takes 0.45 s once compiled, on 2 busy cores
(docs/viability.md); with the same results its steps run as a resumable sweep, also on Dask
(``slipmaps.viability_sweep``, runtime/sweep/viability.py). On a ground whose height is unknown at
the apex, with k_d chosen at the apex or at the bottom: ``slipmaps.robust_viability``
(:mod:`.viability_robust`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..api.params import SlipParams
from ..api.validate import limit, limit_text, real_array
from .viability_kernel import OUTSIDE, cells, viable_set
from .viability_map import Grids, check_memory, speeds_on_energy, transition

__all__ = ["ViableSet", "checked", "from_transition", "grid", "grid_span", "viability"]


@dataclass(frozen=True, eq=False)
class ViableSet:
    """A viability study on a grid (``slipmaps.viability``): arrays over states (S) or states x actions (Q).

    ``failed`` (Q, bool: the step fails), ``status`` (Q, int8 :class:`~slipmaps.Status` codes; OK
    where only the next speed failed), ``next_state`` (Q x state dims, NaN where failed; float64, or
    float32 from ``viability_sweep(..., next_state_dtype="float32")``), ``viable``
    (Q_V), ``kernel`` (S_V), ``measure`` (S, the share of viable actions), ``states`` and ``actions``
    (the grids by name), ``energy`` [J] or None, ``map``, ``params``, ``options``, ``outside``,
    ``rounds`` of the fixed-point iteration, ``seconds`` (``map``: the steps, ``kernel``: the
    iteration) and the touchdown ``ground`` [m]."""

    map: str
    params: SlipParams
    options: dict
    states: dict[str, np.ndarray]
    actions: dict[str, np.ndarray]
    energy: float | None
    failed: np.ndarray
    status: np.ndarray
    next_state: np.ndarray
    viable: np.ndarray
    kernel: np.ndarray
    measure: np.ndarray
    rounds: int
    outside: str
    seconds: dict[str, float] = field(default_factory=dict)
    ground: float = 0.0

    @property
    def state_names(self) -> tuple[str, ...]:
        return tuple(self.states)

    @property
    def action_names(self) -> tuple[str, ...]:
        return tuple(self.actions)

    @property
    def normalized_height(self) -> np.ndarray | None:
        """Vibly's state s = m g_f h / E of the height grid at a fixed energy (None without one)."""
        if self.energy is None:
            return None
        return self.params.m * self.params.g_f * self.states["apex_height"] / self.energy

    def columns(self) -> dict[str, np.ndarray]:
        """A row per state (C order over the state grid): the state, ``kernel``, ``measure``, the
        number of actions that do not fail (``safe_actions``) and of viable ones (``viable_actions``)."""
        grids = np.meshgrid(*self.states.values(), indexing="ij")
        out = {n: g.ravel() for n, g in zip(self.states, grids, strict=True)}
        if self.energy is not None:
            out["apex_speed"] = speeds_on_energy(self.params, self.energy, out["apex_height"])
        axes = tuple(range(self.kernel.ndim, self.viable.ndim))
        out["kernel"] = self.kernel.ravel()
        out["measure"] = self.measure.ravel()
        out["safe_actions"] = (~self.failed).sum(axis=axes).ravel()
        out["viable_actions"] = self.viable.sum(axis=axes).ravel()
        return out

    def to_pandas(self):
        """``columns()`` as a pandas DataFrame (pandas: the ``test`` extra)."""
        import pandas as pd

        return pd.DataFrame(self.columns())

    def summary(self) -> dict:
        """The shape of the sets in numbers: sizes, the kernel's extent per state dimension, where the
        measure peaks."""
        out = {
            "pairs": int(self.failed.size),
            "failed": int(self.failed.sum()),
            "viable_pairs": int(self.viable.sum()),
            "kernel_states": int(self.kernel.sum()),
            "states": int(self.kernel.size),
            "measure_max": float(self.measure.max()) if self.measure.size else math.nan,
            "rounds": self.rounds,
        }
        peak = np.unravel_index(int(np.argmax(self.measure)), self.measure.shape)
        out["measure_peak"] = {n: float(g[i]) for (n, g), i in zip(self.states.items(), peak, strict=True)}
        extent = {}
        for axis, (n, g) in enumerate(self.states.items()):
            others = tuple(a for a in range(self.kernel.ndim) if a != axis)
            on = self.kernel.any(axis=others) if others else self.kernel
            extent[n] = [float(g[on][0]), float(g[on][-1])] if on.any() else None
        out["kernel_extent"] = extent
        return out

    def as_dict(self) -> dict:
        """JSON-ready: the map, parameters, grids (bounds and sizes), the summary and a row per state."""
        cols = self.columns()
        rows = [
            {k: (v[i].item() if hasattr(v[i], "item") else v[i]) for k, v in cols.items()}
            for i in range(self.kernel.size)
        ]

        return {
            "map": self.map,
            "params": self.params.as_dict(),
            "options": dict(self.options),
            "energy": self.energy,
            "outside": self.outside,
            "states": {n: grid_span(g) for n, g in self.states.items()},
            "actions": {n: grid_span(g) for n, g in self.actions.items()},
            "summary": self.summary(),
            "seconds": dict(self.seconds),
            "per_state": rows,
        }

    def arrays(self) -> dict[str, np.ndarray]:
        """Every array by name (``np.savez``): the grids (``state_<name>``, ``action_<name>``),
        ``failed``, ``status``, ``next_state``, ``viable``, ``kernel``, ``measure``."""
        out = {f"state_{n}": g for n, g in self.states.items()}
        out |= {f"action_{n}": g for n, g in self.actions.items()}
        out |= {
            "failed": self.failed,
            "status": self.status,
            "next_state": self.next_state,
            "viable": self.viable,
            "kernel": self.kernel,
            "measure": self.measure,
        }
        if self.energy is not None:
            out["energy"] = np.float64(self.energy)
        return out

    def boundary(self, iterations: int = 20):
        """The kernel's boundary between the grid's nodes, by bisection: on every edge of the grid
        whose two nodes the kernel separates, the state where "some action of the grid steps into a
        viable cell" stops holding, bracketed ``iterations`` halvings finer than the grid (one batch
        of the map per halving); a ``Boundary`` with ``axis``, ``inside``, ``outside``, ``low``,
        ``high`` and ``position`` per edge."""
        from .viability_boundary import boundary

        return boundary(self, iterations)

    def plot(self, path):
        """Write the figure to ``path`` (its suffix chooses the format; returns the path): at a fixed
        energy the state-action plane (failing, leaving the kernel, viable) with the kernel and the
        measure beside it; on (height, speed) the share of safe actions and the measure as images
        with the kernel's outline."""
        from .viability_figure import figure

        return figure(self, path)


def grid_span(g: np.ndarray) -> dict:
    """A 1-D grid as JSON: its first and last values and its length."""
    return {"min": float(g[0]), "max": float(g[-1]), "n": int(g.size)}


def grid(name: str, values, positive: bool = False) -> np.ndarray:
    """``values`` as a 1-D float64 grid: non-empty, finite, strictly increasing (and positive when
    asked); ValueError naming ``name`` otherwise."""
    arr = np.atleast_1d(real_array(name, values)).astype(np.float64)
    if arr.ndim != 1 or arr.size == 0:
        raise ValueError(f"{name} must be a non-empty 1-D grid, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    if arr.size > 1 and not np.all(np.diff(arr) > 0):
        raise ValueError(f"{name} must be strictly increasing")
    if positive and not np.all(arr > 0):
        raise ValueError(f"{name} must be positive")
    return arr


def _grids(params, apex_height, touchdown_angle, apex_speed, energy, k_d, retraction_rate) -> Grids:
    if (apex_speed is None) == (energy is None):
        raise ValueError("give either apex_speed (a grid: the state is height and speed) or energy (J)")
    states = {"apex_height": grid("apex_height", apex_height)}
    if np.any(states["apex_height"] < 0):
        raise ValueError("apex_height must not be negative")
    if energy is not None:
        energy = float(energy)
        if not (math.isfinite(energy) and energy > 0):
            raise ValueError(f"energy must be a positive number of joules, got {energy}")
        if k_d is not None:
            raise ValueError(
                "a k_d grid changes the energy every step (k_c != k_d): give apex_speed, not energy"
            )
        if not params.conserves_energy:
            raise ValueError(
                "a fixed energy needs a step that conserves it (k_c = k_d, g_s = g_f, q_r_td = q_r_lo, "
                "no leg damping c = 0): give apex_speed instead"
            )
        top = energy / (params.m * params.g_f)
        if states["apex_height"][-1] > top:
            raise ValueError(
                f"apex_height reaches {states['apex_height'][-1]:g} m, above the energy's {top:g} m "
                "(E / (m g_f), where the speed is 0)"
            )
    else:
        states["apex_speed"] = grid("apex_speed", apex_speed)
        if np.any(states["apex_speed"] < 0):
            raise ValueError("apex_speed must not be negative (forward running)")
    actions = {"touchdown_angle": grid("touchdown_angle", touchdown_angle)}
    if np.any(np.abs(actions["touchdown_angle"]) >= math.pi / 2):
        raise ValueError("touchdown_angle must lie in (-pi/2, pi/2)")
    if k_d is not None:
        actions["k_d"] = grid("k_d", k_d, positive=True)
    if retraction_rate is not None:
        actions["retraction_rate"] = grid("retraction_rate", retraction_rate)
        if np.any(np.abs(actions["retraction_rate"]) > limit("retraction_rate", params)):  # the maps' range
            raise ValueError(f"retraction_rate must lie in {limit_text('retraction_rate', params)}")
    return Grids(states, actions, energy)


def viability(
    name: str,
    params: SlipParams,
    *,
    apex_height,
    touchdown_angle,
    apex_speed=None,
    energy=None,
    k_d=None,
    retraction_rate=None,
    ground: float = 0.0,
    outside: str = "fail",
    progress: bool | None = None,
    **options,
) -> ViableSet:
    """The viable set Q_V, the viability kernel S_V and the measure of map ``name`` on a grid.

    ``apex_height`` [m], ``apex_speed`` [m/s], ``touchdown_angle`` [rad, from the vertical,
    counterclockwise positive], ``k_d`` [N/m] and ``retraction_rate`` [rad/s] are 1-D increasing
    grids. The state is the apex height at the fixed flight ``energy`` E = m (g_f h + v^2/2) [J]
    (the step must conserve it: k_c = k_d, g_s = g_f, q_r_td = q_r_lo, c = 0; no ``k_d`` grid), or the apex
    height and speed (``apex_speed`` given); give one of ``apex_speed`` and ``energy``. The actions:
    the touchdown angle, then k_d (the parameters' k_c kept) and the retraction rate when given.
    ``ground`` [m] is the touchdown ground's height every step; ``options`` the map's
    (``iterations=20``).

    A step fails, as in Heim and Spröwitz's SLIP: the foot would start underground (no
    touchdown), the body falls (any status that is not OK: a fall, no flight after the stance, a
    backward liftoff, a map that does not converge), or the next apex speed is not positive. A
    pair is viable when every grid node of the cell its next state falls in is in the kernel
    estimate (``np.digitize`` per dimension, as vibly); a next state beyond the grid is not viable
    with ``outside="fail"`` (the default) and judged by the edge node with ``outside="edge"``
    (vibly's rule: it reproduces vibly's published SLIP sets exactly). The estimate starts at the
    states with a step that does not fail and is iterated until it no longer changes. The
    measure of a state is the share of its actions in Q_V. ValueError names a bad argument, and
    a grid larger than the machine's memory.
    """
    grids, call = checked(
        name, params, apex_height, touchdown_angle, apex_speed, energy, k_d, retraction_rate, outside, options
    )
    tm = transition(name, params, grids, ground=float(ground), progress=progress, options=options)
    return from_transition(call, params, grids, tm, outside, float(ground))


def checked(
    name, params, apex_height, touchdown_angle, apex_speed, energy, k_d, retraction_rate, outside, options
):
    """``(grids, call)`` of a study, every argument checked before any work (ValueError naming it):
    the grids, the map and its options, a k_d grid's map, the memory the grid needs."""
    from ..api.calls import Call

    if outside not in OUTSIDE:
        raise ValueError(f"outside must be one of {', '.join(OUTSIDE)}, got {outside!r}")
    grids = _grids(params, apex_height, touchdown_angle, apex_speed, energy, k_d, retraction_rate)
    call = Call.of(name, params, options)  # the map and its options, checked before any work
    if k_d is not None and "k_d" not in call.spec("apex_return").p:
        raise ValueError(
            f"map {call.info.name!r} takes one stiffness k: a k_d grid needs a variable-stiffness map "
            "(exact, iterative, geyer-vs)"
        )
    check_memory(grids)
    return grids, call


def from_transition(
    call, params: SlipParams, grids: Grids, tm, outside: str, ground: float = 0.0, cell=None
) -> ViableSet:
    """The study of a computed transition map ``tm``: its cells (``cell``, when given, the cells of
    its next states already computed: :func:`.viability_kernel.cells`), the fixed point and the
    measure."""
    import time

    start = time.perf_counter()
    state_grids = list(grids.states.values())
    if cell is None:
        cell = cells(tm.next_state, tm.failed, state_grids)
    k = viable_set(tm.failed, cell, len(state_grids), outside)
    seconds = {"map": tm.seconds, "kernel": time.perf_counter() - start}
    return ViableSet(
        call.info.name,
        params,
        dict(call.options),
        grids.states,
        grids.actions,
        grids.energy,
        tm.failed,
        tm.status,
        tm.next_state,
        k.viable,
        k.kernel,
        k.measure,
        k.rounds,
        outside,
        seconds,
        ground,
    )
