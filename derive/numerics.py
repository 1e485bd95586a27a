"""Data of the generator's numerical support modules (rendered from derive/templates/, each a
module of generated/ the kernels import): the DOP853 step of scipy's tableau written out as source,
and the exact stance's constants from the declarations.

- :func:`dop853` for ``dop853.py.j2``: scipy's ``DOP853`` coefficients (read at generation: the
  rendered integrator imports no scipy), the step, error norm and interpolant with every coefficient
  a literal, every loop over the stages unrolled and the tableau's zeros left out
  (:func:`_step_source`), summed in scipy's order so the steps are scipy's bitwise;
- :func:`exact_stance` for ``exact_stance.py.j2``: the stance row's columns (the index's names),
  the polar order, the Jacobian's inputs and the simulator's settings
  (derive/model/simulation.py).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _coef
from scipy.integrate._ivp import rk as _rk

__all__ = ["dop853", "exact_stance"]

N_STAGES = int(_coef.N_STAGES)  # 12 stages of the 8th-order step (the 13th row holds f_new)
N_STAGES_EXTENDED = int(_coef.N_STAGES_EXTENDED)  # 16 with the 3 extra stages of the interpolant
INTERPOLATOR_POWER = int(_coef.INTERPOLATOR_POWER)  # 7 coefficient rows of the dense output
A = np.ascontiguousarray(_coef.A, dtype=np.float64)
B = np.ascontiguousarray(_coef.B, dtype=np.float64)
C = np.ascontiguousarray(_coef.C, dtype=np.float64)
E3 = np.ascontiguousarray(_coef.E3, dtype=np.float64)
E5 = np.ascontiguousarray(_coef.E5, dtype=np.float64)
D = np.ascontiguousarray(_coef.D, dtype=np.float64)
#: The step of a field registered with this state length (the polar stance) has its components
#: written out; any other field's loops over its own.
UNROLLED = 4


def _sum(coefficients: np.ndarray, stages: int, term) -> str:
    """The source of sum_j term(j) * coefficients[j] over the first ``stages`` stages in stage order
    (scipy's, ``K.T @ a``), the tableau's zeros left out (a zero term adds nothing to a finite sum:
    the same value bitwise). The order matters: an error estimate below round-off (the first steps
    from a state with zero components) is round-off, and the steps it chooses must be scipy's."""
    return " + ".join(f"{term(j)} * {float(c)!r}" for j, c in enumerate(coefficients[:stages]) if c != 0.0)


def _advance(y: str, coefficients: np.ndarray, stages: int, term) -> str:
    """The source of y + (sum_j coefficients[j] term(j)) * h over the first ``stages`` stages
    (scipy's ``y + h * (K.T @ a)``)."""
    return f"{y} + ({_sum(coefficients, stages, term)}) * h"


def _step_source() -> str:
    """Python source of the Runge-Kutta step, the error norm and the interpolant's coefficients:
    every coefficient a literal, every loop over the stages unrolled, the tableau's zeros left out
    (:func:`_sum`, :func:`_advance`). The step comes twice, its :data:`UNROLLED` components written
    out (for a registered field, :func:`static`) and looping over any length; the error norm
    branches on the length at run time. Both forms compute the same expressions (bitwise the same
    values: tests/test_exact_compiled.py), those of the loops over the tableau before."""

    def arr(j):
        return f"K[{j}, i]"

    def step(n: str, indent: str) -> list[str]:
        """The step's body: loops over the n components, or (n an int) the components written
        out, every component's value computed before any is stored (no store comes between the
        loads of a stage's combination: the four components are combined side by side)."""
        if n.isdigit():
            # the components written out as scalars: y and every stage's row read once, in one
            # call of support.load (numba lowers each subscript as a call of its own)
            comps = range(int(n))
            every = ", ".join(map(str, comps))

            def names(row: str) -> str:
                return ", ".join(f"{row}_{c}" for c in comps)

            def assign(target: str, coefficients: np.ndarray, stages: int) -> list[str]:
                # (each value a name of its own: numba rewrites a function once per name assigned twice)
                values = [_advance(f"y_{c}", coefficients, stages, lambda j, c=c: f"k{j}_{c}") for c in comps]
                return [f"{indent}v{stages}_{c} = {v}" for c, v in enumerate(values)] + [
                    f"{indent}store({target}, ({names(f'v{stages}')},))"
                ]

            out = [
                f"{indent}({names('y')},) = load(y, {every})",
                f"{indent}({names('k0')},) = load(f, {every})",
                f"{indent}store(K[0], ({names('k0')},))",
            ]
            for st in range(1, N_STAGES):
                out += assign("ys", A[st], st)
                out.append(f"{indent}rhs(t + {float(C[st])!r} * h, ys, p, K[{st}])")
                out.append(f"{indent}({names(f'k{st}')},) = load(K[{st}], {every})")
            out += assign("y_new", B, N_STAGES)
            out.append(f"{indent}rhs(t + h, y_new, p, K[{N_STAGES}])")
            return out
        out = [f"{indent}for i in range({n}):", f"{indent}    K[0, i] = f[i]"]
        for st in range(1, N_STAGES):
            out += [
                f"{indent}for i in range({n}):",
                f"{indent}    ys[i] = {_advance('y[i]', A[st], st, arr)}",
                f"{indent}rhs(t + {float(C[st])!r} * h, ys, p, K[{st}])",
            ]
        out += [
            f"{indent}for i in range({n}):",
            f"{indent}    y_new[i] = {_advance('y[i]', B, N_STAGES, arr)}",
            f"{indent}rhs(t + h, y_new, p, K[{N_STAGES}])",
        ]
        return out

    def norm(n: str, indent: str) -> list[str]:
        return [
            f"{indent}for i in range({n}):",
            f"{indent}    scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol",
            f"{indent}    e5 = ({_sum(E5, N_STAGES + 1, arr)}) / scale",
            f"{indent}    e3 = ({_sum(E3, N_STAGES + 1, arr)}) / scale",
            f"{indent}    s5 += e5 * e5",
            f"{indent}    s3 += e3 * e3",
        ]

    lines = [
        "def _rk_step_unrolled(rhs, p, t, y, f, h, K, y_new, ys, dy):",
        *step(str(UNROLLED), "    "),
        "",
        "",
        "def _rk_step_loop(rhs, p, t, y, f, h, K, y_new, ys, dy):",
        "    n = y.shape[0]",
        *step("n", "    "),
        "",
        "",
        "def _error_norm_py(K, h, y, y_new, rtol, atol, n):",
        "    s5 = 0.0",
        "    s3 = 0.0",
        f"    if n == {UNROLLED}:",
        *norm(str(UNROLLED), "        "),
        "    else:",
        *norm("n", "        "),
        "    e5_2 = math.sqrt(s5) ** 2",
        "    e3_2 = math.sqrt(s3) ** 2",
        "    if e5_2 == 0.0 and e3_2 == 0.0:",
        "        return 0.0",
        "    return abs(h) * e5_2 / math.sqrt((e5_2 + 0.01 * e3_2) * n)",
        "",
        "",
        "def _dense_coefficients_py(rhs, p, t_old, h, y_old, y, K, F, ys, dy):",
        "    n = y.shape[0]",
    ]
    for st in range(N_STAGES + 1, N_STAGES_EXTENDED):
        lines += [
            "    for i in range(n):",
            f"        ys[i] = {_advance('y_old[i]', A[st], st, arr)}",
            f"    rhs(t_old + {float(C[st])!r} * h, ys, p, K[{st}])",
        ]
    lines += [
        "    for i in range(n):",
        "        d = y[i] - y_old[i]",
        "        F[0, i] = d",
        "        F[1, i] = h * K[0, i] - d",
        f"        F[2, i] = 2.0 * d - h * (K[{N_STAGES}, i] + K[0, i])",
    ]
    for r in range(INTERPOLATOR_POWER - 3):
        lines.append(f"        F[{3 + r}, i] = h * ({_sum(D[r], N_STAGES_EXTENDED, arr)})")
    return "\n".join(lines) + "\n"


def dop853() -> dict:
    """The data of ``dop853.py.j2``."""
    order = int(_rk.DOP853.error_estimator_order)
    if -1.0 / (order + 1) != -0.125:
        raise RuntimeError(f"the step-size control's roots assume the exponent -1/8, not {-1 / (order + 1)}")
    return {
        "n_stages": N_STAGES,
        "n_stages_extended": N_STAGES_EXTENDED,
        "interpolator_power": INTERPOLATOR_POWER,
        "safety": repr(float(_rk.SAFETY)),
        "min_factor": repr(float(_rk.MIN_FACTOR)),
        "max_factor": repr(float(_rk.MAX_FACTOR)),
        "unrolled": UNROLLED,
        "step_source": _step_source(),
    }


def exact_stance() -> dict:
    """The data of ``exact_stance.py.j2``: the stance row's columns, the polar order, the Jacobian's
    inputs (the touchdown state, then k_c, k_d and c: derive/maps/exact.py), the codes of its option
    ``liftoff`` and the simulator's settings."""
    from . import catalog
    from .model import simulation

    names = catalog.STANCE.names()
    polar = tuple(f.name for f in catalog.POLAR)
    groups = catalog.STANCE.subgroups()
    for group in ("bottom", "liftoff"):
        j = names.index(groups[group][0])
        if names[j : j + len(polar)] != groups[group]:
            raise RuntimeError(f"the stance row's {group} state is not contiguous in {names}")
    from .maps import exact

    return {
        "stance_names": names,
        "polar": polar,
        "t_bottom": names.index("t_bottom"),
        "t_stance": names.index("t_stance"),
        "bottom": names.index(groups["bottom"][0]),
        "liftoff": names.index(groups["liftoff"][0]),
        "inputs": exact.JACOBIAN_INPUTS,
        "liftoff_force": exact.LIFTOFF.code("force"),
        "liftoff_length": exact.LIFTOFF.code("length"),
        "collapse_fraction": repr(simulation.COLLAPSE_FRACTION),
        "cap_rtol": repr(simulation.DEFAULT_RTOL),
    }
