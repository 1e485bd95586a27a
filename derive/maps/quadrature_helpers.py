"""Gauss-Legendre rules in u = sqrt((sigma - q_r_b)/(x - q_r_b)) for the half-stance integrals of (30)-(32).

Near the bottom p_r vanishes like (sigma - q_r_b)^(1/2), so the integrands of (38)-(40) grow like
(sigma - q_r_b)^(-1/2). With sigma = q_r_b + D u^2 (D = x - q_r_b) the integrals become
int_0^1 f(sigma(u)) 2 D u du with a regular integrand, and the one-node Gauss-Legendre rule on
u in [0, 1] (node 1/2, weight 1) is exactly the mean-value rule of (37) with xi = 3/4 q_r_b + 1/4 x
of (41). N nodes are its refinement (docs/mean_value_point.md). A helper of the map ``iterative``
(:mod:`.iterative`); this module declares no map.

:func:`rule` gives, for N nodes u_j in (0, 1), the weights and the integration matrices of the
Lagrange interpolant through the nodes (collocation): ``S[j][k] = int_0^{u_j} L_k(v) dv`` and
``S1[j][k] = int_0^{u_j} v L_k(v) dv``, ``w`` and ``w1`` the same to u = 1. Values are SymPy Floats
computed at 40 digits from the Legendre polynomial's roots, so generation is deterministic.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

__all__ = ["Rule", "rule"]

_DIGITS = 40
_PRINT_DIGITS = 20


@dataclass(frozen=True)
class Rule:
    """An N-node Gauss-Legendre rule on [0, 1] with its collocation integration matrices."""

    nodes: tuple[sp.Float, ...]
    w: tuple[sp.Float, ...]  # int_0^1 L_k
    w1: tuple[sp.Float, ...]  # int_0^1 v L_k
    S: tuple[tuple[sp.Float, ...], ...]  # int_0^{u_j} L_k
    S1: tuple[tuple[sp.Float, ...], ...]  # int_0^{u_j} v L_k

    @property
    def n(self) -> int:
        return len(self.nodes)


@cache
def rule(n: int) -> Rule:
    """The ``n``-node rule (1 <= n <= 12)."""
    if not 1 <= n <= 12:
        raise ValueError(f"node count {n} outside 1..12")
    x, v = sp.symbols("x v")
    roots = sorted(sp.Poly(sp.legendre(n, x), x).nroots(n=_DIGITS, maxsteps=200))
    nodes = [(r + 1) / 2 for r in roots]
    lagrange = []
    for k, uk in enumerate(nodes):
        poly = sp.Integer(1)
        for j, uj in enumerate(nodes):
            if j != k:
                poly *= (v - uj) / (uk - uj)
        lagrange.append(sp.Poly(sp.expand(poly), v))

    def integral(poly: sp.Poly, upper, weight_v: bool) -> sp.Float:
        p = poly * sp.Poly(v, v) if weight_v else poly
        return sp.Float(p.integrate().eval(upper) - p.integrate().eval(0), _PRINT_DIGITS)

    def row(upper, weight_v):
        return tuple(integral(L, upper, weight_v) for L in lagrange)

    return Rule(
        nodes=tuple(sp.Float(u, _PRINT_DIGITS) for u in nodes),
        w=row(1, False),
        w1=row(1, True),
        S=tuple(row(u, False) for u in nodes),
        S1=tuple(row(u, True) for u in nodes),
    )
