# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:4d6fab274bba303b
#   geyer.py sha256:26ff4a0183dca42d
#   geyer_vs.py sha256:0592a5a2e1c70987
#   gravity_type0.py sha256:04bbbc0de76e2706
#   gravity_type1.py sha256:37299c1835198fd6
#   gravity_type2.py sha256:ba6e5874bb098cda
#   gravity_type3.py sha256:a1deffa577d0b912
#   gravity_type4.py sha256:ea56cd04d2860d7d
#   gravity_type5.py sha256:e95d34e96defb7c2
# ----------------------------------------------------------------------------------------------
"""Iterative stance map (Schwind and Koditschek, converging form) (report section 5.2): stance, state-at-time and apex-return kernels."""

import math

import numpy as np
from numba import njit, prange
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_stance
from .geyer_vs import geyer_vs_stance
from .gravity_type0 import gravity_type0_stance
from .gravity_type1 import gravity_type1_stance
from .gravity_type2 import gravity_type2_stance
from .gravity_type3 import gravity_type3_stance
from .gravity_type4 import gravity_type4_stance
from .gravity_type5 import gravity_type5_stance

NAN = math.nan
STATUS_OK = 0
STATUS_INVALID_INPUT = 1
STATUS_APEX_TOO_LOW = 2
STATUS_TOUCHDOWN_NOT_COMPRESSING = 3
STATUS_NO_REAL_SOLUTION = 4
STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION = 5
STATUS_NO_LIFTOFF = 6
STATUS_FALL = 7
STATUS_LIFTOFF_DOWNWARD = 8
STATUS_LIFTOFF_BACKWARD = 9
STATUS_RECOMPRESSION = 10
STATUS_INTEGRATION_FAILED = 11
STATUS_NUMERICAL_RANGE = 12
STATUS_NOT_CONVERGED = 13
STATUS_ENERGY_DEFICIT = 14
STATUS_IMAGINARY_MOMENTUM = 15


@njit(cache=True, error_model="numpy")
def schwind_compression(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd, nodes, iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of p_r).

    Report equations: 115, 116, 117, 118, 123.

    Arguments:
        q_r: touchdown state: leg length [m]
        q_rd: touchdown state: leg length rate [m/s]
        q_th: touchdown state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: touchdown state: leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        guess_q_r: zeroth iterate's bottom q_r
        guess_q_th: zeroth iterate's bottom q_th
        guess_q_thd: zeroth iterate's bottom q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 2126
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s) and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # node count
    if nodes == 0.0:
        # Picard passes on the 1 node values (collocation in u)
        _D = -guess_q_r + q_r
        _Q0 = 0.5*guess_q_th + 0.5*q_th
        _P0 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
        _passes = 0.0
        _conv0 = False
        for _it0 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x0 = -0.75*_D + q_r
            _x8 = (1.0/_x0)
            _x1 = k_c*l0
            _x2 = g_s*m*math.cos(_Q0)
            _x3 = _x0*k_c
            _x4 = _P0**2*_x8**3/m
            _x5 = 0.5*_x1 - 0.5*_x2 - 0.5*_x3 + 0.5*_x4
            _x6 = math.sqrt(m)
            _x7 = math.sqrt(_D)/math.sqrt(_x5)
            _isigma0 = _x0
            _iF0 = _x1 - _x2 - _x3 + _x4
            _iPsi0 = _x5
            _ift0 = _x6*_x7
            _ifq0 = _P0*_x7*_x8**2/_x6
            _ifp0 = _x0*_x7*g_s*m**(1.5)*math.sin(_Q0)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n0_0 = m*q_rd**2/(1.0*_iF0 - 1.0*k_c*(-_isigma0 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2 + (1.0*_iF0 - 1.0*k_c*(-_isigma0 + l0) + k_c*(l0 - q_r))**2))
            _n0_1 = 0.5*_ifq0 + q_th
            _n0_2 = 0.5*_ifp0 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n0_0
            _Q0 = _n0_1
            _P0 = _n0_2
            _passes += 1.0
            if _conv0:
                break
        if not _conv0 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x9 = -0.75*_D + q_r
        _x17 = (1.0/_x9)
        _x10 = k_c*l0
        _x11 = g_s*m*math.cos(_Q0)
        _x12 = _x9*k_c
        _x13 = _P0**2*_x17**3/m
        _x14 = 0.5*_x10 - 0.5*_x11 - 0.5*_x12 + 0.5*_x13
        _x15 = math.sqrt(m)
        _x16 = math.sqrt(_D)/math.sqrt(_x14)
        _fsigma0 = _x9
        _fF0 = _x10 - _x11 - _x12 + _x13
        _fPsi0 = _x14
        _fft0 = _x15*_x16
        _ffq0 = _P0*_x16*_x17**2/_x15
        _ffp0 = _x16*_x9*g_s*m**(1.5)*math.sin(_Q0)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # bottom state
        _x18 = -_D + q_r
        t_half = 1.0*_fft0
        end_q_th = 1.0*_ffq0 + q_th
        end_q_r = _x18
        end_q_rd = 0.0
        end_q_thd = (1.0*_ffp0 + m*q_r**2*q_thd)/(_x18**2*m)
        passes = _passes
        # bottom leg length q_r_b > 0
        if not ((end_q_r > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    elif nodes == 1.0:
        # Picard passes on the 2 node values (collocation in u)
        _D = -guess_q_r + q_r
        _Q0 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
        _Q1 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
        _P0 = 0.7886751345948129*guess_q_r**2*guess_q_thd*m + 0.2113248654051871*m*q_r**2*q_thd
        _P1 = 0.2113248654051871*guess_q_r**2*guess_q_thd*m + 0.7886751345948129*m*q_r**2*q_thd
        _passes = 0.0
        _conv1 = False
        for _it1 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x19 = -q_r
            _x20 = -0.9553418012614795*_D - _x19
            _x44 = (1.0/_x20)
            _x21 = k_c*l0
            _x22 = g_s*m
            _x23 = _x22*math.cos(_Q0)
            _x24 = _x20*k_c
            _x25 = _P0**2
            _x26 = (1.0/m)
            _x27 = _x44**3
            _x28 = _x25*_x26*_x27
            _x29 = -0.37799153207185376*_D - _x19
            _x45 = (1.0/_x29)
            _x30 = _x22*math.cos(_Q1)
            _x31 = _x29*k_c
            _x32 = _P1**2
            _x33 = _x45**3
            _x34 = _x26*_x32*_x33
            _x35 = 0.5*_x21 - 0.5610042339640731*_x23 - 0.5610042339640731*_x24 + 0.5610042339640731*_x28 + 0.06100423396407311*_x30 + 0.06100423396407311*_x31 - 0.06100423396407311*_x34
            _x36 = (1.0/math.sqrt(_x35))
            _x37 = math.sqrt(_D)
            _x38 = math.sqrt(m)
            _x39 = _x37*_x38
            _x40 = _x37/_x38
            _x41 = _x37*g_s*m**(1.5)
            _x42 = -0.22767090063073978*_x23 - 0.22767090063073978*_x24 + 0.22767090063073978*_x25*_x26*_x27 + 0.27232909936926025*_x26*_x32*_x33 - 0.27232909936926025*_x30 - 0.27232909936926025*_x31 + 0.5*k_c*l0
            _x43 = (1.0/math.sqrt(_x42))
            _isigma0 = _x20
            _iF0 = _x21 - _x23 - _x24 + _x28
            _isigma1 = _x29
            _iF1 = _x21 - _x30 - _x31 + _x34
            _iPsi0 = _x35
            _ift0 = _x36*_x39
            _ifq0 = _P0*_x36*_x40*_x44**2
            _ifp0 = _x20*_x36*_x41*math.sin(_Q0)
            _iPsi1 = _x42
            _ift1 = _x39*_x43
            _ifq1 = _P1*_x40*_x43*_x45**2
            _ifp1 = _x29*_x41*_x43*math.sin(_Q1)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n1_0 = m*q_rd**2/(0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 - 0.2113248654051871*k_c*(-_isigma0 + l0) - 0.7886751345948129*k_c*(-_isigma1 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 - 0.2113248654051871*k_c*(-_isigma0 + l0) - 0.7886751345948129*k_c*(-_isigma1 + l0) + k_c*(l0 - q_r))**2))
            _n1_1 = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
            _n1_2 = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
            _n1_3 = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + m*q_r**2*q_thd
            _n1_4 = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv1 = tol > 0.0 and (abs(_n1_0 - _D) <= tol*(l0)) and (abs(_n1_1 - _Q0) <= tol*(1.0)) and (abs(_n1_2 - _Q1) <= tol*(1.0)) and (abs(_n1_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n1_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n1_0
            _Q0 = _n1_1
            _Q1 = _n1_2
            _P0 = _n1_3
            _P1 = _n1_4
            _passes += 1.0
            if _conv1:
                break
        if not _conv1 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x46 = -q_r
        _x47 = -0.9553418012614795*_D - _x46
        _x71 = (1.0/_x47)
        _x48 = k_c*l0
        _x49 = g_s*m
        _x50 = _x49*math.cos(_Q0)
        _x51 = _x47*k_c
        _x52 = _P0**2
        _x53 = (1.0/m)
        _x54 = _x71**3
        _x55 = _x52*_x53*_x54
        _x56 = -0.37799153207185376*_D - _x46
        _x72 = (1.0/_x56)
        _x57 = _x49*math.cos(_Q1)
        _x58 = _x56*k_c
        _x59 = _P1**2
        _x60 = _x72**3
        _x61 = _x53*_x59*_x60
        _x62 = 0.5*_x48 - 0.5610042339640731*_x50 - 0.5610042339640731*_x51 + 0.5610042339640731*_x55 + 0.06100423396407311*_x57 + 0.06100423396407311*_x58 - 0.06100423396407311*_x61
        _x63 = (1.0/math.sqrt(_x62))
        _x64 = math.sqrt(_D)
        _x65 = math.sqrt(m)
        _x66 = _x64*_x65
        _x67 = _x64/_x65
        _x68 = _x64*g_s*m**(1.5)
        _x69 = -0.22767090063073978*_x50 - 0.22767090063073978*_x51 + 0.22767090063073978*_x52*_x53*_x54 + 0.27232909936926025*_x53*_x59*_x60 - 0.27232909936926025*_x57 - 0.27232909936926025*_x58 + 0.5*k_c*l0
        _x70 = (1.0/math.sqrt(_x69))
        _fsigma0 = _x47
        _fF0 = _x48 - _x50 - _x51 + _x55
        _fsigma1 = _x56
        _fF1 = _x48 - _x57 - _x58 + _x61
        _fPsi0 = _x62
        _fft0 = _x63*_x66
        _ffq0 = _P0*_x63*_x67*_x71**2
        _ffp0 = _x47*_x63*_x68*math.sin(_Q0)
        _fPsi1 = _x69
        _fft1 = _x66*_x70
        _ffq1 = _P1*_x67*_x70*_x72**2
        _ffp1 = _x56*_x68*_x70*math.sin(_Q1)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # bottom state
        _x73 = -_D + q_r
        t_half = 0.5*_fft0 + 0.5*_fft1
        end_q_th = 0.5*_ffq0 + 0.5*_ffq1 + q_th
        end_q_r = _x73
        end_q_rd = 0.0
        end_q_thd = (0.5*_ffp0 + 0.5*_ffp1 + m*q_r**2*q_thd)/(_x73**2*m)
        passes = _passes
        # bottom leg length q_r_b > 0
        if not ((end_q_r > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    elif nodes == 2.0:
        # Picard passes on the 3 node values (collocation in u)
        _D = -guess_q_r + q_r
        _Q0 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
        _Q1 = 0.5*guess_q_th + 0.5*q_th
        _Q2 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
        _P0 = 0.8872983346207417*guess_q_r**2*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd
        _P1 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
        _P2 = 0.11270166537925831*guess_q_r**2*guess_q_thd*m + 0.8872983346207417*m*q_r**2*q_thd
        _passes = 0.0
        _conv2 = False
        for _it2 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x74 = -q_r
            _x75 = -0.9872983346207417*_D - _x74
            _x107 = (1.0/_x75)
            _x76 = k_c*l0
            _x77 = g_s*m
            _x78 = _x77*math.cos(_Q0)
            _x79 = _x75*k_c
            _x80 = _P0**2
            _x81 = (1.0/m)
            _x82 = _x107**3
            _x83 = _x80*_x81*_x82
            _x84 = -0.75*_D - _x74
            _x108 = (1.0/_x84)
            _x85 = _x77*math.cos(_Q1)
            _x86 = _x84*k_c
            _x87 = _P1**2
            _x88 = _x108**3
            _x89 = _x81*_x87*_x88
            _x90 = -0.2127016653792583*_D - _x74
            _x109 = (1.0/_x90)
            _x91 = _x77*math.cos(_Q2)
            _x92 = _x90*k_c
            _x93 = _P2**2
            _x94 = _x109**3
            _x95 = _x81*_x93*_x94
            _x96 = 0.5*_x76 - 0.5762768525670787*_x78 - 0.5762768525670787*_x79 + 0.5762768525670787*_x83 + 0.1040546303448565*_x85 + 0.1040546303448565*_x86 - 0.1040546303448565*_x89 - 0.027777777777777776*_x91 - 0.027777777777777776*_x92 + 0.027777777777777776*_x95
            _x97 = (1.0/math.sqrt(_x96))
            _x98 = math.sqrt(_D)
            _x99 = math.sqrt(m)
            _x100 = _x98*_x99
            _x101 = _x98/_x99
            _x102 = _x98*g_s*m**(1.5)
            _x103 = 0.5*_x76 - 0.17702731517242826*_x78 - 0.17702731517242826*_x79 + 0.17702731517242826*_x83 - 0.3611111111111111*_x85 - 0.3611111111111111*_x86 + 0.3611111111111111*_x89 + 0.038138426283539355*_x91 + 0.038138426283539355*_x92 - 0.038138426283539355*_x95
            _x104 = (1.0/math.sqrt(_x103))
            _x105 = -0.027777777777777776*_x78 - 0.027777777777777776*_x79 + 0.027777777777777776*_x80*_x81*_x82 + 0.3262768525670787*_x81*_x87*_x88 + 0.14594536965514351*_x81*_x93*_x94 - 0.3262768525670787*_x85 - 0.3262768525670787*_x86 - 0.14594536965514351*_x91 - 0.14594536965514351*_x92 + 0.5*k_c*l0
            _x106 = (1.0/math.sqrt(_x105))
            _isigma0 = _x75
            _iF0 = _x76 - _x78 - _x79 + _x83
            _isigma1 = _x84
            _iF1 = _x76 - _x85 - _x86 + _x89
            _isigma2 = _x90
            _iF2 = _x76 - _x91 - _x92 + _x95
            _iPsi0 = _x96
            _ift0 = _x100*_x97
            _ifq0 = _P0*_x101*_x107**2*_x97
            _ifp0 = _x102*_x75*_x97*math.sin(_Q0)
            _iPsi1 = _x103
            _ift1 = _x100*_x104
            _ifq1 = _P1*_x101*_x104*_x108**2
            _ifp1 = _x102*_x104*_x84*math.sin(_Q1)
            _iPsi2 = _x105
            _ift2 = _x100*_x106
            _ifq2 = _P2*_x101*_x106*_x109**2
            _ifp2 = _x102*_x106*_x90*math.sin(_Q2)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n2_0 = m*q_rd**2/(0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 - 0.06261203632181017*k_c*(-_isigma0 + l0) - 0.4444444444444444*k_c*(-_isigma1 + l0) - 0.4929435192337454*k_c*(-_isigma2 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 - 0.06261203632181017*k_c*(-_isigma0 + l0) - 0.4444444444444444*k_c*(-_isigma1 + l0) - 0.4929435192337454*k_c*(-_isigma2 + l0) + k_c*(l0 - q_r))**2))
            _n2_1 = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
            _n2_2 = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
            _n2_3 = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
            _n2_4 = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + m*q_r**2*q_thd
            _n2_5 = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + m*q_r**2*q_thd
            _n2_6 = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv2 = tol > 0.0 and (abs(_n2_0 - _D) <= tol*(l0)) and (abs(_n2_1 - _Q0) <= tol*(1.0)) and (abs(_n2_2 - _Q1) <= tol*(1.0)) and (abs(_n2_3 - _Q2) <= tol*(1.0)) and (abs(_n2_4 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n2_5 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n2_6 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n2_0
            _Q0 = _n2_1
            _Q1 = _n2_2
            _Q2 = _n2_3
            _P0 = _n2_4
            _P1 = _n2_5
            _P2 = _n2_6
            _passes += 1.0
            if _conv2:
                break
        if not _conv2 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x110 = -q_r
        _x111 = -0.9872983346207417*_D - _x110
        _x143 = (1.0/_x111)
        _x112 = k_c*l0
        _x113 = g_s*m
        _x114 = _x113*math.cos(_Q0)
        _x115 = _x111*k_c
        _x116 = _P0**2
        _x117 = (1.0/m)
        _x118 = _x143**3
        _x119 = _x116*_x117*_x118
        _x120 = -0.75*_D - _x110
        _x144 = (1.0/_x120)
        _x121 = _x113*math.cos(_Q1)
        _x122 = _x120*k_c
        _x123 = _P1**2
        _x124 = _x144**3
        _x125 = _x117*_x123*_x124
        _x126 = -0.2127016653792583*_D - _x110
        _x145 = (1.0/_x126)
        _x127 = _x113*math.cos(_Q2)
        _x128 = _x126*k_c
        _x129 = _P2**2
        _x130 = _x145**3
        _x131 = _x117*_x129*_x130
        _x132 = 0.5*_x112 - 0.5762768525670787*_x114 - 0.5762768525670787*_x115 + 0.5762768525670787*_x119 + 0.1040546303448565*_x121 + 0.1040546303448565*_x122 - 0.1040546303448565*_x125 - 0.027777777777777776*_x127 - 0.027777777777777776*_x128 + 0.027777777777777776*_x131
        _x133 = (1.0/math.sqrt(_x132))
        _x134 = math.sqrt(_D)
        _x135 = math.sqrt(m)
        _x136 = _x134*_x135
        _x137 = _x134/_x135
        _x138 = _x134*g_s*m**(1.5)
        _x139 = 0.5*_x112 - 0.17702731517242826*_x114 - 0.17702731517242826*_x115 + 0.17702731517242826*_x119 - 0.3611111111111111*_x121 - 0.3611111111111111*_x122 + 0.3611111111111111*_x125 + 0.038138426283539355*_x127 + 0.038138426283539355*_x128 - 0.038138426283539355*_x131
        _x140 = (1.0/math.sqrt(_x139))
        _x141 = -0.027777777777777776*_x114 - 0.027777777777777776*_x115 + 0.027777777777777776*_x116*_x117*_x118 + 0.3262768525670787*_x117*_x123*_x124 + 0.14594536965514351*_x117*_x129*_x130 - 0.3262768525670787*_x121 - 0.3262768525670787*_x122 - 0.14594536965514351*_x127 - 0.14594536965514351*_x128 + 0.5*k_c*l0
        _x142 = (1.0/math.sqrt(_x141))
        _fsigma0 = _x111
        _fF0 = _x112 - _x114 - _x115 + _x119
        _fsigma1 = _x120
        _fF1 = _x112 - _x121 - _x122 + _x125
        _fsigma2 = _x126
        _fF2 = _x112 - _x127 - _x128 + _x131
        _fPsi0 = _x132
        _fft0 = _x133*_x136
        _ffq0 = _P0*_x133*_x137*_x143**2
        _ffp0 = _x111*_x133*_x138*math.sin(_Q0)
        _fPsi1 = _x139
        _fft1 = _x136*_x140
        _ffq1 = _P1*_x137*_x140*_x144**2
        _ffp1 = _x120*_x138*_x140*math.sin(_Q1)
        _fPsi2 = _x141
        _fft2 = _x136*_x142
        _ffq2 = _P2*_x137*_x142*_x145**2
        _ffp2 = _x126*_x138*_x142*math.sin(_Q2)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # bottom state
        _x146 = -_D + q_r
        t_half = 0.2777777777777778*_fft0 + 0.4444444444444444*_fft1 + 0.2777777777777778*_fft2
        end_q_th = 0.2777777777777778*_ffq0 + 0.4444444444444444*_ffq1 + 0.2777777777777778*_ffq2 + q_th
        end_q_r = _x146
        end_q_rd = 0.0
        end_q_thd = (0.2777777777777778*_ffp0 + 0.4444444444444444*_ffp1 + 0.2777777777777778*_ffp2 + m*q_r**2*q_thd)/(_x146**2*m)
        passes = _passes
        # bottom leg length q_r_b > 0
        if not ((end_q_r > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    elif nodes == 3.0:
        # Picard passes on the 4 node values (collocation in u)
        _D = -guess_q_r + q_r
        _Q0 = 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th
        _Q1 = 0.6699905217924281*guess_q_th + 0.33000947820757187*q_th
        _Q2 = 0.33000947820757187*guess_q_th + 0.6699905217924281*q_th
        _Q3 = 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th
        _P0 = 0.9305681557970263*guess_q_r**2*guess_q_thd*m + 0.06943184420297371*m*q_r**2*q_thd
        _P1 = 0.6699905217924281*guess_q_r**2*guess_q_thd*m + 0.33000947820757187*m*q_r**2*q_thd
        _P2 = 0.33000947820757187*guess_q_r**2*guess_q_thd*m + 0.6699905217924281*m*q_r**2*q_thd
        _P3 = 0.06943184420297371*guess_q_r**2*guess_q_thd*m + 0.9305681557970263*m*q_r**2*q_thd
        _passes = 0.0
        _conv3 = False
        for _it3 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x147 = -q_r
            _x148 = -0.9951792190105739*_D - _x147
            _x190 = (1.0/_x148)
            _x149 = k_c*l0
            _x150 = g_s*m
            _x151 = _x150*math.cos(_Q0)
            _x152 = _x148*k_c
            _x153 = _P0**2
            _x154 = (1.0/m)
            _x155 = _x190**3
            _x156 = _x153*_x154*_x155
            _x157 = -0.8910937442931661*_D - _x147
            _x191 = (1.0/_x157)
            _x158 = _x150*math.cos(_Q1)
            _x159 = _x157*k_c
            _x160 = _P1**2
            _x161 = _x191**3
            _x162 = _x154*_x160*_x161
            _x163 = -0.5511127007083099*_D - _x147
            _x192 = (1.0/_x163)
            _x164 = math.cos(_Q2)
            _x165 = _x150*_x164
            _x166 = _x163*k_c
            _x167 = _P2**2
            _x168 = _x192**3
            _x169 = _x154*_x167*_x168
            _x170 = -0.13404290741652142*_D - _x147
            _x193 = (1.0/_x170)
            _x171 = math.cos(_Q3)
            _x172 = _x150*_x171
            _x173 = _x170*k_c
            _x174 = _P3**2
            _x175 = _x193**3
            _x176 = _x154*_x174*_x175
            _x177 = 0.5*_x149 - 0.582374038291501*_x151 - 0.582374038291501*_x152 + 0.582374038291501*_x156 + 0.12383458041329967*_x158 + 0.12383458041329967*_x159 - 0.12383458041329967*_x162 - 0.0575898635297681*_x165 - 0.0575898635297681*_x166 + 0.0575898635297681*_x169 + 0.016129321407969507*_x172 + 0.016129321407969507*_x173 - 0.016129321407969507*_x176
            _x178 = (1.0/math.sqrt(_x177))
            _x179 = math.sqrt(_D)
            _x180 = math.sqrt(m)
            _x181 = _x179*_x180
            _x182 = _x179/_x180
            _x183 = _x179*g_s*m**(1.5)
            _x184 = -0.16000937841634696*_x151 - 0.16000937841634696*_x152 + 0.16000937841634696*_x153*_x154*_x155 + 0.39252437029865583*_x154*_x160*_x161 + 0.017475652789475504*_x154*_x174*_x175 - 0.39252437029865583*_x158 - 0.39252437029865583*_x159 + 0.0700094015044783*_x163*k_c + 0.0700094015044783*_x164*g_s*m - 0.0700094015044783*_x169 - 0.017475652789475504*_x172 - 0.017475652789475504*_x173 + 0.5*k_c*l0
            _x185 = (1.0/math.sqrt(_x184))
            _x186 = -0.01613725546399532*_x151 - 0.01613725546399532*_x152 + 0.01613725546399532*_x153*_x154*_x155 + 0.2848443432415939*_x154*_x160*_x161 + 0.21871326539550162*_x154*_x167*_x168 - 0.2848443432415939*_x158 - 0.2848443432415939*_x159 - 0.21871326539550162*_x165 - 0.21871326539550162*_x166 + 0.019694864101090868*_x170*k_c + 0.019694864101090868*_x171*g_s*m - 0.019694864101090868*_x176 + 0.5*k_c*l0
            _x187 = (1.0/math.sqrt(_x186))
            _x188 = -0.01796104633752054*_x151 - 0.01796104633752054*_x152 + 0.01796104633752054*_x153*_x154*_x155 + 0.11000222456933441*_x154*_x160*_x161 + 0.2823150697454702*_x154*_x167*_x168 + 0.08972165934767481*_x154*_x174*_x175 - 0.11000222456933441*_x158 - 0.11000222456933441*_x159 - 0.2823150697454702*_x165 - 0.2823150697454702*_x166 - 0.08972165934767481*_x172 - 0.08972165934767481*_x173 + 0.5*k_c*l0
            _x189 = (1.0/math.sqrt(_x188))
            _isigma0 = _x148
            _iF0 = _x149 - _x151 - _x152 + _x156
            _isigma1 = _x157
            _iF1 = _x149 - _x158 - _x159 + _x162
            _isigma2 = _x163
            _iF2 = _x149 - _x165 - _x166 + _x169
            _isigma3 = _x170
            _iF3 = _x149 - _x172 - _x173 + _x176
            _iPsi0 = _x177
            _ift0 = _x178*_x181
            _ifq0 = _P0*_x178*_x182*_x190**2
            _ifp0 = _x148*_x178*_x183*math.sin(_Q0)
            _iPsi1 = _x184
            _ift1 = _x181*_x185
            _ifq1 = _P1*_x182*_x185*_x191**2
            _ifp1 = _x157*_x183*_x185*math.sin(_Q1)
            _iPsi2 = _x186
            _ift2 = _x181*_x187
            _ifq2 = _P2*_x182*_x187*_x192**2
            _ifp2 = _x163*_x183*_x187*math.sin(_Q2)
            _iPsi3 = _x188
            _ift3 = _x181*_x189
            _ifq3 = _P3*_x182*_x189*_x193**2
            _ifp3 = _x170*_x183*_x189*math.sin(_Q3)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi3 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n3_0 = m*q_rd**2/(0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2 + 0.3237026417246206*_iF3 - 0.024152203412833244*k_c*(-_isigma0 + l0) - 0.215214082271785*k_c*(-_isigma1 + l0) - 0.43693107259076114*k_c*(-_isigma2 + l0) - 0.3237026417246206*k_c*(-_isigma3 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2 + 0.3237026417246206*_iF3 - 0.024152203412833244*k_c*(-_isigma0 + l0) - 0.215214082271785*k_c*(-_isigma1 + l0) - 0.43693107259076114*k_c*(-_isigma2 + l0) - 0.3237026417246206*k_c*(-_isigma3 + l0) + k_c*(l0 - q_r))**2))
            _n3_1 = 0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2 + 0.1774825722545226*_ifq3 + q_th
            _n3_2 = -0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2 + 0.16719192197418878*_ifq3 + q_th
            _n3_3 = 0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2 + 0.18811811749986806*_ifq3 + q_th
            _n3_4 = -0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2 + 0.08696371128436346*_ifq3 + q_th
            _n3_5 = 0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2 + 0.1774825722545226*_ifp3 + m*q_r**2*q_thd
            _n3_6 = -0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2 + 0.16719192197418878*_ifp3 + m*q_r**2*q_thd
            _n3_7 = 0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2 + 0.18811811749986806*_ifp3 + m*q_r**2*q_thd
            _n3_8 = -0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2 + 0.08696371128436346*_ifp3 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv3 = tol > 0.0 and (abs(_n3_0 - _D) <= tol*(l0)) and (abs(_n3_1 - _Q0) <= tol*(1.0)) and (abs(_n3_2 - _Q1) <= tol*(1.0)) and (abs(_n3_3 - _Q2) <= tol*(1.0)) and (abs(_n3_4 - _Q3) <= tol*(1.0)) and (abs(_n3_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_7 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_8 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n3_0
            _Q0 = _n3_1
            _Q1 = _n3_2
            _Q2 = _n3_3
            _Q3 = _n3_4
            _P0 = _n3_5
            _P1 = _n3_6
            _P2 = _n3_7
            _P3 = _n3_8
            _passes += 1.0
            if _conv3:
                break
        if not _conv3 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x194 = -q_r
        _x195 = -0.9951792190105739*_D - _x194
        _x237 = (1.0/_x195)
        _x196 = k_c*l0
        _x197 = g_s*m
        _x198 = _x197*math.cos(_Q0)
        _x199 = _x195*k_c
        _x200 = _P0**2
        _x201 = (1.0/m)
        _x202 = _x237**3
        _x203 = _x200*_x201*_x202
        _x204 = -0.8910937442931661*_D - _x194
        _x238 = (1.0/_x204)
        _x205 = _x197*math.cos(_Q1)
        _x206 = _x204*k_c
        _x207 = _P1**2
        _x208 = _x238**3
        _x209 = _x201*_x207*_x208
        _x210 = -0.5511127007083099*_D - _x194
        _x239 = (1.0/_x210)
        _x211 = math.cos(_Q2)
        _x212 = _x197*_x211
        _x213 = _x210*k_c
        _x214 = _P2**2
        _x215 = _x239**3
        _x216 = _x201*_x214*_x215
        _x217 = -0.13404290741652142*_D - _x194
        _x240 = (1.0/_x217)
        _x218 = math.cos(_Q3)
        _x219 = _x197*_x218
        _x220 = _x217*k_c
        _x221 = _P3**2
        _x222 = _x240**3
        _x223 = _x201*_x221*_x222
        _x224 = 0.5*_x196 - 0.582374038291501*_x198 - 0.582374038291501*_x199 + 0.582374038291501*_x203 + 0.12383458041329967*_x205 + 0.12383458041329967*_x206 - 0.12383458041329967*_x209 - 0.0575898635297681*_x212 - 0.0575898635297681*_x213 + 0.0575898635297681*_x216 + 0.016129321407969507*_x219 + 0.016129321407969507*_x220 - 0.016129321407969507*_x223
        _x225 = (1.0/math.sqrt(_x224))
        _x226 = math.sqrt(_D)
        _x227 = math.sqrt(m)
        _x228 = _x226*_x227
        _x229 = _x226/_x227
        _x230 = _x226*g_s*m**(1.5)
        _x231 = -0.16000937841634696*_x198 - 0.16000937841634696*_x199 + 0.16000937841634696*_x200*_x201*_x202 + 0.39252437029865583*_x201*_x207*_x208 + 0.017475652789475504*_x201*_x221*_x222 - 0.39252437029865583*_x205 - 0.39252437029865583*_x206 + 0.0700094015044783*_x210*k_c + 0.0700094015044783*_x211*g_s*m - 0.0700094015044783*_x216 - 0.017475652789475504*_x219 - 0.017475652789475504*_x220 + 0.5*k_c*l0
        _x232 = (1.0/math.sqrt(_x231))
        _x233 = -0.01613725546399532*_x198 - 0.01613725546399532*_x199 + 0.01613725546399532*_x200*_x201*_x202 + 0.2848443432415939*_x201*_x207*_x208 + 0.21871326539550162*_x201*_x214*_x215 - 0.2848443432415939*_x205 - 0.2848443432415939*_x206 - 0.21871326539550162*_x212 - 0.21871326539550162*_x213 + 0.019694864101090868*_x217*k_c + 0.019694864101090868*_x218*g_s*m - 0.019694864101090868*_x223 + 0.5*k_c*l0
        _x234 = (1.0/math.sqrt(_x233))
        _x235 = -0.01796104633752054*_x198 - 0.01796104633752054*_x199 + 0.01796104633752054*_x200*_x201*_x202 + 0.11000222456933441*_x201*_x207*_x208 + 0.2823150697454702*_x201*_x214*_x215 + 0.08972165934767481*_x201*_x221*_x222 - 0.11000222456933441*_x205 - 0.11000222456933441*_x206 - 0.2823150697454702*_x212 - 0.2823150697454702*_x213 - 0.08972165934767481*_x219 - 0.08972165934767481*_x220 + 0.5*k_c*l0
        _x236 = (1.0/math.sqrt(_x235))
        _fsigma0 = _x195
        _fF0 = _x196 - _x198 - _x199 + _x203
        _fsigma1 = _x204
        _fF1 = _x196 - _x205 - _x206 + _x209
        _fsigma2 = _x210
        _fF2 = _x196 - _x212 - _x213 + _x216
        _fsigma3 = _x217
        _fF3 = _x196 - _x219 - _x220 + _x223
        _fPsi0 = _x224
        _fft0 = _x225*_x228
        _ffq0 = _P0*_x225*_x229*_x237**2
        _ffp0 = _x195*_x225*_x230*math.sin(_Q0)
        _fPsi1 = _x231
        _fft1 = _x228*_x232
        _ffq1 = _P1*_x229*_x232*_x238**2
        _ffp1 = _x204*_x230*_x232*math.sin(_Q1)
        _fPsi2 = _x233
        _fft2 = _x228*_x234
        _ffq2 = _P2*_x229*_x234*_x239**2
        _ffp2 = _x210*_x230*_x234*math.sin(_Q2)
        _fPsi3 = _x235
        _fft3 = _x228*_x236
        _ffq3 = _P3*_x229*_x236*_x240**2
        _ffp3 = _x217*_x230*_x236*math.sin(_Q3)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi3 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # bottom state
        _x241 = -_D + q_r
        t_half = 0.17392742256872692*_fft0 + 0.32607257743127305*_fft1 + 0.32607257743127305*_fft2 + 0.17392742256872692*_fft3
        end_q_th = 0.17392742256872692*_ffq0 + 0.32607257743127305*_ffq1 + 0.32607257743127305*_ffq2 + 0.17392742256872692*_ffq3 + q_th
        end_q_r = _x241
        end_q_rd = 0.0
        end_q_thd = (0.17392742256872692*_ffp0 + 0.32607257743127305*_ffp1 + 0.32607257743127305*_ffp2 + 0.17392742256872692*_ffp3 + m*q_r**2*q_thd)/(_x241**2*m)
        passes = _passes
        # bottom leg length q_r_b > 0
        if not ((end_q_r > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    elif nodes == 4.0:
        # Picard passes on the 6 node values (collocation in u)
        _D = -guess_q_r + q_r
        _Q0 = 0.966234757101576*guess_q_th + 0.03376524289842399*q_th
        _Q1 = 0.8306046932331322*guess_q_th + 0.16939530676686773*q_th
        _Q2 = 0.6193095930415985*guess_q_th + 0.38069040695840156*q_th
        _Q3 = 0.38069040695840156*guess_q_th + 0.6193095930415985*q_th
        _Q4 = 0.16939530676686773*guess_q_th + 0.8306046932331322*q_th
        _Q5 = 0.03376524289842399*guess_q_th + 0.966234757101576*q_th
        _P0 = 0.966234757101576*guess_q_r**2*guess_q_thd*m + 0.03376524289842399*m*q_r**2*q_thd
        _P1 = 0.8306046932331322*guess_q_r**2*guess_q_thd*m + 0.16939530676686773*m*q_r**2*q_thd
        _P2 = 0.6193095930415985*guess_q_r**2*guess_q_thd*m + 0.38069040695840156*m*q_r**2*q_thd
        _P3 = 0.38069040695840156*guess_q_r**2*guess_q_thd*m + 0.6193095930415985*m*q_r**2*q_thd
        _P4 = 0.16939530676686773*guess_q_r**2*guess_q_thd*m + 0.8306046932331322*m*q_r**2*q_thd
        _P5 = 0.03376524289842399*guess_q_r**2*guess_q_thd*m + 0.966234757101576*m*q_r**2*q_thd
        _passes = 0.0
        _conv4 = False
        for _it4 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x242 = -q_r
            _x243 = -0.9988599083720104*_D - _x242
            _x305 = (1.0/_x243)
            _x244 = k_c*l0
            _x245 = g_s*m
            _x246 = _x245*math.cos(_Q0)
            _x247 = _x243*k_c
            _x248 = _P0**2
            _x249 = (1.0/m)
            _x250 = _x305**3
            _x251 = _x248*_x249*_x250
            _x252 = -0.9713052300453587*_D - _x242
            _x306 = (1.0/_x252)
            _x253 = _x245*math.cos(_Q1)
            _x254 = _x252*k_c
            _x255 = _P1**2
            _x256 = _x306**3
            _x257 = _x249*_x255*_x256
            _x258 = -0.8550748140498466*_D - _x242
            _x307 = (1.0/_x258)
            _x259 = math.cos(_Q2)
            _x260 = _x245*_x259
            _x261 = _x258*k_c
            _x262 = _P2**2
            _x263 = _x307**3
            _x264 = _x249*_x262*_x263
            _x265 = -0.6164556279666497*_D - _x242
            _x308 = (1.0/_x265)
            _x266 = math.cos(_Q3)
            _x267 = _x245*_x266
            _x268 = _x265*k_c
            _x269 = _P3**2
            _x270 = _x308**3
            _x271 = _x249*_x269*_x270
            _x272 = -0.31009584357909425*_D - _x242
            _x309 = (1.0/_x272)
            _x273 = math.cos(_Q4)
            _x274 = _x245*_x273
            _x275 = _x272*k_c
            _x276 = _P4**2
            _x277 = _x309**3
            _x278 = _x249*_x276*_x277
            _x279 = -0.0663903941688584*_D - _x242
            _x310 = (1.0/_x279)
            _x280 = math.cos(_Q5)
            _x281 = _x245*_x280
            _x282 = _x279*k_c
            _x283 = _P5**2
            _x284 = _x310**3
            _x285 = _x249*_x283*_x284
            _x286 = 0.5*_x244 - 0.5871580340658094*_x246 - 0.5871580340658094*_x247 + 0.5871580340658094*_x251 + 0.140380692261653*_x253 + 0.140380692261653*_x254 - 0.140380692261653*_x257 - 0.08683151831711133*_x260 - 0.08683151831711133*_x261 + 0.08683151831711133*_x264 + 0.052466581536012566*_x267 + 0.052466581536012566*_x268 - 0.052466581536012566*_x271 - 0.026354606039126004*_x274 - 0.026354606039126004*_x275 + 0.026354606039126004*_x278 + 0.007496884624381081*_x281 + 0.007496884624381081*_x282 - 0.007496884624381081*_x285
            _x287 = (1.0/math.sqrt(_x286))
            _x288 = math.sqrt(_D)
            _x289 = math.sqrt(m)
            _x290 = _x288*_x289
            _x291 = _x288/_x289
            _x292 = _x288*g_s*m**(1.5)
            _x293 = -0.5*k_c*l0
            _x294 = -0.147790320897128*_x246 - 0.147790320897128*_x247 + 0.147790320897128*_x248*_x249*_x250 + 0.41567911405660357*_x249*_x255*_x256 + 0.05155355009455148*_x249*_x269*_x270 + 0.006904529857608445*_x249*_x283*_x284 - 0.41567911405660357*_x253 - 0.41567911405660357*_x254 + 0.09720828549085844*_x258*k_c + 0.09720828549085844*_x259*g_s*m - 0.09720828549085844*_x264 - 0.05155355009455148*_x267 - 0.05155355009455148*_x268 + 0.024719229415033087*_x272*k_c + 0.024719229415033087*_x273*g_s*m - 0.024719229415033087*_x278 - 0.006904529857608445*_x281 - 0.006904529857608445*_x282 - _x293
            _x295 = (1.0/math.sqrt(_x294))
            _x296 = -0.010443786721981197*_x246 - 0.010443786721981197*_x247 + 0.010443786721981197*_x248*_x249*_x250 + 0.25540525119175433*_x249*_x255*_x256 + 0.2685463444140672*_x249*_x262*_x263 + 0.01951903325298492*_x249*_x276*_x277 - 0.25540525119175433*_x253 - 0.25540525119175433*_x254 - 0.2685463444140672*_x260 - 0.2685463444140672*_x261 + 0.048794612428541204*_x265*k_c + 0.048794612428541204*_x266*g_s*m - 0.048794612428541204*_x271 - 0.01951903325298492*_x274 - 0.01951903325298492*_x275 + 0.005119803152246505*_x279*k_c + 0.005119803152246505*_x280*g_s*m - 0.005119803152246505*_x285 - _x293
            _x297 = (1.0/math.sqrt(_x296))
            _x298 = -0.5*k_c*l0
            _x299 = -0.01101839635505667*_x246 - 0.01101839635505667*_x247 + 0.01101839635505667*_x248*_x249*_x250 + 0.0662099828438604*_x249*_x255*_x256 + 0.2671819482314443*_x249*_x262*_x263 + 0.1742495636223592*_x249*_x269*_x270 + 0.00530703852813994*_x249*_x283*_x284 - 0.0662099828438604*_x253 - 0.0662099828438604*_x254 - 0.2671819482314443*_x260 - 0.2671819482314443*_x261 - 0.1742495636223592*_x267 - 0.1742495636223592*_x268 + 0.02396692958086051*_x272*k_c + 0.02396692958086051*_x273*g_s*m - 0.02396692958086051*_x278 - 0.00530703852813994*_x281 - 0.00530703852813994*_x282 - _x298
            _x300 = (1.0/math.sqrt(_x299))
            _x301 = -0.0025147977064533143*_x246 - 0.0025147977064533143*_x247 + 0.0025147977064533143*_x248*_x249*_x250 + 0.050345455482979015*_x249*_x255*_x256 + 0.11622097556712797*_x249*_x262*_x263 + 0.2353986790647292*_x249*_x269*_x270 + 0.10372825048336794*_x249*_x276*_x277 - 0.050345455482979015*_x253 - 0.050345455482979015*_x254 - 0.11622097556712797*_x260 - 0.11622097556712797*_x261 - 0.2353986790647292*_x267 - 0.2353986790647292*_x268 - 0.10372825048336794*_x274 - 0.10372825048336794*_x275 + 0.008208158304657426*_x279*k_c + 0.008208158304657426*_x280*g_s*m - 0.008208158304657426*_x285 - _x293
            _x302 = (1.0/math.sqrt(_x301))
            _x303 = -0.003959513229722528*_x246 - 0.003959513229722528*_x247 + 0.003959513229722528*_x248*_x249*_x250 + 0.029703284805013122*_x249*_x255*_x256 + 0.10140664131431479*_x249*_x262*_x263 + 0.14531313573962065*_x249*_x269*_x270 + 0.17612158869639333*_x249*_x276*_x277 + 0.04349583621493557*_x249*_x283*_x284 - 0.029703284805013122*_x253 - 0.029703284805013122*_x254 - 0.10140664131431479*_x260 - 0.10140664131431479*_x261 - 0.14531313573962065*_x267 - 0.14531313573962065*_x268 - 0.17612158869639333*_x274 - 0.17612158869639333*_x275 - 0.04349583621493557*_x281 - 0.04349583621493557*_x282 - _x298
            _x304 = (1.0/math.sqrt(_x303))
            _isigma0 = _x243
            _iF0 = _x244 - _x246 - _x247 + _x251
            _isigma1 = _x252
            _iF1 = _x244 - _x253 - _x254 + _x257
            _isigma2 = _x258
            _iF2 = _x244 - _x260 - _x261 + _x264
            _isigma3 = _x265
            _iF3 = _x244 - _x267 - _x268 + _x271
            _isigma4 = _x272
            _iF4 = _x244 - _x274 - _x275 + _x278
            _isigma5 = _x279
            _iF5 = _x244 - _x281 - _x282 + _x285
            _iPsi0 = _x286
            _ift0 = _x287*_x290
            _ifq0 = _P0*_x287*_x291*_x305**2
            _ifp0 = _x243*_x287*_x292*math.sin(_Q0)
            _iPsi1 = _x294
            _ift1 = _x290*_x295
            _ifq1 = _P1*_x291*_x295*_x306**2
            _ifp1 = _x252*_x292*_x295*math.sin(_Q1)
            _iPsi2 = _x296
            _ift2 = _x290*_x297
            _ifq2 = _P2*_x291*_x297*_x307**2
            _ifp2 = _x258*_x292*_x297*math.sin(_Q2)
            _iPsi3 = _x299
            _ift3 = _x290*_x300
            _ifq3 = _P3*_x291*_x300*_x308**2
            _ifp3 = _x265*_x292*_x300*math.sin(_Q3)
            _iPsi4 = _x301
            _ift4 = _x290*_x302
            _ifq4 = _P4*_x291*_x302*_x309**2
            _ifp4 = _x272*_x292*_x302*math.sin(_Q4)
            _iPsi5 = _x303
            _ift5 = _x290*_x304
            _ifq5 = _P5*_x291*_x304*_x310**2
            _ifp5 = _x279*_x292*_x304*math.sin(_Q5)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi3 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi4 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi5 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n4_0 = m*q_rd**2/(0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2 + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 - 0.005784813099631875*k_c*(-_isigma0 + l0) - 0.06111131733618721*k_c*(-_isigma1 + l0) - 0.17813034617398463*k_c*(-_isigma2 + l0) - 0.28978358839870644*k_c*(-_isigma3 + l0) - 0.2996502557119514*k_c*(-_isigma4 + l0) - 0.16553967927953847*k_c*(-_isigma5 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2 + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 - 0.005784813099631875*k_c*(-_isigma0 + l0) - 0.06111131733618721*k_c*(-_isigma1 + l0) - 0.17813034617398463*k_c*(-_isigma2 + l0) - 0.28978358839870644*k_c*(-_isigma3 + l0) - 0.2996502557119514*k_c*(-_isigma4 + l0) - 0.16553967927953847*k_c*(-_isigma5 + l0) + k_c*(l0 - q_r))**2))
            _n4_1 = 0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2 + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th
            _n4_2 = -0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2 + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th
            _n4_3 = 0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2 + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th
            _n4_4 = -0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2 + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th
            _n4_5 = 0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2 - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th
            _n4_6 = -0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2 + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th
            _n4_7 = 0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2 + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + m*q_r**2*q_thd
            _n4_8 = -0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2 + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + m*q_r**2*q_thd
            _n4_9 = 0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2 + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + m*q_r**2*q_thd
            _n4_10 = -0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2 + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + m*q_r**2*q_thd
            _n4_11 = 0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2 - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + m*q_r**2*q_thd
            _n4_12 = -0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2 + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv4 = tol > 0.0 and (abs(_n4_0 - _D) <= tol*(l0)) and (abs(_n4_1 - _Q0) <= tol*(1.0)) and (abs(_n4_2 - _Q1) <= tol*(1.0)) and (abs(_n4_3 - _Q2) <= tol*(1.0)) and (abs(_n4_4 - _Q3) <= tol*(1.0)) and (abs(_n4_5 - _Q4) <= tol*(1.0)) and (abs(_n4_6 - _Q5) <= tol*(1.0)) and (abs(_n4_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_8 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_9 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_10 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_11 - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_12 - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n4_0
            _Q0 = _n4_1
            _Q1 = _n4_2
            _Q2 = _n4_3
            _Q3 = _n4_4
            _Q4 = _n4_5
            _Q5 = _n4_6
            _P0 = _n4_7
            _P1 = _n4_8
            _P2 = _n4_9
            _P3 = _n4_10
            _P4 = _n4_11
            _P5 = _n4_12
            _passes += 1.0
            if _conv4:
                break
        if not _conv4 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x311 = -q_r
        _x312 = -0.9988599083720104*_D - _x311
        _x374 = (1.0/_x312)
        _x313 = k_c*l0
        _x314 = g_s*m
        _x315 = _x314*math.cos(_Q0)
        _x316 = _x312*k_c
        _x317 = _P0**2
        _x318 = (1.0/m)
        _x319 = _x374**3
        _x320 = _x317*_x318*_x319
        _x321 = -0.9713052300453587*_D - _x311
        _x375 = (1.0/_x321)
        _x322 = _x314*math.cos(_Q1)
        _x323 = _x321*k_c
        _x324 = _P1**2
        _x325 = _x375**3
        _x326 = _x318*_x324*_x325
        _x327 = -0.8550748140498466*_D - _x311
        _x376 = (1.0/_x327)
        _x328 = math.cos(_Q2)
        _x329 = _x314*_x328
        _x330 = _x327*k_c
        _x331 = _P2**2
        _x332 = _x376**3
        _x333 = _x318*_x331*_x332
        _x334 = -0.6164556279666497*_D - _x311
        _x377 = (1.0/_x334)
        _x335 = math.cos(_Q3)
        _x336 = _x314*_x335
        _x337 = _x334*k_c
        _x338 = _P3**2
        _x339 = _x377**3
        _x340 = _x318*_x338*_x339
        _x341 = -0.31009584357909425*_D - _x311
        _x378 = (1.0/_x341)
        _x342 = math.cos(_Q4)
        _x343 = _x314*_x342
        _x344 = _x341*k_c
        _x345 = _P4**2
        _x346 = _x378**3
        _x347 = _x318*_x345*_x346
        _x348 = -0.0663903941688584*_D - _x311
        _x379 = (1.0/_x348)
        _x349 = math.cos(_Q5)
        _x350 = _x314*_x349
        _x351 = _x348*k_c
        _x352 = _P5**2
        _x353 = _x379**3
        _x354 = _x318*_x352*_x353
        _x355 = 0.5*_x313 - 0.5871580340658094*_x315 - 0.5871580340658094*_x316 + 0.5871580340658094*_x320 + 0.140380692261653*_x322 + 0.140380692261653*_x323 - 0.140380692261653*_x326 - 0.08683151831711133*_x329 - 0.08683151831711133*_x330 + 0.08683151831711133*_x333 + 0.052466581536012566*_x336 + 0.052466581536012566*_x337 - 0.052466581536012566*_x340 - 0.026354606039126004*_x343 - 0.026354606039126004*_x344 + 0.026354606039126004*_x347 + 0.007496884624381081*_x350 + 0.007496884624381081*_x351 - 0.007496884624381081*_x354
        _x356 = (1.0/math.sqrt(_x355))
        _x357 = math.sqrt(_D)
        _x358 = math.sqrt(m)
        _x359 = _x357*_x358
        _x360 = _x357/_x358
        _x361 = _x357*g_s*m**(1.5)
        _x362 = -0.5*k_c*l0
        _x363 = -0.147790320897128*_x315 - 0.147790320897128*_x316 + 0.147790320897128*_x317*_x318*_x319 + 0.41567911405660357*_x318*_x324*_x325 + 0.05155355009455148*_x318*_x338*_x339 + 0.006904529857608445*_x318*_x352*_x353 - 0.41567911405660357*_x322 - 0.41567911405660357*_x323 + 0.09720828549085844*_x327*k_c + 0.09720828549085844*_x328*g_s*m - 0.09720828549085844*_x333 - 0.05155355009455148*_x336 - 0.05155355009455148*_x337 + 0.024719229415033087*_x341*k_c + 0.024719229415033087*_x342*g_s*m - 0.024719229415033087*_x347 - 0.006904529857608445*_x350 - 0.006904529857608445*_x351 - _x362
        _x364 = (1.0/math.sqrt(_x363))
        _x365 = -0.010443786721981197*_x315 - 0.010443786721981197*_x316 + 0.010443786721981197*_x317*_x318*_x319 + 0.25540525119175433*_x318*_x324*_x325 + 0.2685463444140672*_x318*_x331*_x332 + 0.01951903325298492*_x318*_x345*_x346 - 0.25540525119175433*_x322 - 0.25540525119175433*_x323 - 0.2685463444140672*_x329 - 0.2685463444140672*_x330 + 0.048794612428541204*_x334*k_c + 0.048794612428541204*_x335*g_s*m - 0.048794612428541204*_x340 - 0.01951903325298492*_x343 - 0.01951903325298492*_x344 + 0.005119803152246505*_x348*k_c + 0.005119803152246505*_x349*g_s*m - 0.005119803152246505*_x354 - _x362
        _x366 = (1.0/math.sqrt(_x365))
        _x367 = -0.5*k_c*l0
        _x368 = -0.01101839635505667*_x315 - 0.01101839635505667*_x316 + 0.01101839635505667*_x317*_x318*_x319 + 0.0662099828438604*_x318*_x324*_x325 + 0.2671819482314443*_x318*_x331*_x332 + 0.1742495636223592*_x318*_x338*_x339 + 0.00530703852813994*_x318*_x352*_x353 - 0.0662099828438604*_x322 - 0.0662099828438604*_x323 - 0.2671819482314443*_x329 - 0.2671819482314443*_x330 - 0.1742495636223592*_x336 - 0.1742495636223592*_x337 + 0.02396692958086051*_x341*k_c + 0.02396692958086051*_x342*g_s*m - 0.02396692958086051*_x347 - 0.00530703852813994*_x350 - 0.00530703852813994*_x351 - _x367
        _x369 = (1.0/math.sqrt(_x368))
        _x370 = -0.0025147977064533143*_x315 - 0.0025147977064533143*_x316 + 0.0025147977064533143*_x317*_x318*_x319 + 0.050345455482979015*_x318*_x324*_x325 + 0.11622097556712797*_x318*_x331*_x332 + 0.2353986790647292*_x318*_x338*_x339 + 0.10372825048336794*_x318*_x345*_x346 - 0.050345455482979015*_x322 - 0.050345455482979015*_x323 - 0.11622097556712797*_x329 - 0.11622097556712797*_x330 - 0.2353986790647292*_x336 - 0.2353986790647292*_x337 - 0.10372825048336794*_x343 - 0.10372825048336794*_x344 + 0.008208158304657426*_x348*k_c + 0.008208158304657426*_x349*g_s*m - 0.008208158304657426*_x354 - _x362
        _x371 = (1.0/math.sqrt(_x370))
        _x372 = -0.003959513229722528*_x315 - 0.003959513229722528*_x316 + 0.003959513229722528*_x317*_x318*_x319 + 0.029703284805013122*_x318*_x324*_x325 + 0.10140664131431479*_x318*_x331*_x332 + 0.14531313573962065*_x318*_x338*_x339 + 0.17612158869639333*_x318*_x345*_x346 + 0.04349583621493557*_x318*_x352*_x353 - 0.029703284805013122*_x322 - 0.029703284805013122*_x323 - 0.10140664131431479*_x329 - 0.10140664131431479*_x330 - 0.14531313573962065*_x336 - 0.14531313573962065*_x337 - 0.17612158869639333*_x343 - 0.17612158869639333*_x344 - 0.04349583621493557*_x350 - 0.04349583621493557*_x351 - _x367
        _x373 = (1.0/math.sqrt(_x372))
        _fsigma0 = _x312
        _fF0 = _x313 - _x315 - _x316 + _x320
        _fsigma1 = _x321
        _fF1 = _x313 - _x322 - _x323 + _x326
        _fsigma2 = _x327
        _fF2 = _x313 - _x329 - _x330 + _x333
        _fsigma3 = _x334
        _fF3 = _x313 - _x336 - _x337 + _x340
        _fsigma4 = _x341
        _fF4 = _x313 - _x343 - _x344 + _x347
        _fsigma5 = _x348
        _fF5 = _x313 - _x350 - _x351 + _x354
        _fPsi0 = _x355
        _fft0 = _x356*_x359
        _ffq0 = _P0*_x356*_x360*_x374**2
        _ffp0 = _x312*_x356*_x361*math.sin(_Q0)
        _fPsi1 = _x363
        _fft1 = _x359*_x364
        _ffq1 = _P1*_x360*_x364*_x375**2
        _ffp1 = _x321*_x361*_x364*math.sin(_Q1)
        _fPsi2 = _x365
        _fft2 = _x359*_x366
        _ffq2 = _P2*_x360*_x366*_x376**2
        _ffp2 = _x327*_x361*_x366*math.sin(_Q2)
        _fPsi3 = _x368
        _fft3 = _x359*_x369
        _ffq3 = _P3*_x360*_x369*_x377**2
        _ffp3 = _x334*_x361*_x369*math.sin(_Q3)
        _fPsi4 = _x370
        _fft4 = _x359*_x371
        _ffq4 = _P4*_x360*_x371*_x378**2
        _ffp4 = _x341*_x361*_x371*math.sin(_Q4)
        _fPsi5 = _x372
        _fft5 = _x359*_x373
        _ffq5 = _P5*_x360*_x373*_x379**2
        _ffp5 = _x348*_x361*_x373*math.sin(_Q5)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi3 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi4 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi5 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # bottom state
        _x380 = -_D + q_r
        t_half = 0.08566224618958518*_fft0 + 0.1803807865240693*_fft1 + 0.23395696728634552*_fft2 + 0.23395696728634552*_fft3 + 0.1803807865240693*_fft4 + 0.08566224618958518*_fft5
        end_q_th = 0.08566224618958518*_ffq0 + 0.1803807865240693*_ffq1 + 0.23395696728634552*_ffq2 + 0.23395696728634552*_ffq3 + 0.1803807865240693*_ffq4 + 0.08566224618958518*_ffq5 + q_th
        end_q_r = _x380
        end_q_rd = 0.0
        end_q_thd = (0.08566224618958518*_ffp0 + 0.1803807865240693*_ffp1 + 0.23395696728634552*_ffp2 + 0.23395696728634552*_ffp3 + 0.1803807865240693*_ffp4 + 0.08566224618958518*_ffp5 + m*q_r**2*q_thd)/(_x380**2*m)
        passes = _passes
        # bottom leg length q_r_b > 0
        if not ((end_q_r > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd) and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, nodes, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of p_r).

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments:
        q_r: bottom state: leg length [m]
        q_rd: bottom state: leg length rate [m/s]
        q_th: bottom state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: bottom state: leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        guess_q_th: zeroth iterate's liftoff q_th
        guess_q_thd: zeroth iterate's liftoff q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]

    Returns a tuple:
        t_half: time of the decompression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 2145
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # node count
    if nodes == 0.0:
        # Picard passes on the 1 node values (collocation in u)
        _D = -q_r + q_r_lo
        _Q0 = 0.5*guess_q_th + 0.5*q_th
        _P0 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
        _passes = 0.0
        _conv0 = False
        for _it0 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x0 = 0.25*_D + q_r
            _x8 = (1.0/_x0)
            _x1 = k_d*l0
            _x2 = g_s*m*math.cos(_Q0)
            _x3 = _x0*k_d
            _x4 = _P0**2*_x8**3/m
            _x5 = 0.5*_x1 - 0.5*_x2 - 0.5*_x3 + 0.5*_x4
            _x6 = math.sqrt(m)
            _x7 = math.sqrt(_D)/math.sqrt(_x5)
            _isigma0 = _x0
            _iF0 = _x1 - _x2 - _x3 + _x4
            _iPsi0 = _x5
            _ift0 = _x6*_x7
            _ifq0 = _P0*_x7*_x8**2/_x6
            _ifp0 = _x0*_x7*g_s*m**(1.5)*math.sin(_Q0)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n0_0 = _D
            _n0_1 = 0.5*_ifq0 + q_th
            _n0_2 = 0.5*_ifp0 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n0_0
            _Q0 = _n0_1
            _P0 = _n0_2
            _passes += 1.0
            if _conv0:
                break
        if not _conv0 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x9 = 0.25*_D + q_r
        _x17 = (1.0/_x9)
        _x10 = k_d*l0
        _x11 = g_s*m*math.cos(_Q0)
        _x12 = _x9*k_d
        _x13 = _P0**2*_x17**3/m
        _x14 = 0.5*_x10 - 0.5*_x11 - 0.5*_x12 + 0.5*_x13
        _x15 = math.sqrt(m)
        _x16 = math.sqrt(_D)/math.sqrt(_x14)
        _fsigma0 = _x9
        _fF0 = _x10 - _x11 - _x12 + _x13
        _fPsi0 = _x14
        _fft0 = _x15*_x16
        _ffq0 = _P0*_x16*_x17**2/_x15
        _ffp0 = _x16*_x9*g_s*m**(1.5)*math.sin(_Q0)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        _work = 0.5*_fF0
        # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
        if not ((_work > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        t_half = 1.0*_fft0
        end_q_th = 1.0*_ffq0 + q_th
        end_q_r = q_r_lo
        end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
        end_q_thd = (1.0*_ffp0 + m*q_r**2*q_thd)/(m*q_r_lo**2)
        passes = _passes
    elif nodes == 1.0:
        # Picard passes on the 2 node values (collocation in u)
        _D = -q_r + q_r_lo
        _Q0 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
        _Q1 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
        _P0 = 0.2113248654051871*guess_q_thd*m*q_r_lo**2 + 0.7886751345948129*m*q_r**2*q_thd
        _P1 = 0.7886751345948129*guess_q_thd*m*q_r_lo**2 + 0.2113248654051871*m*q_r**2*q_thd
        _passes = 0.0
        _conv1 = False
        for _it1 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x18 = 0.04465819873852045*_D + q_r
            _x42 = (1.0/_x18)
            _x19 = k_d*l0
            _x20 = g_s*m
            _x21 = _x20*math.cos(_Q0)
            _x22 = _x18*k_d
            _x23 = _P0**2
            _x24 = (1.0/m)
            _x25 = _x42**3
            _x26 = _x23*_x24*_x25
            _x27 = 0.6220084679281462*_D + q_r
            _x43 = (1.0/_x27)
            _x28 = _x20*math.cos(_Q1)
            _x29 = _x27*k_d
            _x30 = _P1**2
            _x31 = _x43**3
            _x32 = _x24*_x30*_x31
            _x33 = 0.5*_x19 - 0.5610042339640731*_x21 - 0.5610042339640731*_x22 + 0.5610042339640731*_x26 + 0.06100423396407311*_x28 + 0.06100423396407311*_x29 - 0.06100423396407311*_x32
            _x34 = (1.0/math.sqrt(_x33))
            _x35 = math.sqrt(_D)
            _x36 = math.sqrt(m)
            _x37 = _x35*_x36
            _x38 = _x35/_x36
            _x39 = _x35*g_s*m**(1.5)
            _x40 = -0.22767090063073978*_x21 - 0.22767090063073978*_x22 + 0.22767090063073978*_x23*_x24*_x25 + 0.27232909936926025*_x24*_x30*_x31 - 0.27232909936926025*_x28 - 0.27232909936926025*_x29 + 0.5*k_d*l0
            _x41 = (1.0/math.sqrt(_x40))
            _isigma0 = _x18
            _iF0 = _x19 - _x21 - _x22 + _x26
            _isigma1 = _x27
            _iF1 = _x19 - _x28 - _x29 + _x32
            _iPsi0 = _x33
            _ift0 = _x34*_x37
            _ifq0 = _P0*_x34*_x38*_x42**2
            _ifp0 = _x18*_x34*_x39*math.sin(_Q0)
            _iPsi1 = _x40
            _ift1 = _x37*_x41
            _ifq1 = _P1*_x38*_x41*_x43**2
            _ifp1 = _x27*_x39*_x41*math.sin(_Q1)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n1_0 = _D
            _n1_1 = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
            _n1_2 = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
            _n1_3 = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + m*q_r**2*q_thd
            _n1_4 = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv1 = tol > 0.0 and (abs(_n1_0 - _D) <= tol*(l0)) and (abs(_n1_1 - _Q0) <= tol*(1.0)) and (abs(_n1_2 - _Q1) <= tol*(1.0)) and (abs(_n1_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n1_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n1_0
            _Q0 = _n1_1
            _Q1 = _n1_2
            _P0 = _n1_3
            _P1 = _n1_4
            _passes += 1.0
            if _conv1:
                break
        if not _conv1 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x44 = 0.04465819873852045*_D + q_r
        _x68 = (1.0/_x44)
        _x45 = k_d*l0
        _x46 = g_s*m
        _x47 = _x46*math.cos(_Q0)
        _x48 = _x44*k_d
        _x49 = _P0**2
        _x50 = (1.0/m)
        _x51 = _x68**3
        _x52 = _x49*_x50*_x51
        _x53 = 0.6220084679281462*_D + q_r
        _x69 = (1.0/_x53)
        _x54 = _x46*math.cos(_Q1)
        _x55 = _x53*k_d
        _x56 = _P1**2
        _x57 = _x69**3
        _x58 = _x50*_x56*_x57
        _x59 = 0.5*_x45 - 0.5610042339640731*_x47 - 0.5610042339640731*_x48 + 0.5610042339640731*_x52 + 0.06100423396407311*_x54 + 0.06100423396407311*_x55 - 0.06100423396407311*_x58
        _x60 = (1.0/math.sqrt(_x59))
        _x61 = math.sqrt(_D)
        _x62 = math.sqrt(m)
        _x63 = _x61*_x62
        _x64 = _x61/_x62
        _x65 = _x61*g_s*m**(1.5)
        _x66 = -0.22767090063073978*_x47 - 0.22767090063073978*_x48 + 0.22767090063073978*_x49*_x50*_x51 + 0.27232909936926025*_x50*_x56*_x57 - 0.27232909936926025*_x54 - 0.27232909936926025*_x55 + 0.5*k_d*l0
        _x67 = (1.0/math.sqrt(_x66))
        _fsigma0 = _x44
        _fF0 = _x45 - _x47 - _x48 + _x52
        _fsigma1 = _x53
        _fF1 = _x45 - _x54 - _x55 + _x58
        _fPsi0 = _x59
        _fft0 = _x60*_x63
        _ffq0 = _P0*_x60*_x64*_x68**2
        _ffp0 = _x44*_x60*_x65*math.sin(_Q0)
        _fPsi1 = _x66
        _fft1 = _x63*_x67
        _ffq1 = _P1*_x64*_x67*_x69**2
        _ffp1 = _x53*_x65*_x67*math.sin(_Q1)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        _work = 0.10566243270259355*_fF0 + 0.39433756729740643*_fF1
        # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
        if not ((_work > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        t_half = 0.5*_fft0 + 0.5*_fft1
        end_q_th = 0.5*_ffq0 + 0.5*_ffq1 + q_th
        end_q_r = q_r_lo
        end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
        end_q_thd = (0.5*_ffp0 + 0.5*_ffp1 + m*q_r**2*q_thd)/(m*q_r_lo**2)
        passes = _passes
    elif nodes == 2.0:
        # Picard passes on the 3 node values (collocation in u)
        _D = -q_r + q_r_lo
        _Q0 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
        _Q1 = 0.5*guess_q_th + 0.5*q_th
        _Q2 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
        _P0 = 0.11270166537925831*guess_q_thd*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd
        _P1 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
        _P2 = 0.8872983346207417*guess_q_thd*m*q_r_lo**2 + 0.11270166537925831*m*q_r**2*q_thd
        _passes = 0.0
        _conv2 = False
        for _it2 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x70 = 0.012701665379258311*_D + q_r
            _x102 = (1.0/_x70)
            _x71 = k_d*l0
            _x72 = g_s*m
            _x73 = _x72*math.cos(_Q0)
            _x74 = _x70*k_d
            _x75 = _P0**2
            _x76 = (1.0/m)
            _x77 = _x102**3
            _x78 = _x75*_x76*_x77
            _x79 = 0.25*_D + q_r
            _x103 = (1.0/_x79)
            _x80 = _x72*math.cos(_Q1)
            _x81 = _x79*k_d
            _x82 = _P1**2
            _x83 = _x103**3
            _x84 = _x76*_x82*_x83
            _x85 = 0.7872983346207417*_D + q_r
            _x104 = (1.0/_x85)
            _x86 = _x72*math.cos(_Q2)
            _x87 = _x85*k_d
            _x88 = _P2**2
            _x89 = _x104**3
            _x90 = _x76*_x88*_x89
            _x91 = 0.5*_x71 - 0.5762768525670787*_x73 - 0.5762768525670787*_x74 + 0.5762768525670787*_x78 + 0.1040546303448565*_x80 + 0.1040546303448565*_x81 - 0.1040546303448565*_x84 - 0.027777777777777776*_x86 - 0.027777777777777776*_x87 + 0.027777777777777776*_x90
            _x92 = (1.0/math.sqrt(_x91))
            _x93 = math.sqrt(_D)
            _x94 = math.sqrt(m)
            _x95 = _x93*_x94
            _x96 = _x93/_x94
            _x97 = _x93*g_s*m**(1.5)
            _x98 = 0.5*_x71 - 0.17702731517242826*_x73 - 0.17702731517242826*_x74 + 0.17702731517242826*_x78 - 0.3611111111111111*_x80 - 0.3611111111111111*_x81 + 0.3611111111111111*_x84 + 0.038138426283539355*_x86 + 0.038138426283539355*_x87 - 0.038138426283539355*_x90
            _x99 = (1.0/math.sqrt(_x98))
            _x100 = -0.027777777777777776*_x73 - 0.027777777777777776*_x74 + 0.027777777777777776*_x75*_x76*_x77 + 0.3262768525670787*_x76*_x82*_x83 + 0.14594536965514351*_x76*_x88*_x89 - 0.3262768525670787*_x80 - 0.3262768525670787*_x81 - 0.14594536965514351*_x86 - 0.14594536965514351*_x87 + 0.5*k_d*l0
            _x101 = (1.0/math.sqrt(_x100))
            _isigma0 = _x70
            _iF0 = _x71 - _x73 - _x74 + _x78
            _isigma1 = _x79
            _iF1 = _x71 - _x80 - _x81 + _x84
            _isigma2 = _x85
            _iF2 = _x71 - _x86 - _x87 + _x90
            _iPsi0 = _x91
            _ift0 = _x92*_x95
            _ifq0 = _P0*_x102**2*_x92*_x96
            _ifp0 = _x70*_x92*_x97*math.sin(_Q0)
            _iPsi1 = _x98
            _ift1 = _x95*_x99
            _ifq1 = _P1*_x103**2*_x96*_x99
            _ifp1 = _x79*_x97*_x99*math.sin(_Q1)
            _iPsi2 = _x100
            _ift2 = _x101*_x95
            _ifq2 = _P2*_x101*_x104**2*_x96
            _ifp2 = _x101*_x85*_x97*math.sin(_Q2)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n2_0 = _D
            _n2_1 = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
            _n2_2 = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
            _n2_3 = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
            _n2_4 = 0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2 + m*q_r**2*q_thd
            _n2_5 = 0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2 + m*q_r**2*q_thd
            _n2_6 = 0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv2 = tol > 0.0 and (abs(_n2_0 - _D) <= tol*(l0)) and (abs(_n2_1 - _Q0) <= tol*(1.0)) and (abs(_n2_2 - _Q1) <= tol*(1.0)) and (abs(_n2_3 - _Q2) <= tol*(1.0)) and (abs(_n2_4 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n2_5 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n2_6 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n2_0
            _Q0 = _n2_1
            _Q1 = _n2_2
            _Q2 = _n2_3
            _P0 = _n2_4
            _P1 = _n2_5
            _P2 = _n2_6
            _passes += 1.0
            if _conv2:
                break
        if not _conv2 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x105 = 0.012701665379258311*_D + q_r
        _x137 = (1.0/_x105)
        _x106 = k_d*l0
        _x107 = g_s*m
        _x108 = _x107*math.cos(_Q0)
        _x109 = _x105*k_d
        _x110 = _P0**2
        _x111 = (1.0/m)
        _x112 = _x137**3
        _x113 = _x110*_x111*_x112
        _x114 = 0.25*_D + q_r
        _x138 = (1.0/_x114)
        _x115 = _x107*math.cos(_Q1)
        _x116 = _x114*k_d
        _x117 = _P1**2
        _x118 = _x138**3
        _x119 = _x111*_x117*_x118
        _x120 = 0.7872983346207417*_D + q_r
        _x139 = (1.0/_x120)
        _x121 = _x107*math.cos(_Q2)
        _x122 = _x120*k_d
        _x123 = _P2**2
        _x124 = _x139**3
        _x125 = _x111*_x123*_x124
        _x126 = 0.5*_x106 - 0.5762768525670787*_x108 - 0.5762768525670787*_x109 + 0.5762768525670787*_x113 + 0.1040546303448565*_x115 + 0.1040546303448565*_x116 - 0.1040546303448565*_x119 - 0.027777777777777776*_x121 - 0.027777777777777776*_x122 + 0.027777777777777776*_x125
        _x127 = (1.0/math.sqrt(_x126))
        _x128 = math.sqrt(_D)
        _x129 = math.sqrt(m)
        _x130 = _x128*_x129
        _x131 = _x128/_x129
        _x132 = _x128*g_s*m**(1.5)
        _x133 = 0.5*_x106 - 0.17702731517242826*_x108 - 0.17702731517242826*_x109 + 0.17702731517242826*_x113 - 0.3611111111111111*_x115 - 0.3611111111111111*_x116 + 0.3611111111111111*_x119 + 0.038138426283539355*_x121 + 0.038138426283539355*_x122 - 0.038138426283539355*_x125
        _x134 = (1.0/math.sqrt(_x133))
        _x135 = -0.027777777777777776*_x108 - 0.027777777777777776*_x109 + 0.027777777777777776*_x110*_x111*_x112 + 0.3262768525670787*_x111*_x117*_x118 + 0.14594536965514351*_x111*_x123*_x124 - 0.3262768525670787*_x115 - 0.3262768525670787*_x116 - 0.14594536965514351*_x121 - 0.14594536965514351*_x122 + 0.5*k_d*l0
        _x136 = (1.0/math.sqrt(_x135))
        _fsigma0 = _x105
        _fF0 = _x106 - _x108 - _x109 + _x113
        _fsigma1 = _x114
        _fF1 = _x106 - _x115 - _x116 + _x119
        _fsigma2 = _x120
        _fF2 = _x106 - _x121 - _x122 + _x125
        _fPsi0 = _x126
        _fft0 = _x127*_x130
        _ffq0 = _P0*_x127*_x131*_x137**2
        _ffp0 = _x105*_x127*_x132*math.sin(_Q0)
        _fPsi1 = _x133
        _fft1 = _x130*_x134
        _ffq1 = _P1*_x131*_x134*_x138**2
        _ffp1 = _x114*_x132*_x134*math.sin(_Q1)
        _fPsi2 = _x135
        _fft2 = _x130*_x136
        _ffq2 = _P2*_x131*_x136*_x139**2
        _ffp2 = _x120*_x132*_x136*math.sin(_Q2)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        _work = 0.031306018160905086*_fF0 + 0.2222222222222222*_fF1 + 0.2464717596168727*_fF2
        # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
        if not ((_work > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        t_half = 0.2777777777777778*_fft0 + 0.4444444444444444*_fft1 + 0.2777777777777778*_fft2
        end_q_th = 0.2777777777777778*_ffq0 + 0.4444444444444444*_ffq1 + 0.2777777777777778*_ffq2 + q_th
        end_q_r = q_r_lo
        end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
        end_q_thd = (0.2777777777777778*_ffp0 + 0.4444444444444444*_ffp1 + 0.2777777777777778*_ffp2 + m*q_r**2*q_thd)/(m*q_r_lo**2)
        passes = _passes
    elif nodes == 3.0:
        # Picard passes on the 4 node values (collocation in u)
        _D = -q_r + q_r_lo
        _Q0 = 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th
        _Q1 = 0.33000947820757187*guess_q_th + 0.6699905217924281*q_th
        _Q2 = 0.6699905217924281*guess_q_th + 0.33000947820757187*q_th
        _Q3 = 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th
        _P0 = 0.06943184420297371*guess_q_thd*m*q_r_lo**2 + 0.9305681557970263*m*q_r**2*q_thd
        _P1 = 0.33000947820757187*guess_q_thd*m*q_r_lo**2 + 0.6699905217924281*m*q_r**2*q_thd
        _P2 = 0.6699905217924281*guess_q_thd*m*q_r_lo**2 + 0.33000947820757187*m*q_r**2*q_thd
        _P3 = 0.9305681557970263*guess_q_thd*m*q_r_lo**2 + 0.06943184420297371*m*q_r**2*q_thd
        _passes = 0.0
        _conv3 = False
        for _it3 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x140 = 0.004820780989426014*_D + q_r
            _x182 = (1.0/_x140)
            _x141 = k_d*l0
            _x142 = g_s*m
            _x143 = _x142*math.cos(_Q0)
            _x144 = _x140*k_d
            _x145 = _P0**2
            _x146 = (1.0/m)
            _x147 = _x182**3
            _x148 = _x145*_x146*_x147
            _x149 = 0.10890625570683385*_D + q_r
            _x183 = (1.0/_x149)
            _x150 = _x142*math.cos(_Q1)
            _x151 = _x149*k_d
            _x152 = _P1**2
            _x153 = _x183**3
            _x154 = _x146*_x152*_x153
            _x155 = 0.44888729929169013*_D + q_r
            _x184 = (1.0/_x155)
            _x156 = math.cos(_Q2)
            _x157 = _x142*_x156
            _x158 = _x155*k_d
            _x159 = _P2**2
            _x160 = _x184**3
            _x161 = _x146*_x159*_x160
            _x162 = 0.8659570925834786*_D + q_r
            _x185 = (1.0/_x162)
            _x163 = math.cos(_Q3)
            _x164 = _x142*_x163
            _x165 = _x162*k_d
            _x166 = _P3**2
            _x167 = _x185**3
            _x168 = _x146*_x166*_x167
            _x169 = 0.5*_x141 - 0.582374038291501*_x143 - 0.582374038291501*_x144 + 0.582374038291501*_x148 + 0.12383458041329967*_x150 + 0.12383458041329967*_x151 - 0.12383458041329967*_x154 - 0.0575898635297681*_x157 - 0.0575898635297681*_x158 + 0.0575898635297681*_x161 + 0.016129321407969507*_x164 + 0.016129321407969507*_x165 - 0.016129321407969507*_x168
            _x170 = (1.0/math.sqrt(_x169))
            _x171 = math.sqrt(_D)
            _x172 = math.sqrt(m)
            _x173 = _x171*_x172
            _x174 = _x171/_x172
            _x175 = _x171*g_s*m**(1.5)
            _x176 = -0.16000937841634696*_x143 - 0.16000937841634696*_x144 + 0.16000937841634696*_x145*_x146*_x147 + 0.39252437029865583*_x146*_x152*_x153 + 0.017475652789475504*_x146*_x166*_x167 - 0.39252437029865583*_x150 - 0.39252437029865583*_x151 + 0.0700094015044783*_x155*k_d + 0.0700094015044783*_x156*g_s*m - 0.0700094015044783*_x161 - 0.017475652789475504*_x164 - 0.017475652789475504*_x165 + 0.5*k_d*l0
            _x177 = (1.0/math.sqrt(_x176))
            _x178 = -0.01613725546399532*_x143 - 0.01613725546399532*_x144 + 0.01613725546399532*_x145*_x146*_x147 + 0.2848443432415939*_x146*_x152*_x153 + 0.21871326539550162*_x146*_x159*_x160 - 0.2848443432415939*_x150 - 0.2848443432415939*_x151 - 0.21871326539550162*_x157 - 0.21871326539550162*_x158 + 0.019694864101090868*_x162*k_d + 0.019694864101090868*_x163*g_s*m - 0.019694864101090868*_x168 + 0.5*k_d*l0
            _x179 = (1.0/math.sqrt(_x178))
            _x180 = -0.01796104633752054*_x143 - 0.01796104633752054*_x144 + 0.01796104633752054*_x145*_x146*_x147 + 0.11000222456933441*_x146*_x152*_x153 + 0.2823150697454702*_x146*_x159*_x160 + 0.08972165934767481*_x146*_x166*_x167 - 0.11000222456933441*_x150 - 0.11000222456933441*_x151 - 0.2823150697454702*_x157 - 0.2823150697454702*_x158 - 0.08972165934767481*_x164 - 0.08972165934767481*_x165 + 0.5*k_d*l0
            _x181 = (1.0/math.sqrt(_x180))
            _isigma0 = _x140
            _iF0 = _x141 - _x143 - _x144 + _x148
            _isigma1 = _x149
            _iF1 = _x141 - _x150 - _x151 + _x154
            _isigma2 = _x155
            _iF2 = _x141 - _x157 - _x158 + _x161
            _isigma3 = _x162
            _iF3 = _x141 - _x164 - _x165 + _x168
            _iPsi0 = _x169
            _ift0 = _x170*_x173
            _ifq0 = _P0*_x170*_x174*_x182**2
            _ifp0 = _x140*_x170*_x175*math.sin(_Q0)
            _iPsi1 = _x176
            _ift1 = _x173*_x177
            _ifq1 = _P1*_x174*_x177*_x183**2
            _ifp1 = _x149*_x175*_x177*math.sin(_Q1)
            _iPsi2 = _x178
            _ift2 = _x173*_x179
            _ifq2 = _P2*_x174*_x179*_x184**2
            _ifp2 = _x155*_x175*_x179*math.sin(_Q2)
            _iPsi3 = _x180
            _ift3 = _x173*_x181
            _ifq3 = _P3*_x174*_x181*_x185**2
            _ifp3 = _x162*_x175*_x181*math.sin(_Q3)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi3 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n3_0 = _D
            _n3_1 = 0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2 - 0.0035551496857956833*_ifq3 + q_th
            _n3_2 = 0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2 + 0.006735500594538156*_ifq3 + q_th
            _n3_3 = 0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2 - 0.014190694931141144*_ifq3 + q_th
            _n3_4 = 0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2 + 0.08696371128436346*_ifq3 + q_th
            _n3_5 = 0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2 - 0.0035551496857956833*_ifp3 + m*q_r**2*q_thd
            _n3_6 = 0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2 + 0.006735500594538156*_ifp3 + m*q_r**2*q_thd
            _n3_7 = 0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2 - 0.014190694931141144*_ifp3 + m*q_r**2*q_thd
            _n3_8 = 0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2 + 0.08696371128436346*_ifp3 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv3 = tol > 0.0 and (abs(_n3_0 - _D) <= tol*(l0)) and (abs(_n3_1 - _Q0) <= tol*(1.0)) and (abs(_n3_2 - _Q1) <= tol*(1.0)) and (abs(_n3_3 - _Q2) <= tol*(1.0)) and (abs(_n3_4 - _Q3) <= tol*(1.0)) and (abs(_n3_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_7 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n3_8 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n3_0
            _Q0 = _n3_1
            _Q1 = _n3_2
            _Q2 = _n3_3
            _Q3 = _n3_4
            _P0 = _n3_5
            _P1 = _n3_6
            _P2 = _n3_7
            _P3 = _n3_8
            _passes += 1.0
            if _conv3:
                break
        if not _conv3 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x186 = 0.004820780989426014*_D + q_r
        _x228 = (1.0/_x186)
        _x187 = k_d*l0
        _x188 = g_s*m
        _x189 = _x188*math.cos(_Q0)
        _x190 = _x186*k_d
        _x191 = _P0**2
        _x192 = (1.0/m)
        _x193 = _x228**3
        _x194 = _x191*_x192*_x193
        _x195 = 0.10890625570683385*_D + q_r
        _x229 = (1.0/_x195)
        _x196 = _x188*math.cos(_Q1)
        _x197 = _x195*k_d
        _x198 = _P1**2
        _x199 = _x229**3
        _x200 = _x192*_x198*_x199
        _x201 = 0.44888729929169013*_D + q_r
        _x230 = (1.0/_x201)
        _x202 = math.cos(_Q2)
        _x203 = _x188*_x202
        _x204 = _x201*k_d
        _x205 = _P2**2
        _x206 = _x230**3
        _x207 = _x192*_x205*_x206
        _x208 = 0.8659570925834786*_D + q_r
        _x231 = (1.0/_x208)
        _x209 = math.cos(_Q3)
        _x210 = _x188*_x209
        _x211 = _x208*k_d
        _x212 = _P3**2
        _x213 = _x231**3
        _x214 = _x192*_x212*_x213
        _x215 = 0.5*_x187 - 0.582374038291501*_x189 - 0.582374038291501*_x190 + 0.582374038291501*_x194 + 0.12383458041329967*_x196 + 0.12383458041329967*_x197 - 0.12383458041329967*_x200 - 0.0575898635297681*_x203 - 0.0575898635297681*_x204 + 0.0575898635297681*_x207 + 0.016129321407969507*_x210 + 0.016129321407969507*_x211 - 0.016129321407969507*_x214
        _x216 = (1.0/math.sqrt(_x215))
        _x217 = math.sqrt(_D)
        _x218 = math.sqrt(m)
        _x219 = _x217*_x218
        _x220 = _x217/_x218
        _x221 = _x217*g_s*m**(1.5)
        _x222 = -0.16000937841634696*_x189 - 0.16000937841634696*_x190 + 0.16000937841634696*_x191*_x192*_x193 + 0.39252437029865583*_x192*_x198*_x199 + 0.017475652789475504*_x192*_x212*_x213 - 0.39252437029865583*_x196 - 0.39252437029865583*_x197 + 0.0700094015044783*_x201*k_d + 0.0700094015044783*_x202*g_s*m - 0.0700094015044783*_x207 - 0.017475652789475504*_x210 - 0.017475652789475504*_x211 + 0.5*k_d*l0
        _x223 = (1.0/math.sqrt(_x222))
        _x224 = -0.01613725546399532*_x189 - 0.01613725546399532*_x190 + 0.01613725546399532*_x191*_x192*_x193 + 0.2848443432415939*_x192*_x198*_x199 + 0.21871326539550162*_x192*_x205*_x206 - 0.2848443432415939*_x196 - 0.2848443432415939*_x197 - 0.21871326539550162*_x203 - 0.21871326539550162*_x204 + 0.019694864101090868*_x208*k_d + 0.019694864101090868*_x209*g_s*m - 0.019694864101090868*_x214 + 0.5*k_d*l0
        _x225 = (1.0/math.sqrt(_x224))
        _x226 = -0.01796104633752054*_x189 - 0.01796104633752054*_x190 + 0.01796104633752054*_x191*_x192*_x193 + 0.11000222456933441*_x192*_x198*_x199 + 0.2823150697454702*_x192*_x205*_x206 + 0.08972165934767481*_x192*_x212*_x213 - 0.11000222456933441*_x196 - 0.11000222456933441*_x197 - 0.2823150697454702*_x203 - 0.2823150697454702*_x204 - 0.08972165934767481*_x210 - 0.08972165934767481*_x211 + 0.5*k_d*l0
        _x227 = (1.0/math.sqrt(_x226))
        _fsigma0 = _x186
        _fF0 = _x187 - _x189 - _x190 + _x194
        _fsigma1 = _x195
        _fF1 = _x187 - _x196 - _x197 + _x200
        _fsigma2 = _x201
        _fF2 = _x187 - _x203 - _x204 + _x207
        _fsigma3 = _x208
        _fF3 = _x187 - _x210 - _x211 + _x214
        _fPsi0 = _x215
        _fft0 = _x216*_x219
        _ffq0 = _P0*_x216*_x220*_x228**2
        _ffp0 = _x186*_x216*_x221*math.sin(_Q0)
        _fPsi1 = _x222
        _fft1 = _x219*_x223
        _ffq1 = _P1*_x220*_x223*_x229**2
        _ffp1 = _x195*_x221*_x223*math.sin(_Q1)
        _fPsi2 = _x224
        _fft2 = _x219*_x225
        _ffq2 = _P2*_x220*_x225*_x230**2
        _ffp2 = _x201*_x221*_x225*math.sin(_Q2)
        _fPsi3 = _x226
        _fft3 = _x219*_x227
        _ffq3 = _P3*_x220*_x227*_x231**2
        _ffp3 = _x208*_x221*_x227*math.sin(_Q3)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi3 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        _work = 0.012076101706416622*_fF0 + 0.1076070411358925*_fF1 + 0.21846553629538057*_fF2 + 0.1618513208623103*_fF3
        # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
        if not ((_work > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        t_half = 0.17392742256872692*_fft0 + 0.32607257743127305*_fft1 + 0.32607257743127305*_fft2 + 0.17392742256872692*_fft3
        end_q_th = 0.17392742256872692*_ffq0 + 0.32607257743127305*_ffq1 + 0.32607257743127305*_ffq2 + 0.17392742256872692*_ffq3 + q_th
        end_q_r = q_r_lo
        end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
        end_q_thd = (0.17392742256872692*_ffp0 + 0.32607257743127305*_ffp1 + 0.32607257743127305*_ffp2 + 0.17392742256872692*_ffp3 + m*q_r**2*q_thd)/(m*q_r_lo**2)
        passes = _passes
    elif nodes == 4.0:
        # Picard passes on the 6 node values (collocation in u)
        _D = -q_r + q_r_lo
        _Q0 = 0.03376524289842399*guess_q_th + 0.966234757101576*q_th
        _Q1 = 0.16939530676686773*guess_q_th + 0.8306046932331322*q_th
        _Q2 = 0.38069040695840156*guess_q_th + 0.6193095930415985*q_th
        _Q3 = 0.6193095930415985*guess_q_th + 0.38069040695840156*q_th
        _Q4 = 0.8306046932331322*guess_q_th + 0.16939530676686773*q_th
        _Q5 = 0.966234757101576*guess_q_th + 0.03376524289842399*q_th
        _P0 = 0.03376524289842399*guess_q_thd*m*q_r_lo**2 + 0.966234757101576*m*q_r**2*q_thd
        _P1 = 0.16939530676686773*guess_q_thd*m*q_r_lo**2 + 0.8306046932331322*m*q_r**2*q_thd
        _P2 = 0.38069040695840156*guess_q_thd*m*q_r_lo**2 + 0.6193095930415985*m*q_r**2*q_thd
        _P3 = 0.6193095930415985*guess_q_thd*m*q_r_lo**2 + 0.38069040695840156*m*q_r**2*q_thd
        _P4 = 0.8306046932331322*guess_q_thd*m*q_r_lo**2 + 0.16939530676686773*m*q_r**2*q_thd
        _P5 = 0.966234757101576*guess_q_thd*m*q_r_lo**2 + 0.03376524289842399*m*q_r**2*q_thd
        _passes = 0.0
        _conv4 = False
        for _it4 in range(int(iterations)):
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x232 = 0.0011400916279895713*_D + q_r
            _x294 = (1.0/_x232)
            _x233 = k_d*l0
            _x234 = g_s*m
            _x235 = _x234*math.cos(_Q0)
            _x236 = _x232*k_d
            _x237 = _P0**2
            _x238 = (1.0/m)
            _x239 = _x294**3
            _x240 = _x237*_x238*_x239
            _x241 = 0.02869476995464123*_D + q_r
            _x295 = (1.0/_x241)
            _x242 = _x234*math.cos(_Q1)
            _x243 = _x241*k_d
            _x244 = _P1**2
            _x245 = _x295**3
            _x246 = _x238*_x244*_x245
            _x247 = 0.14492518595015338*_D + q_r
            _x296 = (1.0/_x247)
            _x248 = math.cos(_Q2)
            _x249 = _x234*_x248
            _x250 = _x247*k_d
            _x251 = _P2**2
            _x252 = _x296**3
            _x253 = _x238*_x251*_x252
            _x254 = 0.3835443720333503*_D + q_r
            _x297 = (1.0/_x254)
            _x255 = math.cos(_Q3)
            _x256 = _x234*_x255
            _x257 = _x254*k_d
            _x258 = _P3**2
            _x259 = _x297**3
            _x260 = _x238*_x258*_x259
            _x261 = 0.6899041564209057*_D + q_r
            _x298 = (1.0/_x261)
            _x262 = math.cos(_Q4)
            _x263 = _x234*_x262
            _x264 = _x261*k_d
            _x265 = _P4**2
            _x266 = _x298**3
            _x267 = _x238*_x265*_x266
            _x268 = 0.9336096058311416*_D + q_r
            _x299 = (1.0/_x268)
            _x269 = math.cos(_Q5)
            _x270 = _x234*_x269
            _x271 = _x268*k_d
            _x272 = _P5**2
            _x273 = _x299**3
            _x274 = _x238*_x272*_x273
            _x275 = 0.5*_x233 - 0.5871580340658094*_x235 - 0.5871580340658094*_x236 + 0.5871580340658094*_x240 + 0.140380692261653*_x242 + 0.140380692261653*_x243 - 0.140380692261653*_x246 - 0.08683151831711133*_x249 - 0.08683151831711133*_x250 + 0.08683151831711133*_x253 + 0.052466581536012566*_x256 + 0.052466581536012566*_x257 - 0.052466581536012566*_x260 - 0.026354606039126004*_x263 - 0.026354606039126004*_x264 + 0.026354606039126004*_x267 + 0.007496884624381081*_x270 + 0.007496884624381081*_x271 - 0.007496884624381081*_x274
            _x276 = (1.0/math.sqrt(_x275))
            _x277 = math.sqrt(_D)
            _x278 = math.sqrt(m)
            _x279 = _x277*_x278
            _x280 = _x277/_x278
            _x281 = _x277*g_s*m**(1.5)
            _x282 = -0.5*k_d*l0
            _x283 = -0.147790320897128*_x235 - 0.147790320897128*_x236 + 0.147790320897128*_x237*_x238*_x239 + 0.41567911405660357*_x238*_x244*_x245 + 0.05155355009455148*_x238*_x258*_x259 + 0.006904529857608445*_x238*_x272*_x273 - 0.41567911405660357*_x242 - 0.41567911405660357*_x243 + 0.09720828549085844*_x247*k_d + 0.09720828549085844*_x248*g_s*m - 0.09720828549085844*_x253 - 0.05155355009455148*_x256 - 0.05155355009455148*_x257 + 0.024719229415033087*_x261*k_d + 0.024719229415033087*_x262*g_s*m - 0.024719229415033087*_x267 - 0.006904529857608445*_x270 - 0.006904529857608445*_x271 - _x282
            _x284 = (1.0/math.sqrt(_x283))
            _x285 = -0.010443786721981197*_x235 - 0.010443786721981197*_x236 + 0.010443786721981197*_x237*_x238*_x239 + 0.25540525119175433*_x238*_x244*_x245 + 0.2685463444140672*_x238*_x251*_x252 + 0.01951903325298492*_x238*_x265*_x266 - 0.25540525119175433*_x242 - 0.25540525119175433*_x243 - 0.2685463444140672*_x249 - 0.2685463444140672*_x250 + 0.048794612428541204*_x254*k_d + 0.048794612428541204*_x255*g_s*m - 0.048794612428541204*_x260 - 0.01951903325298492*_x263 - 0.01951903325298492*_x264 + 0.005119803152246505*_x268*k_d + 0.005119803152246505*_x269*g_s*m - 0.005119803152246505*_x274 - _x282
            _x286 = (1.0/math.sqrt(_x285))
            _x287 = -0.5*k_d*l0
            _x288 = -0.01101839635505667*_x235 - 0.01101839635505667*_x236 + 0.01101839635505667*_x237*_x238*_x239 + 0.0662099828438604*_x238*_x244*_x245 + 0.2671819482314443*_x238*_x251*_x252 + 0.1742495636223592*_x238*_x258*_x259 + 0.00530703852813994*_x238*_x272*_x273 - 0.0662099828438604*_x242 - 0.0662099828438604*_x243 - 0.2671819482314443*_x249 - 0.2671819482314443*_x250 - 0.1742495636223592*_x256 - 0.1742495636223592*_x257 + 0.02396692958086051*_x261*k_d + 0.02396692958086051*_x262*g_s*m - 0.02396692958086051*_x267 - 0.00530703852813994*_x270 - 0.00530703852813994*_x271 - _x287
            _x289 = (1.0/math.sqrt(_x288))
            _x290 = -0.0025147977064533143*_x235 - 0.0025147977064533143*_x236 + 0.0025147977064533143*_x237*_x238*_x239 + 0.050345455482979015*_x238*_x244*_x245 + 0.11622097556712797*_x238*_x251*_x252 + 0.2353986790647292*_x238*_x258*_x259 + 0.10372825048336794*_x238*_x265*_x266 - 0.050345455482979015*_x242 - 0.050345455482979015*_x243 - 0.11622097556712797*_x249 - 0.11622097556712797*_x250 - 0.2353986790647292*_x256 - 0.2353986790647292*_x257 - 0.10372825048336794*_x263 - 0.10372825048336794*_x264 + 0.008208158304657426*_x268*k_d + 0.008208158304657426*_x269*g_s*m - 0.008208158304657426*_x274 - _x282
            _x291 = (1.0/math.sqrt(_x290))
            _x292 = -0.003959513229722528*_x235 - 0.003959513229722528*_x236 + 0.003959513229722528*_x237*_x238*_x239 + 0.029703284805013122*_x238*_x244*_x245 + 0.10140664131431479*_x238*_x251*_x252 + 0.14531313573962065*_x238*_x258*_x259 + 0.17612158869639333*_x238*_x265*_x266 + 0.04349583621493557*_x238*_x272*_x273 - 0.029703284805013122*_x242 - 0.029703284805013122*_x243 - 0.10140664131431479*_x249 - 0.10140664131431479*_x250 - 0.14531313573962065*_x256 - 0.14531313573962065*_x257 - 0.17612158869639333*_x263 - 0.17612158869639333*_x264 - 0.04349583621493557*_x270 - 0.04349583621493557*_x271 - _x287
            _x293 = (1.0/math.sqrt(_x292))
            _isigma0 = _x232
            _iF0 = _x233 - _x235 - _x236 + _x240
            _isigma1 = _x241
            _iF1 = _x233 - _x242 - _x243 + _x246
            _isigma2 = _x247
            _iF2 = _x233 - _x249 - _x250 + _x253
            _isigma3 = _x254
            _iF3 = _x233 - _x256 - _x257 + _x260
            _isigma4 = _x261
            _iF4 = _x233 - _x263 - _x264 + _x267
            _isigma5 = _x268
            _iF5 = _x233 - _x270 - _x271 + _x274
            _iPsi0 = _x275
            _ift0 = _x276*_x279
            _ifq0 = _P0*_x276*_x280*_x294**2
            _ifp0 = _x232*_x276*_x281*math.sin(_Q0)
            _iPsi1 = _x283
            _ift1 = _x279*_x284
            _ifq1 = _P1*_x280*_x284*_x295**2
            _ifp1 = _x241*_x281*_x284*math.sin(_Q1)
            _iPsi2 = _x285
            _ift2 = _x279*_x286
            _ifq2 = _P2*_x280*_x286*_x296**2
            _ifp2 = _x247*_x281*_x286*math.sin(_Q2)
            _iPsi3 = _x288
            _ift3 = _x279*_x289
            _ifq3 = _P3*_x280*_x289*_x297**2
            _ifp3 = _x254*_x281*_x289*math.sin(_Q3)
            _iPsi4 = _x290
            _ift4 = _x279*_x291
            _ifq4 = _P4*_x280*_x291*_x298**2
            _ifp4 = _x261*_x281*_x291*math.sin(_Q4)
            _iPsi5 = _x292
            _ift5 = _x279*_x293
            _ifq5 = _P5*_x280*_x293*_x299**2
            _ifp5 = _x268*_x281*_x293*math.sin(_Q5)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi0 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi1 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi2 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi3 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi4 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_iPsi5 > 0.0)):
                return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
            _n4_0 = _D
            _n4_1 = 0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2 - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th
            _n4_2 = 0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2 + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th
            _n4_3 = 0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2 - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th
            _n4_4 = 0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2 + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th
            _n4_5 = 0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2 + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th
            _n4_6 = 0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2 + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th
            _n4_7 = 0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2 - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5 + m*q_r**2*q_thd
            _n4_8 = 0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2 + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5 + m*q_r**2*q_thd
            _n4_9 = 0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2 - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5 + m*q_r**2*q_thd
            _n4_10 = 0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2 + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5 + m*q_r**2*q_thd
            _n4_11 = 0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2 + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5 + m*q_r**2*q_thd
            _n4_12 = 0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2 + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5 + m*q_r**2*q_thd
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv4 = tol > 0.0 and (abs(_n4_0 - _D) <= tol*(l0)) and (abs(_n4_1 - _Q0) <= tol*(1.0)) and (abs(_n4_2 - _Q1) <= tol*(1.0)) and (abs(_n4_3 - _Q2) <= tol*(1.0)) and (abs(_n4_4 - _Q3) <= tol*(1.0)) and (abs(_n4_5 - _Q4) <= tol*(1.0)) and (abs(_n4_6 - _Q5) <= tol*(1.0)) and (abs(_n4_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_8 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_9 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_10 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_11 - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n4_12 - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            _D = _n4_0
            _Q0 = _n4_1
            _Q1 = _n4_2
            _Q2 = _n4_3
            _Q3 = _n4_4
            _Q4 = _n4_5
            _Q5 = _n4_6
            _P0 = _n4_7
            _P1 = _n4_8
            _P2 = _n4_9
            _P3 = _n4_10
            _P4 = _n4_11
            _P5 = _n4_12
            _passes += 1.0
            if _conv4:
                break
        if not _conv4 and tol > 0.0 and _passes > 0.0:
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x300 = 0.0011400916279895713*_D + q_r
        _x362 = (1.0/_x300)
        _x301 = k_d*l0
        _x302 = g_s*m
        _x303 = _x302*math.cos(_Q0)
        _x304 = _x300*k_d
        _x305 = _P0**2
        _x306 = (1.0/m)
        _x307 = _x362**3
        _x308 = _x305*_x306*_x307
        _x309 = 0.02869476995464123*_D + q_r
        _x363 = (1.0/_x309)
        _x310 = _x302*math.cos(_Q1)
        _x311 = _x309*k_d
        _x312 = _P1**2
        _x313 = _x363**3
        _x314 = _x306*_x312*_x313
        _x315 = 0.14492518595015338*_D + q_r
        _x364 = (1.0/_x315)
        _x316 = math.cos(_Q2)
        _x317 = _x302*_x316
        _x318 = _x315*k_d
        _x319 = _P2**2
        _x320 = _x364**3
        _x321 = _x306*_x319*_x320
        _x322 = 0.3835443720333503*_D + q_r
        _x365 = (1.0/_x322)
        _x323 = math.cos(_Q3)
        _x324 = _x302*_x323
        _x325 = _x322*k_d
        _x326 = _P3**2
        _x327 = _x365**3
        _x328 = _x306*_x326*_x327
        _x329 = 0.6899041564209057*_D + q_r
        _x366 = (1.0/_x329)
        _x330 = math.cos(_Q4)
        _x331 = _x302*_x330
        _x332 = _x329*k_d
        _x333 = _P4**2
        _x334 = _x366**3
        _x335 = _x306*_x333*_x334
        _x336 = 0.9336096058311416*_D + q_r
        _x367 = (1.0/_x336)
        _x337 = math.cos(_Q5)
        _x338 = _x302*_x337
        _x339 = _x336*k_d
        _x340 = _P5**2
        _x341 = _x367**3
        _x342 = _x306*_x340*_x341
        _x343 = 0.5*_x301 - 0.5871580340658094*_x303 - 0.5871580340658094*_x304 + 0.5871580340658094*_x308 + 0.140380692261653*_x310 + 0.140380692261653*_x311 - 0.140380692261653*_x314 - 0.08683151831711133*_x317 - 0.08683151831711133*_x318 + 0.08683151831711133*_x321 + 0.052466581536012566*_x324 + 0.052466581536012566*_x325 - 0.052466581536012566*_x328 - 0.026354606039126004*_x331 - 0.026354606039126004*_x332 + 0.026354606039126004*_x335 + 0.007496884624381081*_x338 + 0.007496884624381081*_x339 - 0.007496884624381081*_x342
        _x344 = (1.0/math.sqrt(_x343))
        _x345 = math.sqrt(_D)
        _x346 = math.sqrt(m)
        _x347 = _x345*_x346
        _x348 = _x345/_x346
        _x349 = _x345*g_s*m**(1.5)
        _x350 = -0.5*k_d*l0
        _x351 = -0.147790320897128*_x303 - 0.147790320897128*_x304 + 0.147790320897128*_x305*_x306*_x307 + 0.41567911405660357*_x306*_x312*_x313 + 0.05155355009455148*_x306*_x326*_x327 + 0.006904529857608445*_x306*_x340*_x341 - 0.41567911405660357*_x310 - 0.41567911405660357*_x311 + 0.09720828549085844*_x315*k_d + 0.09720828549085844*_x316*g_s*m - 0.09720828549085844*_x321 - 0.05155355009455148*_x324 - 0.05155355009455148*_x325 + 0.024719229415033087*_x329*k_d + 0.024719229415033087*_x330*g_s*m - 0.024719229415033087*_x335 - 0.006904529857608445*_x338 - 0.006904529857608445*_x339 - _x350
        _x352 = (1.0/math.sqrt(_x351))
        _x353 = -0.010443786721981197*_x303 - 0.010443786721981197*_x304 + 0.010443786721981197*_x305*_x306*_x307 + 0.25540525119175433*_x306*_x312*_x313 + 0.2685463444140672*_x306*_x319*_x320 + 0.01951903325298492*_x306*_x333*_x334 - 0.25540525119175433*_x310 - 0.25540525119175433*_x311 - 0.2685463444140672*_x317 - 0.2685463444140672*_x318 + 0.048794612428541204*_x322*k_d + 0.048794612428541204*_x323*g_s*m - 0.048794612428541204*_x328 - 0.01951903325298492*_x331 - 0.01951903325298492*_x332 + 0.005119803152246505*_x336*k_d + 0.005119803152246505*_x337*g_s*m - 0.005119803152246505*_x342 - _x350
        _x354 = (1.0/math.sqrt(_x353))
        _x355 = -0.5*k_d*l0
        _x356 = -0.01101839635505667*_x303 - 0.01101839635505667*_x304 + 0.01101839635505667*_x305*_x306*_x307 + 0.0662099828438604*_x306*_x312*_x313 + 0.2671819482314443*_x306*_x319*_x320 + 0.1742495636223592*_x306*_x326*_x327 + 0.00530703852813994*_x306*_x340*_x341 - 0.0662099828438604*_x310 - 0.0662099828438604*_x311 - 0.2671819482314443*_x317 - 0.2671819482314443*_x318 - 0.1742495636223592*_x324 - 0.1742495636223592*_x325 + 0.02396692958086051*_x329*k_d + 0.02396692958086051*_x330*g_s*m - 0.02396692958086051*_x335 - 0.00530703852813994*_x338 - 0.00530703852813994*_x339 - _x355
        _x357 = (1.0/math.sqrt(_x356))
        _x358 = -0.0025147977064533143*_x303 - 0.0025147977064533143*_x304 + 0.0025147977064533143*_x305*_x306*_x307 + 0.050345455482979015*_x306*_x312*_x313 + 0.11622097556712797*_x306*_x319*_x320 + 0.2353986790647292*_x306*_x326*_x327 + 0.10372825048336794*_x306*_x333*_x334 - 0.050345455482979015*_x310 - 0.050345455482979015*_x311 - 0.11622097556712797*_x317 - 0.11622097556712797*_x318 - 0.2353986790647292*_x324 - 0.2353986790647292*_x325 - 0.10372825048336794*_x331 - 0.10372825048336794*_x332 + 0.008208158304657426*_x336*k_d + 0.008208158304657426*_x337*g_s*m - 0.008208158304657426*_x342 - _x350
        _x359 = (1.0/math.sqrt(_x358))
        _x360 = -0.003959513229722528*_x303 - 0.003959513229722528*_x304 + 0.003959513229722528*_x305*_x306*_x307 + 0.029703284805013122*_x306*_x312*_x313 + 0.10140664131431479*_x306*_x319*_x320 + 0.14531313573962065*_x306*_x326*_x327 + 0.17612158869639333*_x306*_x333*_x334 + 0.04349583621493557*_x306*_x340*_x341 - 0.029703284805013122*_x310 - 0.029703284805013122*_x311 - 0.10140664131431479*_x317 - 0.10140664131431479*_x318 - 0.14531313573962065*_x324 - 0.14531313573962065*_x325 - 0.17612158869639333*_x331 - 0.17612158869639333*_x332 - 0.04349583621493557*_x338 - 0.04349583621493557*_x339 - _x355
        _x361 = (1.0/math.sqrt(_x360))
        _fsigma0 = _x300
        _fF0 = _x301 - _x303 - _x304 + _x308
        _fsigma1 = _x309
        _fF1 = _x301 - _x310 - _x311 + _x314
        _fsigma2 = _x315
        _fF2 = _x301 - _x317 - _x318 + _x321
        _fsigma3 = _x322
        _fF3 = _x301 - _x324 - _x325 + _x328
        _fsigma4 = _x329
        _fF4 = _x301 - _x331 - _x332 + _x335
        _fsigma5 = _x336
        _fF5 = _x301 - _x338 - _x339 + _x342
        _fPsi0 = _x343
        _fft0 = _x344*_x347
        _ffq0 = _P0*_x344*_x348*_x362**2
        _ffp0 = _x300*_x344*_x349*math.sin(_Q0)
        _fPsi1 = _x351
        _fft1 = _x347*_x352
        _ffq1 = _P1*_x348*_x352*_x363**2
        _ffp1 = _x309*_x349*_x352*math.sin(_Q1)
        _fPsi2 = _x353
        _fft2 = _x347*_x354
        _ffq2 = _P2*_x348*_x354*_x364**2
        _ffp2 = _x315*_x349*_x354*math.sin(_Q2)
        _fPsi3 = _x356
        _fft3 = _x347*_x357
        _ffq3 = _P3*_x348*_x357*_x365**2
        _ffp3 = _x322*_x349*_x357*math.sin(_Q3)
        _fPsi4 = _x358
        _fft4 = _x347*_x359
        _ffq4 = _P4*_x348*_x359*_x366**2
        _ffp4 = _x329*_x349*_x359*math.sin(_Q4)
        _fPsi5 = _x360
        _fft5 = _x347*_x361
        _ffq5 = _P5*_x348*_x361*_x367**2
        _ffp5 = _x336*_x349*_x361*math.sin(_Q5)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi0 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi1 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi2 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi3 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi4 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_fPsi5 > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
        _work = 0.0028924065498159377*_fF0 + 0.030555658668093604*_fF1 + 0.08906517308699231*_fF2 + 0.14489179419935322*_fF3 + 0.1498251278559757*_fF4 + 0.08276983963976924*_fF5
        # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
        if not ((_work > 0.0)):
            return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        t_half = 0.08566224618958518*_fft0 + 0.1803807865240693*_fft1 + 0.23395696728634552*_fft2 + 0.23395696728634552*_fft3 + 0.1803807865240693*_fft4 + 0.08566224618958518*_fft5
        end_q_th = 0.08566224618958518*_ffq0 + 0.1803807865240693*_ffq1 + 0.23395696728634552*_ffq2 + 0.23395696728634552*_ffq3 + 0.1803807865240693*_ffq4 + 0.08566224618958518*_ffq5 + q_th
        end_q_r = q_r_lo
        end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
        end_q_thd = (0.08566224618958518*_ffp0 + 0.1803807865240693*_ffp1 + 0.23395696728634552*_ffp2 + 0.23395696728634552*_ffp3 + 0.1803807865240693*_ffp4 + 0.08566224618958518*_ffp5 + m*q_r**2*q_thd)/(m*q_r_lo**2)
        passes = _passes
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd) and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Converging form of (30)-(45) and (116)-(151): p_r^2 = 2 m int F_r (work form) instead of
    (33); N Gauss-Legendre nodes in u (N = 1 is the mean value (41)); bottom leg length from
    p_r_td^2 = 2 m int F_r.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs

    Returns a tuple:
        t_bottom: time from touchdown to the bottom [s]
        t_stance: stance time, touchdown to liftoff [s]
        bottom_q_r: leg length [m]
        bottom_q_rd: leg length rate [m/s]
        bottom_q_th: leg angle from the vertical, counterclockwise positive [rad]
        bottom_q_thd: leg angle rate [rad/s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        passes: Picard passes run (the larger of the two halves) [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 46
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate
    if zeroth == 1.0:
        # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
        _x0 = k_c*q_r_td
        _x1 = g_s*m*math.cos(q_th_td)
        _x2 = q_thd_td**2
        _x3 = m*q_rd_td**2
        _x4 = -_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td + k_c*l0)**2)) + q_r_td
        z_b_q_r = _x4
        z_b_q_th = q_th_td
        z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
        z_lo_q_th = 0.0
        z_lo_q_thd = 0.0
    elif zeroth == 0.0:
        # zeroth iterate: Geyer et al.'s approximate stance map
        _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
        if _c0[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[10])
        z_b_q_r = _c0[2]
        z_b_q_th = _c0[4]
        z_b_q_thd = _c0[5]
        z_lo_q_th = _c0[8]
        z_lo_q_thd = _c0[9]
    elif zeroth == 2.0:
        # zeroth iterate: Gravity correction type 0 (leg length l0)
        _c1 = gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0, 0.0)
        if _c1[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[12])
        z_b_q_r = _c1[2]
        z_b_q_th = _c1[4]
        z_b_q_thd = _c1[5]
        z_lo_q_th = _c1[8]
        z_lo_q_thd = _c1[9]
    elif zeroth == 3.0:
        # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
        _c2 = gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0, 1e-12)
        if _c2[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[12])
        z_b_q_r = _c2[2]
        z_b_q_th = _c2[4]
        z_b_q_thd = _c2[5]
        z_lo_q_th = _c2[8]
        z_lo_q_thd = _c2[9]
    elif zeroth == 4.0:
        # zeroth iterate: Gravity correction type 2 (average leg length)
        _c3 = gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0, 100.0, 1e-12)
        if _c3[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[12])
        z_b_q_r = _c3[2]
        z_b_q_th = _c3[4]
        z_b_q_thd = _c3[5]
        z_lo_q_th = _c3[8]
        z_lo_q_thd = _c3[9]
    elif zeroth == 5.0:
        # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
        _c4 = gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0, 1e-12)
        if _c4[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[12])
        z_b_q_r = _c4[2]
        z_b_q_th = _c4[4]
        z_b_q_thd = _c4[5]
        z_lo_q_th = _c4[8]
        z_lo_q_thd = _c4[9]
    elif zeroth == 6.0:
        # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
        _c5 = gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0, 100.0, 1e-12)
        if _c5[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[12])
        z_b_q_r = _c5[2]
        z_b_q_th = _c5[4]
        z_b_q_thd = _c5[5]
        z_lo_q_th = _c5[8]
        z_lo_q_thd = _c5[9]
    elif zeroth == 7.0:
        # zeroth iterate: Gravity correction type 5 (time-varying momentum)
        _c6 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
        if _c6[12] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c6[12])
        z_b_q_r = _c6[2]
        z_b_q_th = _c6[4]
        z_b_q_thd = _c6[5]
        z_lo_q_th = _c6[8]
        z_lo_q_thd = _c6[9]
    elif zeroth == 8.0:
        # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
        _c7 = geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0, 1e-12)
        if _c7[13] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c7[13])
        z_b_q_r = _c7[2]
        z_b_q_th = _c7[4]
        z_b_q_thd = _c7[5]
        z_lo_q_th = _c7[8]
        z_lo_q_thd = _c7[9]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # compression half, k_c (report 5.2.1)
    _c8 = schwind_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th, z_b_q_thd, nodes, iterations, tol)
    if _c8[6] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c8[6])
    t_bottom = _c8[0]
    bottom_q_r = _c8[1]
    bottom_q_rd = _c8[2]
    bottom_q_th = _c8[3]
    bottom_q_thd = _c8[4]
    c_passes = _c8[5]
    # zeroth iterate at liftoff
    _x5 = (zeroth == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x5 else (z_lo_q_th))
    g_lo_q_thd = ((bottom_q_r**2*bottom_q_thd/q_r_lo**2) if _x5 else (z_lo_q_thd))
    # decompression half, k_d (report 3.2, 5.2.2)
    _c9 = schwind_decompression(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, nodes, iterations, tol)
    if _c9[6] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c9[6])
    t_decompression = _c9[0]
    liftoff_q_r = _c9[1]
    liftoff_q_rd = _c9[2]
    liftoff_q_th = _c9[3]
    liftoff_q_thd = _c9[4]
    d_passes = _c9[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_stance`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 11)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes.
    """
    for i in prange(out.shape[0]):
        res = iterative_stance(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth)
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        out[i, 4] = res[4]
        out[i, 5] = res[5]
        out[i, 6] = res[6]
        out[i, 7] = res[7]
        out[i, 8] = res[8]
        out[i, 9] = res[9]
        out[i, 10] = res[10]
        status[i] = res[11]


@njit(cache=True, error_model="numpy")
def iterative_apex_return(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground [m]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs

    Returns a tuple:
        apex_height: next apex height above the ground the foot stood on [m]
        apex_speed: next apex horizontal speed (signed) [m/s]
        t_descent: flight time from the apex to touchdown [s]
        t_stance: stance time, touchdown to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        step_length: horizontal distance from the apex to the next apex (signed) [m]
        foot_x: horizontal position of the foot at touchdown relative to the apex [m]
        foot_y: height of the foot (the touchdown ground) relative to the apex: ground - apex height [m]
        passes: Picard passes run (the larger of the two halves) [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[6])
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = iterative_stance(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth)
    if _c1[11] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[11])
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[5])
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y) and math.isfinite(passes)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_apex_return`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 13)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, passes.
    """
    for i in prange(out.shape[0]):
        res = iterative_apex_return(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth)
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        out[i, 4] = res[4]
        out[i, 5] = res[5]
        out[i, 6] = res[6]
        out[i, 7] = res[7]
        out[i, 8] = res[8]
        out[i, 9] = res[9]
        out[i, 10] = res[10]
        out[i, 11] = res[11]
        out[i, 12] = res[12]
        status[i] = res[13]
