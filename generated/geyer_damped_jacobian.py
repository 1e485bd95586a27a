# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer_damped.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer_damped: JVP kernels, and for a
map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_OVERDAMPED)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def damped_liftoff_jac_a_omega_D_A_c_B_s_delta_k_d(a, omega_D, A_c, B_s, delta, m, l0, k_d, q_r_lo, liftoff,
        out):
    """Liftoff of the damped decompression half: the first zero of the leg force (or of q_r - q_r_lo) after
    the bottom, safeguarded Halley, and the derivatives of its outputs with respect to a, omega_D, A_c, B_s,
    delta, k_d.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`geyer_damped.damped_liftoff`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer_damped.damped_liftoff`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument a, omega_D, A_c, B_s,
            delta, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 1099
    # liftoff lies in (0, pi / omega_D) after the bottom, where rho increases
    _x3 = (1.0/omega_D)
    _x0 = math.pi*_x3
    _half = _x0
    _d_half__omega_D = -math.pi*_x3**2
    _x1 = (0.5)*delta
    _x2 = math.exp(-_x0*_x1)
    _decay_quarter = _x2
    _d_decay_quarter__omega_D = -_d_half__omega_D*_x1*_x2
    _d_decay_quarter__delta = -0.5*_x0*_x2
    # the k_d spring extends the leg at the bottom
    if not ((A_c < 0.0)):
        return fail(out, STATUS_RECOMPRESSION)
    # the bottom lies below the liftoff
    if not ((A_c + a + ((2.0*delta*m*(-A_c*delta + B_s*omega_D)/k_d) if (liftoff == 0.0) and (q_r_lo/l0
            >= -2.0*delta*m*(-A_c*delta + B_s*omega_D)/k_d + 1.0) else (1.0 - q_r_lo/l0)) < 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # the leg reaches liftoff within half a damped period
    if not ((-A_c*_decay_quarter**2 + a + ((2.0*delta*m*(A_c*_decay_quarter**2*delta
            - B_s*_decay_quarter**2*omega_D)/k_d) if (liftoff == 0.0) and (q_r_lo/l0
            >= -2.0*delta*m*(A_c*_decay_quarter**2*delta - B_s*_decay_quarter**2*omega_D)/k_d + 1.0) else (1.0
            - q_r_lo/l0)) > 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # the form of the condition the first iterate solves
    _x4 = (liftoff == 0.0) and (l0 <= q_r_lo) and (delta > 0.0)
    _form_c = ((a) if _x4 else (a + 1.0 - q_r_lo/l0))
    _x5 = (1.0/k_d)
    _x6 = _x5*m
    _x7 = 2.0*_x6
    _x8 = _x7*delta
    _x9 = B_s*_x8
    _x10 = delta**2
    _x11 = _x10*_x7
    _form_p = ((-A_c*_x11 + A_c + _x9*omega_D) if _x4 else (A_c))
    _d_form_p__omega_D = ((_x9) if _x4 else (0.0))
    _x12 = ((1.0 - _x11) if _x4 else (1.0))
    _d_form_p__A_c = _x12
    _x13 = _x8*omega_D
    _d_form_p__B_s = ((_x13) if _x4 else (0.0))
    _x14 = A_c*delta
    _x15 = 4.0*_x6
    _d_form_p__delta = ((2.0*B_s*_x5*m*omega_D - _x14*_x15) if _x4 else (0.0))
    _x16 = B_s*delta
    _x17 = 2.0*_x5**2*m
    _x18 = _x17*omega_D
    _x19 = _x10*_x17
    _d_form_p__k_d = ((A_c*_x19 - _x16*_x18) if _x4 else (0.0))
    _form_q = ((-A_c*_x13 - B_s*_x11 + B_s) if _x4 else (B_s))
    _d_form_q__omega_D = ((-A_c*_x8) if _x4 else (0.0))
    _d_form_q__A_c = ((-_x13) if _x4 else (0.0))
    _d_form_q__B_s = _x12
    _d_form_q__delta = ((-A_c*_x7*omega_D - _x15*_x16) if _x4 else (0.0))
    _d_form_q__k_d = ((B_s*_x19 + _x14*_x18) if _x4 else (0.0))
    # the root with the decay frozen at a quarter period (the root itself at c = 0)
    _x20 = (1.0/omega_D)
    _x21 = (1.0/_form_p)
    _x22 = (1.0/_decay_quarter)
    _x23 = _form_p**2
    _x24 = _form_q**2 + _x23
    _x25 = (1.0/math.sqrt(_x24))
    _x26 = _x22*_x25
    _x27 = _form_c*_x26
    _x28 = (_x27 < -1.0)
    _x29 = (_x27 > 1.0)
    _x30 = _form_q*_x21 + math.acos(((-1.0) if _x28 else (1.0) if _x29 else (_x27)))
    _first = _x20*_x30
    _x31 = _x28 or _x29
    _x32 = _x22**2
    _x33 = (1.0/math.sqrt(1.0 - ((1.0) if _x31 else (_form_c**2*_x32/_x24))))
    _x34 = _x20*_x33
    _pd__0 = -_x34*((0.0) if _x31 else (-_form_c*_x25*_x32))
    _x35 = _form_c*_x22/(_x24*math.sqrt(_x24))
    _pd__1 = _x20*(-_form_q/_x23 - _x33*((0.0) if _x31 else (-_form_p*_x35)))
    _pd__2 = _x20*(_x21 - _x33*((0.0) if _x31 else (-_form_q*_x35)))
    _d_first__a = -_x34*((0.0) if _x31 else (_x26))
    _d_first__omega_D = (_d_decay_quarter__omega_D*_pd__0 + _d_form_p__omega_D*_pd__1
        + _d_form_q__omega_D*_pd__2 - _x20**2*_x30)
    _d_first__A_c = _d_form_p__A_c*_pd__1 + _d_form_q__A_c*_pd__2
    _d_first__B_s = _d_form_p__B_s*_pd__1 + _d_form_q__B_s*_pd__2
    _d_first__delta = _d_decay_quarter__delta*_pd__0 + _d_form_p__delta*_pd__1 + _d_form_q__delta*_pd__2
    _d_first__k_d = _d_form_p__k_d*_pd__1 + _d_form_q__k_d*_pd__2
    # the first iterate, inside the bracket
    _x36 = max(0.0, _first)
    _x37 = min(_half, _x36)
    _tau0 = _x37
    _x38 = _half - _x36
    _pd__3 = ((((0.0) if (_first < 0.0) else (0.5) if (_first == 0.0) else (1.0)))*(((0.0) if (_x38 < 0.0)
        else (0.5) if (_x38 == 0.0) else (1.0))))
    _d_tau0__a = _d_first__a*_pd__3
    _d_tau0__omega_D = (_d_first__omega_D*_pd__3 + _d_half__omega_D*(((0.0) if (_x38 > 0.0) else (0.5)
        if (_x38 == 0.0) else (1.0))))
    _d_tau0__A_c = _d_first__A_c*_pd__3
    _d_tau0__B_s = _d_first__B_s*_pd__3
    _d_tau0__delta = _d_first__delta*_pd__3
    _d_tau0__k_d = _d_first__k_d*_pd__3
    _x39 = _x37*omega_D
    _x40 = math.cos(_x39)
    _cos0 = _x40
    _x41 = math.sin(_x39)
    _pd__4 = -_x41*omega_D
    _d_cos0__a = _d_tau0__a*_pd__4
    _d_cos0__omega_D = _d_tau0__omega_D*_pd__4 - _x37*_x41
    _d_cos0__A_c = _d_tau0__A_c*_pd__4
    _d_cos0__B_s = _d_tau0__B_s*_pd__4
    _d_cos0__delta = _d_tau0__delta*_pd__4
    _d_cos0__k_d = _d_tau0__k_d*_pd__4
    _sin0 = _x41
    _pd__5 = _x40*omega_D
    _d_sin0__a = _d_tau0__a*_pd__5
    _d_sin0__omega_D = _d_tau0__omega_D*_pd__5 + _x37*_x40
    _d_sin0__A_c = _d_tau0__A_c*_pd__5
    _d_sin0__B_s = _d_tau0__B_s*_pd__5
    _d_sin0__delta = _d_tau0__delta*_pd__5
    _d_sin0__k_d = _d_tau0__k_d*_pd__5
    _x42 = math.exp(-_x37*delta)
    _exp0 = _x42
    _pd__6 = -_x42*delta
    _d_exp0__a = _d_tau0__a*_pd__6
    _d_exp0__omega_D = _d_tau0__omega_D*_pd__6
    _d_exp0__A_c = _d_tau0__A_c*_pd__6
    _d_exp0__B_s = _d_tau0__B_s*_pd__6
    _d_exp0__delta = _d_tau0__delta*_pd__6 - _x37*_x42
    _d_exp0__k_d = _d_tau0__k_d*_pd__6
    # Halley's method on g, safeguarded by bisection on its bracket
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (_tau0, 0.0, 0.0, _half, _cos0, _sin0, _exp0, _d_tau0__a, _d_tau0__omega_D, _d_tau0__A_c,
        _d_tau0__B_s, _d_tau0__delta, _d_tau0__k_d, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, _d_half__omega_D, 0.0, 0.0, 0.0, 0.0, _d_cos0__a, _d_cos0__omega_D, _d_cos0__A_c,
        _d_cos0__B_s, _d_cos0__delta, _d_cos0__k_d, _d_sin0__a, _d_sin0__omega_D, _d_sin0__A_c, _d_sin0__B_s,
        _d_sin0__delta, _d_sin0__k_d, _d_exp0__a, _d_exp0__omega_D, _d_exp0__A_c, _d_exp0__B_s,
        _d_exp0__delta, _d_exp0__k_d, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(60.0), 0)
    for _it0 in range(_last0 + 1):
        (tau, _bisections, _lo, _hi, cos_t, sin_t, exp_t, d_tau__a, d_tau__omega_D, d_tau__A_c, d_tau__B_s,
            d_tau__delta, d_tau__k_d, _d_bisections__a, _d_bisections__omega_D, _d_bisections__A_c,
            _d_bisections__B_s, _d_bisections__delta, _d_bisections__k_d, _d_lo__a, _d_lo__omega_D,
            _d_lo__A_c, _d_lo__B_s, _d_lo__delta, _d_lo__k_d, _d_hi__a, _d_hi__omega_D, _d_hi__A_c,
            _d_hi__B_s, _d_hi__delta, _d_hi__k_d, d_cos_t__a, d_cos_t__omega_D, d_cos_t__A_c, d_cos_t__B_s,
            d_cos_t__delta, d_cos_t__k_d, d_sin_t__a, d_sin_t__omega_D, d_sin_t__A_c, d_sin_t__B_s,
            d_sin_t__delta, d_sin_t__k_d, d_exp_t__a, d_exp_t__omega_D, d_exp_t__A_c, d_exp_t__B_s,
            d_exp_t__delta, d_exp_t__k_d, ) = _pk0
        if _it0 == _last0 and not _conv0 and 1e-06 > 0.0 and _passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        if _conv0 or _it0 == _last0:
            break
        # g and its derivatives at the iterate
        _x43 = A_c*exp_t
        _x44 = _x43*cos_t
        _x45 = _x44*delta
        _x46 = _x43*omega_D
        _x47 = _x46*sin_t
        _x48 = B_s*sin_t
        _x49 = _x48*exp_t
        _x50 = _x49*delta
        _x51 = -B_s*cos_t*exp_t*omega_D + _x45 + _x47 + _x50
        _x52 = -_x51
        _x53 = 2.0*m
        _x109 = (1.0/k_d)
        _x54 = _x109*_x53
        _x55 = _x52*_x54
        _x56 = _x55*delta
        _x57 = q_r_lo/l0
        _x58 = (liftoff == 0.0) and (_x57 >= 1.0 - _x56)
        _x59 = _x44 + _x49
        _g = _x59 + a + ((_x56) if _x58 else (1.0 - _x57))
        _x60 = _x43*delta
        _x61 = _x54*delta
        _pd__7 = _x43 + ((_x61*(B_s*exp_t*omega_D - _x60)) if _x58 else (0.0))
        _x62 = A_c*cos_t
        _x63 = A_c*omega_D*sin_t
        _x64 = -B_s*cos_t*omega_D + _x48*delta + _x62*delta + _x63
        _pd__8 = _x48 + _x62 + ((-_x61*_x64) if _x58 else (0.0))
        _x65 = B_s*exp_t
        _x66 = _x65*delta
        _x67 = _x46 + _x66
        _pd__9 = _x65 + ((-_x61*_x67) if _x58 else (0.0))
        _d_g__a = _pd__7*d_cos_t__a + _pd__8*d_exp_t__a + _pd__9*d_sin_t__a + 1.0
        _x68 = _x43*sin_t
        _d_g__omega_D = (_pd__7*d_cos_t__omega_D + _pd__8*d_exp_t__omega_D + _pd__9*d_sin_t__omega_D
            + ((_x61*(B_s*cos_t*exp_t - _x68)) if _x58 else (0.0)))
        _x69 = cos_t*exp_t
        _x70 = _x69*delta
        _x71 = exp_t*sin_t
        _x72 = _x71*omega_D
        _d_g__A_c = (_pd__7*d_cos_t__A_c + _pd__8*d_exp_t__A_c + _pd__9*d_sin_t__A_c + _x69 + ((_x61*(-_x70
            - _x72)) if _x58 else (0.0)))
        _x73 = _x69*omega_D
        _x74 = _x71*delta
        _x75 = _x73 - _x74
        _d_g__B_s = (_pd__7*d_cos_t__B_s + _pd__8*d_exp_t__B_s + _pd__9*d_sin_t__B_s + _x71 + ((_x61*_x75)
            if _x58 else (0.0)))
        _d_g__delta = (_pd__7*d_cos_t__delta + _pd__8*d_exp_t__delta + _pd__9*d_sin_t__delta + ((_x55
            - _x59*_x61) if _x58 else (0.0)))
        _x76 = _x109**2*_x53*delta
        _d_g__k_d = (_pd__7*d_cos_t__k_d + _pd__8*d_exp_t__k_d + _pd__9*d_sin_t__k_d + ((-_x52*_x76) if _x58
            else (0.0)))
        _x77 = delta**2
        _x78 = _x44*_x77
        _x79 = _x49*_x77
        _x80 = 2.0*omega_D
        _x81 = _x60*_x80
        _x82 = _x65*omega_D
        _x83 = _x82*cos_t
        _x84 = 2.0*delta
        _x85 = omega_D**2
        _x86 = -_x44*_x85 - _x49*_x85 + _x78 + _x79 + _x81*sin_t - _x83*_x84
        _x87 = _x54*_x86
        _dg = -_x51 + ((_x87*delta) if _x58 else (0.0))
        _x88 = _x43*_x85
        _x89 = _x82*_x84
        _pd__10 = -_x60 + _x82 + ((_x61*(A_c*_x77*exp_t - _x88 - _x89)) if _x58 else (0.0))
        _x90 = B_s*cos_t
        _x91 = _x48*_x77 - _x48*_x85 + _x62*_x77 - _x62*_x85 + _x63*_x84 - _x84*_x90*omega_D
        _pd__11 = -_x64 + ((_x61*_x91) if _x58 else (0.0))
        _x92 = _x65*_x77 - _x65*_x85 + _x81
        _pd__12 = -_x67 + ((_x61*_x92) if _x58 else (0.0))
        _d_dg__a = _pd__10*d_cos_t__a + _pd__11*d_exp_t__a + _pd__12*d_sin_t__a
        _x93 = _x65*cos_t
        _x94 = _x44*_x80
        _x95 = 2.0*_x66*cos_t
        _x96 = _x49*_x80
        _d_dg__omega_D = (_pd__10*d_cos_t__omega_D + _pd__11*d_exp_t__omega_D + _pd__12*d_sin_t__omega_D
            - _x68 + _x93 + ((_x61*(2.0*A_c*delta*exp_t*sin_t - _x94 - _x95 - _x96)) if _x58 else (0.0)))
        _x97 = _x69*_x77 - _x69*_x85 + _x72*_x84
        _d_dg__A_c = (_pd__10*d_cos_t__A_c + _pd__11*d_exp_t__A_c + _pd__12*d_sin_t__A_c - _x70 - _x72
            + ((_x61*_x97) if _x58 else (0.0)))
        _x98 = _x71*_x85
        _x99 = _x70*_x80
        _d_dg__B_s = (_pd__10*d_cos_t__B_s + _pd__11*d_exp_t__B_s + _pd__12*d_sin_t__B_s + _x75
            + ((_x61*(_x77*exp_t*sin_t - _x98 - _x99)) if _x58 else (0.0)))
        _x100 = 2.0*_x45 + 2.0*_x47 + 2.0*_x50 - 2.0*_x83
        _d_dg__delta = (_pd__10*d_cos_t__delta + _pd__11*d_exp_t__delta + _pd__12*d_sin_t__delta - _x44 - _x49
            + ((_x100*_x61 + _x87) if _x58 else (0.0)))
        _d_dg__k_d = (_pd__10*d_cos_t__k_d + _pd__11*d_exp_t__k_d + _pd__12*d_sin_t__k_d + ((-_x76*_x86)
            if _x58 else (0.0)))
        _x101 = delta**3
        _x102 = omega_D**3
        _x103 = 3.0*_x77
        _x104 = (A_c*_x102*exp_t*sin_t + 3.0*A_c*_x85*cos_t*delta*exp_t + 3.0*B_s*_x77*cos_t*exp_t*omega_D
            + 3.0*B_s*_x85*delta*exp_t*sin_t - _x101*_x44 - _x101*_x49 - _x102*_x93 - _x103*_x47)
        _x105 = _x104*_x54
        _ddg = _x86 + ((_x105*delta) if _x58 else (0.0))
        _pd__13 = (_x43*_x77 - _x88 - _x89 + ((_x61*(3.0*A_c*_x85*delta*exp_t + 3.0*B_s*_x77*exp_t*omega_D
            - _x101*_x43 - _x102*_x65)) if _x58 else (0.0)))
        _pd__14 = (_x91 + ((_x61*(A_c*_x102*sin_t + 3.0*A_c*_x85*cos_t*delta + 3.0*B_s*_x77*cos_t*omega_D
            + 3.0*B_s*_x85*delta*sin_t - _x101*_x48 - _x101*_x62 - _x102*_x90 - _x103*_x63)) if _x58
            else (0.0)))
        _pd__15 = (_x92 + ((_x61*(A_c*_x102*exp_t + 3.0*B_s*_x85*delta*exp_t - _x101*_x65 - _x103*_x46))
            if _x58 else (0.0)))
        _d_ddg__a = _pd__13*d_cos_t__a + _pd__14*d_exp_t__a + _pd__15*d_sin_t__a
        _x106 = _x60*sin_t
        _x107 = 6.0*omega_D
        _x108 = 3.0*_x85
        _d_ddg__omega_D = (_pd__13*d_cos_t__omega_D + _pd__14*d_exp_t__omega_D + _pd__15*d_sin_t__omega_D
            + 2.0*_x106 - _x94 - _x95 - _x96 + ((_x61*(-_x103*_x68 + _x103*_x93 + _x107*_x45 + _x107*_x50
            + _x108*_x68 - _x108*_x93)) if _x58 else (0.0)))
        _d_ddg__A_c = (_pd__13*d_cos_t__A_c + _pd__14*d_exp_t__A_c + _pd__15*d_sin_t__A_c + _x97
            + ((_x61*(-_x101*_x69 + _x102*exp_t*sin_t - _x103*_x72 + 3.0*_x85*cos_t*delta*exp_t)) if _x58
            else (0.0)))
        _d_ddg__B_s = (_pd__13*d_cos_t__B_s + _pd__14*d_exp_t__B_s + _pd__15*d_sin_t__B_s + _x71*_x77 - _x98
            - _x99 + ((_x61*(-_x101*_x71 - _x102*_x69 + _x103*_x73 + _x108*_x74)) if _x58 else (0.0)))
        _d_ddg__delta = (_pd__13*d_cos_t__delta + _pd__14*d_exp_t__delta + _pd__15*d_sin_t__delta + _x100
            + ((_x105 + _x61*(3.0*A_c*_x85*cos_t*exp_t + 3.0*B_s*_x85*exp_t*sin_t
            + 6.0*B_s*cos_t*delta*exp_t*omega_D - _x106*_x107 - 3.0*_x78 - 3.0*_x79)) if _x58 else (0.0)))
        _d_ddg__k_d = (_pd__13*d_cos_t__k_d + _pd__14*d_exp_t__k_d + _pd__15*d_sin_t__k_d + ((-_x104*_x76)
            if _x58 else (0.0)))
        # the bracket and Halley's step
        _x110 = (_g < 0.0)
        _lo_next = ((tau) if _x110 else (_lo))
        _x111 = ((0.0) if _x110 else (1.0))
        _pd__16 = _x111
        _x112 = ((1.0) if _x110 else (0.0))
        _pd__17 = _x112
        _d_lo_next__a = _d_lo__a*_pd__16 + _pd__17*d_tau__a
        _d_lo_next__omega_D = _d_lo__omega_D*_pd__16 + _pd__17*d_tau__omega_D
        _d_lo_next__A_c = _d_lo__A_c*_pd__16 + _pd__17*d_tau__A_c
        _d_lo_next__B_s = _d_lo__B_s*_pd__16 + _pd__17*d_tau__B_s
        _d_lo_next__delta = _d_lo__delta*_pd__16 + _pd__17*d_tau__delta
        _d_lo_next__k_d = _d_lo__k_d*_pd__16 + _pd__17*d_tau__k_d
        _hi_next = ((_hi) if _x110 else (tau))
        _pd__18 = _x112
        _pd__19 = _x111
        _d_hi_next__a = _d_hi__a*_pd__18 + _pd__19*d_tau__a
        _d_hi_next__omega_D = _d_hi__omega_D*_pd__18 + _pd__19*d_tau__omega_D
        _d_hi_next__A_c = _d_hi__A_c*_pd__18 + _pd__19*d_tau__A_c
        _d_hi_next__B_s = _d_hi__B_s*_pd__18 + _pd__19*d_tau__B_s
        _d_hi_next__delta = _d_hi__delta*_pd__18 + _pd__19*d_tau__delta
        _d_hi_next__k_d = _d_hi__k_d*_pd__18 + _pd__19*d_tau__k_d
        _x113 = _ddg*_g
        _x114 = _dg**2
        _x115 = -_x113 + 2.0*_x114
        _x120 = (1.0/_x115)
        _x116 = 2.0*_x120
        _x117 = _g*_x116
        _halley = -_dg*_x117 + tau
        _x118 = _x120**2
        _x119 = 2.0*_dg*_x118
        _pd__20 = -_g**2*_x119
        _pd__21 = 8.0*_g*_x114*_x118 - _x117
        _pd__22 = -_dg*_x116 - _x113*_x119
        _d_halley__a = _d_ddg__a*_pd__20 + _d_dg__a*_pd__21 + _d_g__a*_pd__22 + d_tau__a
        _d_halley__omega_D = (_d_ddg__omega_D*_pd__20 + _d_dg__omega_D*_pd__21 + _d_g__omega_D*_pd__22
            + d_tau__omega_D)
        _d_halley__A_c = _d_ddg__A_c*_pd__20 + _d_dg__A_c*_pd__21 + _d_g__A_c*_pd__22 + d_tau__A_c
        _d_halley__B_s = _d_ddg__B_s*_pd__20 + _d_dg__B_s*_pd__21 + _d_g__B_s*_pd__22 + d_tau__B_s
        _d_halley__delta = _d_ddg__delta*_pd__20 + _d_dg__delta*_pd__21 + _d_g__delta*_pd__22 + d_tau__delta
        _d_halley__k_d = _d_ddg__k_d*_pd__20 + _d_dg__k_d*_pd__21 + _d_g__k_d*_pd__22 + d_tau__k_d
        # Halley's step where it is safe, else bisection (counted: the loop stops on Halley steps only)
        _x121 = (_halley >= _lo_next) and (_halley <= _hi_next) and (_dg > 0.0)
        _x122 = ((0.0) if _x121 else (1.0))
        _bisect = _x122
        _tau_next = ((_halley) if _x121 else ((0.5)*_hi_next + (0.5)*_lo_next))
        _pd__23 = ((1.0) if _x121 else (0.0))
        _x123 = ((0.0) if _x121 else (0.5))
        _pd__24 = _x123
        _pd__25 = _x123
        _d_tau_next__a = _d_halley__a*_pd__23 + _d_hi_next__a*_pd__24 + _d_lo_next__a*_pd__25
        _d_tau_next__omega_D = (_d_halley__omega_D*_pd__23 + _d_hi_next__omega_D*_pd__24
            + _d_lo_next__omega_D*_pd__25)
        _d_tau_next__A_c = _d_halley__A_c*_pd__23 + _d_hi_next__A_c*_pd__24 + _d_lo_next__A_c*_pd__25
        _d_tau_next__B_s = _d_halley__B_s*_pd__23 + _d_hi_next__B_s*_pd__24 + _d_lo_next__B_s*_pd__25
        _d_tau_next__delta = _d_halley__delta*_pd__23 + _d_hi_next__delta*_pd__24 + _d_lo_next__delta*_pd__25
        _d_tau_next__k_d = _d_halley__k_d*_pd__23 + _d_hi_next__k_d*_pd__24 + _d_lo_next__k_d*_pd__25
        _bisections_next = _bisections + _x122
        # the step in omega_D t and in -delta t
        _x124 = _tau_next - tau
        _du = _x124*omega_D
        _d_du__a = _d_tau_next__a*omega_D - d_tau__a*omega_D
        _d_du__omega_D = _d_tau_next__omega_D*omega_D + _x124 - d_tau__omega_D*omega_D
        _d_du__A_c = _d_tau_next__A_c*omega_D - d_tau__A_c*omega_D
        _d_du__B_s = _d_tau_next__B_s*omega_D - d_tau__B_s*omega_D
        _d_du__delta = _d_tau_next__delta*omega_D - d_tau__delta*omega_D
        _d_du__k_d = _d_tau_next__k_d*omega_D - d_tau__k_d*omega_D
        _dv = -_x124*delta
        _d_dv__a = -_d_tau_next__a*delta + d_tau__a*delta
        _d_dv__omega_D = -_d_tau_next__omega_D*delta + d_tau__omega_D*delta
        _d_dv__A_c = -_d_tau_next__A_c*delta + d_tau__A_c*delta
        _d_dv__B_s = -_d_tau_next__B_s*delta + d_tau__B_s*delta
        _d_dv__delta = -_d_tau_next__delta*delta - _x124 + d_tau__delta*delta
        _d_dv__k_d = -_d_tau_next__k_d*delta + d_tau__k_d*delta
        # cos, sin, exp at the next iterate: Taylor steps when it is close
        _x125 = -0.001388888888888889*_du**6 + (0.041666666666666664)*_du**4 - 0.5*_du**2 + 1.0
        _x126 = _x125*cos_t
        _x127 = (0.16666666666666666)*_du**3
        _x128 = (0.008333333333333333)*_du**5
        _x129 = (0.0001984126984126984)*_du**7 - _du + _x127 - _x128
        _x130 = -_x129
        _x131 = (abs(_du) <= 0.01) and (abs(_dv) <= 0.01)
        _x132 = _tau_next*omega_D
        _x133 = math.cos(_x132)
        _cos_next = ((_x126 - _x130*sin_t) if _x131 else (_x133))
        _x134 = -_du + _x127 - _x128
        _x135 = _x125*sin_t
        _pd__26 = ((_x134*cos_t - _x135) if _x131 else (0.0))
        _x136 = math.sin(_x132)
        _pd__27 = ((0.0) if _x131 else (-_x136*omega_D))
        _x137 = ((_x125) if _x131 else (0.0))
        _pd__28 = _x137
        _pd__29 = ((_x129) if _x131 else (0.0))
        _d_cos_next__a = _d_du__a*_pd__26 + _d_tau_next__a*_pd__27 + _pd__28*d_cos_t__a + _pd__29*d_sin_t__a
        _d_cos_next__omega_D = (_d_du__omega_D*_pd__26 + _d_tau_next__omega_D*_pd__27
            + _pd__28*d_cos_t__omega_D + _pd__29*d_sin_t__omega_D + ((0.0) if _x131 else (-_tau_next*_x136)))
        _d_cos_next__A_c = (_d_du__A_c*_pd__26 + _d_tau_next__A_c*_pd__27 + _pd__28*d_cos_t__A_c
            + _pd__29*d_sin_t__A_c)
        _d_cos_next__B_s = (_d_du__B_s*_pd__26 + _d_tau_next__B_s*_pd__27 + _pd__28*d_cos_t__B_s
            + _pd__29*d_sin_t__B_s)
        _d_cos_next__delta = (_d_du__delta*_pd__26 + _d_tau_next__delta*_pd__27 + _pd__28*d_cos_t__delta
            + _pd__29*d_sin_t__delta)
        _d_cos_next__k_d = (_d_du__k_d*_pd__26 + _d_tau_next__k_d*_pd__27 + _pd__28*d_cos_t__k_d
            + _pd__29*d_sin_t__k_d)
        _sin_next = ((_x130*cos_t + _x135) if _x131 else (_x136))
        _pd__30 = ((_x126 + _x134*sin_t) if _x131 else (0.0))
        _pd__31 = ((0.0) if _x131 else (_x133*omega_D))
        _pd__32 = ((_x130) if _x131 else (0.0))
        _pd__33 = _x137
        _d_sin_next__a = _d_du__a*_pd__30 + _d_tau_next__a*_pd__31 + _pd__32*d_cos_t__a + _pd__33*d_sin_t__a
        _d_sin_next__omega_D = (_d_du__omega_D*_pd__30 + _d_tau_next__omega_D*_pd__31
            + _pd__32*d_cos_t__omega_D + _pd__33*d_sin_t__omega_D + ((0.0) if _x131 else (_tau_next*_x133)))
        _d_sin_next__A_c = (_d_du__A_c*_pd__30 + _d_tau_next__A_c*_pd__31 + _pd__32*d_cos_t__A_c
            + _pd__33*d_sin_t__A_c)
        _d_sin_next__B_s = (_d_du__B_s*_pd__30 + _d_tau_next__B_s*_pd__31 + _pd__32*d_cos_t__B_s
            + _pd__33*d_sin_t__B_s)
        _d_sin_next__delta = (_d_du__delta*_pd__30 + _d_tau_next__delta*_pd__31 + _pd__32*d_cos_t__delta
            + _pd__33*d_sin_t__delta)
        _d_sin_next__k_d = (_d_du__k_d*_pd__30 + _d_tau_next__k_d*_pd__31 + _pd__32*d_cos_t__k_d
            + _pd__33*d_sin_t__k_d)
        _x138 = ((0.001388888888888889)*_dv**6 + (0.008333333333333333)*_dv**5 + (0.041666666666666664)*_dv**4
            + (0.16666666666666666)*_dv**3 + (0.5)*_dv**2 + _dv + 1.0)
        _x139 = (0.0001984126984126984)*_dv**7 + _x138
        _x140 = math.exp(-_tau_next*delta)
        _exp_next = ((_x139*exp_t) if _x131 else (_x140))
        _pd__34 = ((_x138*exp_t) if _x131 else (0.0))
        _pd__35 = ((0.0) if _x131 else (-_x140*delta))
        _pd__36 = ((_x139) if _x131 else (0.0))
        _d_exp_next__a = _d_dv__a*_pd__34 + _d_tau_next__a*_pd__35 + _pd__36*d_exp_t__a
        _d_exp_next__omega_D = (_d_dv__omega_D*_pd__34 + _d_tau_next__omega_D*_pd__35
            + _pd__36*d_exp_t__omega_D)
        _d_exp_next__A_c = _d_dv__A_c*_pd__34 + _d_tau_next__A_c*_pd__35 + _pd__36*d_exp_t__A_c
        _d_exp_next__B_s = _d_dv__B_s*_pd__34 + _d_tau_next__B_s*_pd__35 + _pd__36*d_exp_t__B_s
        _d_exp_next__delta = (_d_dv__delta*_pd__34 + _d_tau_next__delta*_pd__35 + _pd__36*d_exp_t__delta
            + ((0.0) if _x131 else (-_tau_next*_x140)))
        _d_exp_next__k_d = _d_dv__k_d*_pd__34 + _d_tau_next__k_d*_pd__35 + _pd__36*d_exp_t__k_d
        # next values
        tau__next = _tau_next
        _bisections__next = _bisections_next
        _lo__next = _lo_next
        _hi__next = _hi_next
        cos_t__next = _cos_next
        sin_t__next = _sin_next
        exp_t__next = _exp_next
        _n0_13 = _d_bisections__a
        _n0_14 = _d_bisections__omega_D
        _n0_15 = _d_bisections__A_c
        _n0_16 = _d_bisections__B_s
        _n0_17 = _d_bisections__delta
        _n0_18 = _d_bisections__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (1e-06 > 0.0 and (abs(tau__next - tau) <= 1e-06*(_half)) and (abs(_bisections__next
            - _bisections) <= 1e-06*(1.0)))
        _pkn0 = (tau__next, _bisections__next, _lo__next, _hi__next, cos_t__next, sin_t__next, exp_t__next,
            _d_tau_next__a, _d_tau_next__omega_D, _d_tau_next__A_c, _d_tau_next__B_s, _d_tau_next__delta,
            _d_tau_next__k_d, _n0_13, _n0_14, _n0_15, _n0_16, _n0_17, _n0_18, _d_lo_next__a,
            _d_lo_next__omega_D, _d_lo_next__A_c, _d_lo_next__B_s, _d_lo_next__delta, _d_lo_next__k_d,
            _d_hi_next__a, _d_hi_next__omega_D, _d_hi_next__A_c, _d_hi_next__B_s, _d_hi_next__delta,
            _d_hi_next__k_d, _d_cos_next__a, _d_cos_next__omega_D, _d_cos_next__A_c, _d_cos_next__B_s,
            _d_cos_next__delta, _d_cos_next__k_d, _d_sin_next__a, _d_sin_next__omega_D, _d_sin_next__A_c,
            _d_sin_next__B_s, _d_sin_next__delta, _d_sin_next__k_d, _d_exp_next__a, _d_exp_next__omega_D,
            _d_exp_next__A_c, _d_exp_next__B_s, _d_exp_next__delta, _d_exp_next__k_d, )
        _pk0 = _pkn0
        _passes += 1.0
    # 1 where the leg force decides liftoff, 0 where q_r = q_r_lo does
    _x141 = exp_t*sin_t
    by_force = ((1.0) if (liftoff == 0.0) and (q_r_lo/l0 >= -2.0*delta*m*(-A_c*_x141*omega_D
        - A_c*cos_t*delta*exp_t - B_s*_x141*delta + B_s*cos_t*exp_t*omega_D)/k_d + 1.0) else (0.0))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (tau, cos_t, sin_t, exp_t, by_force, d_tau__a, d_tau__omega_D, d_tau__A_c, d_tau__B_s,
        d_tau__delta, d_tau__k_d, d_cos_t__a, d_cos_t__omega_D, d_cos_t__A_c, d_cos_t__B_s, d_cos_t__delta,
        d_cos_t__k_d, d_sin_t__a, d_sin_t__omega_D, d_sin_t__A_c, d_sin_t__B_s, d_sin_t__delta, d_sin_t__k_d,
        d_exp_t__a, d_exp_t__omega_D, d_exp_t__A_c, d_exp_t__B_s, d_exp_t__delta, d_exp_t__k_d, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def geyer_damped_stance_jacobian(x, p, out):
    """Geyer et al.'s map with leg damping (damped radial oscillator per half): stance outputs and their
    derivatives with respect to the touchdown state and the stiffness.

    Report equations: 4, 7, 17, 18, 19, 48, 65, 76.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, liftoff, gravity, iterations, tol); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer_damped.geyer_damped_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer_damped.geyer_damped_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 2945
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3, 4, 8, 7, 9,
        10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff, gravity,
            iterations, tol,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m
            > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0)) & ((q_r_lo
            <= l0) and (q_r_lo > 0.0)) & ((liftoff == 0.0) or (liftoff == 1.0)) & ((gravity == 0.0)
            or (gravity == 1.0) or (gravity == 2.0) or (gravity == 3.0) or (gravity == 4.0) or (gravity
            == 5.0)) & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations
            <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the touchdown angular momentum; delta = c / (2 m)
    _x0 = m*q_r_td**2
    p_td = _x0*q_thd_td
    d_p_td__q_r_td = 2.0*m*q_r_td*q_thd_td
    d_p_td__q_thd_td = _x0
    _x1 = (0.5)/m
    delta = _x1*c
    d_delta__c = _x1
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    _pk0 = _pki0
    passes = 0.0
    _conv0 = False
    _last0 = max(int(((0.0) if (gravity == 0.0) else (iterations))), 0)
    for _it0 in range(_last0 + 1):
        (P_c_compression, P_c_decompression, d_P_c_compression__q_r_td, d_P_c_compression__q_rd_td,
            d_P_c_compression__q_th_td, d_P_c_compression__q_thd_td, d_P_c_compression__k_c,
            d_P_c_compression__k_d, d_P_c_compression__c, d_P_c_decompression__q_r_td,
            d_P_c_decompression__q_rd_td, d_P_c_decompression__q_th_td, d_P_c_decompression__q_thd_td,
            d_P_c_decompression__k_c, d_P_c_decompression__k_d, d_P_c_decompression__c, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # eq (7): omega of the first half, from its mean momentum
        _x2 = 1.0/(l0**2*m)
        i_omega_c = _x2*((0.5)*P_c_compression + p_td)
        _pd__0 = (0.5)*_x2
        _pd__1 = _x2
        d_i_omega_c__q_r_td = _pd__0*d_P_c_compression__q_r_td + _pd__1*d_p_td__q_r_td
        d_i_omega_c__q_rd_td = _pd__0*d_P_c_compression__q_rd_td
        d_i_omega_c__q_th_td = _pd__0*d_P_c_compression__q_th_td
        d_i_omega_c__q_thd_td = _pd__0*d_P_c_compression__q_thd_td + _pd__1*d_p_td__q_thd_td
        d_i_omega_c__k_c = _pd__0*d_P_c_compression__k_c
        d_i_omega_c__k_d = _pd__0*d_P_c_compression__k_d
        d_i_omega_c__c = _pd__0*d_P_c_compression__c
        # the damped radial solution of the c half
        _x3 = i_omega_c**2
        _x4 = (1.0/l0)
        _x5 = _x3 - _x4*g_s
        _x6 = (1.0/m)
        _x7 = 3.0*_x3 + _x6*k_c
        _x8 = (1.0/_x7)
        _x9 = _x5*_x8
        i_c_a = _x9
        _x10 = _x5*_x8**2
        _x11 = 6.0*i_omega_c
        _pd__2 = -_x10*_x11 + 2.0*_x8*i_omega_c
        d_i_c_a__q_r_td = _pd__2*d_i_omega_c__q_r_td
        d_i_c_a__q_rd_td = _pd__2*d_i_omega_c__q_rd_td
        d_i_c_a__q_th_td = _pd__2*d_i_omega_c__q_th_td
        d_i_c_a__q_thd_td = _pd__2*d_i_omega_c__q_thd_td
        d_i_c_a__k_c = _pd__2*d_i_omega_c__k_c - _x10*_x6
        d_i_c_a__k_d = _pd__2*d_i_omega_c__k_d
        d_i_c_a__c = _pd__2*d_i_omega_c__c
        _x12 = _x7 - delta**2
        i_c_omega_D2 = _x12
        d_i_c_omega_D2__q_r_td = _x11*d_i_omega_c__q_r_td
        d_i_c_omega_D2__q_rd_td = _x11*d_i_omega_c__q_rd_td
        d_i_c_omega_D2__q_th_td = _x11*d_i_omega_c__q_th_td
        d_i_c_omega_D2__q_thd_td = _x11*d_i_omega_c__q_thd_td
        d_i_c_omega_D2__k_c = _x11*d_i_omega_c__k_c + _x6
        d_i_c_omega_D2__k_d = _x11*d_i_omega_c__k_d
        d_i_c_omega_D2__c = -2.0*d_delta__c*delta + 6.0*d_i_omega_c__c*i_omega_c
        _x13 = math.sqrt(_x12)
        i_c_omega_D = _x13
        _x14 = (1.0/_x13)
        _pd__3 = (0.5)*_x14
        d_i_c_omega_D__q_r_td = _pd__3*d_i_c_omega_D2__q_r_td
        d_i_c_omega_D__q_rd_td = _pd__3*d_i_c_omega_D2__q_rd_td
        d_i_c_omega_D__q_th_td = _pd__3*d_i_c_omega_D2__q_th_td
        d_i_c_omega_D__q_thd_td = _pd__3*d_i_c_omega_D2__q_thd_td
        d_i_c_omega_D__k_c = _pd__3*d_i_c_omega_D2__k_c
        d_i_c_omega_D__k_d = _pd__3*d_i_c_omega_D2__k_d
        d_i_c_omega_D__c = _pd__3*d_i_c_omega_D2__c
        _x15 = _x4*q_r_td - _x9 - 1.0
        i_c_A_c = _x15
        d_i_c_A_c__q_r_td = _x4 - d_i_c_a__q_r_td
        _x16 = _x15*delta + _x4*q_rd_td
        i_c_B_s = _x14*_x16
        _x17 = _x14*delta
        _pd__4 = -_x17
        _pd__5 = -_x16/_x12
        d_i_c_B_s__q_r_td = _pd__4*d_i_c_a__q_r_td + _pd__5*d_i_c_omega_D__q_r_td + _x17*_x4
        d_i_c_B_s__q_rd_td = _pd__4*d_i_c_a__q_rd_td + _pd__5*d_i_c_omega_D__q_rd_td + _x14*_x4
        d_i_c_B_s__q_th_td = _pd__4*d_i_c_a__q_th_td + _pd__5*d_i_c_omega_D__q_th_td
        d_i_c_B_s__q_thd_td = _pd__4*d_i_c_a__q_thd_td + _pd__5*d_i_c_omega_D__q_thd_td
        d_i_c_B_s__k_c = _pd__4*d_i_c_a__k_c + _pd__5*d_i_c_omega_D__k_c
        d_i_c_B_s__k_d = _pd__4*d_i_c_a__k_d + _pd__5*d_i_c_omega_D__k_d
        d_i_c_B_s__c = _pd__4*d_i_c_a__c + _pd__5*d_i_c_omega_D__c + _x14*_x15*d_delta__c
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_c_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # the bottom (rho' = 0) in closed form; (19)'s angle, (17)'s rate
        _x18 = delta*i_c_A_c
        _x19 = -_x18 + i_c_B_s*i_c_omega_D
        i__P = _x19
        d_i__P__q_r_td = (-d_i_c_A_c__q_r_td*delta + d_i_c_B_s__q_r_td*i_c_omega_D
            + d_i_c_omega_D__q_r_td*i_c_B_s)
        d_i__P__q_rd_td = (d_i_c_B_s__q_rd_td*i_c_omega_D + d_i_c_a__q_rd_td*delta
            + d_i_c_omega_D__q_rd_td*i_c_B_s)
        d_i__P__q_th_td = (d_i_c_B_s__q_th_td*i_c_omega_D + d_i_c_a__q_th_td*delta
            + d_i_c_omega_D__q_th_td*i_c_B_s)
        d_i__P__q_thd_td = (d_i_c_B_s__q_thd_td*i_c_omega_D + d_i_c_a__q_thd_td*delta
            + d_i_c_omega_D__q_thd_td*i_c_B_s)
        d_i__P__k_c = d_i_c_B_s__k_c*i_c_omega_D + d_i_c_a__k_c*delta + d_i_c_omega_D__k_c*i_c_B_s
        d_i__P__k_d = d_i_c_B_s__k_d*i_c_omega_D + d_i_c_a__k_d*delta + d_i_c_omega_D__k_d*i_c_B_s
        d_i__P__c = (-d_delta__c*i_c_A_c + d_i_c_B_s__c*i_c_omega_D + d_i_c_a__c*delta
            + d_i_c_omega_D__c*i_c_B_s)
        _x20 = delta*i_c_B_s
        _x21 = i_c_A_c*i_c_omega_D
        _x22 = -_x20 - _x21
        i__R = _x22
        d_i__R__q_r_td = (-d_i_c_A_c__q_r_td*i_c_omega_D - d_i_c_B_s__q_r_td*delta
            - d_i_c_omega_D__q_r_td*i_c_A_c)
        d_i__R__q_rd_td = (-d_i_c_B_s__q_rd_td*delta + d_i_c_a__q_rd_td*i_c_omega_D
            - d_i_c_omega_D__q_rd_td*i_c_A_c)
        d_i__R__q_th_td = (-d_i_c_B_s__q_th_td*delta + d_i_c_a__q_th_td*i_c_omega_D
            - d_i_c_omega_D__q_th_td*i_c_A_c)
        d_i__R__q_thd_td = (-d_i_c_B_s__q_thd_td*delta + d_i_c_a__q_thd_td*i_c_omega_D
            - d_i_c_omega_D__q_thd_td*i_c_A_c)
        d_i__R__k_c = -d_i_c_B_s__k_c*delta + d_i_c_a__k_c*i_c_omega_D - d_i_c_omega_D__k_c*i_c_A_c
        d_i__R__k_d = -d_i_c_B_s__k_d*delta + d_i_c_a__k_d*i_c_omega_D - d_i_c_omega_D__k_d*i_c_A_c
        d_i__R__c = (-d_delta__c*i_c_B_s - d_i_c_B_s__c*delta + d_i_c_a__c*i_c_omega_D
            - d_i_c_omega_D__c*i_c_A_c)
        _x23 = (1.0/_x19)
        _x24 = _x22*_x23
        i__r = _x24
        _x25 = _x23**2
        _pd__6 = -_x22*_x25
        _pd__7 = _x23
        d_i__r__q_r_td = _pd__6*d_i__P__q_r_td + _pd__7*d_i__R__q_r_td
        d_i__r__q_rd_td = _pd__6*d_i__P__q_rd_td + _pd__7*d_i__R__q_rd_td
        d_i__r__q_th_td = _pd__6*d_i__P__q_th_td + _pd__7*d_i__R__q_th_td
        d_i__r__q_thd_td = _pd__6*d_i__P__q_thd_td + _pd__7*d_i__R__q_thd_td
        d_i__r__k_c = _pd__6*d_i__P__k_c + _pd__7*d_i__R__k_c
        d_i__r__k_d = _pd__6*d_i__P__k_d + _pd__7*d_i__R__k_d
        d_i__r__c = _pd__6*d_i__P__c + _pd__7*d_i__R__c
        _x26 = _x22**2*_x25 + 1.0
        _x27 = (1.0/math.sqrt(_x26))
        i__s = _x27
        _pd__8 = -_x24/(_x26*math.sqrt(_x26))
        d_i__s__q_r_td = _pd__8*d_i__r__q_r_td
        d_i__s__q_rd_td = _pd__8*d_i__r__q_rd_td
        d_i__s__q_th_td = _pd__8*d_i__r__q_th_td
        d_i__s__q_thd_td = _pd__8*d_i__r__q_thd_td
        d_i__s__k_c = _pd__8*d_i__r__k_c
        d_i__s__k_d = _pd__8*d_i__r__k_d
        d_i__s__c = _pd__8*d_i__r__c
        _x28 = (1.0/i_c_omega_D)
        _x29 = math.atan(_x24) + (0.5)*math.pi
        _x30 = _x28*_x29
        i_t_bottom = _x30
        _pd__9 = _x28/_x26
        _x31 = i_c_omega_D**2
        _pd__10 = -_x29/_x31
        d_i_t_bottom__q_r_td = _pd__10*d_i_c_omega_D__q_r_td + _pd__9*d_i__r__q_r_td
        d_i_t_bottom__q_rd_td = _pd__10*d_i_c_omega_D__q_rd_td + _pd__9*d_i__r__q_rd_td
        d_i_t_bottom__q_th_td = _pd__10*d_i_c_omega_D__q_th_td + _pd__9*d_i__r__q_th_td
        d_i_t_bottom__q_thd_td = _pd__10*d_i_c_omega_D__q_thd_td + _pd__9*d_i__r__q_thd_td
        d_i_t_bottom__k_c = _pd__10*d_i_c_omega_D__k_c + _pd__9*d_i__r__k_c
        d_i_t_bottom__k_d = _pd__10*d_i_c_omega_D__k_d + _pd__9*d_i__r__k_d
        d_i_t_bottom__c = _pd__10*d_i_c_omega_D__c + _pd__9*d_i__r__c
        _x32 = _x24*_x27
        i_cos_b = -_x32
        d_i_cos_b__q_r_td = -_x24*d_i__s__q_r_td - _x27*d_i__r__q_r_td
        d_i_cos_b__q_rd_td = -_x24*d_i__s__q_rd_td - _x27*d_i__r__q_rd_td
        d_i_cos_b__q_th_td = -_x24*d_i__s__q_th_td - _x27*d_i__r__q_th_td
        d_i_cos_b__q_thd_td = -_x24*d_i__s__q_thd_td - _x27*d_i__r__q_thd_td
        d_i_cos_b__k_c = -_x24*d_i__s__k_c - _x27*d_i__r__k_c
        d_i_cos_b__k_d = -_x24*d_i__s__k_d - _x27*d_i__r__k_d
        d_i_cos_b__c = -_x24*d_i__s__c - _x27*d_i__r__c
        i_sin_b = _x27
        _x33 = math.exp(-_x30*delta)
        i_exp_b = _x33
        _pd__11 = -_x33*delta
        d_i_exp_b__q_r_td = _pd__11*d_i_t_bottom__q_r_td
        d_i_exp_b__q_rd_td = _pd__11*d_i_t_bottom__q_rd_td
        d_i_exp_b__q_th_td = _pd__11*d_i_t_bottom__q_th_td
        d_i_exp_b__q_thd_td = _pd__11*d_i_t_bottom__q_thd_td
        d_i_exp_b__k_c = _pd__11*d_i_t_bottom__k_c
        d_i_exp_b__k_d = _pd__11*d_i_t_bottom__k_d
        d_i_exp_b__c = _pd__11*d_i_t_bottom__c - _x30*_x33*d_delta__c
        _x34 = _x27*i_c_B_s
        _x35 = _x27*i_c_A_c
        _x36 = _x24*_x35
        _x37 = _x33*_x34 - _x33*_x36 + i_c_a + 1.0
        i_bottom_q_r = _x37*l0
        _x38 = _x33*l0
        _pd__12 = -_x32*_x38
        _pd__13 = _x27*_x38
        _pd__14 = _x38*i_c_A_c
        _x39 = _x27*i_c_B_s - _x36
        _pd__15 = _x39*l0
        _pd__16 = _x38*i_c_B_s
        d_i_bottom_q_r__q_r_td = (_pd__12*d_i_c_A_c__q_r_td + _pd__13*d_i_c_B_s__q_r_td
            + _pd__14*d_i_cos_b__q_r_td + _pd__15*d_i_exp_b__q_r_td + _pd__16*d_i__s__q_r_td
            + d_i_c_a__q_r_td*l0)
        d_i_bottom_q_r__q_rd_td = (-_pd__12*d_i_c_a__q_rd_td + _pd__13*d_i_c_B_s__q_rd_td
            + _pd__14*d_i_cos_b__q_rd_td + _pd__15*d_i_exp_b__q_rd_td + _pd__16*d_i__s__q_rd_td
            + d_i_c_a__q_rd_td*l0)
        d_i_bottom_q_r__q_th_td = (-_pd__12*d_i_c_a__q_th_td + _pd__13*d_i_c_B_s__q_th_td
            + _pd__14*d_i_cos_b__q_th_td + _pd__15*d_i_exp_b__q_th_td + _pd__16*d_i__s__q_th_td
            + d_i_c_a__q_th_td*l0)
        d_i_bottom_q_r__q_thd_td = (-_pd__12*d_i_c_a__q_thd_td + _pd__13*d_i_c_B_s__q_thd_td
            + _pd__14*d_i_cos_b__q_thd_td + _pd__15*d_i_exp_b__q_thd_td + _pd__16*d_i__s__q_thd_td
            + d_i_c_a__q_thd_td*l0)
        d_i_bottom_q_r__k_c = (-_pd__12*d_i_c_a__k_c + _pd__13*d_i_c_B_s__k_c + _pd__14*d_i_cos_b__k_c
            + _pd__15*d_i_exp_b__k_c + _pd__16*d_i__s__k_c + d_i_c_a__k_c*l0)
        d_i_bottom_q_r__k_d = (-_pd__12*d_i_c_a__k_d + _pd__13*d_i_c_B_s__k_d + _pd__14*d_i_cos_b__k_d
            + _pd__15*d_i_exp_b__k_d + _pd__16*d_i__s__k_d + d_i_c_a__k_d*l0)
        d_i_bottom_q_r__c = (-_pd__12*d_i_c_a__c + _pd__13*d_i_c_B_s__c + _pd__14*d_i_cos_b__c
            + _pd__15*d_i_exp_b__c + _pd__16*d_i__s__c + d_i_c_a__c*l0)
        i_bottom_q_rd = 0.0
        _x40 = 1.0 - 2.0*i_c_a
        _x41 = _x31 + delta**2
        _x42 = (1.0/_x41)
        _x43 = i_c_B_s*i_c_omega_D
        _x44 = _x27*delta
        _x45 = _x27*i_c_omega_D
        _x46 = -_x24*_x45 + _x44
        _x47 = _x46*i_c_B_s
        _x48 = -_x24*_x44 - _x45
        _x49 = _x48*i_c_A_c
        _x50 = -2.0*_x18 + 2.0*_x33*(_x47 + _x49) - 2.0*_x43
        _x51 = _x30*_x40 + _x42*_x50
        i_bottom_q_th = _x51*i_omega_c + q_th_td
        _x52 = 2.0*delta
        _x53 = _x42*i_omega_c
        _pd__17 = _x53*(2.0*_x33*_x48 - _x52)
        _x54 = 2.0*i_c_omega_D
        _pd__18 = _x53*(2.0*_x33*_x46 - _x54)
        _pd__19 = -2.0*_x30*i_omega_c
        _x55 = _x42**2*_x50
        _pd__20 = i_omega_c*(_x42*(2.0*_x33*(-_x24*_x34 - _x35) - 2.0*i_c_B_s) - _x54*_x55)
        _x56 = 2.0*_x33*_x53
        _pd__21 = _x56*(_x18 + _x43)
        _pd__22 = _x53*(2.0*_x47 + 2.0*_x49)
        _pd__23 = _x51
        _pd__24 = _x56*(_x20 - _x21)
        _pd__25 = _x40*i_omega_c
        d_i_bottom_q_th__q_r_td = (_pd__17*d_i_c_A_c__q_r_td + _pd__18*d_i_c_B_s__q_r_td
            + _pd__19*d_i_c_a__q_r_td + _pd__20*d_i_c_omega_D__q_r_td + _pd__21*d_i_cos_b__q_r_td
            + _pd__22*d_i_exp_b__q_r_td + _pd__23*d_i_omega_c__q_r_td + _pd__24*d_i__s__q_r_td
            + _pd__25*d_i_t_bottom__q_r_td)
        d_i_bottom_q_th__q_rd_td = (-_pd__17*d_i_c_a__q_rd_td + _pd__18*d_i_c_B_s__q_rd_td
            + _pd__19*d_i_c_a__q_rd_td + _pd__20*d_i_c_omega_D__q_rd_td + _pd__21*d_i_cos_b__q_rd_td
            + _pd__22*d_i_exp_b__q_rd_td + _pd__23*d_i_omega_c__q_rd_td + _pd__24*d_i__s__q_rd_td
            + _pd__25*d_i_t_bottom__q_rd_td)
        d_i_bottom_q_th__q_th_td = (-_pd__17*d_i_c_a__q_th_td + _pd__18*d_i_c_B_s__q_th_td
            + _pd__19*d_i_c_a__q_th_td + _pd__20*d_i_c_omega_D__q_th_td + _pd__21*d_i_cos_b__q_th_td
            + _pd__22*d_i_exp_b__q_th_td + _pd__23*d_i_omega_c__q_th_td + _pd__24*d_i__s__q_th_td
            + _pd__25*d_i_t_bottom__q_th_td + 1.0)
        d_i_bottom_q_th__q_thd_td = (-_pd__17*d_i_c_a__q_thd_td + _pd__18*d_i_c_B_s__q_thd_td
            + _pd__19*d_i_c_a__q_thd_td + _pd__20*d_i_c_omega_D__q_thd_td + _pd__21*d_i_cos_b__q_thd_td
            + _pd__22*d_i_exp_b__q_thd_td + _pd__23*d_i_omega_c__q_thd_td + _pd__24*d_i__s__q_thd_td
            + _pd__25*d_i_t_bottom__q_thd_td)
        d_i_bottom_q_th__k_c = (-_pd__17*d_i_c_a__k_c + _pd__18*d_i_c_B_s__k_c + _pd__19*d_i_c_a__k_c
            + _pd__20*d_i_c_omega_D__k_c + _pd__21*d_i_cos_b__k_c + _pd__22*d_i_exp_b__k_c
            + _pd__23*d_i_omega_c__k_c + _pd__24*d_i__s__k_c + _pd__25*d_i_t_bottom__k_c)
        d_i_bottom_q_th__k_d = (-_pd__17*d_i_c_a__k_d + _pd__18*d_i_c_B_s__k_d + _pd__19*d_i_c_a__k_d
            + _pd__20*d_i_c_omega_D__k_d + _pd__21*d_i_cos_b__k_d + _pd__22*d_i_exp_b__k_d
            + _pd__23*d_i_omega_c__k_d + _pd__24*d_i__s__k_d + _pd__25*d_i_t_bottom__k_d)
        d_i_bottom_q_th__c = (-_pd__17*d_i_c_a__c + _pd__18*d_i_c_B_s__c + _pd__19*d_i_c_a__c
            + _pd__20*d_i_c_omega_D__c + _pd__21*d_i_cos_b__c + _pd__22*d_i_exp_b__c + _pd__23*d_i_omega_c__c
            + _pd__24*d_i__s__c + _pd__25*d_i_t_bottom__c + d_delta__c*i_omega_c*(_x42*(2.0*_x33*_x39
            - 2.0*i_c_A_c) - _x52*_x55))
        _x57 = P_c_compression + p_td
        i_p_b = _x57
        d_i_p_b__q_r_td = d_P_c_compression__q_r_td + d_p_td__q_r_td
        d_i_p_b__q_thd_td = d_P_c_compression__q_thd_td + d_p_td__q_thd_td
        _x58 = (1.0/m)
        _x62 = (1.0/l0)
        _x59 = _x58*_x62**2
        _x61 = (1.0/_x37)
        _x60 = _x59*_x61**2
        i_bottom_q_thd = _x57*_x60
        _pd__26 = -2.0*_x57*_x58*_x61**3*_x62**3
        _pd__27 = _x60
        d_i_bottom_q_thd__q_r_td = _pd__26*d_i_bottom_q_r__q_r_td + _pd__27*d_i_p_b__q_r_td
        d_i_bottom_q_thd__q_rd_td = _pd__26*d_i_bottom_q_r__q_rd_td + _pd__27*d_P_c_compression__q_rd_td
        d_i_bottom_q_thd__q_th_td = _pd__26*d_i_bottom_q_r__q_th_td + _pd__27*d_P_c_compression__q_th_td
        d_i_bottom_q_thd__q_thd_td = _pd__26*d_i_bottom_q_r__q_thd_td + _pd__27*d_i_p_b__q_thd_td
        d_i_bottom_q_thd__k_c = _pd__26*d_i_bottom_q_r__k_c + _pd__27*d_P_c_compression__k_c
        d_i_bottom_q_thd__k_d = _pd__26*d_i_bottom_q_r__k_d + _pd__27*d_P_c_compression__k_d
        d_i_bottom_q_thd__c = _pd__26*d_i_bottom_q_r__c + _pd__27*d_P_c_compression__c
        i_omega_d = _x59*((0.5)*P_c_decompression + _x57)
        _pd__28 = (0.5)*_x59
        _pd__29 = _x59
        d_i_omega_d__q_r_td = _pd__28*d_P_c_decompression__q_r_td + _pd__29*d_i_p_b__q_r_td
        d_i_omega_d__q_rd_td = _pd__28*d_P_c_decompression__q_rd_td + _pd__29*d_P_c_compression__q_rd_td
        d_i_omega_d__q_th_td = _pd__28*d_P_c_decompression__q_th_td + _pd__29*d_P_c_compression__q_th_td
        d_i_omega_d__q_thd_td = _pd__28*d_P_c_decompression__q_thd_td + _pd__29*d_i_p_b__q_thd_td
        d_i_omega_d__k_c = _pd__28*d_P_c_decompression__k_c + _pd__29*d_P_c_compression__k_c
        d_i_omega_d__k_d = _pd__28*d_P_c_decompression__k_d + _pd__29*d_P_c_compression__k_d
        d_i_omega_d__c = _pd__28*d_P_c_decompression__c + _pd__29*d_P_c_compression__c
        # the leg collapses: bottom leg length q_r_b > 0
        if not ((i_bottom_q_r > 0.0)):
            return fail(out, STATUS_FALL)
        # the damped radial solution of the d half
        _x63 = i_omega_d**2
        _x64 = (1.0/l0)
        _x65 = _x63 - _x64*g_s
        _x66 = (1.0/m)
        _x67 = 3.0*_x63 + _x66*k_d
        _x68 = (1.0/_x67)
        _x69 = _x65*_x68
        i_d_a = _x69
        _x70 = _x65*_x68**2
        _x71 = 6.0*i_omega_d
        _pd__30 = 2.0*_x68*i_omega_d - _x70*_x71
        d_i_d_a__q_r_td = _pd__30*d_i_omega_d__q_r_td
        d_i_d_a__q_rd_td = _pd__30*d_i_omega_d__q_rd_td
        d_i_d_a__q_th_td = _pd__30*d_i_omega_d__q_th_td
        d_i_d_a__q_thd_td = _pd__30*d_i_omega_d__q_thd_td
        d_i_d_a__k_c = _pd__30*d_i_omega_d__k_c
        d_i_d_a__k_d = _pd__30*d_i_omega_d__k_d - _x66*_x70
        d_i_d_a__c = _pd__30*d_i_omega_d__c
        _x72 = _x67 - delta**2
        i_d_omega_D2 = _x72
        d_i_d_omega_D2__q_r_td = _x71*d_i_omega_d__q_r_td
        d_i_d_omega_D2__q_rd_td = _x71*d_i_omega_d__q_rd_td
        d_i_d_omega_D2__q_th_td = _x71*d_i_omega_d__q_th_td
        d_i_d_omega_D2__q_thd_td = _x71*d_i_omega_d__q_thd_td
        d_i_d_omega_D2__k_c = _x71*d_i_omega_d__k_c
        d_i_d_omega_D2__k_d = _x66 + _x71*d_i_omega_d__k_d
        d_i_d_omega_D2__c = -2.0*d_delta__c*delta + 6.0*d_i_omega_d__c*i_omega_d
        _x73 = math.sqrt(_x72)
        i_d_omega_D = _x73
        _x74 = (1.0/_x73)
        _pd__31 = (0.5)*_x74
        d_i_d_omega_D__q_r_td = _pd__31*d_i_d_omega_D2__q_r_td
        d_i_d_omega_D__q_rd_td = _pd__31*d_i_d_omega_D2__q_rd_td
        d_i_d_omega_D__q_th_td = _pd__31*d_i_d_omega_D2__q_th_td
        d_i_d_omega_D__q_thd_td = _pd__31*d_i_d_omega_D2__q_thd_td
        d_i_d_omega_D__k_c = _pd__31*d_i_d_omega_D2__k_c
        d_i_d_omega_D__k_d = _pd__31*d_i_d_omega_D2__k_d
        d_i_d_omega_D__c = _pd__31*d_i_d_omega_D2__c
        _x75 = _x64*i_bottom_q_r - _x69 - 1.0
        i_d_A_c = _x75
        _pd__32 = _x64
        d_i_d_A_c__q_r_td = _pd__32*d_i_bottom_q_r__q_r_td - d_i_d_a__q_r_td
        d_i_d_A_c__q_rd_td = _pd__32*d_i_bottom_q_r__q_rd_td - d_i_d_a__q_rd_td
        d_i_d_A_c__q_th_td = _pd__32*d_i_bottom_q_r__q_th_td - d_i_d_a__q_th_td
        d_i_d_A_c__q_thd_td = _pd__32*d_i_bottom_q_r__q_thd_td - d_i_d_a__q_thd_td
        d_i_d_A_c__k_c = _pd__32*d_i_bottom_q_r__k_c - d_i_d_a__k_c
        d_i_d_A_c__k_d = _pd__32*d_i_bottom_q_r__k_d - d_i_d_a__k_d
        d_i_d_A_c__c = _pd__32*d_i_bottom_q_r__c - d_i_d_a__c
        _x76 = _x74*delta
        i_d_B_s = _x75*_x76
        _pd__33 = _x64*_x76
        _pd__34 = -_x76
        _pd__35 = -_x75*delta/_x72
        d_i_d_B_s__q_r_td = (_pd__33*d_i_bottom_q_r__q_r_td + _pd__34*d_i_d_a__q_r_td
            + _pd__35*d_i_d_omega_D__q_r_td)
        d_i_d_B_s__q_rd_td = (_pd__33*d_i_bottom_q_r__q_rd_td + _pd__34*d_i_d_a__q_rd_td
            + _pd__35*d_i_d_omega_D__q_rd_td)
        d_i_d_B_s__q_th_td = (_pd__33*d_i_bottom_q_r__q_th_td + _pd__34*d_i_d_a__q_th_td
            + _pd__35*d_i_d_omega_D__q_th_td)
        d_i_d_B_s__q_thd_td = (_pd__33*d_i_bottom_q_r__q_thd_td + _pd__34*d_i_d_a__q_thd_td
            + _pd__35*d_i_d_omega_D__q_thd_td)
        d_i_d_B_s__k_c = _pd__33*d_i_bottom_q_r__k_c + _pd__34*d_i_d_a__k_c + _pd__35*d_i_d_omega_D__k_c
        d_i_d_B_s__k_d = _pd__33*d_i_bottom_q_r__k_d + _pd__34*d_i_d_a__k_d + _pd__35*d_i_d_omega_D__k_d
        d_i_d_B_s__c = (_pd__33*d_i_bottom_q_r__c + _pd__34*d_i_d_a__c + _pd__35*d_i_d_omega_D__c
            + _x74*_x75*d_delta__c)
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_d_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # liftoff: the leg force's zero (or q_r = q_r_lo) after the bottom
        _o0 = carray(stack(35), 35)
        _c0 = (damped_liftoff_jac_a_omega_D_A_c_B_s_delta_k_d(i_d_a, i_d_omega_D, i_d_A_c, i_d_B_s, delta, m,
            l0, k_d, q_r_lo, liftoff, _o0))
        if _c0 != STATUS_OK:
            return fail(out, _c0)
        (i_tau, i_cos_t, i_sin_t, i_exp_t, i_by_force, _j_i_tau__a, _j_i_tau__omega_D, _j_i_tau__A_c,
            _j_i_tau__B_s, _j_i_tau__delta, _j_i_tau__k_d, _j_i_cos_t__a, _j_i_cos_t__omega_D,
            _j_i_cos_t__A_c, _j_i_cos_t__B_s, _j_i_cos_t__delta, _j_i_cos_t__k_d, _j_i_sin_t__a,
            _j_i_sin_t__omega_D, _j_i_sin_t__A_c, _j_i_sin_t__B_s, _j_i_sin_t__delta, _j_i_sin_t__k_d,
            _j_i_exp_t__a, _j_i_exp_t__omega_D, _j_i_exp_t__A_c, _j_i_exp_t__B_s, _j_i_exp_t__delta,
            _j_i_exp_t__k_d,) = (load(_o0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18,
            19, 20, 21, 22, 23, 24, 25, 26, 27, 28))
        # chain rule through damped_liftoff
        d_i_tau__q_r_td = (_j_i_tau__A_c*d_i_d_A_c__q_r_td + _j_i_tau__B_s*d_i_d_B_s__q_r_td
            + _j_i_tau__a*d_i_d_a__q_r_td + _j_i_tau__omega_D*d_i_d_omega_D__q_r_td)
        d_i_tau__q_rd_td = (_j_i_tau__A_c*d_i_d_A_c__q_rd_td + _j_i_tau__B_s*d_i_d_B_s__q_rd_td
            + _j_i_tau__a*d_i_d_a__q_rd_td + _j_i_tau__omega_D*d_i_d_omega_D__q_rd_td)
        d_i_tau__q_th_td = (_j_i_tau__A_c*d_i_d_A_c__q_th_td + _j_i_tau__B_s*d_i_d_B_s__q_th_td
            + _j_i_tau__a*d_i_d_a__q_th_td + _j_i_tau__omega_D*d_i_d_omega_D__q_th_td)
        d_i_tau__q_thd_td = (_j_i_tau__A_c*d_i_d_A_c__q_thd_td + _j_i_tau__B_s*d_i_d_B_s__q_thd_td
            + _j_i_tau__a*d_i_d_a__q_thd_td + _j_i_tau__omega_D*d_i_d_omega_D__q_thd_td)
        d_i_tau__k_c = (_j_i_tau__A_c*d_i_d_A_c__k_c + _j_i_tau__B_s*d_i_d_B_s__k_c + _j_i_tau__a*d_i_d_a__k_c
            + _j_i_tau__omega_D*d_i_d_omega_D__k_c)
        d_i_tau__k_d = (_j_i_tau__A_c*d_i_d_A_c__k_d + _j_i_tau__B_s*d_i_d_B_s__k_d + _j_i_tau__a*d_i_d_a__k_d
            + _j_i_tau__k_d + _j_i_tau__omega_D*d_i_d_omega_D__k_d)
        d_i_tau__c = (_j_i_tau__A_c*d_i_d_A_c__c + _j_i_tau__B_s*d_i_d_B_s__c + _j_i_tau__a*d_i_d_a__c
            + _j_i_tau__delta*d_delta__c + _j_i_tau__omega_D*d_i_d_omega_D__c)
        d_i_cos_t__q_r_td = (_j_i_cos_t__A_c*d_i_d_A_c__q_r_td + _j_i_cos_t__B_s*d_i_d_B_s__q_r_td
            + _j_i_cos_t__a*d_i_d_a__q_r_td + _j_i_cos_t__omega_D*d_i_d_omega_D__q_r_td)
        d_i_cos_t__q_rd_td = (_j_i_cos_t__A_c*d_i_d_A_c__q_rd_td + _j_i_cos_t__B_s*d_i_d_B_s__q_rd_td
            + _j_i_cos_t__a*d_i_d_a__q_rd_td + _j_i_cos_t__omega_D*d_i_d_omega_D__q_rd_td)
        d_i_cos_t__q_th_td = (_j_i_cos_t__A_c*d_i_d_A_c__q_th_td + _j_i_cos_t__B_s*d_i_d_B_s__q_th_td
            + _j_i_cos_t__a*d_i_d_a__q_th_td + _j_i_cos_t__omega_D*d_i_d_omega_D__q_th_td)
        d_i_cos_t__q_thd_td = (_j_i_cos_t__A_c*d_i_d_A_c__q_thd_td + _j_i_cos_t__B_s*d_i_d_B_s__q_thd_td
            + _j_i_cos_t__a*d_i_d_a__q_thd_td + _j_i_cos_t__omega_D*d_i_d_omega_D__q_thd_td)
        d_i_cos_t__k_c = (_j_i_cos_t__A_c*d_i_d_A_c__k_c + _j_i_cos_t__B_s*d_i_d_B_s__k_c
            + _j_i_cos_t__a*d_i_d_a__k_c + _j_i_cos_t__omega_D*d_i_d_omega_D__k_c)
        d_i_cos_t__k_d = (_j_i_cos_t__A_c*d_i_d_A_c__k_d + _j_i_cos_t__B_s*d_i_d_B_s__k_d
            + _j_i_cos_t__a*d_i_d_a__k_d + _j_i_cos_t__k_d + _j_i_cos_t__omega_D*d_i_d_omega_D__k_d)
        d_i_cos_t__c = (_j_i_cos_t__A_c*d_i_d_A_c__c + _j_i_cos_t__B_s*d_i_d_B_s__c + _j_i_cos_t__a*d_i_d_a__c
            + _j_i_cos_t__delta*d_delta__c + _j_i_cos_t__omega_D*d_i_d_omega_D__c)
        d_i_sin_t__q_r_td = (_j_i_sin_t__A_c*d_i_d_A_c__q_r_td + _j_i_sin_t__B_s*d_i_d_B_s__q_r_td
            + _j_i_sin_t__a*d_i_d_a__q_r_td + _j_i_sin_t__omega_D*d_i_d_omega_D__q_r_td)
        d_i_sin_t__q_rd_td = (_j_i_sin_t__A_c*d_i_d_A_c__q_rd_td + _j_i_sin_t__B_s*d_i_d_B_s__q_rd_td
            + _j_i_sin_t__a*d_i_d_a__q_rd_td + _j_i_sin_t__omega_D*d_i_d_omega_D__q_rd_td)
        d_i_sin_t__q_th_td = (_j_i_sin_t__A_c*d_i_d_A_c__q_th_td + _j_i_sin_t__B_s*d_i_d_B_s__q_th_td
            + _j_i_sin_t__a*d_i_d_a__q_th_td + _j_i_sin_t__omega_D*d_i_d_omega_D__q_th_td)
        d_i_sin_t__q_thd_td = (_j_i_sin_t__A_c*d_i_d_A_c__q_thd_td + _j_i_sin_t__B_s*d_i_d_B_s__q_thd_td
            + _j_i_sin_t__a*d_i_d_a__q_thd_td + _j_i_sin_t__omega_D*d_i_d_omega_D__q_thd_td)
        d_i_sin_t__k_c = (_j_i_sin_t__A_c*d_i_d_A_c__k_c + _j_i_sin_t__B_s*d_i_d_B_s__k_c
            + _j_i_sin_t__a*d_i_d_a__k_c + _j_i_sin_t__omega_D*d_i_d_omega_D__k_c)
        d_i_sin_t__k_d = (_j_i_sin_t__A_c*d_i_d_A_c__k_d + _j_i_sin_t__B_s*d_i_d_B_s__k_d
            + _j_i_sin_t__a*d_i_d_a__k_d + _j_i_sin_t__k_d + _j_i_sin_t__omega_D*d_i_d_omega_D__k_d)
        d_i_sin_t__c = (_j_i_sin_t__A_c*d_i_d_A_c__c + _j_i_sin_t__B_s*d_i_d_B_s__c + _j_i_sin_t__a*d_i_d_a__c
            + _j_i_sin_t__delta*d_delta__c + _j_i_sin_t__omega_D*d_i_d_omega_D__c)
        d_i_exp_t__q_r_td = (_j_i_exp_t__A_c*d_i_d_A_c__q_r_td + _j_i_exp_t__B_s*d_i_d_B_s__q_r_td
            + _j_i_exp_t__a*d_i_d_a__q_r_td + _j_i_exp_t__omega_D*d_i_d_omega_D__q_r_td)
        d_i_exp_t__q_rd_td = (_j_i_exp_t__A_c*d_i_d_A_c__q_rd_td + _j_i_exp_t__B_s*d_i_d_B_s__q_rd_td
            + _j_i_exp_t__a*d_i_d_a__q_rd_td + _j_i_exp_t__omega_D*d_i_d_omega_D__q_rd_td)
        d_i_exp_t__q_th_td = (_j_i_exp_t__A_c*d_i_d_A_c__q_th_td + _j_i_exp_t__B_s*d_i_d_B_s__q_th_td
            + _j_i_exp_t__a*d_i_d_a__q_th_td + _j_i_exp_t__omega_D*d_i_d_omega_D__q_th_td)
        d_i_exp_t__q_thd_td = (_j_i_exp_t__A_c*d_i_d_A_c__q_thd_td + _j_i_exp_t__B_s*d_i_d_B_s__q_thd_td
            + _j_i_exp_t__a*d_i_d_a__q_thd_td + _j_i_exp_t__omega_D*d_i_d_omega_D__q_thd_td)
        d_i_exp_t__k_c = (_j_i_exp_t__A_c*d_i_d_A_c__k_c + _j_i_exp_t__B_s*d_i_d_B_s__k_c
            + _j_i_exp_t__a*d_i_d_a__k_c + _j_i_exp_t__omega_D*d_i_d_omega_D__k_c)
        d_i_exp_t__k_d = (_j_i_exp_t__A_c*d_i_d_A_c__k_d + _j_i_exp_t__B_s*d_i_d_B_s__k_d
            + _j_i_exp_t__a*d_i_d_a__k_d + _j_i_exp_t__k_d + _j_i_exp_t__omega_D*d_i_d_omega_D__k_d)
        d_i_exp_t__c = (_j_i_exp_t__A_c*d_i_d_A_c__c + _j_i_exp_t__B_s*d_i_d_B_s__c + _j_i_exp_t__a*d_i_d_a__c
            + _j_i_exp_t__delta*d_delta__c + _j_i_exp_t__omega_D*d_i_d_omega_D__c)
        # the liftoff state: the damped solution at the root, (19)'s angle, (17)'s rate
        i_t_stance = i_t_bottom + i_tau
        d_i_t_stance__q_r_td = d_i_t_bottom__q_r_td + d_i_tau__q_r_td
        d_i_t_stance__q_rd_td = d_i_t_bottom__q_rd_td + d_i_tau__q_rd_td
        d_i_t_stance__q_th_td = d_i_t_bottom__q_th_td + d_i_tau__q_th_td
        d_i_t_stance__q_thd_td = d_i_t_bottom__q_thd_td + d_i_tau__q_thd_td
        d_i_t_stance__k_c = d_i_t_bottom__k_c + d_i_tau__k_c
        d_i_t_stance__k_d = d_i_t_bottom__k_d + d_i_tau__k_d
        d_i_t_stance__c = d_i_t_bottom__c + d_i_tau__c
        _x77 = 2.0*delta
        _x78 = delta*i_cos_t
        _x79 = _x78*i_exp_t
        _x80 = delta*i_sin_t
        _x81 = _x80*i_exp_t
        _x82 = i_d_omega_D*i_sin_t
        _x83 = _x82*i_exp_t
        _x84 = -_x79*i_d_A_c - _x81*i_d_B_s - _x83*i_d_A_c + i_cos_t*i_d_B_s*i_d_omega_D*i_exp_t
        _x123 = (1.0/k_d)
        _x85 = _x123*m
        _x86 = _x84*_x85
        _x87 = -_x77*_x86 + 1.0
        _x88 = (i_by_force == 1.0)
        i_liftoff_q_r = ((_x87*l0) if _x88 else (q_r_lo))
        _x89 = delta*i_d_A_c
        _x90 = l0*(-_x89*i_exp_t + i_d_B_s*i_d_omega_D*i_exp_t)
        _x91 = _x77*_x85
        _pd__36 = ((-_x90*_x91) if _x88 else (0.0))
        _x92 = l0*(-_x79 - _x83)
        _pd__37 = ((-_x91*_x92) if _x88 else (0.0))
        _x93 = l0*(-_x81 + i_cos_t*i_d_omega_D*i_exp_t)
        _pd__38 = ((-_x91*_x93) if _x88 else (0.0))
        _x94 = i_cos_t*i_d_B_s
        _x95 = i_d_A_c*i_sin_t
        _x96 = l0*(_x94*i_exp_t - _x95*i_exp_t)
        _pd__39 = ((-_x91*_x96) if _x88 else (0.0))
        _x97 = l0*(-_x78*i_d_A_c - _x80*i_d_B_s - _x82*i_d_A_c + i_cos_t*i_d_B_s*i_d_omega_D)
        _pd__40 = ((-_x91*_x97) if _x88 else (0.0))
        _x98 = delta*i_d_B_s
        _x99 = i_d_A_c*i_d_omega_D
        _x100 = l0*(-_x98*i_exp_t - _x99*i_exp_t)
        _pd__41 = ((-_x100*_x91) if _x88 else (0.0))
        d_i_liftoff_q_r__q_r_td = (_pd__36*d_i_cos_t__q_r_td + _pd__37*d_i_d_A_c__q_r_td
            + _pd__38*d_i_d_B_s__q_r_td + _pd__39*d_i_d_omega_D__q_r_td + _pd__40*d_i_exp_t__q_r_td
            + _pd__41*d_i_sin_t__q_r_td)
        d_i_liftoff_q_r__q_rd_td = (_pd__36*d_i_cos_t__q_rd_td + _pd__37*d_i_d_A_c__q_rd_td
            + _pd__38*d_i_d_B_s__q_rd_td + _pd__39*d_i_d_omega_D__q_rd_td + _pd__40*d_i_exp_t__q_rd_td
            + _pd__41*d_i_sin_t__q_rd_td)
        d_i_liftoff_q_r__q_th_td = (_pd__36*d_i_cos_t__q_th_td + _pd__37*d_i_d_A_c__q_th_td
            + _pd__38*d_i_d_B_s__q_th_td + _pd__39*d_i_d_omega_D__q_th_td + _pd__40*d_i_exp_t__q_th_td
            + _pd__41*d_i_sin_t__q_th_td)
        d_i_liftoff_q_r__q_thd_td = (_pd__36*d_i_cos_t__q_thd_td + _pd__37*d_i_d_A_c__q_thd_td
            + _pd__38*d_i_d_B_s__q_thd_td + _pd__39*d_i_d_omega_D__q_thd_td + _pd__40*d_i_exp_t__q_thd_td
            + _pd__41*d_i_sin_t__q_thd_td)
        d_i_liftoff_q_r__k_c = (_pd__36*d_i_cos_t__k_c + _pd__37*d_i_d_A_c__k_c + _pd__38*d_i_d_B_s__k_c
            + _pd__39*d_i_d_omega_D__k_c + _pd__40*d_i_exp_t__k_c + _pd__41*d_i_sin_t__k_c)
        _x101 = _x84*l0
        d_i_liftoff_q_r__k_d = (_pd__36*d_i_cos_t__k_d + _pd__37*d_i_d_A_c__k_d + _pd__38*d_i_d_B_s__k_d
            + _pd__39*d_i_d_omega_D__k_d + _pd__40*d_i_exp_t__k_d + _pd__41*d_i_sin_t__k_d
            + ((_x101*_x123**2*_x77*m) if _x88 else (0.0)))
        _x102 = i_cos_t*i_d_A_c
        _x103 = i_d_B_s*i_sin_t
        _x104 = -_x102*i_exp_t - _x103*i_exp_t
        d_i_liftoff_q_r__c = (_pd__36*d_i_cos_t__c + _pd__37*d_i_d_A_c__c + _pd__38*d_i_d_B_s__c
            + _pd__39*d_i_d_omega_D__c + _pd__40*d_i_exp_t__c + _pd__41*d_i_sin_t__c
            + d_delta__c*((l0*(-_x104*_x91 - 2.0*_x86)) if _x88 else (0.0)))
        i_liftoff_q_rd = _x101
        _pd__42 = _x90
        _pd__43 = _x92
        _pd__44 = _x93
        _pd__45 = _x96
        _pd__46 = _x97
        _pd__47 = _x100
        d_i_liftoff_q_rd__q_r_td = (_pd__42*d_i_cos_t__q_r_td + _pd__43*d_i_d_A_c__q_r_td
            + _pd__44*d_i_d_B_s__q_r_td + _pd__45*d_i_d_omega_D__q_r_td + _pd__46*d_i_exp_t__q_r_td
            + _pd__47*d_i_sin_t__q_r_td)
        d_i_liftoff_q_rd__q_rd_td = (_pd__42*d_i_cos_t__q_rd_td + _pd__43*d_i_d_A_c__q_rd_td
            + _pd__44*d_i_d_B_s__q_rd_td + _pd__45*d_i_d_omega_D__q_rd_td + _pd__46*d_i_exp_t__q_rd_td
            + _pd__47*d_i_sin_t__q_rd_td)
        d_i_liftoff_q_rd__q_th_td = (_pd__42*d_i_cos_t__q_th_td + _pd__43*d_i_d_A_c__q_th_td
            + _pd__44*d_i_d_B_s__q_th_td + _pd__45*d_i_d_omega_D__q_th_td + _pd__46*d_i_exp_t__q_th_td
            + _pd__47*d_i_sin_t__q_th_td)
        d_i_liftoff_q_rd__q_thd_td = (_pd__42*d_i_cos_t__q_thd_td + _pd__43*d_i_d_A_c__q_thd_td
            + _pd__44*d_i_d_B_s__q_thd_td + _pd__45*d_i_d_omega_D__q_thd_td + _pd__46*d_i_exp_t__q_thd_td
            + _pd__47*d_i_sin_t__q_thd_td)
        d_i_liftoff_q_rd__k_c = (_pd__42*d_i_cos_t__k_c + _pd__43*d_i_d_A_c__k_c + _pd__44*d_i_d_B_s__k_c
            + _pd__45*d_i_d_omega_D__k_c + _pd__46*d_i_exp_t__k_c + _pd__47*d_i_sin_t__k_c)
        d_i_liftoff_q_rd__k_d = (_pd__42*d_i_cos_t__k_d + _pd__43*d_i_d_A_c__k_d + _pd__44*d_i_d_B_s__k_d
            + _pd__45*d_i_d_omega_D__k_d + _pd__46*d_i_exp_t__k_d + _pd__47*d_i_sin_t__k_d)
        d_i_liftoff_q_rd__c = (_pd__42*d_i_cos_t__c + _pd__43*d_i_d_A_c__c + _pd__44*d_i_d_B_s__c
            + _pd__45*d_i_d_omega_D__c + _pd__46*d_i_exp_t__c + _pd__47*d_i_sin_t__c + _x104*d_delta__c*l0)
        _x105 = 1.0 - 2.0*i_d_a
        _x106 = delta**2 + i_d_omega_D**2
        _x107 = (1.0/_x106)
        _x108 = i_d_B_s*i_d_omega_D
        _x109 = _x80 + i_cos_t*i_d_omega_D
        _x110 = _x109*i_d_B_s
        _x111 = _x78 - _x82
        _x112 = _x111*i_d_A_c
        _x113 = -2.0*_x108 - 2.0*_x89 + 2.0*i_exp_t*(_x110 + _x112)
        _x114 = _x105*i_tau + _x107*_x113
        i_liftoff_q_th = _x114*i_omega_d + i_bottom_q_th
        _x115 = _x107*i_omega_d
        _x116 = 2.0*_x115*i_exp_t
        _pd__48 = _x116*(_x108 + _x89)
        _pd__49 = _x115*(2.0*_x111*i_exp_t - _x77)
        _x117 = 2.0*i_d_omega_D
        _pd__50 = _x115*(2.0*_x109*i_exp_t - _x117)
        _pd__51 = -2.0*i_omega_d*i_tau
        _x118 = _x107**2*_x113
        _pd__52 = i_omega_d*(_x107*(-2.0*i_d_B_s + 2.0*i_exp_t*(_x94 - _x95)) - _x117*_x118)
        _pd__53 = _x115*(2.0*_x110 + 2.0*_x112)
        _pd__54 = _x114
        _pd__55 = _x116*(_x98 - _x99)
        _pd__56 = _x105*i_omega_d
        d_i_liftoff_q_th__q_r_td = (_pd__48*d_i_cos_t__q_r_td + _pd__49*d_i_d_A_c__q_r_td
            + _pd__50*d_i_d_B_s__q_r_td + _pd__51*d_i_d_a__q_r_td + _pd__52*d_i_d_omega_D__q_r_td
            + _pd__53*d_i_exp_t__q_r_td + _pd__54*d_i_omega_d__q_r_td + _pd__55*d_i_sin_t__q_r_td
            + _pd__56*d_i_tau__q_r_td + d_i_bottom_q_th__q_r_td)
        d_i_liftoff_q_th__q_rd_td = (_pd__48*d_i_cos_t__q_rd_td + _pd__49*d_i_d_A_c__q_rd_td
            + _pd__50*d_i_d_B_s__q_rd_td + _pd__51*d_i_d_a__q_rd_td + _pd__52*d_i_d_omega_D__q_rd_td
            + _pd__53*d_i_exp_t__q_rd_td + _pd__54*d_i_omega_d__q_rd_td + _pd__55*d_i_sin_t__q_rd_td
            + _pd__56*d_i_tau__q_rd_td + d_i_bottom_q_th__q_rd_td)
        d_i_liftoff_q_th__q_th_td = (_pd__48*d_i_cos_t__q_th_td + _pd__49*d_i_d_A_c__q_th_td
            + _pd__50*d_i_d_B_s__q_th_td + _pd__51*d_i_d_a__q_th_td + _pd__52*d_i_d_omega_D__q_th_td
            + _pd__53*d_i_exp_t__q_th_td + _pd__54*d_i_omega_d__q_th_td + _pd__55*d_i_sin_t__q_th_td
            + _pd__56*d_i_tau__q_th_td + d_i_bottom_q_th__q_th_td)
        d_i_liftoff_q_th__q_thd_td = (_pd__48*d_i_cos_t__q_thd_td + _pd__49*d_i_d_A_c__q_thd_td
            + _pd__50*d_i_d_B_s__q_thd_td + _pd__51*d_i_d_a__q_thd_td + _pd__52*d_i_d_omega_D__q_thd_td
            + _pd__53*d_i_exp_t__q_thd_td + _pd__54*d_i_omega_d__q_thd_td + _pd__55*d_i_sin_t__q_thd_td
            + _pd__56*d_i_tau__q_thd_td + d_i_bottom_q_th__q_thd_td)
        d_i_liftoff_q_th__k_c = (_pd__48*d_i_cos_t__k_c + _pd__49*d_i_d_A_c__k_c + _pd__50*d_i_d_B_s__k_c
            + _pd__51*d_i_d_a__k_c + _pd__52*d_i_d_omega_D__k_c + _pd__53*d_i_exp_t__k_c
            + _pd__54*d_i_omega_d__k_c + _pd__55*d_i_sin_t__k_c + _pd__56*d_i_tau__k_c + d_i_bottom_q_th__k_c)
        d_i_liftoff_q_th__k_d = (_pd__48*d_i_cos_t__k_d + _pd__49*d_i_d_A_c__k_d + _pd__50*d_i_d_B_s__k_d
            + _pd__51*d_i_d_a__k_d + _pd__52*d_i_d_omega_D__k_d + _pd__53*d_i_exp_t__k_d
            + _pd__54*d_i_omega_d__k_d + _pd__55*d_i_sin_t__k_d + _pd__56*d_i_tau__k_d + d_i_bottom_q_th__k_d)
        d_i_liftoff_q_th__c = (_pd__48*d_i_cos_t__c + _pd__49*d_i_d_A_c__c + _pd__50*d_i_d_B_s__c
            + _pd__51*d_i_d_a__c + _pd__52*d_i_d_omega_D__c + _pd__53*d_i_exp_t__c + _pd__54*d_i_omega_d__c
            + _pd__55*d_i_sin_t__c + _pd__56*d_i_tau__c + d_delta__c*i_omega_d*(_x107*(-2.0*i_d_A_c
            + 2.0*i_exp_t*(_x102 + _x103)) - _x118*_x77) + d_i_bottom_q_th__c)
        _x119 = P_c_decompression + i_p_b
        _x120 = (1.0/m)
        _x122 = (1.0/_x87)
        _x124 = (1.0/l0)
        _x125 = (1.0/q_r_lo)
        _x121 = _x120*((_x122**2*_x124**2) if _x88 else (_x125**2))
        i_liftoff_q_thd = _x119*_x121
        _pd__57 = _x121
        _pd__58 = -2.0*_x119*_x120*((_x122**3*_x124**3) if _x88 else (_x125**3))
        _pd__59 = _x121
        d_i_liftoff_q_thd__q_r_td = (_pd__57*d_P_c_decompression__q_r_td + _pd__58*d_i_liftoff_q_r__q_r_td
            + _pd__59*d_i_p_b__q_r_td)
        d_i_liftoff_q_thd__q_rd_td = (_pd__57*d_P_c_decompression__q_rd_td + _pd__58*d_i_liftoff_q_r__q_rd_td
            + _pd__59*d_P_c_compression__q_rd_td)
        d_i_liftoff_q_thd__q_th_td = (_pd__57*d_P_c_decompression__q_th_td + _pd__58*d_i_liftoff_q_r__q_th_td
            + _pd__59*d_P_c_compression__q_th_td)
        d_i_liftoff_q_thd__q_thd_td = (_pd__57*d_P_c_decompression__q_thd_td
            + _pd__58*d_i_liftoff_q_r__q_thd_td + _pd__59*d_i_p_b__q_thd_td)
        d_i_liftoff_q_thd__k_c = (_pd__57*d_P_c_decompression__k_c + _pd__58*d_i_liftoff_q_r__k_c
            + _pd__59*d_P_c_compression__k_c)
        d_i_liftoff_q_thd__k_d = (_pd__57*d_P_c_decompression__k_d + _pd__58*d_i_liftoff_q_r__k_d
            + _pd__59*d_P_c_compression__k_d)
        d_i_liftoff_q_thd__c = (_pd__57*d_P_c_decompression__c + _pd__58*d_i_liftoff_q_r__c
            + _pd__59*d_P_c_compression__c)
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
            # tangents as every branch names them
            d_i_P_new1__q_r_td = 0.0
            d_i_P_new1__q_rd_td = 0.0
            d_i_P_new1__q_th_td = 0.0
            d_i_P_new1__q_thd_td = 0.0
            d_i_P_new1__k_c = 0.0
            d_i_P_new1__k_d = 0.0
            d_i_P_new1__c = 0.0
            d_i_P_new2__q_r_td = 0.0
            d_i_P_new2__q_rd_td = 0.0
            d_i_P_new2__q_th_td = 0.0
            d_i_P_new2__q_thd_td = 0.0
            d_i_P_new2__k_c = 0.0
            d_i_P_new2__k_d = 0.0
            d_i_P_new2__c = 0.0
        elif gravity == 1.0:
            # eq (48) on each half at l0, as (49)
            _x126 = g_s*l0*m
            _x127 = _x126*math.sin(i_bottom_q_th)
            _x128 = _x126*math.sin(q_th_td)
            _x129 = (0.5)*i_t_bottom
            i_P_new1 = _x129*(_x127 + _x128)
            _x130 = math.cos(i_bottom_q_th)
            _x131 = _x126*_x129
            _pd__60 = _x130*_x131
            _x132 = (0.5)*_x127
            _pd__61 = (0.5)*_x128 + _x132
            d_i_P_new1__q_r_td = _pd__60*d_i_bottom_q_th__q_r_td + _pd__61*d_i_t_bottom__q_r_td
            d_i_P_new1__q_rd_td = _pd__60*d_i_bottom_q_th__q_rd_td + _pd__61*d_i_t_bottom__q_rd_td
            d_i_P_new1__q_th_td = (_pd__60*d_i_bottom_q_th__q_th_td + _pd__61*d_i_t_bottom__q_th_td
                + _x131*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = _pd__60*d_i_bottom_q_th__q_thd_td + _pd__61*d_i_t_bottom__q_thd_td
            d_i_P_new1__k_c = _pd__60*d_i_bottom_q_th__k_c + _pd__61*d_i_t_bottom__k_c
            d_i_P_new1__k_d = _pd__60*d_i_bottom_q_th__k_d + _pd__61*d_i_t_bottom__k_d
            d_i_P_new1__c = _pd__60*d_i_bottom_q_th__c + _pd__61*d_i_t_bottom__c
            _x133 = _x126*math.sin(i_liftoff_q_th)
            _x134 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x134*(_x127 + _x133)
            _x135 = _x126*_x134
            _pd__62 = _x130*_x135
            _pd__63 = _x135*math.cos(i_liftoff_q_th)
            _x136 = _x132 + (0.5)*_x133
            _pd__64 = -_x136
            _pd__65 = _x136
            d_i_P_new2__q_r_td = (_pd__62*d_i_bottom_q_th__q_r_td + _pd__63*d_i_liftoff_q_th__q_r_td
                + _pd__64*d_i_t_bottom__q_r_td + _pd__65*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_pd__62*d_i_bottom_q_th__q_rd_td + _pd__63*d_i_liftoff_q_th__q_rd_td
                + _pd__64*d_i_t_bottom__q_rd_td + _pd__65*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_pd__62*d_i_bottom_q_th__q_th_td + _pd__63*d_i_liftoff_q_th__q_th_td
                + _pd__64*d_i_t_bottom__q_th_td + _pd__65*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_pd__62*d_i_bottom_q_th__q_thd_td + _pd__63*d_i_liftoff_q_th__q_thd_td
                + _pd__64*d_i_t_bottom__q_thd_td + _pd__65*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_pd__62*d_i_bottom_q_th__k_c + _pd__63*d_i_liftoff_q_th__k_c
                + _pd__64*d_i_t_bottom__k_c + _pd__65*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_pd__62*d_i_bottom_q_th__k_d + _pd__63*d_i_liftoff_q_th__k_d
                + _pd__64*d_i_t_bottom__k_d + _pd__65*d_i_t_stance__k_d)
            d_i_P_new2__c = (_pd__62*d_i_bottom_q_th__c + _pd__63*d_i_liftoff_q_th__c
                + _pd__64*d_i_t_bottom__c + _pd__65*d_i_t_stance__c)
        elif gravity == 2.0:
            # eq (48) on each half at (l0 + q_r_b)/2, as (52)
            _x137 = math.sin(i_bottom_q_th)
            _x138 = g_s*m
            _x139 = _x138*((0.5)*i_bottom_q_r + (0.5)*l0)
            _x140 = _x137*_x139
            _x141 = math.sin(q_th_td)
            _x142 = _x139*_x141
            _x143 = (0.5)*i_t_bottom
            i_P_new1 = _x143*(_x140 + _x142)
            _x144 = (0.5)*_x138
            _x145 = _x137*_x144
            _pd__66 = _x143*(_x141*_x144 + _x145)
            _x146 = math.cos(i_bottom_q_th)
            _x147 = _x139*_x143
            _pd__67 = _x146*_x147
            _x148 = (0.5)*_x140
            _pd__68 = (0.5)*_x142 + _x148
            d_i_P_new1__q_r_td = (_pd__66*d_i_bottom_q_r__q_r_td + _pd__67*d_i_bottom_q_th__q_r_td
                + _pd__68*d_i_t_bottom__q_r_td)
            d_i_P_new1__q_rd_td = (_pd__66*d_i_bottom_q_r__q_rd_td + _pd__67*d_i_bottom_q_th__q_rd_td
                + _pd__68*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_pd__66*d_i_bottom_q_r__q_th_td + _pd__67*d_i_bottom_q_th__q_th_td
                + _pd__68*d_i_t_bottom__q_th_td + _x147*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_pd__66*d_i_bottom_q_r__q_thd_td + _pd__67*d_i_bottom_q_th__q_thd_td
                + _pd__68*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = (_pd__66*d_i_bottom_q_r__k_c + _pd__67*d_i_bottom_q_th__k_c
                + _pd__68*d_i_t_bottom__k_c)
            d_i_P_new1__k_d = (_pd__66*d_i_bottom_q_r__k_d + _pd__67*d_i_bottom_q_th__k_d
                + _pd__68*d_i_t_bottom__k_d)
            d_i_P_new1__c = _pd__66*d_i_bottom_q_r__c + _pd__67*d_i_bottom_q_th__c + _pd__68*d_i_t_bottom__c
            _x149 = math.sin(i_liftoff_q_th)
            _x150 = _x139*_x149
            _x151 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x151*(_x140 + _x150)
            _pd__69 = _x151*(_x144*_x149 + _x145)
            _x152 = _x139*_x151
            _pd__70 = _x146*_x152
            _pd__71 = _x152*math.cos(i_liftoff_q_th)
            _x153 = _x148 + (0.5)*_x150
            _pd__72 = -_x153
            _pd__73 = _x153
            d_i_P_new2__q_r_td = (_pd__69*d_i_bottom_q_r__q_r_td + _pd__70*d_i_bottom_q_th__q_r_td
                + _pd__71*d_i_liftoff_q_th__q_r_td + _pd__72*d_i_t_bottom__q_r_td
                + _pd__73*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_pd__69*d_i_bottom_q_r__q_rd_td + _pd__70*d_i_bottom_q_th__q_rd_td
                + _pd__71*d_i_liftoff_q_th__q_rd_td + _pd__72*d_i_t_bottom__q_rd_td
                + _pd__73*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_pd__69*d_i_bottom_q_r__q_th_td + _pd__70*d_i_bottom_q_th__q_th_td
                + _pd__71*d_i_liftoff_q_th__q_th_td + _pd__72*d_i_t_bottom__q_th_td
                + _pd__73*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_pd__69*d_i_bottom_q_r__q_thd_td + _pd__70*d_i_bottom_q_th__q_thd_td
                + _pd__71*d_i_liftoff_q_th__q_thd_td + _pd__72*d_i_t_bottom__q_thd_td
                + _pd__73*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_pd__69*d_i_bottom_q_r__k_c + _pd__70*d_i_bottom_q_th__k_c
                + _pd__71*d_i_liftoff_q_th__k_c + _pd__72*d_i_t_bottom__k_c + _pd__73*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_pd__69*d_i_bottom_q_r__k_d + _pd__70*d_i_bottom_q_th__k_d
                + _pd__71*d_i_liftoff_q_th__k_d + _pd__72*d_i_t_bottom__k_d + _pd__73*d_i_t_stance__k_d)
            d_i_P_new2__c = (_pd__69*d_i_bottom_q_r__c + _pd__70*d_i_bottom_q_th__c
                + _pd__71*d_i_liftoff_q_th__c + _pd__72*d_i_t_bottom__c + _pd__73*d_i_t_stance__c)
        elif gravity == 3.0:
            # eq (48) on each half at the stance-average leg length of the damped rho(t), as (62)
            _x154 = -delta*i_cos_b + i_c_omega_D*i_sin_b
            _x155 = _x154*i_exp_b + delta
            _x156 = delta*i_sin_b + i_c_omega_D*i_cos_b
            _x157 = -_x156*i_exp_b + i_c_omega_D
            _x158 = _x155*i_c_A_c + _x157*i_c_B_s
            _x159 = (1.0/i_t_bottom)
            _x160 = delta**2
            _x161 = _x160 + i_c_omega_D**2
            _x162 = (1.0/_x161)
            _x163 = _x159*_x162
            _x164 = l0*(_x158*_x163 + i_c_a + 1.0)
            _i_L1 = _x164
            _x165 = _x163*l0
            _pd__74 = _x155*_x165
            _pd__75 = _x157*_x165
            _x166 = i_c_A_c*i_exp_b
            _x167 = -i_cos_b*i_exp_b + 1.0
            _x168 = 2.0*_x158*_x159*_x162**2
            _pd__76 = l0*(_x159*_x162*(_x166*i_sin_b + _x167*i_c_B_s) - _x168*i_c_omega_D)
            _x169 = i_c_B_s*i_exp_b
            _pd__77 = _x165*(-_x166*delta - _x169*i_c_omega_D)
            _pd__78 = _x165*(_x154*i_c_A_c - _x156*i_c_B_s)
            _pd__79 = _x165*(-_x169*delta + i_c_A_c*i_c_omega_D*i_exp_b)
            _pd__80 = -_x158*_x159**2*_x162*l0
            _d_i_L1__q_r_td = (_pd__74*d_i_c_A_c__q_r_td + _pd__75*d_i_c_B_s__q_r_td
                + _pd__76*d_i_c_omega_D__q_r_td + _pd__77*d_i_cos_b__q_r_td + _pd__78*d_i_exp_b__q_r_td
                + _pd__79*d_i__s__q_r_td + _pd__80*d_i_t_bottom__q_r_td + d_i_c_a__q_r_td*l0)
            _d_i_L1__q_rd_td = (-_pd__74*d_i_c_a__q_rd_td + _pd__75*d_i_c_B_s__q_rd_td
                + _pd__76*d_i_c_omega_D__q_rd_td + _pd__77*d_i_cos_b__q_rd_td + _pd__78*d_i_exp_b__q_rd_td
                + _pd__79*d_i__s__q_rd_td + _pd__80*d_i_t_bottom__q_rd_td + d_i_c_a__q_rd_td*l0)
            _d_i_L1__q_th_td = (-_pd__74*d_i_c_a__q_th_td + _pd__75*d_i_c_B_s__q_th_td
                + _pd__76*d_i_c_omega_D__q_th_td + _pd__77*d_i_cos_b__q_th_td + _pd__78*d_i_exp_b__q_th_td
                + _pd__79*d_i__s__q_th_td + _pd__80*d_i_t_bottom__q_th_td + d_i_c_a__q_th_td*l0)
            _d_i_L1__q_thd_td = (-_pd__74*d_i_c_a__q_thd_td + _pd__75*d_i_c_B_s__q_thd_td
                + _pd__76*d_i_c_omega_D__q_thd_td + _pd__77*d_i_cos_b__q_thd_td + _pd__78*d_i_exp_b__q_thd_td
                + _pd__79*d_i__s__q_thd_td + _pd__80*d_i_t_bottom__q_thd_td + d_i_c_a__q_thd_td*l0)
            _d_i_L1__k_c = (-_pd__74*d_i_c_a__k_c + _pd__75*d_i_c_B_s__k_c + _pd__76*d_i_c_omega_D__k_c
                + _pd__77*d_i_cos_b__k_c + _pd__78*d_i_exp_b__k_c + _pd__79*d_i__s__k_c
                + _pd__80*d_i_t_bottom__k_c + d_i_c_a__k_c*l0)
            _d_i_L1__k_d = (-_pd__74*d_i_c_a__k_d + _pd__75*d_i_c_B_s__k_d + _pd__76*d_i_c_omega_D__k_d
                + _pd__77*d_i_cos_b__k_d + _pd__78*d_i_exp_b__k_d + _pd__79*d_i__s__k_d
                + _pd__80*d_i_t_bottom__k_d + d_i_c_a__k_d*l0)
            _x170 = d_delta__c*l0
            _d_i_L1__c = (-_pd__74*d_i_c_a__c + _pd__75*d_i_c_B_s__c + _pd__76*d_i_c_omega_D__c
                + _pd__77*d_i_cos_b__c + _pd__78*d_i_exp_b__c + _pd__79*d_i__s__c + _pd__80*d_i_t_bottom__c
                + _x170*(_x159*_x162*(_x167*i_c_A_c - _x169*i_sin_b) - _x168*delta) + d_i_c_a__c*l0)
            _x171 = -delta*i_cos_t + i_d_omega_D*i_sin_t
            _x172 = _x171*i_exp_t + delta
            _x173 = delta*i_sin_t + i_cos_t*i_d_omega_D
            _x174 = -_x173*i_exp_t + i_d_omega_D
            _x175 = _x172*i_d_A_c + _x174*i_d_B_s
            _x176 = (1.0/i_tau)
            _x177 = _x160 + i_d_omega_D**2
            _x178 = (1.0/_x177)
            _x179 = _x176*_x178
            _x180 = l0*(_x175*_x179 + i_d_a + 1.0)
            _i_L2 = _x180
            _x181 = i_d_A_c*i_exp_t
            _x182 = i_d_B_s*i_exp_t
            _x183 = _x179*l0
            _pd__81 = _x183*(-_x181*delta - _x182*i_d_omega_D)
            _pd__82 = _x172*_x183
            _pd__83 = _x174*_x183
            _x184 = -i_cos_t*i_exp_t + 1.0
            _x185 = 2.0*_x175*_x176*_x178**2
            _pd__84 = l0*(_x176*_x178*(_x181*i_sin_t + _x184*i_d_B_s) - _x185*i_d_omega_D)
            _pd__85 = _x183*(_x171*i_d_A_c - _x173*i_d_B_s)
            _pd__86 = _x183*(-_x182*delta + i_d_A_c*i_d_omega_D*i_exp_t)
            _pd__87 = -_x175*_x176**2*_x178*l0
            _d_i_L2__q_r_td = (_pd__81*d_i_cos_t__q_r_td + _pd__82*d_i_d_A_c__q_r_td
                + _pd__83*d_i_d_B_s__q_r_td + _pd__84*d_i_d_omega_D__q_r_td + _pd__85*d_i_exp_t__q_r_td
                + _pd__86*d_i_sin_t__q_r_td + _pd__87*d_i_tau__q_r_td + d_i_d_a__q_r_td*l0)
            _d_i_L2__q_rd_td = (_pd__81*d_i_cos_t__q_rd_td + _pd__82*d_i_d_A_c__q_rd_td
                + _pd__83*d_i_d_B_s__q_rd_td + _pd__84*d_i_d_omega_D__q_rd_td + _pd__85*d_i_exp_t__q_rd_td
                + _pd__86*d_i_sin_t__q_rd_td + _pd__87*d_i_tau__q_rd_td + d_i_d_a__q_rd_td*l0)
            _d_i_L2__q_th_td = (_pd__81*d_i_cos_t__q_th_td + _pd__82*d_i_d_A_c__q_th_td
                + _pd__83*d_i_d_B_s__q_th_td + _pd__84*d_i_d_omega_D__q_th_td + _pd__85*d_i_exp_t__q_th_td
                + _pd__86*d_i_sin_t__q_th_td + _pd__87*d_i_tau__q_th_td + d_i_d_a__q_th_td*l0)
            _d_i_L2__q_thd_td = (_pd__81*d_i_cos_t__q_thd_td + _pd__82*d_i_d_A_c__q_thd_td
                + _pd__83*d_i_d_B_s__q_thd_td + _pd__84*d_i_d_omega_D__q_thd_td + _pd__85*d_i_exp_t__q_thd_td
                + _pd__86*d_i_sin_t__q_thd_td + _pd__87*d_i_tau__q_thd_td + d_i_d_a__q_thd_td*l0)
            _d_i_L2__k_c = (_pd__81*d_i_cos_t__k_c + _pd__82*d_i_d_A_c__k_c + _pd__83*d_i_d_B_s__k_c
                + _pd__84*d_i_d_omega_D__k_c + _pd__85*d_i_exp_t__k_c + _pd__86*d_i_sin_t__k_c
                + _pd__87*d_i_tau__k_c + d_i_d_a__k_c*l0)
            _d_i_L2__k_d = (_pd__81*d_i_cos_t__k_d + _pd__82*d_i_d_A_c__k_d + _pd__83*d_i_d_B_s__k_d
                + _pd__84*d_i_d_omega_D__k_d + _pd__85*d_i_exp_t__k_d + _pd__86*d_i_sin_t__k_d
                + _pd__87*d_i_tau__k_d + d_i_d_a__k_d*l0)
            _d_i_L2__c = (_pd__81*d_i_cos_t__c + _pd__82*d_i_d_A_c__c + _pd__83*d_i_d_B_s__c
                + _pd__84*d_i_d_omega_D__c + _pd__85*d_i_exp_t__c + _pd__86*d_i_sin_t__c + _pd__87*d_i_tau__c
                + _x170*(_x176*_x178*(-_x182*i_sin_t + _x184*i_d_A_c) - _x185*delta) + d_i_d_a__c*l0)
            _x186 = (1.0/i_t_stance)
            _x187 = -i_t_bottom + i_t_stance
            _x188 = _x164*i_t_bottom + _x180*_x187
            _x189 = _x186*_x188
            _i_L = _x189
            _pd__88 = _x186*i_t_bottom
            _pd__89 = _x186*_x187
            _pd__90 = _x186*(_x164 - _x180)
            _pd__91 = _x180*_x186 - _x186**2*_x188
            _d_i_L__q_r_td = (_d_i_L1__q_r_td*_pd__88 + _d_i_L2__q_r_td*_pd__89 + _pd__90*d_i_t_bottom__q_r_td
                + _pd__91*d_i_t_stance__q_r_td)
            _d_i_L__q_rd_td = (_d_i_L1__q_rd_td*_pd__88 + _d_i_L2__q_rd_td*_pd__89
                + _pd__90*d_i_t_bottom__q_rd_td + _pd__91*d_i_t_stance__q_rd_td)
            _d_i_L__q_th_td = (_d_i_L1__q_th_td*_pd__88 + _d_i_L2__q_th_td*_pd__89
                + _pd__90*d_i_t_bottom__q_th_td + _pd__91*d_i_t_stance__q_th_td)
            _d_i_L__q_thd_td = (_d_i_L1__q_thd_td*_pd__88 + _d_i_L2__q_thd_td*_pd__89
                + _pd__90*d_i_t_bottom__q_thd_td + _pd__91*d_i_t_stance__q_thd_td)
            _d_i_L__k_c = (_d_i_L1__k_c*_pd__88 + _d_i_L2__k_c*_pd__89 + _pd__90*d_i_t_bottom__k_c
                + _pd__91*d_i_t_stance__k_c)
            _d_i_L__k_d = (_d_i_L1__k_d*_pd__88 + _d_i_L2__k_d*_pd__89 + _pd__90*d_i_t_bottom__k_d
                + _pd__91*d_i_t_stance__k_d)
            _d_i_L__c = (_d_i_L1__c*_pd__88 + _d_i_L2__c*_pd__89 + _pd__90*d_i_t_bottom__c
                + _pd__91*d_i_t_stance__c)
            _x190 = g_s*m
            _x191 = _x190*math.sin(i_bottom_q_th)
            _x192 = _x189*_x191
            _x193 = _x190*math.sin(q_th_td)
            _x194 = _x189*_x193
            _x195 = (0.5)*i_t_bottom
            i_P_new1 = _x195*(_x192 + _x194)
            _pd__92 = _x195*(_x191 + _x193)
            _x196 = math.cos(i_bottom_q_th)
            _x197 = _x189*_x190
            _x198 = _x195*_x197
            _pd__93 = _x196*_x198
            _x199 = (0.5)*_x192
            _pd__94 = (0.5)*_x194 + _x199
            d_i_P_new1__q_r_td = (_d_i_L__q_r_td*_pd__92 + _pd__93*d_i_bottom_q_th__q_r_td
                + _pd__94*d_i_t_bottom__q_r_td)
            d_i_P_new1__q_rd_td = (_d_i_L__q_rd_td*_pd__92 + _pd__93*d_i_bottom_q_th__q_rd_td
                + _pd__94*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_d_i_L__q_th_td*_pd__92 + _pd__93*d_i_bottom_q_th__q_th_td
                + _pd__94*d_i_t_bottom__q_th_td + _x198*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_d_i_L__q_thd_td*_pd__92 + _pd__93*d_i_bottom_q_th__q_thd_td
                + _pd__94*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = _d_i_L__k_c*_pd__92 + _pd__93*d_i_bottom_q_th__k_c + _pd__94*d_i_t_bottom__k_c
            d_i_P_new1__k_d = _d_i_L__k_d*_pd__92 + _pd__93*d_i_bottom_q_th__k_d + _pd__94*d_i_t_bottom__k_d
            d_i_P_new1__c = _d_i_L__c*_pd__92 + _pd__93*d_i_bottom_q_th__c + _pd__94*d_i_t_bottom__c
            _x200 = _x190*math.sin(i_liftoff_q_th)
            _x201 = _x189*_x200
            _x202 = (0.5)*_x187
            i_P_new2 = _x202*(_x192 + _x201)
            _pd__95 = _x202*(_x191 + _x200)
            _x203 = _x197*_x202
            _pd__96 = _x196*_x203
            _pd__97 = _x203*math.cos(i_liftoff_q_th)
            _x204 = _x199 + (0.5)*_x201
            _pd__98 = -_x204
            _pd__99 = _x204
            d_i_P_new2__q_r_td = (_d_i_L__q_r_td*_pd__95 + _pd__96*d_i_bottom_q_th__q_r_td
                + _pd__97*d_i_liftoff_q_th__q_r_td + _pd__98*d_i_t_bottom__q_r_td
                + _pd__99*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_d_i_L__q_rd_td*_pd__95 + _pd__96*d_i_bottom_q_th__q_rd_td
                + _pd__97*d_i_liftoff_q_th__q_rd_td + _pd__98*d_i_t_bottom__q_rd_td
                + _pd__99*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_d_i_L__q_th_td*_pd__95 + _pd__96*d_i_bottom_q_th__q_th_td
                + _pd__97*d_i_liftoff_q_th__q_th_td + _pd__98*d_i_t_bottom__q_th_td
                + _pd__99*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_d_i_L__q_thd_td*_pd__95 + _pd__96*d_i_bottom_q_th__q_thd_td
                + _pd__97*d_i_liftoff_q_th__q_thd_td + _pd__98*d_i_t_bottom__q_thd_td
                + _pd__99*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_d_i_L__k_c*_pd__95 + _pd__96*d_i_bottom_q_th__k_c
                + _pd__97*d_i_liftoff_q_th__k_c + _pd__98*d_i_t_bottom__k_c + _pd__99*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_d_i_L__k_d*_pd__95 + _pd__96*d_i_bottom_q_th__k_d
                + _pd__97*d_i_liftoff_q_th__k_d + _pd__98*d_i_t_bottom__k_d + _pd__99*d_i_t_stance__k_d)
            d_i_P_new2__c = (_d_i_L__c*_pd__95 + _pd__96*d_i_bottom_q_th__c + _pd__97*d_i_liftoff_q_th__c
                + _pd__98*d_i_t_bottom__c + _pd__99*d_i_t_stance__c)
        elif gravity == 4.0:
            # eq (65) on each half
            _x205 = g_s*m
            _x206 = _x205*math.sin(i_bottom_q_th)
            _x207 = _x206*i_bottom_q_r
            _x208 = _x205*math.sin(q_th_td)
            _x209 = _x208*q_r_td
            _x210 = (0.5)*i_t_bottom
            i_P_new1 = _x210*(_x207 + _x209)
            _pd__100 = _x206*_x210
            _x211 = _x205*_x210
            _x212 = i_bottom_q_r*math.cos(i_bottom_q_th)
            _pd__101 = _x211*_x212
            _x213 = (0.5)*_x207
            _pd__102 = (0.5)*_x209 + _x213
            d_i_P_new1__q_r_td = (_pd__100*d_i_bottom_q_r__q_r_td + _pd__101*d_i_bottom_q_th__q_r_td
                + _pd__102*d_i_t_bottom__q_r_td + _x208*_x210)
            d_i_P_new1__q_rd_td = (_pd__100*d_i_bottom_q_r__q_rd_td + _pd__101*d_i_bottom_q_th__q_rd_td
                + _pd__102*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_pd__100*d_i_bottom_q_r__q_th_td + _pd__101*d_i_bottom_q_th__q_th_td
                + _pd__102*d_i_t_bottom__q_th_td + _x211*q_r_td*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_pd__100*d_i_bottom_q_r__q_thd_td + _pd__101*d_i_bottom_q_th__q_thd_td
                + _pd__102*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = (_pd__100*d_i_bottom_q_r__k_c + _pd__101*d_i_bottom_q_th__k_c
                + _pd__102*d_i_t_bottom__k_c)
            d_i_P_new1__k_d = (_pd__100*d_i_bottom_q_r__k_d + _pd__101*d_i_bottom_q_th__k_d
                + _pd__102*d_i_t_bottom__k_d)
            d_i_P_new1__c = (_pd__100*d_i_bottom_q_r__c + _pd__101*d_i_bottom_q_th__c
                + _pd__102*d_i_t_bottom__c)
            _x214 = _x205*math.sin(i_liftoff_q_th)
            _x215 = _x214*i_liftoff_q_r
            _x216 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x216*(_x207 + _x215)
            _pd__103 = _x206*_x216
            _x217 = _x205*_x216
            _pd__104 = _x212*_x217
            _pd__105 = _x214*_x216
            _pd__106 = _x217*i_liftoff_q_r*math.cos(i_liftoff_q_th)
            _x218 = _x213 + (0.5)*_x215
            _pd__107 = -_x218
            _pd__108 = _x218
            d_i_P_new2__q_r_td = (_pd__103*d_i_bottom_q_r__q_r_td + _pd__104*d_i_bottom_q_th__q_r_td
                + _pd__105*d_i_liftoff_q_r__q_r_td + _pd__106*d_i_liftoff_q_th__q_r_td
                + _pd__107*d_i_t_bottom__q_r_td + _pd__108*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_pd__103*d_i_bottom_q_r__q_rd_td + _pd__104*d_i_bottom_q_th__q_rd_td
                + _pd__105*d_i_liftoff_q_r__q_rd_td + _pd__106*d_i_liftoff_q_th__q_rd_td
                + _pd__107*d_i_t_bottom__q_rd_td + _pd__108*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_pd__103*d_i_bottom_q_r__q_th_td + _pd__104*d_i_bottom_q_th__q_th_td
                + _pd__105*d_i_liftoff_q_r__q_th_td + _pd__106*d_i_liftoff_q_th__q_th_td
                + _pd__107*d_i_t_bottom__q_th_td + _pd__108*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_pd__103*d_i_bottom_q_r__q_thd_td + _pd__104*d_i_bottom_q_th__q_thd_td
                + _pd__105*d_i_liftoff_q_r__q_thd_td + _pd__106*d_i_liftoff_q_th__q_thd_td
                + _pd__107*d_i_t_bottom__q_thd_td + _pd__108*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_pd__103*d_i_bottom_q_r__k_c + _pd__104*d_i_bottom_q_th__k_c
                + _pd__105*d_i_liftoff_q_r__k_c + _pd__106*d_i_liftoff_q_th__k_c + _pd__107*d_i_t_bottom__k_c
                + _pd__108*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_pd__103*d_i_bottom_q_r__k_d + _pd__104*d_i_bottom_q_th__k_d
                + _pd__105*d_i_liftoff_q_r__k_d + _pd__106*d_i_liftoff_q_th__k_d + _pd__107*d_i_t_bottom__k_d
                + _pd__108*d_i_t_stance__k_d)
            d_i_P_new2__c = (_pd__103*d_i_bottom_q_r__c + _pd__104*d_i_bottom_q_th__c
                + _pd__105*d_i_liftoff_q_r__c + _pd__106*d_i_liftoff_q_th__c + _pd__107*d_i_t_bottom__c
                + _pd__108*d_i_t_stance__c)
        elif gravity == 5.0:
            # eq (76) on each half, the average leg length of the damped rho(t) on it
            _x219 = -delta*i_cos_b + i_c_omega_D*i_sin_b
            _x220 = _x219*i_exp_b + delta
            _x221 = delta*i_sin_b + i_c_omega_D*i_cos_b
            _x222 = -_x221*i_exp_b + i_c_omega_D
            _x223 = _x220*i_c_A_c + _x222*i_c_B_s
            _x224 = (1.0/i_t_bottom)
            _x225 = delta**2
            _x226 = _x225 + i_c_omega_D**2
            _x227 = (1.0/_x226)
            _x228 = _x224*_x227
            _x229 = l0*(_x223*_x228 + i_c_a + 1.0)
            _i_L1 = _x229
            _x230 = _x228*l0
            _pd__109 = _x220*_x230
            _pd__110 = _x222*_x230
            _x231 = i_c_A_c*i_exp_b
            _x232 = -i_cos_b*i_exp_b + 1.0
            _x233 = 2.0*_x223*_x224*_x227**2
            _pd__111 = l0*(_x224*_x227*(_x231*i_sin_b + _x232*i_c_B_s) - _x233*i_c_omega_D)
            _x234 = i_c_B_s*i_exp_b
            _pd__112 = _x230*(-_x231*delta - _x234*i_c_omega_D)
            _pd__113 = _x230*(_x219*i_c_A_c - _x221*i_c_B_s)
            _pd__114 = _x230*(-_x234*delta + i_c_A_c*i_c_omega_D*i_exp_b)
            _pd__115 = -_x223*_x224**2*_x227*l0
            _d_i_L1__q_r_td = (_pd__109*d_i_c_A_c__q_r_td + _pd__110*d_i_c_B_s__q_r_td
                + _pd__111*d_i_c_omega_D__q_r_td + _pd__112*d_i_cos_b__q_r_td + _pd__113*d_i_exp_b__q_r_td
                + _pd__114*d_i__s__q_r_td + _pd__115*d_i_t_bottom__q_r_td + d_i_c_a__q_r_td*l0)
            _d_i_L1__q_rd_td = (-_pd__109*d_i_c_a__q_rd_td + _pd__110*d_i_c_B_s__q_rd_td
                + _pd__111*d_i_c_omega_D__q_rd_td + _pd__112*d_i_cos_b__q_rd_td + _pd__113*d_i_exp_b__q_rd_td
                + _pd__114*d_i__s__q_rd_td + _pd__115*d_i_t_bottom__q_rd_td + d_i_c_a__q_rd_td*l0)
            _d_i_L1__q_th_td = (-_pd__109*d_i_c_a__q_th_td + _pd__110*d_i_c_B_s__q_th_td
                + _pd__111*d_i_c_omega_D__q_th_td + _pd__112*d_i_cos_b__q_th_td + _pd__113*d_i_exp_b__q_th_td
                + _pd__114*d_i__s__q_th_td + _pd__115*d_i_t_bottom__q_th_td + d_i_c_a__q_th_td*l0)
            _d_i_L1__q_thd_td = (-_pd__109*d_i_c_a__q_thd_td + _pd__110*d_i_c_B_s__q_thd_td
                + _pd__111*d_i_c_omega_D__q_thd_td + _pd__112*d_i_cos_b__q_thd_td
                + _pd__113*d_i_exp_b__q_thd_td + _pd__114*d_i__s__q_thd_td + _pd__115*d_i_t_bottom__q_thd_td
                + d_i_c_a__q_thd_td*l0)
            _d_i_L1__k_c = (-_pd__109*d_i_c_a__k_c + _pd__110*d_i_c_B_s__k_c + _pd__111*d_i_c_omega_D__k_c
                + _pd__112*d_i_cos_b__k_c + _pd__113*d_i_exp_b__k_c + _pd__114*d_i__s__k_c
                + _pd__115*d_i_t_bottom__k_c + d_i_c_a__k_c*l0)
            _d_i_L1__k_d = (-_pd__109*d_i_c_a__k_d + _pd__110*d_i_c_B_s__k_d + _pd__111*d_i_c_omega_D__k_d
                + _pd__112*d_i_cos_b__k_d + _pd__113*d_i_exp_b__k_d + _pd__114*d_i__s__k_d
                + _pd__115*d_i_t_bottom__k_d + d_i_c_a__k_d*l0)
            _x235 = d_delta__c*l0
            _d_i_L1__c = (-_pd__109*d_i_c_a__c + _pd__110*d_i_c_B_s__c + _pd__111*d_i_c_omega_D__c
                + _pd__112*d_i_cos_b__c + _pd__113*d_i_exp_b__c + _pd__114*d_i__s__c
                + _pd__115*d_i_t_bottom__c + _x235*(_x224*_x227*(_x232*i_c_A_c - _x234*i_sin_b) - _x233*delta)
                + d_i_c_a__c*l0)
            _x236 = -delta*i_cos_t + i_d_omega_D*i_sin_t
            _x237 = _x236*i_exp_t + delta
            _x238 = delta*i_sin_t + i_cos_t*i_d_omega_D
            _x239 = -_x238*i_exp_t + i_d_omega_D
            _x240 = _x237*i_d_A_c + _x239*i_d_B_s
            _x241 = (1.0/i_tau)
            _x242 = _x225 + i_d_omega_D**2
            _x243 = (1.0/_x242)
            _x244 = _x241*_x243
            _x245 = l0*(_x240*_x244 + i_d_a + 1.0)
            _i_L2 = _x245
            _x246 = i_d_A_c*i_exp_t
            _x247 = i_d_B_s*i_exp_t
            _x248 = _x244*l0
            _pd__116 = _x248*(-_x246*delta - _x247*i_d_omega_D)
            _pd__117 = _x237*_x248
            _pd__118 = _x239*_x248
            _x249 = -i_cos_t*i_exp_t + 1.0
            _x250 = 2.0*_x240*_x241*_x243**2
            _pd__119 = l0*(_x241*_x243*(_x246*i_sin_t + _x249*i_d_B_s) - _x250*i_d_omega_D)
            _pd__120 = _x248*(_x236*i_d_A_c - _x238*i_d_B_s)
            _pd__121 = _x248*(-_x247*delta + i_d_A_c*i_d_omega_D*i_exp_t)
            _pd__122 = -_x240*_x241**2*_x243*l0
            _d_i_L2__q_r_td = (_pd__116*d_i_cos_t__q_r_td + _pd__117*d_i_d_A_c__q_r_td
                + _pd__118*d_i_d_B_s__q_r_td + _pd__119*d_i_d_omega_D__q_r_td + _pd__120*d_i_exp_t__q_r_td
                + _pd__121*d_i_sin_t__q_r_td + _pd__122*d_i_tau__q_r_td + d_i_d_a__q_r_td*l0)
            _d_i_L2__q_rd_td = (_pd__116*d_i_cos_t__q_rd_td + _pd__117*d_i_d_A_c__q_rd_td
                + _pd__118*d_i_d_B_s__q_rd_td + _pd__119*d_i_d_omega_D__q_rd_td + _pd__120*d_i_exp_t__q_rd_td
                + _pd__121*d_i_sin_t__q_rd_td + _pd__122*d_i_tau__q_rd_td + d_i_d_a__q_rd_td*l0)
            _d_i_L2__q_th_td = (_pd__116*d_i_cos_t__q_th_td + _pd__117*d_i_d_A_c__q_th_td
                + _pd__118*d_i_d_B_s__q_th_td + _pd__119*d_i_d_omega_D__q_th_td + _pd__120*d_i_exp_t__q_th_td
                + _pd__121*d_i_sin_t__q_th_td + _pd__122*d_i_tau__q_th_td + d_i_d_a__q_th_td*l0)
            _d_i_L2__q_thd_td = (_pd__116*d_i_cos_t__q_thd_td + _pd__117*d_i_d_A_c__q_thd_td
                + _pd__118*d_i_d_B_s__q_thd_td + _pd__119*d_i_d_omega_D__q_thd_td
                + _pd__120*d_i_exp_t__q_thd_td + _pd__121*d_i_sin_t__q_thd_td + _pd__122*d_i_tau__q_thd_td
                + d_i_d_a__q_thd_td*l0)
            _d_i_L2__k_c = (_pd__116*d_i_cos_t__k_c + _pd__117*d_i_d_A_c__k_c + _pd__118*d_i_d_B_s__k_c
                + _pd__119*d_i_d_omega_D__k_c + _pd__120*d_i_exp_t__k_c + _pd__121*d_i_sin_t__k_c
                + _pd__122*d_i_tau__k_c + d_i_d_a__k_c*l0)
            _d_i_L2__k_d = (_pd__116*d_i_cos_t__k_d + _pd__117*d_i_d_A_c__k_d + _pd__118*d_i_d_B_s__k_d
                + _pd__119*d_i_d_omega_D__k_d + _pd__120*d_i_exp_t__k_d + _pd__121*d_i_sin_t__k_d
                + _pd__122*d_i_tau__k_d + d_i_d_a__k_d*l0)
            _d_i_L2__c = (_pd__116*d_i_cos_t__c + _pd__117*d_i_d_A_c__c + _pd__118*d_i_d_B_s__c
                + _pd__119*d_i_d_omega_D__c + _pd__120*d_i_exp_t__c + _pd__121*d_i_sin_t__c
                + _pd__122*d_i_tau__c + _x235*(_x241*_x243*(-_x247*i_sin_t + _x249*i_d_A_c) - _x250*delta)
                + d_i_d_a__c*l0)
            _x251 = g_s*m
            _x252 = _x251*math.sin(i_bottom_q_th)
            _x253 = _x229*_x252
            _x254 = _x251*math.sin(q_th_td)
            _x255 = _x229*_x254
            _x256 = (0.5)*i_t_bottom
            i_P_new1 = _x256*(_x253 + _x255)
            _pd__123 = _x256*(_x252 + _x254)
            _x257 = _x251*math.cos(i_bottom_q_th)
            _x258 = _x229*_x256
            _pd__124 = _x257*_x258
            _pd__125 = (0.5)*_x253 + (0.5)*_x255
            d_i_P_new1__q_r_td = (_d_i_L1__q_r_td*_pd__123 + _pd__124*d_i_bottom_q_th__q_r_td
                + _pd__125*d_i_t_bottom__q_r_td)
            d_i_P_new1__q_rd_td = (_d_i_L1__q_rd_td*_pd__123 + _pd__124*d_i_bottom_q_th__q_rd_td
                + _pd__125*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_d_i_L1__q_th_td*_pd__123 + _pd__124*d_i_bottom_q_th__q_th_td
                + _pd__125*d_i_t_bottom__q_th_td + _x251*_x258*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_d_i_L1__q_thd_td*_pd__123 + _pd__124*d_i_bottom_q_th__q_thd_td
                + _pd__125*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = (_d_i_L1__k_c*_pd__123 + _pd__124*d_i_bottom_q_th__k_c
                + _pd__125*d_i_t_bottom__k_c)
            d_i_P_new1__k_d = (_d_i_L1__k_d*_pd__123 + _pd__124*d_i_bottom_q_th__k_d
                + _pd__125*d_i_t_bottom__k_d)
            d_i_P_new1__c = _d_i_L1__c*_pd__123 + _pd__124*d_i_bottom_q_th__c + _pd__125*d_i_t_bottom__c
            _x259 = _x245*_x252
            _x260 = _x251*math.sin(i_liftoff_q_th)
            _x261 = _x245*_x260
            _x262 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x262*(_x259 + _x261)
            _pd__126 = _x262*(_x252 + _x260)
            _x263 = _x245*_x262
            _pd__127 = _x257*_x263
            _pd__128 = _x251*_x263*math.cos(i_liftoff_q_th)
            _x264 = (0.5)*_x259 + (0.5)*_x261
            _pd__129 = -_x264
            _pd__130 = _x264
            d_i_P_new2__q_r_td = (_d_i_L2__q_r_td*_pd__126 + _pd__127*d_i_bottom_q_th__q_r_td
                + _pd__128*d_i_liftoff_q_th__q_r_td + _pd__129*d_i_t_bottom__q_r_td
                + _pd__130*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_d_i_L2__q_rd_td*_pd__126 + _pd__127*d_i_bottom_q_th__q_rd_td
                + _pd__128*d_i_liftoff_q_th__q_rd_td + _pd__129*d_i_t_bottom__q_rd_td
                + _pd__130*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_d_i_L2__q_th_td*_pd__126 + _pd__127*d_i_bottom_q_th__q_th_td
                + _pd__128*d_i_liftoff_q_th__q_th_td + _pd__129*d_i_t_bottom__q_th_td
                + _pd__130*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_d_i_L2__q_thd_td*_pd__126 + _pd__127*d_i_bottom_q_th__q_thd_td
                + _pd__128*d_i_liftoff_q_th__q_thd_td + _pd__129*d_i_t_bottom__q_thd_td
                + _pd__130*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_d_i_L2__k_c*_pd__126 + _pd__127*d_i_bottom_q_th__k_c
                + _pd__128*d_i_liftoff_q_th__k_c + _pd__129*d_i_t_bottom__k_c + _pd__130*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_d_i_L2__k_d*_pd__126 + _pd__127*d_i_bottom_q_th__k_d
                + _pd__128*d_i_liftoff_q_th__k_d + _pd__129*d_i_t_bottom__k_d + _pd__130*d_i_t_stance__k_d)
            d_i_P_new2__c = (_d_i_L2__c*_pd__126 + _pd__127*d_i_bottom_q_th__c + _pd__128*d_i_liftoff_q_th__c
                + _pd__129*d_i_t_bottom__c + _pd__130*d_i_t_stance__c)
        else:
            return fail(out, STATUS_INVALID_INPUT)
        # next values
        P_c_compression__next = i_P_new1
        P_c_decompression__next = i_P_new2
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(P_c_compression__next - P_c_compression)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td))) and (abs(P_c_decompression__next
            - P_c_decompression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td))))
        _pkn0 = (P_c_compression__next, P_c_decompression__next, d_i_P_new1__q_r_td, d_i_P_new1__q_rd_td,
            d_i_P_new1__q_th_td, d_i_P_new1__q_thd_td, d_i_P_new1__k_c, d_i_P_new1__k_d, d_i_P_new1__c,
            d_i_P_new2__q_r_td, d_i_P_new2__q_rd_td, d_i_P_new2__q_th_td, d_i_P_new2__q_thd_td,
            d_i_P_new2__k_c, d_i_P_new2__k_d, d_i_P_new2__c, )
        _pk0 = _pkn0
        passes += 1.0
    # the stance outputs: the pass at the final iterate
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = i_bottom_q_r
    bottom_q_rd = i_bottom_q_rd
    bottom_q_th = i_bottom_q_th
    bottom_q_thd = i_bottom_q_thd
    liftoff_q_r = i_liftoff_q_r
    liftoff_q_rd = i_liftoff_q_rd
    liftoff_q_th = i_liftoff_q_th
    liftoff_q_thd = i_liftoff_q_thd
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_i_t_bottom__q_r_td
    d_t_bottom__q_rd_td = d_i_t_bottom__q_rd_td
    d_t_bottom__q_th_td = d_i_t_bottom__q_th_td
    d_t_bottom__q_thd_td = d_i_t_bottom__q_thd_td
    d_t_bottom__k_c = d_i_t_bottom__k_c
    d_t_bottom__k_d = d_i_t_bottom__k_d
    d_t_bottom__c = d_i_t_bottom__c
    d_t_stance__q_r_td = d_i_t_stance__q_r_td
    d_t_stance__q_rd_td = d_i_t_stance__q_rd_td
    d_t_stance__q_th_td = d_i_t_stance__q_th_td
    d_t_stance__q_thd_td = d_i_t_stance__q_thd_td
    d_t_stance__k_c = d_i_t_stance__k_c
    d_t_stance__k_d = d_i_t_stance__k_d
    d_t_stance__c = d_i_t_stance__c
    d_bottom_q_r__q_r_td = d_i_bottom_q_r__q_r_td
    d_bottom_q_r__q_rd_td = d_i_bottom_q_r__q_rd_td
    d_bottom_q_r__q_th_td = d_i_bottom_q_r__q_th_td
    d_bottom_q_r__q_thd_td = d_i_bottom_q_r__q_thd_td
    d_bottom_q_r__k_c = d_i_bottom_q_r__k_c
    d_bottom_q_r__k_d = d_i_bottom_q_r__k_d
    d_bottom_q_r__c = d_i_bottom_q_r__c
    d_bottom_q_th__q_r_td = d_i_bottom_q_th__q_r_td
    d_bottom_q_th__q_rd_td = d_i_bottom_q_th__q_rd_td
    d_bottom_q_th__q_th_td = d_i_bottom_q_th__q_th_td
    d_bottom_q_th__q_thd_td = d_i_bottom_q_th__q_thd_td
    d_bottom_q_th__k_c = d_i_bottom_q_th__k_c
    d_bottom_q_th__k_d = d_i_bottom_q_th__k_d
    d_bottom_q_th__c = d_i_bottom_q_th__c
    d_bottom_q_thd__q_r_td = d_i_bottom_q_thd__q_r_td
    d_bottom_q_thd__q_rd_td = d_i_bottom_q_thd__q_rd_td
    d_bottom_q_thd__q_th_td = d_i_bottom_q_thd__q_th_td
    d_bottom_q_thd__q_thd_td = d_i_bottom_q_thd__q_thd_td
    d_bottom_q_thd__k_c = d_i_bottom_q_thd__k_c
    d_bottom_q_thd__k_d = d_i_bottom_q_thd__k_d
    d_bottom_q_thd__c = d_i_bottom_q_thd__c
    d_liftoff_q_r__q_r_td = d_i_liftoff_q_r__q_r_td
    d_liftoff_q_r__q_rd_td = d_i_liftoff_q_r__q_rd_td
    d_liftoff_q_r__q_th_td = d_i_liftoff_q_r__q_th_td
    d_liftoff_q_r__q_thd_td = d_i_liftoff_q_r__q_thd_td
    d_liftoff_q_r__k_c = d_i_liftoff_q_r__k_c
    d_liftoff_q_r__k_d = d_i_liftoff_q_r__k_d
    d_liftoff_q_r__c = d_i_liftoff_q_r__c
    d_liftoff_q_rd__q_r_td = d_i_liftoff_q_rd__q_r_td
    d_liftoff_q_rd__q_rd_td = d_i_liftoff_q_rd__q_rd_td
    d_liftoff_q_rd__q_th_td = d_i_liftoff_q_rd__q_th_td
    d_liftoff_q_rd__q_thd_td = d_i_liftoff_q_rd__q_thd_td
    d_liftoff_q_rd__k_c = d_i_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = d_i_liftoff_q_rd__k_d
    d_liftoff_q_rd__c = d_i_liftoff_q_rd__c
    d_liftoff_q_th__q_r_td = d_i_liftoff_q_th__q_r_td
    d_liftoff_q_th__q_rd_td = d_i_liftoff_q_th__q_rd_td
    d_liftoff_q_th__q_th_td = d_i_liftoff_q_th__q_th_td
    d_liftoff_q_th__q_thd_td = d_i_liftoff_q_th__q_thd_td
    d_liftoff_q_th__k_c = d_i_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = d_i_liftoff_q_th__k_d
    d_liftoff_q_th__c = d_i_liftoff_q_th__c
    d_liftoff_q_thd__q_r_td = d_i_liftoff_q_thd__q_r_td
    d_liftoff_q_thd__q_rd_td = d_i_liftoff_q_thd__q_rd_td
    d_liftoff_q_thd__q_th_td = d_i_liftoff_q_thd__q_th_td
    d_liftoff_q_thd__q_thd_td = d_i_liftoff_q_thd__q_thd_td
    d_liftoff_q_thd__k_c = d_i_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = d_i_liftoff_q_thd__k_d
    d_liftoff_q_thd__c = d_i_liftoff_q_thd__c
    # every output finite, or the inputs were far outside a physical range
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c,
        d_t_bottom__k_d, d_t_bottom__c, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td,
        d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_t_stance__c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_r__c, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_th__c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td,
        d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__c, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td,
        d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_r__c,
        d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td,
        d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_rd__c, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_th__c, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td,
        d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d,
        d_liftoff_q_thd__c, d_P_c_compression__q_r_td, d_P_c_compression__q_rd_td, d_P_c_compression__q_th_td,
        d_P_c_compression__q_thd_td, d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_compression__c,
        d_P_c_decompression__q_r_td, d_P_c_decompression__q_rd_td, d_P_c_decompression__q_th_td,
        d_P_c_decompression__q_thd_td, d_P_c_decompression__k_c, d_P_c_decompression__k_d,
        d_P_c_decompression__c, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_damped_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_damped_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_damped_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_damped_apex_return_jacobian(x, p, out):
    """Apex-return map by Geyer et al.'s map with leg damping (damped radial oscillator per half), and its
    derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 4, 7, 17, 18, 19, 48, 65, 76.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, liftoff, gravity, iterations, tol); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer_damped.geyer_damped_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer_damped.geyer_damped_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 394
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, g_f, q_r_td, q_r_lo, liftoff, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3,
        4, 8, 5, 6, 7, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, c, g_f,
            q_r_td, q_r_lo, liftoff, gravity, iterations, tol,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((c >= 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo
            > 0.0)) & ((liftoff == 0.0) or (liftoff == 1.0)) & ((gravity == 0.0) or (gravity == 1.0)
            or (gravity == 2.0) or (gravity == 3.0) or (gravity == 4.0) or (gravity == 5.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, foot_x, _j_td_q_rd__b_y_apex, _j_td_q_rd__b_xd_apex,
        _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _j_td_q_rd__retraction_rate, _j_td_q_th__b_y_apex,
        _j_td_q_th__q_th_td, _j_td_q_th__ground, _j_td_q_th__retraction_rate, _j_td_q_thd__b_y_apex,
        _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground, _j_td_q_thd__retraction_rate,
        _o0_26, _o0_28, _o0_29, _o0_30, _j_foot_x__b_y_apex, _j_foot_x__b_xd_apex, _j_foot_x__q_th_td,
        _j_foot_x__ground, _j_foot_x__retraction_rate,) = (load(_o0, 0, 1, 2, 3, 4, 5, 11, 12, 13, 14, 15, 16,
        18, 19, 20, 21, 22, 23, 24, 25, 26, 28, 29, 30, 31, 32, 33, 34, 35))
    # stance: Geyer et al.'s map with leg damping (damped radial oscillator per half)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(104), 104)
    _c1 = geyer_damped_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11, _o1_12,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _o1_24, _o1_25, _o1_26,
        _j_liftoff_q_r__q_rd_td, _j_liftoff_q_r__q_th_td, _j_liftoff_q_r__q_thd_td, _j_liftoff_q_r__k_c,
        _j_liftoff_q_r__k_d, _j_liftoff_q_r__c, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td,
        _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__c,
        _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__c, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__c,
        _j_P_c_compression__q_rd_td, _j_P_c_compression__q_th_td, _j_P_c_compression__q_thd_td, _o1_87,
        _o1_88, _o1_89, _j_P_c_decompression__q_rd_td, _j_P_c_decompression__q_th_td,
        _j_P_c_decompression__q_thd_td, _o1_94, _o1_95, _o1_96,) = (load(_o1, 1, 6, 7, 8, 9, 10, 11, 12, 21,
        22, 23, 24, 25, 26, 56, 57, 58, 59, 60, 61, 63, 64, 65, 66, 67, 68, 70, 71, 72, 73, 74, 75, 77, 78,
        79, 80, 81, 82, 84, 85, 86, 87, 88, 89, 91, 92, 93, 94, 95, 96))
    # chain rule through geyer_damped_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_th_td*_j_td_q_th__b_y_apex + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = (_j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_th_td*_j_td_q_th__ground
        + _j_t_stance__q_thd_td*_j_td_q_thd__ground)
    d_t_stance__retraction_rate = (_j_t_stance__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_t_stance__q_th_td*_j_td_q_th__retraction_rate
        + _j_t_stance__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_r__b_y_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_r__b_xd_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_r__q_th_td = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_r__ground = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__ground + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_r__retraction_rate = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_rd__retraction_rate = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__ground = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__ground + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_th__retraction_rate = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__retraction_rate = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__retraction_rate)
    d_P_c_compression__b_y_apex = (_j_P_c_compression__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_P_c_compression__q_th_td*_j_td_q_th__b_y_apex
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__b_y_apex)
    d_P_c_compression__b_xd_apex = (_j_P_c_compression__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_P_c_compression__q_th_td = (_j_P_c_compression__q_rd_td*_j_td_q_rd__q_th_td
        + _j_P_c_compression__q_th_td*_j_td_q_th__q_th_td + _j_P_c_compression__q_thd_td*_j_td_q_thd__q_th_td)
    d_P_c_compression__ground = (_j_P_c_compression__q_rd_td*_j_td_q_rd__ground
        + _j_P_c_compression__q_th_td*_j_td_q_th__ground + _j_P_c_compression__q_thd_td*_j_td_q_thd__ground)
    d_P_c_compression__retraction_rate = (_j_P_c_compression__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_P_c_compression__q_th_td*_j_td_q_th__retraction_rate
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__retraction_rate)
    d_P_c_decompression__b_y_apex = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_P_c_decompression__q_th_td*_j_td_q_th__b_y_apex
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__b_y_apex)
    d_P_c_decompression__b_xd_apex = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_P_c_decompression__q_th_td = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__q_th_td
        + _j_P_c_decompression__q_th_td*_j_td_q_th__q_th_td
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__q_th_td)
    d_P_c_decompression__ground = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__ground
        + _j_P_c_decompression__q_th_td*_j_td_q_th__ground
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__ground)
    d_P_c_decompression__retraction_rate = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_P_c_decompression__q_th_td*_j_td_q_th__retraction_rate
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__retraction_rate)
    # liftoff -> next apex: exact ballistic ascent
    _o2 = carray(stack(25), 25)
    _c2 = (liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        g_f, direction, _o2))
    if _c2 != STATUS_OK:
        return fail(out, _c2)
    (_o2_0, _o2_1, _o2_2, next_apex_x, _j_apex_height__q_r, _j_apex_height__q_rd, _j_apex_height__q_th,
        _j_apex_height__q_thd, _j_apex_speed__q_r, _j_apex_speed__q_rd, _j_apex_speed__q_th,
        _j_apex_speed__q_thd, _j_t_ascent__q_r, _j_t_ascent__q_rd, _j_t_ascent__q_th, _j_t_ascent__q_thd,
        _j_next_apex_x__q_r, _j_next_apex_x__q_rd, _j_next_apex_x__q_th, _j_next_apex_x__q_thd,) = (load(_o2,
        0, 1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 21, 22, 23, 24))
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_r*d_liftoff_q_r__b_y_apex
        + _j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex
        + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_r*d_liftoff_q_r__b_xd_apex
        + _j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex
        + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_r*d_liftoff_q_r__q_th_td
        + _j_apex_height__q_rd*d_liftoff_q_rd__q_th_td + _j_apex_height__q_th*d_liftoff_q_th__q_th_td
        + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_r*d_liftoff_q_r__ground
        + _j_apex_height__q_rd*d_liftoff_q_rd__ground + _j_apex_height__q_th*d_liftoff_q_th__ground
        + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
    d_apex_height__retraction_rate = (_j_apex_height__q_r*d_liftoff_q_r__retraction_rate
        + _j_apex_height__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_height__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_height__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_height__k_c = (_j_apex_height__q_r*_j_liftoff_q_r__k_c + _j_apex_height__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_height__q_th*_j_liftoff_q_th__k_c + _j_apex_height__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_height__k_d = (_j_apex_height__q_r*_j_liftoff_q_r__k_d + _j_apex_height__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_height__q_th*_j_liftoff_q_th__k_d + _j_apex_height__q_thd*_j_liftoff_q_thd__k_d)
    d_apex_height__c = (_j_apex_height__q_r*_j_liftoff_q_r__c + _j_apex_height__q_rd*_j_liftoff_q_rd__c
        + _j_apex_height__q_th*_j_liftoff_q_th__c + _j_apex_height__q_thd*_j_liftoff_q_thd__c)
    d_apex_speed__b_y_apex = (_j_apex_speed__q_r*d_liftoff_q_r__b_y_apex
        + _j_apex_speed__q_rd*d_liftoff_q_rd__b_y_apex + _j_apex_speed__q_th*d_liftoff_q_th__b_y_apex
        + _j_apex_speed__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_speed__b_xd_apex = (_j_apex_speed__q_r*d_liftoff_q_r__b_xd_apex
        + _j_apex_speed__q_rd*d_liftoff_q_rd__b_xd_apex + _j_apex_speed__q_th*d_liftoff_q_th__b_xd_apex
        + _j_apex_speed__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_speed__q_th_td = (_j_apex_speed__q_r*d_liftoff_q_r__q_th_td
        + _j_apex_speed__q_rd*d_liftoff_q_rd__q_th_td + _j_apex_speed__q_th*d_liftoff_q_th__q_th_td
        + _j_apex_speed__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_speed__ground = (_j_apex_speed__q_r*d_liftoff_q_r__ground
        + _j_apex_speed__q_rd*d_liftoff_q_rd__ground + _j_apex_speed__q_th*d_liftoff_q_th__ground
        + _j_apex_speed__q_thd*d_liftoff_q_thd__ground)
    d_apex_speed__retraction_rate = (_j_apex_speed__q_r*d_liftoff_q_r__retraction_rate
        + _j_apex_speed__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_speed__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_speed__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_speed__k_c = (_j_apex_speed__q_r*_j_liftoff_q_r__k_c + _j_apex_speed__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_speed__q_th*_j_liftoff_q_th__k_c + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_speed__k_d = (_j_apex_speed__q_r*_j_liftoff_q_r__k_d + _j_apex_speed__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_speed__q_th*_j_liftoff_q_th__k_d + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_d)
    d_apex_speed__c = (_j_apex_speed__q_r*_j_liftoff_q_r__c + _j_apex_speed__q_rd*_j_liftoff_q_rd__c
        + _j_apex_speed__q_th*_j_liftoff_q_th__c + _j_apex_speed__q_thd*_j_liftoff_q_thd__c)
    d_t_ascent__b_y_apex = (_j_t_ascent__q_r*d_liftoff_q_r__b_y_apex
        + _j_t_ascent__q_rd*d_liftoff_q_rd__b_y_apex + _j_t_ascent__q_th*d_liftoff_q_th__b_y_apex
        + _j_t_ascent__q_thd*d_liftoff_q_thd__b_y_apex)
    d_t_ascent__b_xd_apex = (_j_t_ascent__q_r*d_liftoff_q_r__b_xd_apex
        + _j_t_ascent__q_rd*d_liftoff_q_rd__b_xd_apex + _j_t_ascent__q_th*d_liftoff_q_th__b_xd_apex
        + _j_t_ascent__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_t_ascent__q_th_td = (_j_t_ascent__q_r*d_liftoff_q_r__q_th_td + _j_t_ascent__q_rd*d_liftoff_q_rd__q_th_td
        + _j_t_ascent__q_th*d_liftoff_q_th__q_th_td + _j_t_ascent__q_thd*d_liftoff_q_thd__q_th_td)
    d_t_ascent__ground = (_j_t_ascent__q_r*d_liftoff_q_r__ground + _j_t_ascent__q_rd*d_liftoff_q_rd__ground
        + _j_t_ascent__q_th*d_liftoff_q_th__ground + _j_t_ascent__q_thd*d_liftoff_q_thd__ground)
    d_t_ascent__retraction_rate = (_j_t_ascent__q_r*d_liftoff_q_r__retraction_rate
        + _j_t_ascent__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_t_ascent__q_th*d_liftoff_q_th__retraction_rate
        + _j_t_ascent__q_thd*d_liftoff_q_thd__retraction_rate)
    d_t_ascent__k_c = (_j_liftoff_q_r__k_c*_j_t_ascent__q_r + _j_liftoff_q_rd__k_c*_j_t_ascent__q_rd
        + _j_liftoff_q_th__k_c*_j_t_ascent__q_th + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_r__k_d*_j_t_ascent__q_r + _j_liftoff_q_rd__k_d*_j_t_ascent__q_rd
        + _j_liftoff_q_th__k_d*_j_t_ascent__q_th + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
    d_t_ascent__c = (_j_liftoff_q_r__c*_j_t_ascent__q_r + _j_liftoff_q_rd__c*_j_t_ascent__q_rd
        + _j_liftoff_q_th__c*_j_t_ascent__q_th + _j_liftoff_q_thd__c*_j_t_ascent__q_thd)
    d_next_apex_x__b_y_apex = (_j_next_apex_x__q_r*d_liftoff_q_r__b_y_apex
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__b_y_apex + _j_next_apex_x__q_th*d_liftoff_q_th__b_y_apex
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_y_apex)
    d_next_apex_x__b_xd_apex = (_j_next_apex_x__q_r*d_liftoff_q_r__b_xd_apex
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__b_xd_apex + _j_next_apex_x__q_th*d_liftoff_q_th__b_xd_apex
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_next_apex_x__q_th_td = (_j_next_apex_x__q_r*d_liftoff_q_r__q_th_td
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__q_th_td + _j_next_apex_x__q_th*d_liftoff_q_th__q_th_td
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__q_th_td)
    d_next_apex_x__ground = (_j_next_apex_x__q_r*d_liftoff_q_r__ground
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__ground + _j_next_apex_x__q_th*d_liftoff_q_th__ground
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__ground)
    d_next_apex_x__retraction_rate = (_j_next_apex_x__q_r*d_liftoff_q_r__retraction_rate
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_next_apex_x__q_th*d_liftoff_q_th__retraction_rate
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__retraction_rate)
    d_next_apex_x__k_c = (_j_liftoff_q_r__k_c*_j_next_apex_x__q_r + _j_liftoff_q_rd__k_c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_c*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_c*_j_next_apex_x__q_thd)
    d_next_apex_x__k_d = (_j_liftoff_q_r__k_d*_j_next_apex_x__q_r + _j_liftoff_q_rd__k_d*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_d*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_d*_j_next_apex_x__q_thd)
    d_next_apex_x__c = (_j_liftoff_q_r__c*_j_next_apex_x__q_r + _j_liftoff_q_rd__c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__c*_j_next_apex_x__q_th + _j_liftoff_q_thd__c*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    d_step_length__retraction_rate = _j_foot_x__retraction_rate + d_next_apex_x__retraction_rate
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_liftoff_q_r__k_c = _j_liftoff_q_r__k_c
    d_liftoff_q_r__k_d = _j_liftoff_q_r__k_d
    d_liftoff_q_r__c = _j_liftoff_q_r__c
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_rd__c = _j_liftoff_q_rd__c
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_th__c = _j_liftoff_q_th__c
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_liftoff_q_thd__c = _j_liftoff_q_thd__c
    d_step_length__k_c = d_next_apex_x__k_c
    d_step_length__k_d = d_next_apex_x__k_d
    d_step_length__c = d_next_apex_x__c
    d_foot_x__b_y_apex = _j_foot_x__b_y_apex
    d_foot_x__b_xd_apex = _j_foot_x__b_xd_apex
    d_foot_x__q_th_td = _j_foot_x__q_th_td
    d_foot_x__ground = _j_foot_x__ground
    d_foot_x__retraction_rate = _j_foot_x__retraction_rate
    d_touchdown_q_th__b_y_apex = _j_td_q_th__b_y_apex
    d_touchdown_q_th__q_th_td = _j_td_q_th__q_th_td
    d_touchdown_q_th__ground = _j_td_q_th__ground
    d_touchdown_q_th__retraction_rate = _j_td_q_th__retraction_rate
    # every output finite, or the inputs were far outside a physical range
    store(out, (_o2_0, _o2_1, _o0_4, _o1_1, _o2_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        step_length, foot_x, foot_y, _o0_2, _o1_10, _o1_11, _o1_12, d_apex_height__b_y_apex,
        d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground,
        d_apex_height__retraction_rate, d_apex_height__k_c, d_apex_height__k_d, d_apex_height__c,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__retraction_rate, d_apex_speed__k_c, d_apex_speed__k_d, d_apex_speed__c, _o0_26, 0.0,
        _o0_28, _o0_29, _o0_30, 0.0, 0.0, 0.0, d_t_stance__b_y_apex, d_t_stance__b_xd_apex,
        d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__retraction_rate, _o1_24, _o1_25, _o1_26,
        d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground,
        d_t_ascent__retraction_rate, d_t_ascent__k_c, d_t_ascent__k_d, d_t_ascent__c, d_liftoff_q_r__b_y_apex,
        d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground,
        d_liftoff_q_r__retraction_rate, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_r__c,
        d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground,
        d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_rd__c,
        d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground,
        d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_th__c,
        d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__ground, d_liftoff_q_thd__retraction_rate, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d,
        d_liftoff_q_thd__c, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td,
        d_step_length__ground, d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d,
        d_step_length__c, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground,
        d_foot_x__retraction_rate, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0,
        d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td, d_touchdown_q_th__ground,
        d_touchdown_q_th__retraction_rate, 0.0, 0.0, 0.0, d_P_c_compression__b_y_apex,
        d_P_c_compression__b_xd_apex, d_P_c_compression__q_th_td, d_P_c_compression__ground,
        d_P_c_compression__retraction_rate, _o1_87, _o1_88, _o1_89, d_P_c_decompression__b_y_apex,
        d_P_c_decompression__b_xd_apex, d_P_c_decompression__q_th_td, d_P_c_decompression__ground,
        d_P_c_decompression__retraction_rate, _o1_94, _o1_95, _o1_96, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        ))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_damped_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_damped_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_damped_apex_return_jacobian(row(X, i), p, row(OUT, i))
