"""Derived forms shared by the rows of the iterative map (section 3.2, eqs 27-45, and both halves of
section 5.2, eqs 114-151): the Hamiltonian and its vector field, the rates per leg length, the
iterates and the corrected radial momentum of the (n+1)-th iterate. It registers no equation.
"""

from __future__ import annotations

import sympy as sp

from ..maps import iterative_helpers
from ..maps.iterative_helpers import P_TH_NEXT, Q_TH_NEXT
from ..model import mechanics
from ..symbols import g_s, l0, m, p_th, q_r, q_th, t
from . import forms

XI = sp.Symbol("xi", positive=True)  # the mean-value point xi_hat_r, as a symbol
T_NEXT, P_R_NEXT = sp.Function("t_n1", real=True), sp.Function("p_r_n1", real=True)  # (n+1)-th iterates
_RATES = sp.symbols("q_rd q_thd p_rd p_thd")


def hamiltonian_form(name: str, stiffness):
    """``name`` = H of (27) with the stiffness ``stiffness`` ((27), (114), (137))."""
    return forms((sp.Symbol(name), mechanics.hamiltonian(stiffness)))


def vector_field_forms(stiffness):
    """Hamilton's equations (29) of H with ``stiffness``: (dq_r/dt, dq_th/dt, dp_r/dt, dp_th/dt)."""
    return forms(*zip(_RATES, mechanics.hamiltonian_vector_field(stiffness), strict=True))


def rate_form(stiffness, row: int):
    """Row ``row`` of (30)-(32) ((116)-(118)): d(t, q_th, p_th)/dq_r = the rate of (29) over dq_r/dt."""
    variable = (t, q_th, p_th)[row]
    return forms((sp.Derivative(variable, q_r), iterative_helpers.leg_length_derivatives(stiffness)[row]))


def iterate_form(rows, row: int, point=None):
    """Row ``row`` of an iterate ``rows`` (t, q_th, p_th of the (n+1)-th iterate at q_r), and the
    mean-value point xi = ``point`` when given."""
    lhs = (T_NEXT, Q_TH_NEXT, P_TH_NEXT)[row](q_r)
    return forms((lhs, rows[row])) + (forms((XI, point)) if point is not None else ())


def next_momentum(stiffness, energy, sign: int):
    """Corrected (45), (127), (136), (142), (151): p_r of the (n+1)-th iterate at q_r (not at xi),
    ``sign`` H^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), energy)."""
    return sign * sp.sqrt(
        2 * m * (energy - stiffness / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(Q_TH_NEXT(q_r)))
        - P_TH_NEXT(q_r) ** 2 / q_r**2
    )


def next_momentum_form(stiffness, energy, sign: int):
    return forms((P_R_NEXT(q_r), next_momentum(stiffness, energy, sign)))
