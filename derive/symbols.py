"""SymPy symbols of the report's Table 1, named as in generated code.

Conventions (written once here and in the README): leg angle ``q_th`` from the vertical,
counterclockwise positive; the body sits at (b_x, b_y) = (-q_r sin q_th, q_r cos q_th) relative
to the toe; SI units. Parameters are positive reals; ``k`` is the stiffness of a
constant-stiffness leg (the report's section 3), ``k_c``/``k_d`` the compression/decompression
stiffnesses (section 5).
"""

from __future__ import annotations

import sympy as sp

t = sp.Symbol("t", real=True)

# Parameters (Table 1).
m, l0, k, k_c, k_d, g_s, g_f = sp.symbols("m l0 k k_c k_d g_s g_f", positive=True)
# Leg damping (not in the report: the lossy leg's radial force -c q_rd), non-negative.
c = sp.Symbol("c", nonnegative=True)

# Polar stance coordinates as functions of time (for the Lagrangian derivation).
q_r_t = sp.Function("q_r", positive=True)(t)
q_th_t = sp.Function("q_th", real=True)(t)

# Polar state as plain symbols (for kernels): leg length, its rate, leg angle, its rate.
q_r = sp.Symbol("q_r", positive=True)
q_th = sp.Symbol("q_th", real=True)
q_rd, q_thd = sp.symbols("q_rd q_thd", real=True)
q_rdd, q_thdd = sp.symbols("q_rdd q_thdd", real=True)

# Momenta (Table 1).
p_r, p_th = sp.symbols("p_r p_th", real=True)

# Cartesian body state relative to the toe.
b_x_t = sp.Function("b_x", real=True)(t)
b_y_t = sp.Function("b_y", real=True)(t)
b_x, b_y, b_xd, b_yd = sp.symbols("b_x b_y b_xd b_yd", real=True)

# Touchdown and liftoff quantities.
q_r_td = sp.Symbol("q_r_td", positive=True)
q_rd_td, q_th_td, q_thd_td = sp.symbols("q_rd_td q_th_td q_thd_td", real=True)
q_r_lo = sp.Symbol("q_r_lo", positive=True)

# Apex quantities.
b_y_apex, b_xd_apex = sp.symbols("b_y_apex b_xd_apex", real=True)
#: Height of the touchdown ground above the ground under the apex (a step up is positive).
ground = sp.Symbol("ground", real=True)

# Geyer et al.'s dimensionless quantities (eq 7) and solution parameters (eqs 9, 11).
rho = sp.Symbol("rho", real=True)
rho_d = sp.Symbol("rho_d", real=True)
epsilon, omega = sp.symbols("epsilon omega", real=True)
omega0 = sp.Symbol("omega0", positive=True)
omega0_hat = sp.Symbol("omega0_hat", positive=True)
lam, mu, nu = sp.symbols("lambda mu nu", real=True)
a, b = sp.symbols("a b", real=True)
E = sp.Symbol("E", real=True)
