# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:8b20bd5230ccfe19
#   geyer.py sha256:4737273d6d8636d4
#   geyer_vs.py sha256:2af0829e07a0cf1b
#   gravity_type0.py sha256:307fd5b7e0072824
#   gravity_type1.py sha256:46607008446ed15d
#   gravity_type2.py sha256:97fb4f568b945f42
#   gravity_type3.py sha256:d4ac1d04e125ac4a
#   gravity_type4.py sha256:81186cbbb1247b9f
#   gravity_type5.py sha256:f4510b5010050beb
# ----------------------------------------------------------------------------------------------
"""Iterative stance map (Schwind and Koditschek, converging form) (report section 5.2): stance, state-at-time
and apex-return kernels."""

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

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED,
    STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN6 = (NAN,) * 6
_NAN11 = (NAN,) * 11
_NAN13 = (NAN,) * 13


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r).

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
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 277
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
            > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
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
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = -0.9951792190105739*_D - _x0
        _x43 = (1.0/_x1)
        _x2 = k_c*l0
        _x3 = g_s*m
        _x4 = _x3*math.cos(_Q0)
        _x5 = _x1*k_c
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x8 = _x43**3
        _x9 = _x6*_x7*_x8
        _x10 = -0.8910937442931661*_D - _x0
        _x44 = (1.0/_x10)
        _x11 = _x3*math.cos(_Q1)
        _x12 = _x10*k_c
        _x13 = _P1**2
        _x14 = _x44**3
        _x15 = _x13*_x14*_x7
        _x16 = -0.5511127007083099*_D - _x0
        _x45 = (1.0/_x16)
        _x17 = math.cos(_Q2)
        _x18 = _x17*_x3
        _x19 = _x16*k_c
        _x20 = _P2**2
        _x21 = _x45**3
        _x22 = _x20*_x21*_x7
        _x23 = -0.13404290741652142*_D - _x0
        _x46 = (1.0/_x23)
        _x24 = math.cos(_Q3)
        _x25 = _x24*_x3
        _x26 = _x23*k_c
        _x27 = _P3**2
        _x28 = _x46**3
        _x29 = _x27*_x28*_x7
        _x30 = (0.12383458041329967*_x11 + 0.12383458041329967*_x12 - 0.12383458041329967*_x15
            - 0.0575898635297681*_x18 - 0.0575898635297681*_x19 + 0.5*_x2 + 0.0575898635297681*_x22
            + 0.016129321407969507*_x25 + 0.016129321407969507*_x26 - 0.016129321407969507*_x29
            - 0.582374038291501*_x4 - 0.582374038291501*_x5 + 0.582374038291501*_x9)
        _x31 = (1.0/math.sqrt(_x30))
        _x32 = math.sqrt(_D)
        _x33 = math.sqrt(m)
        _x34 = _x32*_x33
        _x35 = _x32/_x33
        _x36 = _x32*g_s*(m*math.sqrt(m))
        _x37 = (-0.39252437029865583*_x11 - 0.39252437029865583*_x12 + 0.39252437029865583*_x13*_x14*_x7
            + 0.0700094015044783*_x16*k_c + 0.0700094015044783*_x17*g_s*m - 0.0700094015044783*_x22
            - 0.017475652789475504*_x25 - 0.017475652789475504*_x26 + 0.017475652789475504*_x27*_x28*_x7
            - 0.16000937841634696*_x4 - 0.16000937841634696*_x5 + 0.16000937841634696*_x6*_x7*_x8
            + 0.5*k_c*l0)
        _x38 = (1.0/math.sqrt(_x37))
        _x39 = (-0.2848443432415939*_x11 - 0.2848443432415939*_x12 + 0.2848443432415939*_x13*_x14*_x7
            - 0.21871326539550162*_x18 - 0.21871326539550162*_x19 + 0.21871326539550162*_x20*_x21*_x7
            + 0.019694864101090868*_x23*k_c + 0.019694864101090868*_x24*g_s*m - 0.019694864101090868*_x29
            - 0.01613725546399532*_x4 - 0.01613725546399532*_x5 + 0.01613725546399532*_x6*_x7*_x8
            + 0.5*k_c*l0)
        _x40 = (1.0/math.sqrt(_x39))
        _x41 = (-0.11000222456933441*_x11 - 0.11000222456933441*_x12 + 0.11000222456933441*_x13*_x14*_x7
            - 0.2823150697454702*_x18 - 0.2823150697454702*_x19 + 0.2823150697454702*_x20*_x21*_x7
            - 0.08972165934767481*_x25 - 0.08972165934767481*_x26 + 0.08972165934767481*_x27*_x28*_x7
            - 0.01796104633752054*_x4 - 0.01796104633752054*_x5 + 0.01796104633752054*_x6*_x7*_x8
            + 0.5*k_c*l0)
        _x42 = (1.0/math.sqrt(_x41))
        _isigma0 = _x1
        _iF0 = _x2 - _x4 - _x5 + _x9
        _isigma1 = _x10
        _iF1 = -_x11 - _x12 + _x15 + _x2
        _isigma2 = _x16
        _iF2 = -_x18 - _x19 + _x2 + _x22
        _isigma3 = _x23
        _iF3 = _x2 - _x25 - _x26 + _x29
        _iPsi0 = _x30
        _ift0 = _x31*_x34
        _ifq0 = _P0*_x31*_x35*_x43**2
        _ifp0 = _x1*_x31*_x36*math.sin(_Q0)
        _iPsi1 = _x37
        _ift1 = _x34*_x38
        _ifq1 = _P1*_x35*_x38*_x44**2
        _ifp1 = _x10*_x36*_x38*math.sin(_Q1)
        _iPsi2 = _x39
        _ift2 = _x34*_x40
        _ifq2 = _P2*_x35*_x40*_x45**2
        _ifp2 = _x16*_x36*_x40*math.sin(_Q2)
        _iPsi3 = _x41
        _ift3 = _x34*_x42
        _ifq3 = _P3*_x35*_x42*_x46**2
        _ifp3 = _x23*_x36*_x42*math.sin(_Q3)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = (m*q_rd**2/(0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 - 0.024152203412833244*k_c*(-_isigma0 + l0)
            - 0.215214082271785*k_c*(-_isigma1 + l0) - 0.43693107259076114*k_c*(-_isigma2 + l0)
            - 0.3237026417246206*k_c*(-_isigma3 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2
            + (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 - 0.024152203412833244*k_c*(-_isigma0 + l0)
            - 0.215214082271785*k_c*(-_isigma1 + l0) - 0.43693107259076114*k_c*(-_isigma2 + l0)
            - 0.3237026417246206*k_c*(-_isigma3 + l0) + k_c*(l0 - q_r))**2)))
        _n0_1 = (0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2
            + 0.1774825722545226*_ifq3 + q_th)
        _n0_2 = (-0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2
            + 0.16719192197418878*_ifq3 + q_th)
        _n0_3 = (0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2
            + 0.18811811749986806*_ifq3 + q_th)
        _n0_4 = (-0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _n0_5 = (0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2
            + 0.1774825722545226*_ifp3 + m*q_r**2*q_thd)
        _n0_6 = (-0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2
            + 0.16719192197418878*_ifp3 + m*q_r**2*q_thd)
        _n0_7 = (0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2
            + 0.18811811749986806*_ifp3 + m*q_r**2*q_thd)
        _n0_8 = (-0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2
            + 0.08696371128436346*_ifp3 + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_7 - _P2) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _passes += 1.0
    # bottom state
    _x47 = -_D + q_r
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    end_q_r = _x47
    end_q_rd = 0.0
    end_q_thd = ((0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + m*q_r**2*q_thd)/(_x47**2*m))
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_4(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r).

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
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

    Returns a tuple:
        t_half: time of the decompression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 285
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
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
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.004820780989426014*_D + q_r
        _x42 = (1.0/_x0)
        _x1 = k_d*l0
        _x2 = g_s*m
        _x3 = _x2*math.cos(_Q0)
        _x4 = _x0*k_d
        _x5 = _P0**2
        _x6 = (1.0/m)
        _x7 = _x42**3
        _x8 = _x5*_x6*_x7
        _x9 = 0.10890625570683385*_D + q_r
        _x45 = (1.0/_x9)
        _x10 = _x2*math.cos(_Q1)
        _x11 = _x9*k_d
        _x12 = _P1**2
        _x13 = _x45**3
        _x14 = _x12*_x13*_x6
        _x15 = 0.44888729929169013*_D + q_r
        _x43 = (1.0/_x15)
        _x16 = math.cos(_Q2)
        _x17 = _x16*_x2
        _x18 = _x15*k_d
        _x19 = _P2**2
        _x20 = _x43**3
        _x21 = _x19*_x20*_x6
        _x22 = 0.8659570925834786*_D + q_r
        _x44 = (1.0/_x22)
        _x23 = math.cos(_Q3)
        _x24 = _x2*_x23
        _x25 = _x22*k_d
        _x26 = _P3**2
        _x27 = _x44**3
        _x28 = _x26*_x27*_x6
        _x29 = (0.5*_x1 + 0.12383458041329967*_x10 + 0.12383458041329967*_x11 - 0.12383458041329967*_x14
            - 0.0575898635297681*_x17 - 0.0575898635297681*_x18 + 0.0575898635297681*_x21
            + 0.016129321407969507*_x24 + 0.016129321407969507*_x25 - 0.016129321407969507*_x28
            - 0.582374038291501*_x3 - 0.582374038291501*_x4 + 0.582374038291501*_x8)
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _x34 = _x31/_x32
        _x35 = _x31*g_s*(m*math.sqrt(m))
        _x36 = (-0.39252437029865583*_x10 - 0.39252437029865583*_x11 + 0.39252437029865583*_x12*_x13*_x6
            + 0.0700094015044783*_x15*k_d + 0.0700094015044783*_x16*g_s*m - 0.0700094015044783*_x21
            - 0.017475652789475504*_x24 - 0.017475652789475504*_x25 + 0.017475652789475504*_x26*_x27*_x6
            - 0.16000937841634696*_x3 - 0.16000937841634696*_x4 + 0.16000937841634696*_x5*_x6*_x7
            + 0.5*k_d*l0)
        _x37 = (1.0/math.sqrt(_x36))
        _x38 = (-0.2848443432415939*_x10 - 0.2848443432415939*_x11 + 0.2848443432415939*_x12*_x13*_x6
            - 0.21871326539550162*_x17 - 0.21871326539550162*_x18 + 0.21871326539550162*_x19*_x20*_x6
            + 0.019694864101090868*_x22*k_d + 0.019694864101090868*_x23*g_s*m - 0.019694864101090868*_x28
            - 0.01613725546399532*_x3 - 0.01613725546399532*_x4 + 0.01613725546399532*_x5*_x6*_x7
            + 0.5*k_d*l0)
        _x39 = (1.0/math.sqrt(_x38))
        _x40 = (-0.11000222456933441*_x10 - 0.11000222456933441*_x11 + 0.11000222456933441*_x12*_x13*_x6
            - 0.2823150697454702*_x17 - 0.2823150697454702*_x18 + 0.2823150697454702*_x19*_x20*_x6
            - 0.08972165934767481*_x24 - 0.08972165934767481*_x25 + 0.08972165934767481*_x26*_x27*_x6
            - 0.01796104633752054*_x3 - 0.01796104633752054*_x4 + 0.01796104633752054*_x5*_x6*_x7
            + 0.5*k_d*l0)
        _x41 = (1.0/math.sqrt(_x40))
        _isigma0 = _x0
        _iF0 = _x1 - _x3 - _x4 + _x8
        _isigma1 = _x9
        _iF1 = _x1 - _x10 - _x11 + _x14
        _isigma2 = _x15
        _iF2 = _x1 - _x17 - _x18 + _x21
        _isigma3 = _x22
        _iF3 = _x1 - _x24 - _x25 + _x28
        _iPsi0 = _x29
        _ift0 = _x30*_x33
        _ifq0 = _P0*_x30*_x34*_x42**2
        _ifp0 = _x0*_x30*_x35*math.sin(_Q0)
        _iPsi1 = _x36
        _ift1 = _x33*_x37
        _ifq1 = _P1*_x34*_x37*_x45**2
        _ifp1 = _x35*_x37*_x9*math.sin(_Q1)
        _iPsi2 = _x38
        _ift2 = _x33*_x39
        _ifq2 = _P2*_x34*_x39*_x43**2
        _ifp2 = _x15*_x35*_x39*math.sin(_Q2)
        _iPsi3 = _x40
        _ift3 = _x33*_x41
        _ifq3 = _P3*_x34*_x41*_x44**2
        _ifp3 = _x22*_x35*_x41*math.sin(_Q3)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _D
        _n0_1 = (0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2
            - 0.0035551496857956833*_ifq3 + q_th)
        _n0_2 = (0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2
            + 0.006735500594538156*_ifq3 + q_th)
        _n0_3 = (0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2
            - 0.014190694931141144*_ifq3 + q_th)
        _n0_4 = (0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _n0_5 = (0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2
            - 0.0035551496857956833*_ifp3 + m*q_r**2*q_thd)
        _n0_6 = (0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2
            + 0.006735500594538156*_ifp3 + m*q_r**2*q_thd)
        _n0_7 = (0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2
            - 0.014190694931141144*_ifp3 + m*q_r**2*q_thd)
        _n0_8 = (0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2
            + 0.08696371128436346*_ifp3 + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_7 - _P2) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _passes += 1.0
    _work = (0.012076101706416622*_iF0 + 0.1076070411358925*_iF1 + 0.21846553629538057*_iF2
        + 0.1618513208623103*_iF3)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    end_q_r = q_r_lo
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    end_q_thd = ((0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + m*q_r**2*q_thd)/(m*q_r_lo**2))
    passes = _passes
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_1(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`schwind_compression_nodes_4`'s.
    """
    # Total ops: 53
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
            > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 1 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
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
        _ifp0 = _x0*_x7*g_s*(m*math.sqrt(m))*math.sin(_Q0)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = (m*q_rd**2/(1.0*_iF0 - 1.0*k_c*(-_isigma0 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2
            + (1.0*_iF0 - 1.0*k_c*(-_isigma0 + l0) + k_c*(l0 - q_r))**2)))
        _n0_1 = 0.5*_ifq0 + q_th
        _n0_2 = 0.5*_ifp0 + m*q_r**2*q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _passes += 1.0
    # bottom state
    _x9 = -_D + q_r
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    end_q_r = _x9
    end_q_rd = 0.0
    end_q_thd = (1.0*_ifp0 + m*q_r**2*q_thd)/(_x9**2*m)
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: the same as :func:`schwind_decompression_nodes_4`'s.
    """
    # Total ops: 60
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
    # Picard passes on the 1 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
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
        _ifp0 = _x0*_x7*g_s*(m*math.sqrt(m))*math.sin(_Q0)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _D
        _n0_1 = 0.5*_ifq0 + q_th
        _n0_2 = 0.5*_ifp0 + m*q_r**2*q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _passes += 1.0
    _work = 0.5*_iF0
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    end_q_r = q_r_lo
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    end_q_thd = (1.0*_ifp0 + m*q_r**2*q_thd)/(m*q_r_lo**2)
    passes = _passes
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_2(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`schwind_compression_nodes_4`'s.
    """
    # Total ops: 115
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
            > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 2 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _Q1 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _P0 = 0.7886751345948129*guess_q_r**2*guess_q_thd*m + 0.2113248654051871*m*q_r**2*q_thd
    _P1 = 0.2113248654051871*guess_q_r**2*guess_q_thd*m + 0.7886751345948129*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = -0.9553418012614795*_D - _x0
        _x25 = (1.0/_x1)
        _x2 = k_c*l0
        _x3 = g_s*m
        _x4 = _x3*math.cos(_Q0)
        _x5 = _x1*k_c
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x8 = _x25**3
        _x9 = _x6*_x7*_x8
        _x10 = -0.37799153207185376*_D - _x0
        _x26 = (1.0/_x10)
        _x11 = _x3*math.cos(_Q1)
        _x12 = _x10*k_c
        _x13 = _P1**2
        _x14 = _x26**3
        _x15 = _x13*_x14*_x7
        _x16 = (0.06100423396407311*_x11 + 0.06100423396407311*_x12 - 0.06100423396407311*_x15 + 0.5*_x2
            - 0.5610042339640731*_x4 - 0.5610042339640731*_x5 + 0.5610042339640731*_x9)
        _x17 = (1.0/math.sqrt(_x16))
        _x18 = math.sqrt(_D)
        _x19 = math.sqrt(m)
        _x20 = _x18*_x19
        _x21 = _x18/_x19
        _x22 = _x18*g_s*(m*math.sqrt(m))
        _x23 = (-0.27232909936926025*_x11 - 0.27232909936926025*_x12 + 0.27232909936926025*_x13*_x14*_x7
            - 0.22767090063073978*_x4 - 0.22767090063073978*_x5 + 0.22767090063073978*_x6*_x7*_x8
            + 0.5*k_c*l0)
        _x24 = (1.0/math.sqrt(_x23))
        _isigma0 = _x1
        _iF0 = _x2 - _x4 - _x5 + _x9
        _isigma1 = _x10
        _iF1 = -_x11 - _x12 + _x15 + _x2
        _iPsi0 = _x16
        _ift0 = _x17*_x20
        _ifq0 = _P0*_x17*_x21*_x25**2
        _ifp0 = _x1*_x17*_x22*math.sin(_Q0)
        _iPsi1 = _x23
        _ift1 = _x20*_x24
        _ifq1 = _P1*_x21*_x24*_x26**2
        _ifp1 = _x10*_x22*_x24*math.sin(_Q1)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = (m*q_rd**2/(0.2113248654051871*_iF0 + 0.7886751345948129*_iF1
            - 0.2113248654051871*k_c*(-_isigma0 + l0) - 0.7886751345948129*k_c*(-_isigma1 + l0) + k_c*(l0
            - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.2113248654051871*_iF0 + 0.7886751345948129*_iF1
            - 0.2113248654051871*k_c*(-_isigma0 + l0) - 0.7886751345948129*k_c*(-_isigma1 + l0) + k_c*(l0
            - q_r))**2)))
        _n0_1 = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
        _n0_2 = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
        _n0_3 = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + m*q_r**2*q_thd
        _n0_4 = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + m*q_r**2*q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _passes += 1.0
    # bottom state
    _x27 = -_D + q_r
    t_half = 0.5*_ift0 + 0.5*_ift1
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    end_q_r = _x27
    end_q_rd = 0.0
    end_q_thd = (0.5*_ifp0 + 0.5*_ifp1 + m*q_r**2*q_thd)/(_x27**2*m)
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_2(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: the same as :func:`schwind_decompression_nodes_4`'s.
    """
    # Total ops: 121
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
    # Picard passes on the 2 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _Q1 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _P0 = 0.2113248654051871*guess_q_thd*m*q_r_lo**2 + 0.7886751345948129*m*q_r**2*q_thd
    _P1 = 0.7886751345948129*guess_q_thd*m*q_r_lo**2 + 0.2113248654051871*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.04465819873852045*_D + q_r
        _x24 = (1.0/_x0)
        _x1 = k_d*l0
        _x2 = g_s*m
        _x3 = _x2*math.cos(_Q0)
        _x4 = _x0*k_d
        _x5 = _P0**2
        _x6 = (1.0/m)
        _x7 = _x24**3
        _x8 = _x5*_x6*_x7
        _x9 = 0.6220084679281462*_D + q_r
        _x25 = (1.0/_x9)
        _x10 = _x2*math.cos(_Q1)
        _x11 = _x9*k_d
        _x12 = _P1**2
        _x13 = _x25**3
        _x14 = _x12*_x13*_x6
        _x15 = (0.5*_x1 + 0.06100423396407311*_x10 + 0.06100423396407311*_x11 - 0.06100423396407311*_x14
            - 0.5610042339640731*_x3 - 0.5610042339640731*_x4 + 0.5610042339640731*_x8)
        _x16 = (1.0/math.sqrt(_x15))
        _x17 = math.sqrt(_D)
        _x18 = math.sqrt(m)
        _x19 = _x17*_x18
        _x20 = _x17/_x18
        _x21 = _x17*g_s*(m*math.sqrt(m))
        _x22 = (-0.27232909936926025*_x10 - 0.27232909936926025*_x11 + 0.27232909936926025*_x12*_x13*_x6
            - 0.22767090063073978*_x3 - 0.22767090063073978*_x4 + 0.22767090063073978*_x5*_x6*_x7
            + 0.5*k_d*l0)
        _x23 = (1.0/math.sqrt(_x22))
        _isigma0 = _x0
        _iF0 = _x1 - _x3 - _x4 + _x8
        _isigma1 = _x9
        _iF1 = _x1 - _x10 - _x11 + _x14
        _iPsi0 = _x15
        _ift0 = _x16*_x19
        _ifq0 = _P0*_x16*_x20*_x24**2
        _ifp0 = _x0*_x16*_x21*math.sin(_Q0)
        _iPsi1 = _x22
        _ift1 = _x19*_x23
        _ifq1 = _P1*_x20*_x23*_x25**2
        _ifp1 = _x21*_x23*_x9*math.sin(_Q1)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _D
        _n0_1 = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
        _n0_2 = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
        _n0_3 = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + m*q_r**2*q_thd
        _n0_4 = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + m*q_r**2*q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _passes += 1.0
    _work = 0.10566243270259355*_iF0 + 0.39433756729740643*_iF1
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.5*_ift0 + 0.5*_ift1
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    end_q_r = q_r_lo
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    end_q_thd = (0.5*_ifp0 + 0.5*_ifp1 + m*q_r**2*q_thd)/(m*q_r_lo**2)
    passes = _passes
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`schwind_compression_nodes_4`'s.
    """
    # Total ops: 180
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
            > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 3 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _P0 = 0.8872983346207417*guess_q_r**2*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _P2 = 0.11270166537925831*guess_q_r**2*guess_q_thd*m + 0.8872983346207417*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = -0.9872983346207417*_D - _x0
        _x33 = (1.0/_x1)
        _x2 = k_c*l0
        _x3 = g_s*m
        _x4 = _x3*math.cos(_Q0)
        _x5 = _x1*k_c
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x8 = _x33**3
        _x9 = _x6*_x7*_x8
        _x10 = -0.75*_D - _x0
        _x34 = (1.0/_x10)
        _x11 = _x3*math.cos(_Q1)
        _x12 = _x10*k_c
        _x13 = _P1**2
        _x14 = _x34**3
        _x15 = _x13*_x14*_x7
        _x16 = -0.2127016653792583*_D - _x0
        _x35 = (1.0/_x16)
        _x17 = _x3*math.cos(_Q2)
        _x18 = _x16*k_c
        _x19 = _P2**2
        _x20 = _x35**3
        _x21 = _x19*_x20*_x7
        _x22 = (0.1040546303448565*_x11 + 0.1040546303448565*_x12 - 0.1040546303448565*_x15
            - 0.027777777777777776*_x17 - 0.027777777777777776*_x18 + 0.5*_x2 + 0.027777777777777776*_x21
            - 0.5762768525670787*_x4 - 0.5762768525670787*_x5 + 0.5762768525670787*_x9)
        _x23 = (1.0/math.sqrt(_x22))
        _x24 = math.sqrt(_D)
        _x25 = math.sqrt(m)
        _x26 = _x24*_x25
        _x27 = _x24/_x25
        _x28 = _x24*g_s*(m*math.sqrt(m))
        _x29 = (-0.3611111111111111*_x11 - 0.3611111111111111*_x12 + 0.3611111111111111*_x15
            + 0.038138426283539355*_x17 + 0.038138426283539355*_x18 + 0.5*_x2 - 0.038138426283539355*_x21
            - 0.17702731517242826*_x4 - 0.17702731517242826*_x5 + 0.17702731517242826*_x9)
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = (-0.3262768525670787*_x11 - 0.3262768525670787*_x12 + 0.3262768525670787*_x13*_x14*_x7
            - 0.14594536965514351*_x17 - 0.14594536965514351*_x18 + 0.14594536965514351*_x19*_x20*_x7
            - 0.027777777777777776*_x4 - 0.027777777777777776*_x5 + 0.027777777777777776*_x6*_x7*_x8
            + 0.5*k_c*l0)
        _x32 = (1.0/math.sqrt(_x31))
        _isigma0 = _x1
        _iF0 = _x2 - _x4 - _x5 + _x9
        _isigma1 = _x10
        _iF1 = -_x11 - _x12 + _x15 + _x2
        _isigma2 = _x16
        _iF2 = -_x17 - _x18 + _x2 + _x21
        _iPsi0 = _x22
        _ift0 = _x23*_x26
        _ifq0 = _P0*_x23*_x27*_x33**2
        _ifp0 = _x1*_x23*_x28*math.sin(_Q0)
        _iPsi1 = _x29
        _ift1 = _x26*_x30
        _ifq1 = _P1*_x27*_x30*_x34**2
        _ifp1 = _x10*_x28*_x30*math.sin(_Q1)
        _iPsi2 = _x31
        _ift2 = _x26*_x32
        _ifq2 = _P2*_x27*_x32*_x35**2
        _ifp2 = _x16*_x28*_x32*math.sin(_Q2)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = (m*q_rd**2/(0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2
            - 0.06261203632181017*k_c*(-_isigma0 + l0) - 0.4444444444444444*k_c*(-_isigma1 + l0)
            - 0.4929435192337454*k_c*(-_isigma2 + l0) + k_c*(l0 - q_r) + math.sqrt(k_c*m*q_rd**2
            + (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2
            - 0.06261203632181017*k_c*(-_isigma0 + l0) - 0.4444444444444444*k_c*(-_isigma1 + l0)
            - 0.4929435192337454*k_c*(-_isigma2 + l0) + k_c*(l0 - q_r))**2)))
        _n0_1 = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
        _n0_2 = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
        _n0_3 = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _n0_4 = (0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2
            + m*q_r**2*q_thd)
        _n0_5 = (-0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2
            + m*q_r**2*q_thd)
        _n0_6 = (0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2
            + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    # bottom state
    _x36 = -_D + q_r
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    end_q_r = _x36
    end_q_rd = 0.0
    end_q_thd = ((0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2
        + m*q_r**2*q_thd)/(_x36**2*m))
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_3(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: the same as :func:`schwind_decompression_nodes_4`'s.
    """
    # Total ops: 187
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
    # Picard passes on the 3 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _P0 = 0.11270166537925831*guess_q_thd*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _P2 = 0.8872983346207417*guess_q_thd*m*q_r_lo**2 + 0.11270166537925831*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.012701665379258311*_D + q_r
        _x32 = (1.0/_x0)
        _x1 = k_d*l0
        _x2 = g_s*m
        _x3 = _x2*math.cos(_Q0)
        _x4 = _x0*k_d
        _x5 = _P0**2
        _x6 = (1.0/m)
        _x7 = _x32**3
        _x8 = _x5*_x6*_x7
        _x9 = 0.25*_D + q_r
        _x34 = (1.0/_x9)
        _x10 = _x2*math.cos(_Q1)
        _x11 = _x9*k_d
        _x12 = _P1**2
        _x13 = _x34**3
        _x14 = _x12*_x13*_x6
        _x15 = 0.7872983346207417*_D + q_r
        _x33 = (1.0/_x15)
        _x16 = _x2*math.cos(_Q2)
        _x17 = _x15*k_d
        _x18 = _P2**2
        _x19 = _x33**3
        _x20 = _x18*_x19*_x6
        _x21 = (0.5*_x1 + 0.1040546303448565*_x10 + 0.1040546303448565*_x11 - 0.1040546303448565*_x14
            - 0.027777777777777776*_x16 - 0.027777777777777776*_x17 + 0.027777777777777776*_x20
            - 0.5762768525670787*_x3 - 0.5762768525670787*_x4 + 0.5762768525670787*_x8)
        _x22 = (1.0/math.sqrt(_x21))
        _x23 = math.sqrt(_D)
        _x24 = math.sqrt(m)
        _x25 = _x23*_x24
        _x26 = _x23/_x24
        _x27 = _x23*g_s*(m*math.sqrt(m))
        _x28 = (0.5*_x1 - 0.3611111111111111*_x10 - 0.3611111111111111*_x11 + 0.3611111111111111*_x14
            + 0.038138426283539355*_x16 + 0.038138426283539355*_x17 - 0.038138426283539355*_x20
            - 0.17702731517242826*_x3 - 0.17702731517242826*_x4 + 0.17702731517242826*_x8)
        _x29 = (1.0/math.sqrt(_x28))
        _x30 = (-0.3262768525670787*_x10 - 0.3262768525670787*_x11 + 0.3262768525670787*_x12*_x13*_x6
            - 0.14594536965514351*_x16 - 0.14594536965514351*_x17 + 0.14594536965514351*_x18*_x19*_x6
            - 0.027777777777777776*_x3 - 0.027777777777777776*_x4 + 0.027777777777777776*_x5*_x6*_x7
            + 0.5*k_d*l0)
        _x31 = (1.0/math.sqrt(_x30))
        _isigma0 = _x0
        _iF0 = _x1 - _x3 - _x4 + _x8
        _isigma1 = _x9
        _iF1 = _x1 - _x10 - _x11 + _x14
        _isigma2 = _x15
        _iF2 = _x1 - _x16 - _x17 + _x20
        _iPsi0 = _x21
        _ift0 = _x22*_x25
        _ifq0 = _P0*_x22*_x26*_x32**2
        _ifp0 = _x0*_x22*_x27*math.sin(_Q0)
        _iPsi1 = _x28
        _ift1 = _x25*_x29
        _ifq1 = _P1*_x26*_x29*_x34**2
        _ifp1 = _x27*_x29*_x9*math.sin(_Q1)
        _iPsi2 = _x30
        _ift2 = _x25*_x31
        _ifq2 = _P2*_x26*_x31*_x33**2
        _ifp2 = _x15*_x27*_x31*math.sin(_Q2)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _D
        _n0_1 = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
        _n0_2 = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
        _n0_3 = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _n0_4 = (0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2
            + m*q_r**2*q_thd)
        _n0_5 = (0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2
            + m*q_r**2*q_thd)
        _n0_6 = (0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2
            + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    _work = 0.031306018160905086*_iF0 + 0.2222222222222222*_iF1 + 0.2464717596168727*_iF2
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    end_q_r = q_r_lo
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    end_q_thd = ((0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2
        + m*q_r**2*q_thd)/(m*q_r_lo**2))
    passes = _passes
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_6(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`schwind_compression_nodes_4`'s.
    """
    # Total ops: 501
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
            > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
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
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = -0.9988599083720104*_D - _x0
        _x63 = (1.0/_x1)
        _x2 = k_c*l0
        _x3 = g_s*m
        _x4 = _x3*math.cos(_Q0)
        _x5 = _x1*k_c
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x8 = _x63**3
        _x9 = _x6*_x7*_x8
        _x10 = -0.9713052300453587*_D - _x0
        _x64 = (1.0/_x10)
        _x11 = _x3*math.cos(_Q1)
        _x12 = _x10*k_c
        _x13 = _P1**2
        _x14 = _x64**3
        _x15 = _x13*_x14*_x7
        _x16 = -0.8550748140498466*_D - _x0
        _x65 = (1.0/_x16)
        _x17 = math.cos(_Q2)
        _x18 = _x17*_x3
        _x19 = _x16*k_c
        _x20 = _P2**2
        _x21 = _x65**3
        _x22 = _x20*_x21*_x7
        _x23 = -0.6164556279666497*_D - _x0
        _x66 = (1.0/_x23)
        _x24 = math.cos(_Q3)
        _x25 = _x24*_x3
        _x26 = _x23*k_c
        _x27 = _P3**2
        _x28 = _x66**3
        _x29 = _x27*_x28*_x7
        _x30 = -0.31009584357909425*_D - _x0
        _x67 = (1.0/_x30)
        _x31 = math.cos(_Q4)
        _x32 = _x3*_x31
        _x33 = _x30*k_c
        _x34 = _P4**2
        _x35 = _x67**3
        _x36 = _x34*_x35*_x7
        _x37 = -0.0663903941688584*_D - _x0
        _x68 = (1.0/_x37)
        _x38 = math.cos(_Q5)
        _x39 = _x3*_x38
        _x40 = _x37*k_c
        _x41 = _P5**2
        _x42 = _x68**3
        _x43 = _x41*_x42*_x7
        _x44 = (0.140380692261653*_x11 + 0.140380692261653*_x12 - 0.140380692261653*_x15
            - 0.08683151831711133*_x18 - 0.08683151831711133*_x19 + 0.5*_x2 + 0.08683151831711133*_x22
            + 0.052466581536012566*_x25 + 0.052466581536012566*_x26 - 0.052466581536012566*_x29
            - 0.026354606039126004*_x32 - 0.026354606039126004*_x33 + 0.026354606039126004*_x36
            + 0.007496884624381081*_x39 - 0.5871580340658094*_x4 + 0.007496884624381081*_x40
            - 0.007496884624381081*_x43 - 0.5871580340658094*_x5 + 0.5871580340658094*_x9)
        _x45 = (1.0/math.sqrt(_x44))
        _x46 = math.sqrt(_D)
        _x47 = math.sqrt(m)
        _x48 = _x46*_x47
        _x49 = _x46/_x47
        _x50 = _x46*g_s*(m*math.sqrt(m))
        _x51 = -0.5*k_c*l0
        _x52 = (-0.41567911405660357*_x11 - 0.41567911405660357*_x12 + 0.41567911405660357*_x13*_x14*_x7
            + 0.09720828549085844*_x16*k_c + 0.09720828549085844*_x17*g_s*m - 0.09720828549085844*_x22
            - 0.05155355009455148*_x25 - 0.05155355009455148*_x26 + 0.05155355009455148*_x27*_x28*_x7
            + 0.024719229415033087*_x30*k_c + 0.024719229415033087*_x31*g_s*m - 0.024719229415033087*_x36
            - 0.006904529857608445*_x39 - 0.147790320897128*_x4 - 0.006904529857608445*_x40
            + 0.006904529857608445*_x41*_x42*_x7 - 0.147790320897128*_x5 - _x51
            + 0.147790320897128*_x6*_x7*_x8)
        _x53 = (1.0/math.sqrt(_x52))
        _x54 = (-0.25540525119175433*_x11 - 0.25540525119175433*_x12 + 0.25540525119175433*_x13*_x14*_x7
            - 0.2685463444140672*_x18 - 0.2685463444140672*_x19 + 0.2685463444140672*_x20*_x21*_x7
            + 0.048794612428541204*_x23*k_c + 0.048794612428541204*_x24*g_s*m - 0.048794612428541204*_x29
            - 0.01951903325298492*_x32 - 0.01951903325298492*_x33 + 0.01951903325298492*_x34*_x35*_x7
            + 0.005119803152246505*_x37*k_c + 0.005119803152246505*_x38*g_s*m - 0.010443786721981197*_x4
            - 0.005119803152246505*_x43 - 0.010443786721981197*_x5 - _x51 + 0.010443786721981197*_x6*_x7*_x8)
        _x55 = (1.0/math.sqrt(_x54))
        _x56 = -0.5*k_c*l0
        _x57 = (-0.0662099828438604*_x11 - 0.0662099828438604*_x12 + 0.0662099828438604*_x13*_x14*_x7
            - 0.2671819482314443*_x18 - 0.2671819482314443*_x19 + 0.2671819482314443*_x20*_x21*_x7
            - 0.1742495636223592*_x25 - 0.1742495636223592*_x26 + 0.1742495636223592*_x27*_x28*_x7
            + 0.02396692958086051*_x30*k_c + 0.02396692958086051*_x31*g_s*m - 0.02396692958086051*_x36
            - 0.00530703852813994*_x39 - 0.01101839635505667*_x4 - 0.00530703852813994*_x40
            + 0.00530703852813994*_x41*_x42*_x7 - 0.01101839635505667*_x5 - _x56
            + 0.01101839635505667*_x6*_x7*_x8)
        _x58 = (1.0/math.sqrt(_x57))
        _x59 = (-0.050345455482979015*_x11 - 0.050345455482979015*_x12 + 0.050345455482979015*_x13*_x14*_x7
            - 0.11622097556712797*_x18 - 0.11622097556712797*_x19 + 0.11622097556712797*_x20*_x21*_x7
            - 0.2353986790647292*_x25 - 0.2353986790647292*_x26 + 0.2353986790647292*_x27*_x28*_x7
            - 0.10372825048336794*_x32 - 0.10372825048336794*_x33 + 0.10372825048336794*_x34*_x35*_x7
            + 0.008208158304657426*_x37*k_c + 0.008208158304657426*_x38*g_s*m - 0.0025147977064533143*_x4
            - 0.008208158304657426*_x43 - 0.0025147977064533143*_x5 - _x51
            + 0.0025147977064533143*_x6*_x7*_x8)
        _x60 = (1.0/math.sqrt(_x59))
        _x61 = (-0.029703284805013122*_x11 - 0.029703284805013122*_x12 + 0.029703284805013122*_x13*_x14*_x7
            - 0.10140664131431479*_x18 - 0.10140664131431479*_x19 + 0.10140664131431479*_x20*_x21*_x7
            - 0.14531313573962065*_x25 - 0.14531313573962065*_x26 + 0.14531313573962065*_x27*_x28*_x7
            - 0.17612158869639333*_x32 - 0.17612158869639333*_x33 + 0.17612158869639333*_x34*_x35*_x7
            - 0.04349583621493557*_x39 - 0.003959513229722528*_x4 - 0.04349583621493557*_x40
            + 0.04349583621493557*_x41*_x42*_x7 - 0.003959513229722528*_x5 - _x56
            + 0.003959513229722528*_x6*_x7*_x8)
        _x62 = (1.0/math.sqrt(_x61))
        _isigma0 = _x1
        _iF0 = _x2 - _x4 - _x5 + _x9
        _isigma1 = _x10
        _iF1 = -_x11 - _x12 + _x15 + _x2
        _isigma2 = _x16
        _iF2 = -_x18 - _x19 + _x2 + _x22
        _isigma3 = _x23
        _iF3 = _x2 - _x25 - _x26 + _x29
        _isigma4 = _x30
        _iF4 = _x2 - _x32 - _x33 + _x36
        _isigma5 = _x37
        _iF5 = _x2 - _x39 - _x40 + _x43
        _iPsi0 = _x44
        _ift0 = _x45*_x48
        _ifq0 = _P0*_x45*_x49*_x63**2
        _ifp0 = _x1*_x45*_x50*math.sin(_Q0)
        _iPsi1 = _x52
        _ift1 = _x48*_x53
        _ifq1 = _P1*_x49*_x53*_x64**2
        _ifp1 = _x10*_x50*_x53*math.sin(_Q1)
        _iPsi2 = _x54
        _ift2 = _x48*_x55
        _ifq2 = _P2*_x49*_x55*_x65**2
        _ifp2 = _x16*_x50*_x55*math.sin(_Q2)
        _iPsi3 = _x57
        _ift3 = _x48*_x58
        _ifq3 = _P3*_x49*_x58*_x66**2
        _ifp3 = _x23*_x50*_x58*math.sin(_Q3)
        _iPsi4 = _x59
        _ift4 = _x48*_x60
        _ifq4 = _P4*_x49*_x60*_x67**2
        _ifp4 = _x30*_x50*_x60*math.sin(_Q4)
        _iPsi5 = _x61
        _ift5 = _x48*_x62
        _ifq5 = _P5*_x49*_x62*_x68**2
        _ifp5 = _x37*_x50*_x62*math.sin(_Q5)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = (m*q_rd**2/(0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2
            + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5
            - 0.005784813099631875*k_c*(-_isigma0 + l0) - 0.06111131733618721*k_c*(-_isigma1 + l0)
            - 0.17813034617398463*k_c*(-_isigma2 + l0) - 0.28978358839870644*k_c*(-_isigma3 + l0)
            - 0.2996502557119514*k_c*(-_isigma4 + l0) - 0.16553967927953847*k_c*(-_isigma5 + l0) + k_c*(l0
            - q_r) + math.sqrt(k_c*m*q_rd**2 + (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1
            + 0.17813034617398463*_iF2 + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4
            + 0.16553967927953847*_iF5 - 0.005784813099631875*k_c*(-_isigma0 + l0)
            - 0.06111131733618721*k_c*(-_isigma1 + l0) - 0.17813034617398463*k_c*(-_isigma2 + l0)
            - 0.28978358839870644*k_c*(-_isigma3 + l0) - 0.2996502557119514*k_c*(-_isigma4 + l0)
            - 0.16553967927953847*k_c*(-_isigma5 + l0) + k_c*(l0 - q_r))**2)))
        _n0_1 = (0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2
            + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th)
        _n0_2 = (-0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2
            + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th)
        _n0_3 = (0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2
            + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th)
        _n0_4 = (-0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2
            + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th)
        _n0_5 = (0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2
            - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th)
        _n0_6 = (-0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2
            + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _n0_7 = (0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2
            + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5
            + m*q_r**2*q_thd)
        _n0_8 = (-0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2
            + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5
            + m*q_r**2*q_thd)
        _n0_9 = (0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2
            + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5
            + m*q_r**2*q_thd)
        _n0_10 = (-0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2
            + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5
            + m*q_r**2*q_thd)
        _n0_11 = (0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2
            - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5
            + m*q_r**2*q_thd)
        _n0_12 = (-0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2
            + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5
            + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_8 - _P1) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_9 - _P2) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_10 - _P3) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_11 - _P4) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_12 - _P5) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _Q4 = _n0_5
        _Q5 = _n0_6
        _P0 = _n0_7
        _P1 = _n0_8
        _P2 = _n0_9
        _P3 = _n0_10
        _P4 = _n0_11
        _P5 = _n0_12
        _passes += 1.0
    # bottom state
    _x69 = -_D + q_r
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    end_q_r = _x69
    end_q_rd = 0.0
    end_q_thd = ((0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5
        + m*q_r**2*q_thd)/(_x69**2*m))
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_6(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
        iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r).

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: the same as :func:`schwind_decompression_nodes_4`'s.
    """
    # Total ops: 511
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
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
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.0011400916279895713*_D + q_r
        _x62 = (1.0/_x0)
        _x1 = k_d*l0
        _x2 = g_s*m
        _x3 = _x2*math.cos(_Q0)
        _x4 = _x0*k_d
        _x5 = _P0**2
        _x6 = (1.0/m)
        _x7 = _x62**3
        _x8 = _x5*_x6*_x7
        _x9 = 0.02869476995464123*_D + q_r
        _x67 = (1.0/_x9)
        _x10 = _x2*math.cos(_Q1)
        _x11 = _x9*k_d
        _x12 = _P1**2
        _x13 = _x67**3
        _x14 = _x12*_x13*_x6
        _x15 = 0.14492518595015338*_D + q_r
        _x63 = (1.0/_x15)
        _x16 = math.cos(_Q2)
        _x17 = _x16*_x2
        _x18 = _x15*k_d
        _x19 = _P2**2
        _x20 = _x63**3
        _x21 = _x19*_x20*_x6
        _x22 = 0.3835443720333503*_D + q_r
        _x64 = (1.0/_x22)
        _x23 = math.cos(_Q3)
        _x24 = _x2*_x23
        _x25 = _x22*k_d
        _x26 = _P3**2
        _x27 = _x64**3
        _x28 = _x26*_x27*_x6
        _x29 = 0.6899041564209057*_D + q_r
        _x65 = (1.0/_x29)
        _x30 = math.cos(_Q4)
        _x31 = _x2*_x30
        _x32 = _x29*k_d
        _x33 = _P4**2
        _x34 = _x65**3
        _x35 = _x33*_x34*_x6
        _x36 = 0.9336096058311416*_D + q_r
        _x66 = (1.0/_x36)
        _x37 = math.cos(_Q5)
        _x38 = _x2*_x37
        _x39 = _x36*k_d
        _x40 = _P5**2
        _x41 = _x66**3
        _x42 = _x40*_x41*_x6
        _x43 = (0.5*_x1 + 0.140380692261653*_x10 + 0.140380692261653*_x11 - 0.140380692261653*_x14
            - 0.08683151831711133*_x17 - 0.08683151831711133*_x18 + 0.08683151831711133*_x21
            + 0.052466581536012566*_x24 + 0.052466581536012566*_x25 - 0.052466581536012566*_x28
            - 0.5871580340658094*_x3 - 0.026354606039126004*_x31 - 0.026354606039126004*_x32
            + 0.026354606039126004*_x35 + 0.007496884624381081*_x38 + 0.007496884624381081*_x39
            - 0.5871580340658094*_x4 - 0.007496884624381081*_x42 + 0.5871580340658094*_x8)
        _x44 = (1.0/math.sqrt(_x43))
        _x45 = math.sqrt(_D)
        _x46 = math.sqrt(m)
        _x47 = _x45*_x46
        _x48 = _x45/_x46
        _x49 = _x45*g_s*(m*math.sqrt(m))
        _x50 = -0.5*k_d*l0
        _x51 = (-0.41567911405660357*_x10 - 0.41567911405660357*_x11 + 0.41567911405660357*_x12*_x13*_x6
            + 0.09720828549085844*_x15*k_d + 0.09720828549085844*_x16*g_s*m - 0.09720828549085844*_x21
            - 0.05155355009455148*_x24 - 0.05155355009455148*_x25 + 0.05155355009455148*_x26*_x27*_x6
            + 0.024719229415033087*_x29*k_d - 0.147790320897128*_x3 + 0.024719229415033087*_x30*g_s*m
            - 0.024719229415033087*_x35 - 0.006904529857608445*_x38 - 0.006904529857608445*_x39
            - 0.147790320897128*_x4 + 0.006904529857608445*_x40*_x41*_x6 + 0.147790320897128*_x5*_x6*_x7
            - _x50)
        _x52 = (1.0/math.sqrt(_x51))
        _x53 = (-0.25540525119175433*_x10 - 0.25540525119175433*_x11 + 0.25540525119175433*_x12*_x13*_x6
            - 0.2685463444140672*_x17 - 0.2685463444140672*_x18 + 0.2685463444140672*_x19*_x20*_x6
            + 0.048794612428541204*_x22*k_d + 0.048794612428541204*_x23*g_s*m - 0.048794612428541204*_x28
            - 0.010443786721981197*_x3 - 0.01951903325298492*_x31 - 0.01951903325298492*_x32
            + 0.01951903325298492*_x33*_x34*_x6 + 0.005119803152246505*_x36*k_d
            + 0.005119803152246505*_x37*g_s*m - 0.010443786721981197*_x4 - 0.005119803152246505*_x42
            + 0.010443786721981197*_x5*_x6*_x7 - _x50)
        _x54 = (1.0/math.sqrt(_x53))
        _x55 = -0.5*k_d*l0
        _x56 = (-0.0662099828438604*_x10 - 0.0662099828438604*_x11 + 0.0662099828438604*_x12*_x13*_x6
            - 0.2671819482314443*_x17 - 0.2671819482314443*_x18 + 0.2671819482314443*_x19*_x20*_x6
            - 0.1742495636223592*_x24 - 0.1742495636223592*_x25 + 0.1742495636223592*_x26*_x27*_x6
            + 0.02396692958086051*_x29*k_d - 0.01101839635505667*_x3 + 0.02396692958086051*_x30*g_s*m
            - 0.02396692958086051*_x35 - 0.00530703852813994*_x38 - 0.00530703852813994*_x39
            - 0.01101839635505667*_x4 + 0.00530703852813994*_x40*_x41*_x6 + 0.01101839635505667*_x5*_x6*_x7
            - _x55)
        _x57 = (1.0/math.sqrt(_x56))
        _x58 = (-0.050345455482979015*_x10 - 0.050345455482979015*_x11 + 0.050345455482979015*_x12*_x13*_x6
            - 0.11622097556712797*_x17 - 0.11622097556712797*_x18 + 0.11622097556712797*_x19*_x20*_x6
            - 0.2353986790647292*_x24 - 0.2353986790647292*_x25 + 0.2353986790647292*_x26*_x27*_x6
            - 0.0025147977064533143*_x3 - 0.10372825048336794*_x31 - 0.10372825048336794*_x32
            + 0.10372825048336794*_x33*_x34*_x6 + 0.008208158304657426*_x36*k_d
            + 0.008208158304657426*_x37*g_s*m - 0.0025147977064533143*_x4 - 0.008208158304657426*_x42
            + 0.0025147977064533143*_x5*_x6*_x7 - _x50)
        _x59 = (1.0/math.sqrt(_x58))
        _x60 = (-0.029703284805013122*_x10 - 0.029703284805013122*_x11 + 0.029703284805013122*_x12*_x13*_x6
            - 0.10140664131431479*_x17 - 0.10140664131431479*_x18 + 0.10140664131431479*_x19*_x20*_x6
            - 0.14531313573962065*_x24 - 0.14531313573962065*_x25 + 0.14531313573962065*_x26*_x27*_x6
            - 0.003959513229722528*_x3 - 0.17612158869639333*_x31 - 0.17612158869639333*_x32
            + 0.17612158869639333*_x33*_x34*_x6 - 0.04349583621493557*_x38 - 0.04349583621493557*_x39
            - 0.003959513229722528*_x4 + 0.04349583621493557*_x40*_x41*_x6 + 0.003959513229722528*_x5*_x6*_x7
            - _x55)
        _x61 = (1.0/math.sqrt(_x60))
        _isigma0 = _x0
        _iF0 = _x1 - _x3 - _x4 + _x8
        _isigma1 = _x9
        _iF1 = _x1 - _x10 - _x11 + _x14
        _isigma2 = _x15
        _iF2 = _x1 - _x17 - _x18 + _x21
        _isigma3 = _x22
        _iF3 = _x1 - _x24 - _x25 + _x28
        _isigma4 = _x29
        _iF4 = _x1 - _x31 - _x32 + _x35
        _isigma5 = _x36
        _iF5 = _x1 - _x38 - _x39 + _x42
        _iPsi0 = _x43
        _ift0 = _x44*_x47
        _ifq0 = _P0*_x44*_x48*_x62**2
        _ifp0 = _x0*_x44*_x49*math.sin(_Q0)
        _iPsi1 = _x51
        _ift1 = _x47*_x52
        _ifq1 = _P1*_x48*_x52*_x67**2
        _ifp1 = _x49*_x52*_x9*math.sin(_Q1)
        _iPsi2 = _x53
        _ift2 = _x47*_x54
        _ifq2 = _P2*_x48*_x54*_x63**2
        _ifp2 = _x15*_x49*_x54*math.sin(_Q2)
        _iPsi3 = _x56
        _ift3 = _x47*_x57
        _ifq3 = _P3*_x48*_x57*_x64**2
        _ifp3 = _x22*_x49*_x57*math.sin(_Q3)
        _iPsi4 = _x58
        _ift4 = _x47*_x59
        _ifq4 = _P4*_x48*_x59*_x65**2
        _ifp4 = _x29*_x49*_x59*math.sin(_Q4)
        _iPsi5 = _x60
        _ift5 = _x47*_x61
        _ifq5 = _P5*_x48*_x61*_x66**2
        _ifp5 = _x36*_x49*_x61*math.sin(_Q5)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _D
        _n0_1 = (0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2
            - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th)
        _n0_2 = (0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2
            + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th)
        _n0_3 = (0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2
            - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th)
        _n0_4 = (0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2
            + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th)
        _n0_5 = (0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2
            + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th)
        _n0_6 = (0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2
            + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _n0_7 = (0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2
            - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5
            + m*q_r**2*q_thd)
        _n0_8 = (0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2
            + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5
            + m*q_r**2*q_thd)
        _n0_9 = (0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2
            - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5
            + m*q_r**2*q_thd)
        _n0_10 = (0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2
            + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5
            + m*q_r**2*q_thd)
        _n0_11 = (0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2
            + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5
            + m*q_r**2*q_thd)
        _n0_12 = (0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2
            + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5
            + m*q_r**2*q_thd)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_8 - _P1) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_9 - _P2) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_10 - _P3) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_11 - _P4) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_12 - _P5) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _Q4 = _n0_5
        _Q5 = _n0_6
        _P0 = _n0_7
        _P1 = _n0_8
        _P2 = _n0_9
        _P3 = _n0_10
        _P4 = _n0_11
        _P5 = _n0_12
        _passes += 1.0
    _work = (0.0028924065498159377*_iF0 + 0.030555658668093604*_iF1 + 0.08906517308699231*_iF2
        + 0.14489179419935322*_iF3 + 0.1498251278559757*_iF4 + 0.08276983963976924*_iF5)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    end_q_r = q_r_lo
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    end_q_thd = ((0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5
        + m*q_r**2*q_thd)/(m*q_r_lo**2))
    passes = _passes
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

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
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

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
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN11 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 11); the columns are the outputs of
    :func:`iterative_stance_nodes_4_zeroth_geyer`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward
            +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

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
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 13); the columns are the outputs of
    :func:`iterative_apex_return_nodes_4_zeroth_geyer`, in order) and its status code to ``status[i]``
    (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 43
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_decompression = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    d_passes = _c1[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_held`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_held`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN11 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_4_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_4_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_4_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_4_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_4_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_4_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_4_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN11 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_geyer`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_geyer`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 43
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_decompression = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    d_passes = _c1[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_held`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_held`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN11 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_1_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_1_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_1_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_1_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_1_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_1_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_1_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN11 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_geyer`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_geyer`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 43
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_decompression = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    d_passes = _c1[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_held`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_held`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN11 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_2_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_2_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_2_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_2_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_2_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_2_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_2_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN11 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_geyer`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_geyer`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 43
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_decompression = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    d_passes = _c1[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_held`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_held`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN11 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_3_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_3_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_3_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_3_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_3_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_3_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_3_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN11 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_geyer`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_geyer`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 43
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_decompression = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    d_passes = _c1[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_held`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_held`: arguments, out and status as
    :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN11 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_stance_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 8
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo)
            and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
            and (tol <= 1.0))):
        return _NAN11 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN11 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN11 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN11 + (_c1[6],)
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    c_passes = _c1[5]
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s,
        q_r_lo, g_lo_q_th, g_lo_q_thd, iterations, tol))
    if _c2[6] != STATUS_OK:
        return _NAN11 + (_c2[6],)
    t_decompression = _c2[0]
    liftoff_q_r = _c2[1]
    liftoff_q_rd = _c2[2]
    liftoff_q_th = _c2[3]
    liftoff_q_thd = _c2[4]
    d_passes = _c2[5]
    t_stance = t_bottom + t_decompression
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN11 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_nodes_6_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_nodes_6_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_stance_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_nodes_6_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: the same as :func:`iterative_apex_return_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex
            >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN13 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN13 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_nodes_6_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol))
    if _c1[11] != STATUS_OK:
        return _NAN13 + (_c1[11],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN13 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN13 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_nodes_6_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_nodes_6_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_apex_return_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_nodes_6_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], out[i, 12], status[i]) = res
