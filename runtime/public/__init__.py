"""slipmaps: approximate stance maps of the Spring-Loaded Inverted Pendulum (SLIP).

Derived in SymPy (``slipmaps.derive``), generated as numba kernels (``slipmaps.generated``),
checked against numerical integration (``slipmaps.runtime``). The public API, generic over maps::

    import slipmaps

    params = slipmaps.SlipParams(m=80.0, l0=1.0, k=20_000.0)
    [m.name for m in slipmaps.maps()]                      # "geyer", ..., "exact"
    res = slipmaps.apex_return("geyer", params, 1.0, 5.0, 0.35)
    res.next_apex_height, res.next_apex_speed, res.status               # the next apex
    batch = slipmaps.apex_return_batch("geyer", params, 1.0, speeds, angles)   # arrays broadcast
    batch["next_apex_height"], batch["status"], batch.to_pandas()        # inputs, outputs, status
    gaits = slipmaps.fixed_points("exact", params, apex_height=1.0, speed=5.0)  # periodic gaits
    gaits[0].touchdown_angle, gaits[0].eigenvalue, gaits[0].stable
    vs = slipmaps.viability("exact", params, apex_height=heights, touchdown_angle=angles, energy=1900.0)
    plan = slipmaps.deadbeat("iterative", params, 1.0, 5.0, 1.0, 5.2)   # touchdown angle and k_d
    plan.touchdown_angle, plan.k_d, plan.status                          # REACHED
    plan.apply().next_apex_speed                                         # the plan on the exact map
    policy = slipmaps.swing_policy("iterative", params, 1.3, 5.0, 1.3, 5.0, grounds=(-0.3, 0.3),
                                   controls=("touchdown_angle", "k_d"))  # blind: any ground in range
    trip = slipmaps.run("examples/stairs.toml")                          # steps on the exact plant
    plan = slipmaps.footholds("iterative", params, {"height": 1.0, "speed": 5.0}, stones)  # 2 hops

Conventions (all of them: docs/conventions.md): SI units; leg angle from the vertical,
counterclockwise positive; polar state ``(q_r, q_rd, q_th, q_thd)``; times in a stance from
touchdown. This file is installed as the top-level package ``slipmaps`` (``pyproject.toml``,
``package-dir``).

numba caches the compiled kernels in ``NUMBA_CACHE_DIR`` when it is set, else in
``~/.cache/slipmaps/numba`` (``$XDG_CACHE_HOME``), never inside the installed package; importing
``slipmaps`` sets this up (``slipmaps.kernel_cache``).
"""

from __future__ import annotations

import importlib

#: Public name -> the module that defines it. Loaded on first use (PEP 562), so that importing
#: ``slipmaps.derive`` (``slipmaps generate``) never needs the generated kernels.
_EXPORTS = {
    "SlipParams": "slipmaps.runtime.api.params",
    "HUMAN_RUNNER": "slipmaps.runtime.api.params",
    "ROBOT_HOPPER": "slipmaps.runtime.api.params",
    "maps": "slipmaps.runtime.api.index",
    "MapInfo": "slipmaps.runtime.api.index",
    "stance": "slipmaps.runtime.api.maps",
    "stance_batch": "slipmaps.runtime.api.maps",
    "apex_return": "slipmaps.runtime.api.maps",
    "apex_return_batch": "slipmaps.runtime.api.maps",
    "trajectory": "slipmaps.runtime.api.maps",
    "half_stance": "slipmaps.runtime.api.maps",
    "half_stance_batch": "slipmaps.runtime.api.maps",
    "stance_jacobian": "slipmaps.runtime.api.jacobian",
    "stance_jacobian_batch": "slipmaps.runtime.api.jacobian",
    "apex_return_jacobian": "slipmaps.runtime.api.jacobian",
    "apex_return_jacobian_batch": "slipmaps.runtime.api.jacobian",
    "Jacobian": "slipmaps.runtime.api.jacobian",
    "JacobianBatch": "slipmaps.runtime.api.jacobian",
    "fixed_points": "slipmaps.runtime.analysis.gait",
    "FixedPoint": "slipmaps.runtime.analysis.gait",
    "viability": "slipmaps.runtime.analysis.viability",
    "ViableSet": "slipmaps.runtime.analysis.viability",
    "viability_sweep": "slipmaps.runtime.sweep.viability",
    "robust_viability": "slipmaps.runtime.analysis.viability_robust",
    "RobustSet": "slipmaps.runtime.analysis.viability_robust",
    "Result": "slipmaps.runtime.api.results",
    "BatchResult": "slipmaps.runtime.api.results",
    "BatchInterrupted": "slipmaps.runtime.api.batch",
    "Status": "slipmaps.generated.status",
    "Sweep": "slipmaps.runtime.sweep.run",
    "sweep": "slipmaps.runtime.sweep.run",
    "read_sweep": "slipmaps.runtime.sweep.run",
    "MESSAGES": "slipmaps.generated.status",
    "deadbeat": "slipmaps.runtime.control.deadbeat",
    "deadbeat_batch": "slipmaps.runtime.control.deadbeat",
    "Deadbeat": "slipmaps.runtime.control.deadbeat",
    "DeadbeatResult": "slipmaps.runtime.control.deadbeat",
    "DeadbeatBatch": "slipmaps.runtime.control.deadbeat",
    "PlanStatus": "slipmaps.runtime.control.deadbeat",
    "apply_plan": "slipmaps.runtime.control.deadbeat",
    "BottomDeadbeat": "slipmaps.runtime.control.bottom",
    "swing_policy": "slipmaps.runtime.control.swing",
    "SwingPolicy": "slipmaps.runtime.control.swing",
    "run": "slipmaps.runtime.control.runs",
    "run_batch": "slipmaps.runtime.control.runs",
    "Run": "slipmaps.runtime.control.runs",
    "RunBatch": "slipmaps.runtime.control.runs",
    "Scenario": "slipmaps.runtime.control.scenarios",
    "identify": "slipmaps.runtime.control.identify",
    "Identified": "slipmaps.runtime.control.identify",
    "Hops": "slipmaps.runtime.control.identify",
    "RaibertGains": "slipmaps.runtime.control.raibert",
    "load_scenario": "slipmaps.runtime.control.scenarios",
    "footholds": "slipmaps.runtime.control.footholds",
    "Footholds": "slipmaps.runtime.control.footholds",
    "FootholdPlan": "slipmaps.runtime.control.footholds",
    "FootholdStatus": "slipmaps.runtime.control.footholds",
    "Course": "slipmaps.runtime.control.stones",
    "random_course": "slipmaps.runtime.control.stones",
    "notices": "slipmaps.runtime.api.notices",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    if name in _EXPORTS:
        value = getattr(importlib.import_module(_EXPORTS[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'slipmaps' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))


# Before any kernel module is imported: numba caches slipmaps' compiled kernels in a user cache
# directory, never inside the installed package (runtime/public/kernel_cache.py says why and where).
importlib.import_module("slipmaps.kernel_cache").install()
