# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:771c593f135b91d2
#   geyer_jacobian.py sha256:ee22e292aadbecf4
#   geyer_vs_jacobian.py sha256:5dbda8f251d8b5ae
#   gravity_type0_jacobian.py sha256:a64ce5867ac287ba
#   gravity_type1_jacobian.py sha256:0e1ebc1b92b0959d
#   gravity_type2_jacobian.py sha256:24319b58be9e307c
#   gravity_type3_jacobian.py sha256:528071c82af16cbd
#   gravity_type4_jacobian.py sha256:072027d2a2926da4
#   gravity_type5_jacobian.py sha256:ac195c3c1fbd33ad
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative: JVP kernels, and for a
map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_stance_jacobian
from .geyer_vs_jacobian import geyer_vs_stance_jacobian
from .gravity_type0_jacobian import gravity_type0_stance_jacobian
from .gravity_type1_jacobian import gravity_type1_stance_jacobian
from .gravity_type2_jacobian import gravity_type2_stance_jacobian
from .gravity_type3_jacobian import gravity_type3_stance_jacobian
from .gravity_type4_jacobian import gravity_type4_stance_jacobian
from .gravity_type5_jacobian import gravity_type5_stance_jacobian

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED,
    STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN36 = (NAN,) * 36
_NAN42 = (NAN,) * 42
_NAN77 = (NAN,) * 77
_NAN91 = (NAN,) * 91


@njit(cache=True, error_model="numpy")
def _store_row_11_77(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (77 outputs, the
    derivatives from column 11, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    if res[77] == STATUS_OK and not (math.isfinite(res[11]) and math.isfinite(res[12])
            and math.isfinite(res[13]) and math.isfinite(res[14]) and math.isfinite(res[15])
            and math.isfinite(res[16]) and math.isfinite(res[17]) and math.isfinite(res[18])
            and math.isfinite(res[19]) and math.isfinite(res[20]) and math.isfinite(res[21])
            and math.isfinite(res[22]) and math.isfinite(res[23]) and math.isfinite(res[24])
            and math.isfinite(res[25]) and math.isfinite(res[26]) and math.isfinite(res[27])
            and math.isfinite(res[28]) and math.isfinite(res[29]) and math.isfinite(res[30])
            and math.isfinite(res[31]) and math.isfinite(res[32]) and math.isfinite(res[33])
            and math.isfinite(res[34]) and math.isfinite(res[35]) and math.isfinite(res[36])
            and math.isfinite(res[37]) and math.isfinite(res[38]) and math.isfinite(res[39])
            and math.isfinite(res[40]) and math.isfinite(res[41]) and math.isfinite(res[42])
            and math.isfinite(res[43]) and math.isfinite(res[44]) and math.isfinite(res[45])
            and math.isfinite(res[46]) and math.isfinite(res[47]) and math.isfinite(res[48])
            and math.isfinite(res[49]) and math.isfinite(res[50]) and math.isfinite(res[51])
            and math.isfinite(res[52]) and math.isfinite(res[53]) and math.isfinite(res[54])
            and math.isfinite(res[55]) and math.isfinite(res[56]) and math.isfinite(res[57])
            and math.isfinite(res[58]) and math.isfinite(res[59]) and math.isfinite(res[60])
            and math.isfinite(res[61]) and math.isfinite(res[62]) and math.isfinite(res[63])
            and math.isfinite(res[64]) and math.isfinite(res[65]) and math.isfinite(res[66])
            and math.isfinite(res[67]) and math.isfinite(res[68]) and math.isfinite(res[69])
            and math.isfinite(res[70]) and math.isfinite(res[71]) and math.isfinite(res[72])
            and math.isfinite(res[73]) and math.isfinite(res[74]) and math.isfinite(res[75])
            and math.isfinite(res[76])):
        res = _NAN77 + (STATUS_NUMERICAL_RANGE,)
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], out[i, 70], out[i, 71], out[i, 72], out[i, 73], out[i, 74], out[i, 75], out[i, 76],
        status[i]) = res


@njit(cache=True, error_model="numpy")
def _store_row_13_91(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (91 outputs, the
    derivatives from column 13, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    if res[91] == STATUS_OK and not (math.isfinite(res[13]) and math.isfinite(res[14])
            and math.isfinite(res[15]) and math.isfinite(res[16]) and math.isfinite(res[17])
            and math.isfinite(res[18]) and math.isfinite(res[19]) and math.isfinite(res[20])
            and math.isfinite(res[21]) and math.isfinite(res[22]) and math.isfinite(res[23])
            and math.isfinite(res[24]) and math.isfinite(res[25]) and math.isfinite(res[26])
            and math.isfinite(res[27]) and math.isfinite(res[28]) and math.isfinite(res[29])
            and math.isfinite(res[30]) and math.isfinite(res[31]) and math.isfinite(res[32])
            and math.isfinite(res[33]) and math.isfinite(res[34]) and math.isfinite(res[35])
            and math.isfinite(res[36]) and math.isfinite(res[37]) and math.isfinite(res[38])
            and math.isfinite(res[39]) and math.isfinite(res[40]) and math.isfinite(res[41])
            and math.isfinite(res[42]) and math.isfinite(res[43]) and math.isfinite(res[44])
            and math.isfinite(res[45]) and math.isfinite(res[46]) and math.isfinite(res[47])
            and math.isfinite(res[48]) and math.isfinite(res[49]) and math.isfinite(res[50])
            and math.isfinite(res[51]) and math.isfinite(res[52]) and math.isfinite(res[53])
            and math.isfinite(res[54]) and math.isfinite(res[55]) and math.isfinite(res[56])
            and math.isfinite(res[57]) and math.isfinite(res[58]) and math.isfinite(res[59])
            and math.isfinite(res[60]) and math.isfinite(res[61]) and math.isfinite(res[62])
            and math.isfinite(res[63]) and math.isfinite(res[64]) and math.isfinite(res[65])
            and math.isfinite(res[66]) and math.isfinite(res[67]) and math.isfinite(res[68])
            and math.isfinite(res[69]) and math.isfinite(res[70]) and math.isfinite(res[71])
            and math.isfinite(res[72]) and math.isfinite(res[73]) and math.isfinite(res[74])
            and math.isfinite(res[75]) and math.isfinite(res[76]) and math.isfinite(res[77])
            and math.isfinite(res[78]) and math.isfinite(res[79]) and math.isfinite(res[80])
            and math.isfinite(res[81]) and math.isfinite(res[82]) and math.isfinite(res[83])
            and math.isfinite(res[84]) and math.isfinite(res[85]) and math.isfinite(res[86])
            and math.isfinite(res[87]) and math.isfinite(res[88]) and math.isfinite(res[89])
            and math.isfinite(res[90])):
        res = _NAN91 + (STATUS_NUMERICAL_RANGE,)
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], out[i, 70], out[i, 71], out[i, 72], out[i, 73], out[i, 74], out[i, 75], out[i, 76], out[i,
        77], out[i, 78], out[i, 79], out[i, 80], out[i, 81], out[i, 82], out[i, 83], out[i, 84], out[i, 85],
        out[i, 86], out[i, 87], out[i, 88], out[i, 89], out[i, 90], status[i]) = res


@njit(cache=True, error_model="numpy")
def _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd, iterations,
        tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1, d_guess_q_th__1,
        d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3, d_guess_q_th__3,
        d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """The input checks of 5 kernels of this module (one per choice): every argument finite and inside its
    domain."""
    return (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
        and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
        and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
        and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
        > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
        and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)))


@njit(cache=True, error_model="numpy")
def _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations,
        tol):
    """The input checks of 5 kernels of this module (one per choice): every argument finite and inside its
    domain."""
    return (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
        and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
        and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
        and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
        > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations
        == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0)
        and (tol <= 1.0)))


@njit(cache=True, error_model="numpy")
def _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
    """The input checks of 45 kernels of this module (one per choice): every argument finite and inside its
    domain."""
    return (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
        and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
        and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
        and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
        and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo
        <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
        and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)))


@njit(cache=True, error_model="numpy")
def _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
        iterations, tol):
    """The input checks of 45 kernels of this module (one per choice): every argument finite and inside its
    domain."""
    return (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
        and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
        and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
        and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex >= 0.0))
        and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
        > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo
        <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
        and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)))


@njit(cache=True, error_model="numpy")
def _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd, iterations,
        tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1, d_guess_q_th__1,
        d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3, d_guess_q_th__3,
        d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5,
        d_guess_q_thd__5):
    """The input checks of 5 kernels of this module (one per choice): every argument finite and inside its
    domain."""
    return (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
        and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
        and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
        and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c
        > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
        and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)))


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_4_jvp5_408d60(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 5 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

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
        d_guess_q_r__0: direction 0: its component along guess_q_r
        d_guess_q_th__0: direction 0: its component along guess_q_th
        d_guess_q_thd__0: direction 0: its component along guess_q_thd
        d_guess_q_r__1: direction 1: its component along guess_q_r
        d_guess_q_th__1: direction 1: its component along guess_q_th
        d_guess_q_thd__1: direction 1: its component along guess_q_thd
        d_guess_q_r__2: direction 2: its component along guess_q_r
        d_guess_q_th__2: direction 2: its component along guess_q_th
        d_guess_q_thd__2: direction 2: its component along guess_q_thd
        d_guess_q_r__3: direction 3: its component along guess_q_r
        d_guess_q_th__3: direction 3: its component along guess_q_th
        d_guess_q_thd__3: direction 3: its component along guess_q_thd
        d_guess_q_r__4: direction 4: its component along guess_q_r
        d_guess_q_th__4: direction 4: its component along guess_q_th
        d_guess_q_thd__4: direction 4: its component along guess_q_thd

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1022
    # inputs: finite and inside their domains
    if not _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4):
        return _NAN36 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((41, 5))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN36 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], ) = (d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
        d_guess_q_r__3, d_guess_q_r__4, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], ) = (d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
        d_guess_q_th__3, d_guess_q_th__4, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], ) = (0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], ) = (1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], ) = (0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], ) = (0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], ) = (0.0, 0.0, 0.0, 1.0, 0.0, )
    # the initial values
    _x0 = 1.8611363115940527*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.9305681557970263*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.13886368840594743*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.06943184420297371*_x5
    _x6 = _x1*m
    _pd__4 = 1.3399810435848563*_x6
    _pd__5 = 0.6699905217924281*_x2
    _pd__6 = 0.6600189564151437*_x4
    _pd__7 = 0.33000947820757187*_x5
    _pd__8 = 0.6600189564151437*_x6
    _pd__9 = 0.33000947820757187*_x2
    _pd__10 = 1.3399810435848563*_x4
    _pd__11 = 0.6699905217924281*_x5
    _pd__12 = 0.13886368840594743*_x6
    _pd__13 = 0.06943184420297371*_x2
    _pd__14 = _x0*_x3
    _pd__15 = 0.9305681557970263*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(5):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.9305681557970263*d_guess_q_th__j + 0.06943184420297371*d_q_th__j
        _d_Q1__start__j = 0.6699905217924281*d_guess_q_th__j + 0.33000947820757187*d_q_th__j
        _d_Q2__start__j = 0.33000947820757187*d_guess_q_th__j + 0.6699905217924281*d_q_th__j
        _d_Q3__start__j = 0.06943184420297371*d_guess_q_th__j + 0.9305681557970263*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _d_P3__start__j = (_pd__12*d_guess_q_r__j + _pd__13*d_guess_q_thd__j + _pd__14*d_q_r__j
            + _pd__15*d_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_Q3__start__j
        _T[13, _j0] = _d_P0__start__j
        _T[14, _j0] = _d_P1__start__j
        _T[15, _j0] = _d_P2__start__j
        _T[16, _j0] = _d_P3__start__j
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
            return _NAN36 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9951792190105739*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x109 = (1.0/_x9)
        _x17 = _x109**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__16 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__17 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__18 = -_x109**4*_x15*_x22 - k_c
        _pd__19 = _x8 + l0
        _x23 = 0.8910937442931661*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x106 = (1.0/_x24)
        _x29 = _x106**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__20 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__21 = _x12*_x33
        _pd__22 = -_x106**4*_x22*_x28 - k_c
        _pd__23 = _x23 + l0
        _x34 = 0.5511127007083099*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x107 = (1.0/_x35)
        _x40 = _x107**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__24 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__25 = _x12*_x44
        _pd__26 = -_x107**4*_x22*_x39 - k_c
        _pd__27 = _x34 + l0
        _x45 = 0.13404290741652142*_D + _x7
        _x46 = -_x45
        _isigma3 = _x46
        _x47 = math.cos(_Q3)
        _x48 = _x12*_x47
        _x49 = _x46*k_c
        _x50 = _P3**2
        _x108 = (1.0/_x46)
        _x51 = _x108**3
        _x52 = _x16*_x51
        _x53 = _x50*_x52
        _iF3 = _x10 - _x48 - _x49 + _x53
        _x54 = 2.0*_P3
        _pd__28 = _x52*_x54
        _x55 = math.sin(_Q3)
        _pd__29 = _x12*_x55
        _pd__30 = -_x108**4*_x22*_x50 - k_c
        _pd__31 = _x45 + l0
        _x56 = (0.5*_x10 - 0.582374038291501*_x13 - 0.582374038291501*_x14 + 0.582374038291501*_x19
            + 0.12383458041329967*_x26 + 0.12383458041329967*_x27 - 0.12383458041329967*_x31
            - 0.0575898635297681*_x37 - 0.0575898635297681*_x38 + 0.0575898635297681*_x42
            + 0.016129321407969507*_x48 + 0.016129321407969507*_x49 - 0.016129321407969507*_x53)
        _iPsi0 = _x56
        _x57 = (1.0/math.sqrt(_x56))
        _x58 = math.sqrt(_D)
        _x59 = math.sqrt(m)
        _x60 = _x58*_x59
        _ift0 = _x57*_x60
        _x61 = (0.5)/_x58
        _x62 = _x59*_x61
        _pd__32 = _x57*_x62
        _x63 = _x56**(-1.5)
        _x64 = (0.5)*_x60
        _pd__33 = -_x63*_x64
        _x65 = (1.0/_x59)
        _x66 = _x58*_x65
        _x67 = _x109**2
        _x68 = _x57*_x67
        _x69 = _x66*_x68
        _ifq0 = _P0*_x69
        _x70 = _x61*_x65
        _pd__34 = _P0*_x68*_x70
        _pd__35 = _x69
        _x71 = (0.5)*_x66
        _pd__36 = -_P0*_x63*_x67*_x71
        _pd__37 = -_x17*_x20*_x57*_x66
        _x72 = g_s*m**(1.5)
        _x73 = _x58*_x72
        _x74 = _x57*_x73
        _x75 = _x21*_x74
        _ifp0 = _x75*_x9
        _x76 = _x21*_x9
        _x77 = _x61*_x72
        _pd__38 = _x57*_x76*_x77
        _pd__39 = _x11*_x74*_x9
        _x78 = (0.5)*_x73
        _pd__40 = -_x63*_x76*_x78
        _pd__41 = _x75
        _x79 = (-0.16000937841634696*_x13 - 0.16000937841634696*_x14 + 0.16000937841634696*_x15*_x16*_x17
            + 0.39252437029865583*_x16*_x28*_x29 + 0.017475652789475504*_x16*_x50*_x51
            - 0.39252437029865583*_x26 - 0.39252437029865583*_x27 + 0.0700094015044783*_x35*k_c
            + 0.0700094015044783*_x36*g_s*m - 0.0700094015044783*_x42 - 0.017475652789475504*_x48
            - 0.017475652789475504*_x49 + 0.5*k_c*l0)
        _iPsi1 = _x79
        _x80 = (1.0/math.sqrt(_x79))
        _ift1 = _x60*_x80
        _pd__42 = _x62*_x80
        _x81 = _x79**(-1.5)
        _pd__43 = -_x64*_x81
        _x82 = _x106**2
        _x83 = _x80*_x82
        _x84 = _x66*_x83
        _ifq1 = _P1*_x84
        _pd__44 = _P1*_x70*_x83
        _pd__45 = _x84
        _pd__46 = -_P1*_x71*_x81*_x82
        _pd__47 = -_x29*_x32*_x66*_x80
        _x85 = _x73*_x80
        _x86 = _x33*_x85
        _ifp1 = _x24*_x86
        _x87 = _x24*_x33
        _pd__48 = _x77*_x80*_x87
        _pd__49 = _x24*_x25*_x85
        _pd__50 = -_x78*_x81*_x87
        _pd__51 = _x86
        _x88 = (-0.01613725546399532*_x13 - 0.01613725546399532*_x14 + 0.01613725546399532*_x15*_x16*_x17
            + 0.2848443432415939*_x16*_x28*_x29 + 0.21871326539550162*_x16*_x39*_x40 - 0.2848443432415939*_x26
            - 0.2848443432415939*_x27 - 0.21871326539550162*_x37 - 0.21871326539550162*_x38
            + 0.019694864101090868*_x46*k_c + 0.019694864101090868*_x47*g_s*m - 0.019694864101090868*_x53
            + 0.5*k_c*l0)
        _iPsi2 = _x88
        _x89 = (1.0/math.sqrt(_x88))
        _ift2 = _x60*_x89
        _pd__52 = _x62*_x89
        _x90 = _x88**(-1.5)
        _pd__53 = -_x64*_x90
        _x91 = _x107**2
        _x92 = _x89*_x91
        _x93 = _x66*_x92
        _ifq2 = _P2*_x93
        _pd__54 = _P2*_x70*_x92
        _pd__55 = _x93
        _pd__56 = -_P2*_x71*_x90*_x91
        _pd__57 = -_x40*_x43*_x66*_x89
        _x94 = _x73*_x89
        _x95 = _x44*_x94
        _ifp2 = _x35*_x95
        _x96 = _x35*_x44
        _pd__58 = _x77*_x89*_x96
        _pd__59 = _x35*_x36*_x94
        _pd__60 = -_x78*_x90*_x96
        _pd__61 = _x95
        _x97 = (-0.01796104633752054*_x13 - 0.01796104633752054*_x14 + 0.01796104633752054*_x15*_x16*_x17
            + 0.11000222456933441*_x16*_x28*_x29 + 0.2823150697454702*_x16*_x39*_x40
            + 0.08972165934767481*_x16*_x50*_x51 - 0.11000222456933441*_x26 - 0.11000222456933441*_x27
            - 0.2823150697454702*_x37 - 0.2823150697454702*_x38 - 0.08972165934767481*_x48
            - 0.08972165934767481*_x49 + 0.5*k_c*l0)
        _iPsi3 = _x97
        _x98 = (1.0/math.sqrt(_x97))
        _ift3 = _x60*_x98
        _pd__62 = _x62*_x98
        _x99 = _x97**(-1.5)
        _pd__63 = -_x64*_x99
        _x100 = _x108**2
        _x101 = _x100*_x98
        _x102 = _x101*_x66
        _ifq3 = _P3*_x102
        _pd__64 = _P3*_x101*_x70
        _pd__65 = _x102
        _pd__66 = -_P3*_x100*_x71*_x99
        _pd__67 = -_x51*_x54*_x66*_x98
        _x103 = _x73*_x98
        _x104 = _x103*_x55
        _ifp3 = _x104*_x46
        _x105 = _x46*_x55
        _pd__68 = _x105*_x77*_x98
        _pd__69 = _x103*_x46*_x47
        _pd__70 = -_x105*_x78*_x99
        _pd__71 = _x104
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(5):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_Q3__j = _T[12, _j1]
            _d_P0__j = _T[13, _j1]
            _d_P1__j = _T[14, _j1]
            _d_P2__j = _T[15, _j1]
            _d_P3__j = _T[16, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x110 = -d_q_r__j
            _d_isigma0__j = -0.9951792190105739*_d_D__j - _x110
            _d_iF0__j = _d_P0__j*_pd__16 + _d_Q0__j*_pd__17 + _d_isigma0__j*_pd__18 + _pd__19*d_k_c__j
            _d_isigma1__j = -0.8910937442931661*_d_D__j - _x110
            _d_iF1__j = _d_P1__j*_pd__20 + _d_Q1__j*_pd__21 + _d_isigma1__j*_pd__22 + _pd__23*d_k_c__j
            _d_isigma2__j = -0.5511127007083099*_d_D__j - _x110
            _d_iF2__j = _d_P2__j*_pd__24 + _d_Q2__j*_pd__25 + _d_isigma2__j*_pd__26 + _pd__27*d_k_c__j
            _d_isigma3__j = -0.13404290741652142*_d_D__j - _x110
            _d_iF3__j = _d_P3__j*_pd__28 + _d_Q3__j*_pd__29 + _d_isigma3__j*_pd__30 + _pd__31*d_k_c__j
            _d_iPsi0__j = (0.582374038291501*_d_iF0__j - 0.12383458041329967*_d_iF1__j
                + 0.0575898635297681*_d_iF2__j - 0.016129321407969507*_d_iF3__j)
            _d_ift0__j = _d_D__j*_pd__32 + _d_iPsi0__j*_pd__33
            _d_ifq0__j = _d_D__j*_pd__34 + _d_P0__j*_pd__35 + _d_iPsi0__j*_pd__36 + _d_isigma0__j*_pd__37
            _d_ifp0__j = _d_D__j*_pd__38 + _d_Q0__j*_pd__39 + _d_iPsi0__j*_pd__40 + _d_isigma0__j*_pd__41
            _d_iPsi1__j = (0.16000937841634696*_d_iF0__j + 0.39252437029865583*_d_iF1__j
                - 0.0700094015044783*_d_iF2__j + 0.017475652789475504*_d_iF3__j)
            _d_ift1__j = _d_D__j*_pd__42 + _d_iPsi1__j*_pd__43
            _d_ifq1__j = _d_D__j*_pd__44 + _d_P1__j*_pd__45 + _d_iPsi1__j*_pd__46 + _d_isigma1__j*_pd__47
            _d_ifp1__j = _d_D__j*_pd__48 + _d_Q1__j*_pd__49 + _d_iPsi1__j*_pd__50 + _d_isigma1__j*_pd__51
            _d_iPsi2__j = (0.01613725546399532*_d_iF0__j + 0.2848443432415939*_d_iF1__j
                + 0.21871326539550162*_d_iF2__j - 0.019694864101090868*_d_iF3__j)
            _d_ift2__j = _d_D__j*_pd__52 + _d_iPsi2__j*_pd__53
            _d_ifq2__j = _d_D__j*_pd__54 + _d_P2__j*_pd__55 + _d_iPsi2__j*_pd__56 + _d_isigma2__j*_pd__57
            _d_ifp2__j = _d_D__j*_pd__58 + _d_Q2__j*_pd__59 + _d_iPsi2__j*_pd__60 + _d_isigma2__j*_pd__61
            _d_iPsi3__j = (0.01796104633752054*_d_iF0__j + 0.11000222456933441*_d_iF1__j
                + 0.2823150697454702*_d_iF2__j + 0.08972165934767481*_d_iF3__j)
            _d_ift3__j = _d_D__j*_pd__62 + _d_iPsi3__j*_pd__63
            _d_ifq3__j = _d_D__j*_pd__64 + _d_P3__j*_pd__65 + _d_iPsi3__j*_pd__66 + _d_isigma3__j*_pd__67
            _d_ifp3__j = _d_D__j*_pd__68 + _d_Q3__j*_pd__69 + _d_iPsi3__j*_pd__70 + _d_isigma3__j*_pd__71
            _T[17, _j1] = _d_isigma0__j
            _T[18, _j1] = _d_iF0__j
            _T[19, _j1] = _d_isigma1__j
            _T[20, _j1] = _d_iF1__j
            _T[21, _j1] = _d_isigma2__j
            _T[22, _j1] = _d_iF2__j
            _T[23, _j1] = _d_isigma3__j
            _T[24, _j1] = _d_iF3__j
            _T[25, _j1] = _d_ift0__j
            _T[26, _j1] = _d_ifq0__j
            _T[27, _j1] = _d_ifp0__j
            _T[28, _j1] = _d_ift1__j
            _T[29, _j1] = _d_ifq1__j
            _T[30, _j1] = _d_ifp1__j
            _T[31, _j1] = _d_ift2__j
            _T[32, _j1] = _d_ifq2__j
            _T[33, _j1] = _d_ifp2__j
            _T[34, _j1] = _d_ift3__j
            _T[35, _j1] = _d_ifq3__j
            _T[36, _j1] = _d_ifp3__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x111 = m*q_rd**2
        _x112 = -q_r
        _x113 = k_c*(_x112 + l0)
        _x114 = -l0
        _x115 = -_isigma0 - _x114
        _x116 = 0.024152203412833244*k_c
        _x117 = -_isigma1 - _x114
        _x118 = 0.215214082271785*k_c
        _x119 = -_isigma2 - _x114
        _x120 = 0.43693107259076114*k_c
        _x121 = -_isigma3 - _x114
        _x122 = 0.3237026417246206*k_c
        _x123 = (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 + _x113 - _x115*_x116 - _x117*_x118 - _x119*_x120 - _x121*_x122)
        _x124 = math.sqrt(_x111*k_c + _x123**2)
        _x125 = _x123 + _x124
        _x126 = (1.0/_x125)
        _D__next = _x111*_x126
        _x127 = _x115*k_c
        _x128 = 0.0051978942923343804*k_c
        _x129 = _x119*k_c
        _x130 = _x121*k_c
        _x131 = (1.0/_x124)
        _x132 = _x126**2
        _x133 = _x111*_x132
        _pd__72 = (_x133*(-_x131*(0.0005833289296948737*_iF0 + 0.0051978942923343804*_iF1
            + 0.01055284814259947*_iF2 + 0.007818132048204519*_iF3 + 0.024152203412833244*_x113 - _x117*_x128
            - 0.0005833289296948737*_x127 - 0.01055284814259947*_x129 - 0.007818132048204519*_x130)
            - 0.024152203412833244))
        _x134 = _x117*k_c
        _pd__73 = (_x133*(-_x131*(0.0051978942923343804*_iF0 + 0.046317101208086645*_iF1
            + 0.09403371980364733*_iF2 + 0.06966536696771665*_iF3 + 0.215214082271785*_x113 - _x115*_x128
            - 0.09403371980364733*_x129 - 0.06966536696771665*_x130 - 0.046317101208086645*_x134)
            - 0.215214082271785))
        _pd__74 = (_x133*(-_x131*(0.01055284814259947*_iF0 + 0.09403371980364733*_iF1
            + 0.19090876219531297*_iF2 + 0.14143574244920135*_iF3 + 0.43693107259076114*_x113
            - 0.01055284814259947*_x127 - 0.19090876219531297*_x129 - 0.14143574244920135*_x130
            - 0.09403371980364733*_x134) - 0.43693107259076114))
        _pd__75 = (_x133*(-_x131*(0.007818132048204519*_iF0 + 0.06966536696771665*_iF1
            + 0.14143574244920135*_iF2 + 0.10478340025949809*_iF3 + 0.3237026417246206*_x113
            - 0.007818132048204519*_x127 - 0.14143574244920135*_x129 - 0.10478340025949809*_x130
            - 0.06966536696771665*_x134) - 0.3237026417246206))
        _x135 = _x123*_x131
        _pd__76 = _x133*(-_x116*_x135 - _x116)
        _pd__77 = _x133*(-_x118*_x135 - _x118)
        _pd__78 = _x133*(-_x120*_x135 - _x120)
        _pd__79 = _x133*(-_x122*_x135 - _x122)
        _x136 = 2.0*q_r
        _pd__80 = (_x133*(-0.024152203412833244*_isigma0 - 0.215214082271785*_isigma1
            - 0.43693107259076114*_isigma2 - 0.3237026417246206*_isigma3 - _x112 - _x131*((0.5)*_x111
            + (0.5)*_x123*(0.04830440682566649*_isigma0 + 0.43042816454357*_isigma1
            + 0.8738621451815223*_isigma2 + 0.6474052834492412*_isigma3 - _x136 - 8.470329472543003e-22*l0))
            + 4.235164736271502e-22*l0))
        _pd__81 = _x133*(_x135*k_c + k_c)
        _pd__82 = 2.0*_x126*m*q_rd - _x131*_x132*k_c*m**2*q_rd**3
        _Q0__next = (0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2
            + 0.1774825722545226*_ifq3 + q_th)
        _Q1__next = (-0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2
            + 0.16719192197418878*_ifq3 + q_th)
        _Q2__next = (0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2
            + 0.18811811749986806*_ifq3 + q_th)
        _Q3__next = (-0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _x137 = m*q_r**2
        _x138 = _x137*q_thd
        _P0__next = (0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2
            + 0.1774825722545226*_ifp3 + _x138)
        _x139 = _x136*m*q_thd
        _pd__83 = _x139
        _pd__84 = _x137
        _P1__next = (-0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2
            + 0.16719192197418878*_ifp3 + _x138)
        _pd__85 = _x139
        _pd__86 = _x137
        _P2__next = (0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2
            + 0.18811811749986806*_ifp3 + _x138)
        _pd__87 = _x139
        _pd__88 = _x137
        _P3__next = (-0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2
            + 0.08696371128436346*_ifp3 + _x138)
        _pd__89 = _x139
        _pd__90 = _x137
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[17, _j2]
            _d_iF0__j = _T[18, _j2]
            _d_isigma1__j = _T[19, _j2]
            _d_iF1__j = _T[20, _j2]
            _d_isigma2__j = _T[21, _j2]
            _d_iF2__j = _T[22, _j2]
            _d_isigma3__j = _T[23, _j2]
            _d_iF3__j = _T[24, _j2]
            _d_ifq0__j = _T[26, _j2]
            _d_ifp0__j = _T[27, _j2]
            _d_ifq1__j = _T[29, _j2]
            _d_ifp1__j = _T[30, _j2]
            _d_ifq2__j = _T[32, _j2]
            _d_ifp2__j = _T[33, _j2]
            _d_ifq3__j = _T[35, _j2]
            _d_ifp3__j = _T[36, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__72 + _d_iF1__j*_pd__73 + _d_iF2__j*_pd__74 + _d_iF3__j*_pd__75
                + _d_isigma0__j*_pd__76 + _d_isigma1__j*_pd__77 + _d_isigma2__j*_pd__78
                + _d_isigma3__j*_pd__79 + _pd__80*d_k_c__j + _pd__81*d_q_r__j + _pd__82*d_q_rd__j)
            _d_Q0__next__j = (0.08696371128436346*_d_ifq0__j + 0.35267675751627187*_d_ifq1__j
                + 0.31344511474186837*_d_ifq2__j + 0.1774825722545226*_d_ifq3__j + d_q_th__j)
            _d_Q1__next__j = (-0.014190694931141144*_d_ifq0__j + 0.16303628871563652*_d_ifq1__j
                + 0.35395300603374397*_d_ifq2__j + 0.16719192197418878*_d_ifq3__j + d_q_th__j)
            _d_Q2__next__j = (0.006735500594538156*_d_ifq0__j - 0.027880428602470895*_d_ifq1__j
                + 0.16303628871563652*_d_ifq2__j + 0.18811811749986806*_d_ifq3__j + d_q_th__j)
            _d_Q3__next__j = (-0.0035551496857956833*_d_ifq0__j + 0.012627462689404725*_d_ifq1__j
                - 0.026604180084998794*_d_ifq2__j + 0.08696371128436346*_d_ifq3__j + d_q_th__j)
            _d_P0__next__j = (0.08696371128436346*_d_ifp0__j + 0.35267675751627187*_d_ifp1__j
                + 0.31344511474186837*_d_ifp2__j + 0.1774825722545226*_d_ifp3__j + _pd__83*d_q_r__j
                + _pd__84*d_q_thd__j)
            _d_P1__next__j = (-0.014190694931141144*_d_ifp0__j + 0.16303628871563652*_d_ifp1__j
                + 0.35395300603374397*_d_ifp2__j + 0.16719192197418878*_d_ifp3__j + _pd__85*d_q_r__j
                + _pd__86*d_q_thd__j)
            _d_P2__next__j = (0.006735500594538156*_d_ifp0__j - 0.027880428602470895*_d_ifp1__j
                + 0.16303628871563652*_d_ifp2__j + 0.18811811749986806*_d_ifp3__j + _pd__87*d_q_r__j
                + _pd__88*d_q_thd__j)
            _d_P3__next__j = (-0.0035551496857956833*_d_ifp0__j + 0.012627462689404725*_d_ifp1__j
                - 0.026604180084998794*_d_ifp2__j + 0.08696371128436346*_d_ifp3__j + _pd__89*d_q_r__j
                + _pd__90*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_Q3__next__j
            _T[13, _j2] = _d_P0__next__j
            _T[14, _j2] = _d_P1__next__j
            _T[15, _j2] = _d_P2__next__j
            _T[16, _j2] = _d_P3__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _P0__next
        _n0_6 = _P1__next
        _n0_7 = _P2__next
        _n0_8 = _P3__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7
            - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    _x140 = -_D + q_r
    end_q_r = _x140
    end_q_rd = 0.0
    _x141 = q_r**2
    _x142 = (0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x141*m*q_thd)
    _x148 = (1.0/_x140)
    _x143 = _x148**2
    _x144 = (1.0/m)
    _x145 = _x143*_x144
    end_q_thd = _x142*_x145
    _x146 = 0.17392742256872692*_x145
    _pd__91 = _x146
    _x147 = 0.32607257743127305*_x145
    _pd__92 = _x147
    _pd__93 = _x147
    _pd__94 = _x146
    _pd__95 = -2.0*_x142*_x144*_x148**3
    _pd__96 = 2.0*_x143*q_r*q_thd
    _pd__97 = _x141*_x143
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN36 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(5):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[25, _j3]
        _d_ifq0__j = _T[26, _j3]
        _d_ifp0__j = _T[27, _j3]
        _d_ift1__j = _T[28, _j3]
        _d_ifq1__j = _T[29, _j3]
        _d_ifp1__j = _T[30, _j3]
        _d_ift2__j = _T[31, _j3]
        _d_ifq2__j = _T[32, _j3]
        _d_ifp2__j = _T[33, _j3]
        _d_ift3__j = _T[34, _j3]
        _d_ifq3__j = _T[35, _j3]
        _d_ifp3__j = _T[36, _j3]
        # bottom state
        d_t_half__j = (0.17392742256872692*_d_ift0__j + 0.32607257743127305*_d_ift1__j
            + 0.32607257743127305*_d_ift2__j + 0.17392742256872692*_d_ift3__j)
        d_end_q_th__j = (0.17392742256872692*_d_ifq0__j + 0.32607257743127305*_d_ifq1__j
            + 0.32607257743127305*_d_ifq2__j + 0.17392742256872692*_d_ifq3__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__91 + _d_ifp1__j*_pd__92 + _d_ifp2__j*_pd__93 + _d_ifp3__j*_pd__94
            + _pd__95*d_end_q_r__j + _pd__96*d_q_r__j + _pd__97*d_q_thd__j)
        _T[37, _j3] = d_t_half__j
        _T[38, _j3] = d_end_q_th__j
        _T[39, _j3] = d_end_q_r__j
        _T[40, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, ) = (_T[37, 0], _T[37, 1], _T[37, 2],
        _T[37, 3], _T[37, 4], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, ) = (_T[38, 0], _T[38, 1],
        _T[38, 2], _T[38, 3], _T[38, 4], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, ) = (_T[39, 0], _T[39, 1], _T[39,
        2], _T[39, 3], _T[39, 4], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, ) = (_T[40, 0], _T[40,
        1], _T[40, 2], _T[40, 3], _T[40, 4], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4, d_end_q_th__0,
        d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_thd__0, d_end_q_thd__1,
        d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_passes__0, d_passes__1, d_passes__2, d_passes__3,
        d_passes__4, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0,
        k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r, q_th, q_thd,
            k_d, guess_q_th, guess_q_thd (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 805
    # inputs: finite and inside their domains
    if not _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
            iterations, tol):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((35, 6))
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (0.0, 0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    # the initial values
    _x0 = m*q_r_lo**2
    _pd__0 = 0.06943184420297371*_x0
    _x1 = m*q_r*q_thd
    _pd__1 = 1.8611363115940527*_x1
    _x2 = m*q_r**2
    _pd__2 = 0.9305681557970263*_x2
    _pd__3 = 0.33000947820757187*_x0
    _pd__4 = 1.3399810435848563*_x1
    _pd__5 = 0.6699905217924281*_x2
    _pd__6 = 0.6699905217924281*_x0
    _pd__7 = 0.6600189564151437*_x1
    _pd__8 = 0.33000947820757187*_x2
    _pd__9 = 0.9305681557970263*_x0
    _pd__10 = 0.13886368840594743*_x1
    _pd__11 = 0.06943184420297371*_x2
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_th__j = _T[0, _j0]
        d_guess_q_thd__j = _T[1, _j0]
        d_q_r__j = _T[3, _j0]
        d_q_th__j = _T[4, _j0]
        d_q_thd__j = _T[5, _j0]
        # the initial values
        _d_Q0__start__j = 0.06943184420297371*d_guess_q_th__j + 0.9305681557970263*d_q_th__j
        _d_Q1__start__j = 0.33000947820757187*d_guess_q_th__j + 0.6699905217924281*d_q_th__j
        _d_Q2__start__j = 0.6699905217924281*d_guess_q_th__j + 0.33000947820757187*d_q_th__j
        _d_Q3__start__j = 0.9305681557970263*d_guess_q_th__j + 0.06943184420297371*d_q_th__j
        _d_P0__start__j = _pd__0*d_guess_q_thd__j + _pd__1*d_q_r__j + _pd__2*d_q_thd__j
        _d_P1__start__j = _pd__3*d_guess_q_thd__j + _pd__4*d_q_r__j + _pd__5*d_q_thd__j
        _d_P2__start__j = _pd__6*d_guess_q_thd__j + _pd__7*d_q_r__j + _pd__8*d_q_thd__j
        _d_P3__start__j = _pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__9*d_guess_q_thd__j
        _T[6, _j0] = -d_q_r__j
        _T[7, _j0] = _d_Q0__start__j
        _T[8, _j0] = _d_Q1__start__j
        _T[9, _j0] = _d_Q2__start__j
        _T[10, _j0] = _d_Q3__start__j
        _T[11, _j0] = _d_P0__start__j
        _T[12, _j0] = _d_P1__start__j
        _T[13, _j0] = _d_P2__start__j
        _T[14, _j0] = _d_P3__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x3 = 0.004820780989426014*_D + q_r
        _isigma0 = _x3
        _x4 = k_d*l0
        _x5 = math.cos(_Q0)
        _x6 = g_s*m
        _x7 = _x5*_x6
        _x8 = _x3*k_d
        _x9 = _P0**2
        _x10 = (1.0/m)
        _x100 = (1.0/_x3)
        _x11 = _x100**3
        _x12 = _x10*_x11
        _x13 = _x12*_x9
        _iF0 = _x13 + _x4 - _x7 - _x8
        _x14 = 2.0*_P0
        _pd__12 = _x12*_x14
        _x15 = math.sin(_Q0)
        _pd__13 = _x15*_x6
        _x16 = 3.0*_x10
        _pd__14 = -_x100**4*_x16*_x9 - k_d
        _x17 = -l0
        _pd__15 = -_x17 - _x3
        _x18 = 0.10890625570683385*_D + q_r
        _isigma1 = _x18
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x6
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x98 = (1.0/_x18)
        _x23 = _x98**3
        _x24 = _x10*_x23
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x4
        _x26 = 2.0*_P1
        _pd__16 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__17 = _x27*_x6
        _pd__18 = -_x16*_x22*_x98**4 - k_d
        _pd__19 = -_x17 - _x18
        _x28 = 0.44888729929169013*_D + q_r
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x6
        _x31 = _x28*k_d
        _x32 = _P2**2
        _x99 = (1.0/_x28)
        _x33 = _x99**3
        _x34 = _x10*_x33
        _x35 = _x32*_x34
        _iF2 = -_x30 - _x31 + _x35 + _x4
        _x36 = 2.0*_P2
        _pd__20 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__21 = _x37*_x6
        _pd__22 = -_x16*_x32*_x99**4 - k_d
        _pd__23 = -_x17 - _x28
        _x38 = 0.8659570925834786*_D + q_r
        _isigma3 = _x38
        _x39 = math.cos(_Q3)
        _x40 = _x39*_x6
        _x41 = _x38*k_d
        _x42 = _P3**2
        _x101 = (1.0/_x38)
        _x43 = _x101**3
        _x44 = _x10*_x43
        _x45 = _x42*_x44
        _iF3 = _x4 - _x40 - _x41 + _x45
        _x46 = 2.0*_P3
        _pd__24 = _x44*_x46
        _x47 = math.sin(_Q3)
        _pd__25 = _x47*_x6
        _pd__26 = -_x101**4*_x16*_x42 - k_d
        _pd__27 = -_x17 - _x38
        _x48 = (0.582374038291501*_x13 + 0.12383458041329967*_x20 + 0.12383458041329967*_x21
            - 0.12383458041329967*_x25 - 0.0575898635297681*_x30 - 0.0575898635297681*_x31
            + 0.0575898635297681*_x35 + 0.5*_x4 + 0.016129321407969507*_x40 + 0.016129321407969507*_x41
            - 0.016129321407969507*_x45 - 0.582374038291501*_x7 - 0.582374038291501*_x8)
        _iPsi0 = _x48
        _x49 = (1.0/math.sqrt(_x48))
        _x50 = math.sqrt(_D)
        _x51 = math.sqrt(m)
        _x52 = _x50*_x51
        _ift0 = _x49*_x52
        _x53 = (0.5)/_x50
        _x54 = _x51*_x53
        _pd__28 = _x49*_x54
        _x55 = _x48**(-1.5)
        _x56 = (0.5)*_x52
        _pd__29 = -_x55*_x56
        _x57 = (1.0/_x51)
        _x58 = _x50*_x57
        _x59 = _x100**2
        _x60 = _x49*_x59
        _x61 = _x58*_x60
        _ifq0 = _P0*_x61
        _x62 = _x53*_x57
        _pd__30 = _P0*_x60*_x62
        _pd__31 = _x61
        _x63 = (0.5)*_x58
        _pd__32 = -_P0*_x55*_x59*_x63
        _pd__33 = -_x11*_x14*_x49*_x58
        _x64 = g_s*m**(1.5)
        _x65 = _x50*_x64
        _x66 = _x49*_x65
        _x67 = _x15*_x66
        _ifp0 = _x3*_x67
        _x68 = _x15*_x3
        _x69 = _x53*_x64
        _pd__34 = _x49*_x68*_x69
        _pd__35 = _x3*_x5*_x66
        _x70 = (0.5)*_x65
        _pd__36 = -_x55*_x68*_x70
        _pd__37 = _x67
        _x71 = (0.16000937841634696*_x10*_x11*_x9 + 0.39252437029865583*_x10*_x22*_x23
            + 0.017475652789475504*_x10*_x42*_x43 - 0.39252437029865583*_x20 - 0.39252437029865583*_x21
            + 0.0700094015044783*_x28*k_d + 0.0700094015044783*_x29*g_s*m - 0.0700094015044783*_x35
            - 0.017475652789475504*_x40 - 0.017475652789475504*_x41 - 0.16000937841634696*_x7
            - 0.16000937841634696*_x8 + 0.5*k_d*l0)
        _iPsi1 = _x71
        _x72 = (1.0/math.sqrt(_x71))
        _ift1 = _x52*_x72
        _pd__38 = _x54*_x72
        _x73 = _x71**(-1.5)
        _pd__39 = -_x56*_x73
        _x74 = _x98**2
        _x75 = _x72*_x74
        _x76 = _x58*_x75
        _ifq1 = _P1*_x76
        _pd__40 = _P1*_x62*_x75
        _pd__41 = _x76
        _pd__42 = -_P1*_x63*_x73*_x74
        _pd__43 = -_x23*_x26*_x58*_x72
        _x77 = _x65*_x72
        _x78 = _x27*_x77
        _ifp1 = _x18*_x78
        _x79 = _x18*_x27
        _pd__44 = _x69*_x72*_x79
        _pd__45 = _x18*_x19*_x77
        _pd__46 = -_x70*_x73*_x79
        _pd__47 = _x78
        _x80 = (0.01613725546399532*_x10*_x11*_x9 + 0.2848443432415939*_x10*_x22*_x23
            + 0.21871326539550162*_x10*_x32*_x33 - 0.2848443432415939*_x20 - 0.2848443432415939*_x21
            - 0.21871326539550162*_x30 - 0.21871326539550162*_x31 + 0.019694864101090868*_x38*k_d
            + 0.019694864101090868*_x39*g_s*m - 0.019694864101090868*_x45 - 0.01613725546399532*_x7
            - 0.01613725546399532*_x8 + 0.5*k_d*l0)
        _iPsi2 = _x80
        _x81 = (1.0/math.sqrt(_x80))
        _ift2 = _x52*_x81
        _pd__48 = _x54*_x81
        _x82 = _x80**(-1.5)
        _pd__49 = -_x56*_x82
        _x83 = _x99**2
        _x84 = _x81*_x83
        _x85 = _x58*_x84
        _ifq2 = _P2*_x85
        _pd__50 = _P2*_x62*_x84
        _pd__51 = _x85
        _pd__52 = -_P2*_x63*_x82*_x83
        _pd__53 = -_x33*_x36*_x58*_x81
        _x86 = _x65*_x81
        _x87 = _x37*_x86
        _ifp2 = _x28*_x87
        _x88 = _x28*_x37
        _pd__54 = _x69*_x81*_x88
        _pd__55 = _x28*_x29*_x86
        _pd__56 = -_x70*_x82*_x88
        _pd__57 = _x87
        _x89 = (0.01796104633752054*_x10*_x11*_x9 + 0.11000222456933441*_x10*_x22*_x23
            + 0.2823150697454702*_x10*_x32*_x33 + 0.08972165934767481*_x10*_x42*_x43
            - 0.11000222456933441*_x20 - 0.11000222456933441*_x21 - 0.2823150697454702*_x30
            - 0.2823150697454702*_x31 - 0.08972165934767481*_x40 - 0.08972165934767481*_x41
            - 0.01796104633752054*_x7 - 0.01796104633752054*_x8 + 0.5*k_d*l0)
        _iPsi3 = _x89
        _x90 = (1.0/math.sqrt(_x89))
        _ift3 = _x52*_x90
        _pd__58 = _x54*_x90
        _x91 = _x89**(-1.5)
        _pd__59 = -_x56*_x91
        _x92 = _x101**2
        _x93 = _x90*_x92
        _x94 = _x58*_x93
        _ifq3 = _P3*_x94
        _pd__60 = _P3*_x62*_x93
        _pd__61 = _x94
        _pd__62 = -_P3*_x63*_x91*_x92
        _pd__63 = -_x43*_x46*_x58*_x90
        _x95 = _x65*_x90
        _x96 = _x47*_x95
        _ifp3 = _x38*_x96
        _x97 = _x38*_x47
        _pd__64 = _x69*_x90*_x97
        _pd__65 = _x38*_x39*_x95
        _pd__66 = -_x70*_x91*_x97
        _pd__67 = _x96
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_d__j = _T[2, _j1]
            d_q_r__j = _T[3, _j1]
            _d_D__j = _T[6, _j1]
            _d_Q0__j = _T[7, _j1]
            _d_Q1__j = _T[8, _j1]
            _d_Q2__j = _T[9, _j1]
            _d_Q3__j = _T[10, _j1]
            _d_P0__j = _T[11, _j1]
            _d_P1__j = _T[12, _j1]
            _d_P2__j = _T[13, _j1]
            _d_P3__j = _T[14, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.004820780989426014*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__12 + _d_Q0__j*_pd__13 + _d_isigma0__j*_pd__14 + _pd__15*d_k_d__j
            _d_isigma1__j = 0.10890625570683385*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__16 + _d_Q1__j*_pd__17 + _d_isigma1__j*_pd__18 + _pd__19*d_k_d__j
            _d_isigma2__j = 0.44888729929169013*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__20 + _d_Q2__j*_pd__21 + _d_isigma2__j*_pd__22 + _pd__23*d_k_d__j
            _d_isigma3__j = 0.8659570925834786*_d_D__j + d_q_r__j
            _d_iF3__j = _d_P3__j*_pd__24 + _d_Q3__j*_pd__25 + _d_isigma3__j*_pd__26 + _pd__27*d_k_d__j
            _d_iPsi0__j = (0.582374038291501*_d_iF0__j - 0.12383458041329967*_d_iF1__j
                + 0.0575898635297681*_d_iF2__j - 0.016129321407969507*_d_iF3__j)
            _d_ift0__j = _d_D__j*_pd__28 + _d_iPsi0__j*_pd__29
            _d_ifq0__j = _d_D__j*_pd__30 + _d_P0__j*_pd__31 + _d_iPsi0__j*_pd__32 + _d_isigma0__j*_pd__33
            _d_ifp0__j = _d_D__j*_pd__34 + _d_Q0__j*_pd__35 + _d_iPsi0__j*_pd__36 + _d_isigma0__j*_pd__37
            _d_iPsi1__j = (0.16000937841634696*_d_iF0__j + 0.39252437029865583*_d_iF1__j
                - 0.0700094015044783*_d_iF2__j + 0.017475652789475504*_d_iF3__j)
            _d_ift1__j = _d_D__j*_pd__38 + _d_iPsi1__j*_pd__39
            _d_ifq1__j = _d_D__j*_pd__40 + _d_P1__j*_pd__41 + _d_iPsi1__j*_pd__42 + _d_isigma1__j*_pd__43
            _d_ifp1__j = _d_D__j*_pd__44 + _d_Q1__j*_pd__45 + _d_iPsi1__j*_pd__46 + _d_isigma1__j*_pd__47
            _d_iPsi2__j = (0.01613725546399532*_d_iF0__j + 0.2848443432415939*_d_iF1__j
                + 0.21871326539550162*_d_iF2__j - 0.019694864101090868*_d_iF3__j)
            _d_ift2__j = _d_D__j*_pd__48 + _d_iPsi2__j*_pd__49
            _d_ifq2__j = _d_D__j*_pd__50 + _d_P2__j*_pd__51 + _d_iPsi2__j*_pd__52 + _d_isigma2__j*_pd__53
            _d_ifp2__j = _d_D__j*_pd__54 + _d_Q2__j*_pd__55 + _d_iPsi2__j*_pd__56 + _d_isigma2__j*_pd__57
            _d_iPsi3__j = (0.01796104633752054*_d_iF0__j + 0.11000222456933441*_d_iF1__j
                + 0.2823150697454702*_d_iF2__j + 0.08972165934767481*_d_iF3__j)
            _d_ift3__j = _d_D__j*_pd__58 + _d_iPsi3__j*_pd__59
            _d_ifq3__j = _d_D__j*_pd__60 + _d_P3__j*_pd__61 + _d_iPsi3__j*_pd__62 + _d_isigma3__j*_pd__63
            _d_ifp3__j = _d_D__j*_pd__64 + _d_Q3__j*_pd__65 + _d_iPsi3__j*_pd__66 + _d_isigma3__j*_pd__67
            _T[15, _j1] = _d_iF0__j
            _T[16, _j1] = _d_iF1__j
            _T[17, _j1] = _d_iF2__j
            _T[18, _j1] = _d_iF3__j
            _T[19, _j1] = _d_ift0__j
            _T[20, _j1] = _d_ifq0__j
            _T[21, _j1] = _d_ifp0__j
            _T[22, _j1] = _d_ift1__j
            _T[23, _j1] = _d_ifq1__j
            _T[24, _j1] = _d_ifp1__j
            _T[25, _j1] = _d_ift2__j
            _T[26, _j1] = _d_ifq2__j
            _T[27, _j1] = _d_ifp2__j
            _T[28, _j1] = _d_ift3__j
            _T[29, _j1] = _d_ifq3__j
            _T[30, _j1] = _d_ifp3__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2
            - 0.0035551496857956833*_ifq3 + q_th)
        _Q1__next = (0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2
            + 0.006735500594538156*_ifq3 + q_th)
        _Q2__next = (0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2
            - 0.014190694931141144*_ifq3 + q_th)
        _Q3__next = (0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _x102 = m*q_r**2
        _x103 = _x102*q_thd
        _P0__next = (0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2
            - 0.0035551496857956833*_ifp3 + _x103)
        _x104 = 2.0*m*q_r*q_thd
        _pd__68 = _x104
        _pd__69 = _x102
        _P1__next = (0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2
            + 0.006735500594538156*_ifp3 + _x103)
        _pd__70 = _x104
        _pd__71 = _x102
        _P2__next = (0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2
            - 0.014190694931141144*_ifp3 + _x103)
        _pd__72 = _x104
        _pd__73 = _x102
        _P3__next = (0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2
            + 0.08696371128436346*_ifp3 + _x103)
        _pd__74 = _x104
        _pd__75 = _x102
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_q_r__j = _T[3, _j2]
            d_q_th__j = _T[4, _j2]
            d_q_thd__j = _T[5, _j2]
            _d_D__j = _T[6, _j2]
            _d_ifq0__j = _T[20, _j2]
            _d_ifp0__j = _T[21, _j2]
            _d_ifq1__j = _T[23, _j2]
            _d_ifp1__j = _T[24, _j2]
            _d_ifq2__j = _T[26, _j2]
            _d_ifp2__j = _T[27, _j2]
            _d_ifq3__j = _T[29, _j2]
            _d_ifp3__j = _T[30, _j2]
            # next values
            _d_Q0__next__j = (0.08696371128436346*_d_ifq0__j - 0.026604180084998794*_d_ifq1__j
                + 0.012627462689404725*_d_ifq2__j - 0.0035551496857956833*_d_ifq3__j + d_q_th__j)
            _d_Q1__next__j = (0.18811811749986806*_d_ifq0__j + 0.16303628871563652*_d_ifq1__j
                - 0.027880428602470895*_d_ifq2__j + 0.006735500594538156*_d_ifq3__j + d_q_th__j)
            _d_Q2__next__j = (0.16719192197418878*_d_ifq0__j + 0.35395300603374397*_d_ifq1__j
                + 0.16303628871563652*_d_ifq2__j - 0.014190694931141144*_d_ifq3__j + d_q_th__j)
            _d_Q3__next__j = (0.1774825722545226*_d_ifq0__j + 0.31344511474186837*_d_ifq1__j
                + 0.35267675751627187*_d_ifq2__j + 0.08696371128436346*_d_ifq3__j + d_q_th__j)
            _d_P0__next__j = (0.08696371128436346*_d_ifp0__j - 0.026604180084998794*_d_ifp1__j
                + 0.012627462689404725*_d_ifp2__j - 0.0035551496857956833*_d_ifp3__j + _pd__68*d_q_r__j
                + _pd__69*d_q_thd__j)
            _d_P1__next__j = (0.18811811749986806*_d_ifp0__j + 0.16303628871563652*_d_ifp1__j
                - 0.027880428602470895*_d_ifp2__j + 0.006735500594538156*_d_ifp3__j + _pd__70*d_q_r__j
                + _pd__71*d_q_thd__j)
            _d_P2__next__j = (0.16719192197418878*_d_ifp0__j + 0.35395300603374397*_d_ifp1__j
                + 0.16303628871563652*_d_ifp2__j - 0.014190694931141144*_d_ifp3__j + _pd__72*d_q_r__j
                + _pd__73*d_q_thd__j)
            _d_P3__next__j = (0.1774825722545226*_d_ifp0__j + 0.31344511474186837*_d_ifp1__j
                + 0.35267675751627187*_d_ifp2__j + 0.08696371128436346*_d_ifp3__j + _pd__74*d_q_r__j
                + _pd__75*d_q_thd__j)
            _T[6, _j2] = _d_D__j
            _T[7, _j2] = _d_Q0__next__j
            _T[8, _j2] = _d_Q1__next__j
            _T[9, _j2] = _d_Q2__next__j
            _T[10, _j2] = _d_Q3__next__j
            _T[11, _j2] = _d_P0__next__j
            _T[12, _j2] = _d_P1__next__j
            _T[13, _j2] = _d_P2__next__j
            _T[14, _j2] = _d_P3__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _P0__next
        _n0_6 = _P1__next
        _n0_7 = _P2__next
        _n0_8 = _P3__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7
            - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    end_q_r = q_r_lo
    _x105 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x105
    _pd__76 = _x105/_D
    _pd__77 = _x105/_work
    _x106 = q_r**2
    _x107 = q_r_lo**-2
    _x108 = _x107/m
    end_q_thd = (_x108*(0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x106*m*q_thd))
    _x109 = 0.17392742256872692*_x108
    _pd__78 = _x109
    _x110 = 0.32607257743127305*_x108
    _pd__79 = _x110
    _pd__80 = _x110
    _pd__81 = _x109
    _pd__82 = 2.0*_x107*q_r*q_thd
    _pd__83 = _x106*_x107
    passes = _passes
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[3, _j3]
        d_q_th__j = _T[4, _j3]
        d_q_thd__j = _T[5, _j3]
        _d_D__j = _T[6, _j3]
        _d_iF0__j = _T[15, _j3]
        _d_iF1__j = _T[16, _j3]
        _d_iF2__j = _T[17, _j3]
        _d_iF3__j = _T[18, _j3]
        _d_ift0__j = _T[19, _j3]
        _d_ifq0__j = _T[20, _j3]
        _d_ifp0__j = _T[21, _j3]
        _d_ift1__j = _T[22, _j3]
        _d_ifq1__j = _T[23, _j3]
        _d_ifp1__j = _T[24, _j3]
        _d_ift2__j = _T[25, _j3]
        _d_ifq2__j = _T[26, _j3]
        _d_ifp2__j = _T[27, _j3]
        _d_ift3__j = _T[28, _j3]
        _d_ifq3__j = _T[29, _j3]
        _d_ifp3__j = _T[30, _j3]
        _d_work__j = (0.012076101706416622*_d_iF0__j + 0.1076070411358925*_d_iF1__j
            + 0.21846553629538057*_d_iF2__j + 0.1618513208623103*_d_iF3__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.17392742256872692*_d_ift0__j + 0.32607257743127305*_d_ift1__j
            + 0.32607257743127305*_d_ift2__j + 0.17392742256872692*_d_ift3__j)
        d_end_q_th__j = (0.17392742256872692*_d_ifq0__j + 0.32607257743127305*_d_ifq1__j
            + 0.32607257743127305*_d_ifq2__j + 0.17392742256872692*_d_ifq3__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__76 + _d_work__j*_pd__77
        d_end_q_thd__j = (_d_ifp0__j*_pd__78 + _d_ifp1__j*_pd__79 + _d_ifp2__j*_pd__80 + _d_ifp3__j*_pd__81
            + _pd__82*d_q_r__j + _pd__83*d_q_thd__j)
        _T[31, _j3] = d_t_half__j
        _T[32, _j3] = d_end_q_th__j
        _T[33, _j3] = d_end_q_rd__j
        _T[34, _j3] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[31, 0], _T[31, 1], _T[31, 2], _T[31, 3], _T[31, 4], _T[31, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[32, 0], _T[32, 1], _T[32, 2], _T[32, 3], _T[32, 4], _T[32, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[33, 0], _T[33, 1], _T[33, 2], _T[33, 3], _T[33, 4], _T[33, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[34, 0], _T[34, 1], _T[34, 2], _T[34, 3], _T[34, 4], _T[34, 5], )
    # derivatives of the outputs
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression):
    """The code of iterative_stance_jacobian's kernels per choice after their choice's own calls, shared by
    the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 185
    # chain rule through schwind_decompression
    d_t_decompression__q_r_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_t_decompression__q_r*d_bottom_q_r__q_r_td
        + _j_t_decompression__q_th*d_bottom_q_th__q_r_td + _j_t_decompression__q_thd*d_bottom_q_thd__q_r_td)
    d_t_decompression__q_rd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_rd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_rd_td + _j_t_decompression__q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_rd_td)
    d_t_decompression__q_th_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_th_td + _j_t_decompression__q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_th_td)
    d_t_decompression__q_thd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_thd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_thd_td + _j_t_decompression__q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_thd_td)
    d_t_decompression__k_c = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__k
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__k + _j_t_decompression__q_r*d_bottom_q_r__k_c
        + _j_t_decompression__q_th*d_bottom_q_th__k_c + _j_t_decompression__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_rd__q_r_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_rd__q_rd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_th_td + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_rd__q_thd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_rd__k_c = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_th__q_r_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_th__q_r*d_bottom_q_r__q_th_td + _j_liftoff_q_th__q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_th__q_thd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_th__k_c = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_th__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_th__q_th*d_bottom_q_th__k_c + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_thd__q_r_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_thd__q_rd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_th_td + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_thd__q_thd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_thd__k_c = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_c)
    t_stance = t_bottom + t_decompression
    d_t_stance__q_r_td = d_t_bottom__q_r_td + d_t_decompression__q_r_td
    d_t_stance__q_rd_td = d_t_bottom__q_rd_td + d_t_decompression__q_rd_td
    d_t_stance__q_th_td = d_t_bottom__q_th_td + d_t_decompression__q_th_td
    d_t_stance__q_thd_td = d_t_bottom__q_thd_td + d_t_decompression__q_thd_td
    d_t_stance__k_c = d_t_bottom__k_c + d_t_decompression__k_c
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN77 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__k_d = 0.0
    d_t_stance__k_d = _j_t_decompression__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_passes__q_r_td = 0.0
    d_passes__q_rd_td = 0.0
    d_passes__q_th_td = 0.0
    d_passes__q_thd_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN77 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
        d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td,
        d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td,
        d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td,
        d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN77 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td, 0.0,
        _j_z_b_q_th__q_th_td, 0.0, _j_z_b_q_r__q_thd_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 77); the columns are the outputs of
    :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer`, in order) and its status code to ``status[i]``
    (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`_store_row_11_77`).
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex, _j_foot_x__ground,
        _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_rd_td,
        _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d,
        _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_thd__k_c,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance):
    """The code of iterative_apex_return_jacobian's kernels per choice after their choice's own calls, shared
    by the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 183
    # chain rule through iterative_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = _j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_thd_td*_j_td_q_thd__ground
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__ground = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    # liftoff -> next apex: exact ballistic ascent
    _c0 = (liftoff_to_apex_jac_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f,
        direction))
    if _c0[20] != STATUS_OK:
        return _NAN91 + (_c0[20],)
    (apex_height, apex_speed, t_ascent, _, next_apex_x, _j_apex_height__q_rd, _j_apex_height__q_th,
        _j_apex_height__q_thd, _j_apex_speed__q_rd, _j_apex_speed__q_th, _j_apex_speed__q_thd,
        _j_t_ascent__q_rd, _j_t_ascent__q_th, _j_t_ascent__q_thd, _, _, _, _j_next_apex_x__q_rd,
        _j_next_apex_x__q_th, _j_next_apex_x__q_thd, _) = _c0
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_height__q_th*d_liftoff_q_th__q_th_td + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_rd*d_liftoff_q_rd__ground
        + _j_apex_height__q_th*d_liftoff_q_th__ground + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
    d_apex_height__k_c = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_height__q_th*_j_liftoff_q_th__k_c + _j_apex_height__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_height__k_d = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_height__q_th*_j_liftoff_q_th__k_d + _j_apex_height__q_thd*_j_liftoff_q_thd__k_d)
    d_apex_speed__b_y_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_y_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_speed__b_xd_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_speed__q_th_td = (_j_apex_speed__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_speed__q_th*d_liftoff_q_th__q_th_td + _j_apex_speed__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_speed__ground = (_j_apex_speed__q_rd*d_liftoff_q_rd__ground
        + _j_apex_speed__q_th*d_liftoff_q_th__ground + _j_apex_speed__q_thd*d_liftoff_q_thd__ground)
    d_apex_speed__k_c = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_c + _j_apex_speed__q_th*_j_liftoff_q_th__k_c
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_speed__k_d = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_d + _j_apex_speed__q_th*_j_liftoff_q_th__k_d
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_d)
    d_t_ascent__b_y_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_y_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_y_apex)
    d_t_ascent__b_xd_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_xd_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_t_ascent__q_th_td = (_j_t_ascent__q_rd*d_liftoff_q_rd__q_th_td
        + _j_t_ascent__q_th*d_liftoff_q_th__q_th_td + _j_t_ascent__q_thd*d_liftoff_q_thd__q_th_td)
    d_t_ascent__ground = (_j_t_ascent__q_rd*d_liftoff_q_rd__ground + _j_t_ascent__q_th*d_liftoff_q_th__ground
        + _j_t_ascent__q_thd*d_liftoff_q_thd__ground)
    d_t_ascent__k_c = (_j_liftoff_q_rd__k_c*_j_t_ascent__q_rd + _j_liftoff_q_th__k_c*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_rd__k_d*_j_t_ascent__q_rd + _j_liftoff_q_th__k_d*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
    d_next_apex_x__b_y_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_y_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_y_apex)
    d_next_apex_x__b_xd_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_xd_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_next_apex_x__q_th_td = (_j_next_apex_x__q_rd*d_liftoff_q_rd__q_th_td
        + _j_next_apex_x__q_th*d_liftoff_q_th__q_th_td + _j_next_apex_x__q_thd*d_liftoff_q_thd__q_th_td)
    d_next_apex_x__ground = (_j_next_apex_x__q_rd*d_liftoff_q_rd__ground
        + _j_next_apex_x__q_th*d_liftoff_q_th__ground + _j_next_apex_x__q_thd*d_liftoff_q_thd__ground)
    d_next_apex_x__k_c = (_j_liftoff_q_rd__k_c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_c*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_c*_j_next_apex_x__q_thd)
    d_next_apex_x__k_d = (_j_liftoff_q_rd__k_d*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_d*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_d*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_t_descent__b_y_apex = _j_t_descent__b_y_apex
    d_t_descent__b_xd_apex = 0.0
    d_t_descent__q_th_td = _j_t_descent__q_th_td
    d_t_descent__ground = _j_t_descent__ground
    d_t_descent__k_c = 0.0
    d_t_descent__k_d = 0.0
    d_t_stance__k_c = _j_t_stance__k_c
    d_t_stance__k_d = _j_t_stance__k_d
    d_liftoff_q_r__b_y_apex = 0.0
    d_liftoff_q_r__b_xd_apex = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__ground = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_step_length__k_c = d_next_apex_x__k_c
    d_step_length__k_d = d_next_apex_x__k_d
    d_foot_x__b_y_apex = _j_foot_x__b_y_apex
    d_foot_x__b_xd_apex = _j_foot_x__b_xd_apex
    d_foot_x__q_th_td = _j_foot_x__q_th_td
    d_foot_x__ground = _j_foot_x__ground
    d_foot_x__k_c = 0.0
    d_foot_x__k_d = 0.0
    d_foot_y__b_y_apex = -1.0
    d_foot_y__b_xd_apex = 0.0
    d_foot_y__q_th_td = 0.0
    d_foot_y__ground = 1.0
    d_foot_y__k_c = 0.0
    d_foot_y__k_d = 0.0
    d_passes__b_y_apex = 0.0
    d_passes__b_xd_apex = 0.0
    d_passes__q_th_td = 0.0
    d_passes__ground = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)
            and math.isfinite(passes)):
        return _NAN91 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
        d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex,
        d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex,
        d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d,
        d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c,
        d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td,
        d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex,
        d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c,
        d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td,
        d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c,
        d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td,
        d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d,
        d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c,
        d_foot_y__k_d, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__ground,
        d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

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
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 91); the columns are the outputs of
    :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`, in order) and its status code to
    ``status[i]`` (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`_store_row_13_91`).
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression):
    """The code of iterative_stance_jacobian's kernels per choice after their choice's own calls, shared by
    the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 193
    # chain rule through schwind_decompression
    d_t_decompression__q_r_td = (_j_t_decompression__guess_q_th*d_bottom_q_th__q_r_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_t_decompression__q_r*d_bottom_q_r__q_r_td
        + _j_t_decompression__q_th*d_bottom_q_th__q_r_td + _j_t_decompression__q_thd*d_bottom_q_thd__q_r_td)
    d_t_decompression__q_rd_td = (_j_t_decompression__guess_q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_rd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_rd_td + _j_t_decompression__q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_rd_td)
    d_t_decompression__q_th_td = (_j_t_decompression__guess_q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_th_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_th_td + _j_t_decompression__q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_th_td)
    d_t_decompression__q_thd_td = (_j_t_decompression__guess_q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_thd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_thd_td + _j_t_decompression__q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_thd_td)
    d_t_decompression__k_c = (_j_t_decompression__guess_q_th*d_bottom_q_th__k_c
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__k_c + _j_t_decompression__q_r*d_bottom_q_r__k_c
        + _j_t_decompression__q_th*d_bottom_q_th__k_c + _j_t_decompression__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_rd__q_r_td = (_j_liftoff_q_rd__guess_q_th*d_bottom_q_th__q_r_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_rd__q_rd_td = (_j_liftoff_q_rd__guess_q_th*d_bottom_q_th__q_rd_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__guess_q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_rd__q_thd_td = (_j_liftoff_q_rd__guess_q_th*d_bottom_q_th__q_thd_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_rd__k_c = (_j_liftoff_q_rd__guess_q_th*d_bottom_q_th__k_c
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_th__q_r_td = (_j_liftoff_q_th__guess_q_th*d_bottom_q_th__q_r_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_liftoff_q_th__guess_q_th*d_bottom_q_th__q_rd_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__guess_q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_th__q_thd_td = (_j_liftoff_q_th__guess_q_th*d_bottom_q_th__q_thd_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_th__k_c = (_j_liftoff_q_th__guess_q_th*d_bottom_q_th__k_c
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_th__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_th__q_th*d_bottom_q_th__k_c + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_thd__q_r_td = (_j_liftoff_q_thd__guess_q_th*d_bottom_q_th__q_r_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_thd__q_rd_td = (_j_liftoff_q_thd__guess_q_th*d_bottom_q_th__q_rd_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__guess_q_th*d_bottom_q_th__q_th_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_thd__q_thd_td = (_j_liftoff_q_thd__guess_q_th*d_bottom_q_th__q_thd_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_thd__k_c = (_j_liftoff_q_thd__guess_q_th*d_bottom_q_th__k_c
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_c)
    t_stance = t_bottom + t_decompression
    d_t_stance__q_r_td = d_t_bottom__q_r_td + d_t_decompression__q_r_td
    d_t_stance__q_rd_td = d_t_bottom__q_rd_td + d_t_decompression__q_rd_td
    d_t_stance__q_th_td = d_t_bottom__q_th_td + d_t_decompression__q_th_td
    d_t_stance__q_thd_td = d_t_bottom__q_thd_td + d_t_decompression__q_thd_td
    d_t_stance__k_c = d_t_bottom__k_c + d_t_decompression__k_c
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN77 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__k_d = 0.0
    d_t_stance__k_d = _j_t_decompression__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_passes__q_r_td = 0.0
    d_passes__q_rd_td = 0.0
    d_passes__q_th_td = 0.0
    d_passes__q_thd_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN77 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
        d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td,
        d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td,
        d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td,
        d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 122
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x6 = m*q_rd_td**2
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    z_b_q_r = _x11
    _x12 = (1.0/_x8)
    _x13 = (0.5)*_x7
    _x14 = _x10**2
    _x15 = _x14*_x6
    d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
    d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
    _x16 = _x2*math.sin(q_th_td)
    _x17 = _x12*_x7
    d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
    _x18 = 2.0*q_r_td
    _x19 = _x18*q_thd_td
    _x20 = _x19*m
    d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
    d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
    z_b_q_th = q_th_td
    _x21 = q_r_td**2
    _x24 = (1.0/_x11)
    _x22 = _x24**2
    _x23 = _x21*_x22
    z_b_q_thd = _x23*q_thd_td
    _pd__0 = -2.0*_x21*_x24**3*q_thd_td
    d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
    d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
    d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
    d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
    d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, d_z_b_q_r__q_r_td, 0.0, d_z_b_q_thd__q_r_td,
        d_z_b_q_r__q_rd_td, 0.0, d_z_b_q_thd__q_rd_td, d_z_b_q_r__q_th_td, 1.0, d_z_b_q_thd__q_th_td,
        d_z_b_q_r__q_thd_td, 0.0, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, 0.0, d_z_b_q_thd__k_c))
    if _c0[36] != STATUS_OK:
        return _NAN77 + (_c0[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c0
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x25 = q_r_lo**-2
    _x26 = _x25*bottom_q_r**2
    g_lo_q_thd = _x26*bottom_q_thd
    _pd__1 = 2.0*_x25*bottom_q_r*bottom_q_thd
    _pd__2 = _x26
    d_g_lo_q_thd__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _pd__2*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td + _pd__2*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__1*d_bottom_q_r__q_th_td + _pd__2*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td + _pd__2*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__1*d_bottom_q_r__k_c + _pd__2*d_bottom_q_thd__k_c
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c1
    # the code shared between choices
    return (iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_held`: arguments, out and status
    as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_held`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression):
    """The code of iterative_stance_jacobian's kernels per choice after their choice's own calls, shared by
    the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 193
    # chain rule through schwind_decompression
    d_t_decompression__q_r_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_t_decompression__q_r*d_bottom_q_r__q_r_td
        + _j_t_decompression__q_th*d_bottom_q_th__q_r_td + _j_t_decompression__q_thd*d_bottom_q_thd__q_r_td)
    d_t_decompression__q_rd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_rd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_rd_td + _j_t_decompression__q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_rd_td)
    d_t_decompression__q_th_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_th_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_th_td + _j_t_decompression__q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_th_td)
    d_t_decompression__q_thd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_thd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_thd_td + _j_t_decompression__q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_thd_td)
    d_t_decompression__k_c = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__k
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__k + _j_t_decompression__q_r*d_bottom_q_r__k_c
        + _j_t_decompression__q_th*d_bottom_q_th__k_c + _j_t_decompression__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_rd__q_r_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_rd__q_rd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_rd__q_thd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_rd__k_c = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_th__q_r_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_th__q_thd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_th__k_c = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_th__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_th__q_th*d_bottom_q_th__k_c + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_thd__q_r_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_thd__q_rd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_thd__q_thd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_thd__k_c = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__k
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__k + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_c)
    t_stance = t_bottom + t_decompression
    d_t_stance__q_r_td = d_t_bottom__q_r_td + d_t_decompression__q_r_td
    d_t_stance__q_rd_td = d_t_bottom__q_rd_td + d_t_decompression__q_rd_td
    d_t_stance__q_th_td = d_t_bottom__q_th_td + d_t_decompression__q_th_td
    d_t_stance__q_thd_td = d_t_bottom__q_thd_td + d_t_decompression__q_thd_td
    d_t_stance__k_c = d_t_bottom__k_c + d_t_decompression__k_c
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN77 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__k_d = 0.0
    d_t_stance__k_d = _j_t_decompression__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_passes__q_r_td = 0.0
    d_passes__q_rd_td = 0.0
    d_passes__q_th_td = 0.0
    d_passes__q_thd_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN77 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
        d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td,
        d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td,
        d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td,
        d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_4_jvp6_a742c3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5,
        d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

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
        d_guess_q_r__0: direction 0: its component along guess_q_r
        d_guess_q_th__0: direction 0: its component along guess_q_th
        d_guess_q_thd__0: direction 0: its component along guess_q_thd
        d_guess_q_r__1: direction 1: its component along guess_q_r
        d_guess_q_th__1: direction 1: its component along guess_q_th
        d_guess_q_thd__1: direction 1: its component along guess_q_thd
        d_guess_q_r__2: direction 2: its component along guess_q_r
        d_guess_q_th__2: direction 2: its component along guess_q_th
        d_guess_q_thd__2: direction 2: its component along guess_q_thd
        d_guess_q_r__3: direction 3: its component along guess_q_r
        d_guess_q_th__3: direction 3: its component along guess_q_th
        d_guess_q_thd__3: direction 3: its component along guess_q_thd
        d_guess_q_r__4: direction 4: its component along guess_q_r
        d_guess_q_th__4: direction 4: its component along guess_q_th
        d_guess_q_thd__4: direction 4: its component along guess_q_thd
        d_guess_q_r__5: direction 5: its component along guess_q_r
        d_guess_q_th__5: direction 5: its component along guess_q_th
        d_guess_q_thd__5: direction 5: its component along guess_q_thd

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1022
    # inputs: finite and inside their domains
    if not _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((41, 6))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (d_guess_q_r__0, d_guess_q_r__1,
        d_guess_q_r__2, d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (d_guess_q_th__0, d_guess_q_th__1,
        d_guess_q_th__2, d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], _T[6, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], _T[7, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    # the initial values
    _x0 = 1.8611363115940527*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.9305681557970263*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.13886368840594743*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.06943184420297371*_x5
    _x6 = _x1*m
    _pd__4 = 1.3399810435848563*_x6
    _pd__5 = 0.6699905217924281*_x2
    _pd__6 = 0.6600189564151437*_x4
    _pd__7 = 0.33000947820757187*_x5
    _pd__8 = 0.6600189564151437*_x6
    _pd__9 = 0.33000947820757187*_x2
    _pd__10 = 1.3399810435848563*_x4
    _pd__11 = 0.6699905217924281*_x5
    _pd__12 = 0.13886368840594743*_x6
    _pd__13 = 0.06943184420297371*_x2
    _pd__14 = _x0*_x3
    _pd__15 = 0.9305681557970263*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.9305681557970263*d_guess_q_th__j + 0.06943184420297371*d_q_th__j
        _d_Q1__start__j = 0.6699905217924281*d_guess_q_th__j + 0.33000947820757187*d_q_th__j
        _d_Q2__start__j = 0.33000947820757187*d_guess_q_th__j + 0.6699905217924281*d_q_th__j
        _d_Q3__start__j = 0.06943184420297371*d_guess_q_th__j + 0.9305681557970263*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _d_P3__start__j = (_pd__12*d_guess_q_r__j + _pd__13*d_guess_q_thd__j + _pd__14*d_q_r__j
            + _pd__15*d_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_Q3__start__j
        _T[13, _j0] = _d_P0__start__j
        _T[14, _j0] = _d_P1__start__j
        _T[15, _j0] = _d_P2__start__j
        _T[16, _j0] = _d_P3__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9951792190105739*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x109 = (1.0/_x9)
        _x17 = _x109**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__16 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__17 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__18 = -_x109**4*_x15*_x22 - k_c
        _pd__19 = _x8 + l0
        _x23 = 0.8910937442931661*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x106 = (1.0/_x24)
        _x29 = _x106**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__20 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__21 = _x12*_x33
        _pd__22 = -_x106**4*_x22*_x28 - k_c
        _pd__23 = _x23 + l0
        _x34 = 0.5511127007083099*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x107 = (1.0/_x35)
        _x40 = _x107**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__24 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__25 = _x12*_x44
        _pd__26 = -_x107**4*_x22*_x39 - k_c
        _pd__27 = _x34 + l0
        _x45 = 0.13404290741652142*_D + _x7
        _x46 = -_x45
        _isigma3 = _x46
        _x47 = math.cos(_Q3)
        _x48 = _x12*_x47
        _x49 = _x46*k_c
        _x50 = _P3**2
        _x108 = (1.0/_x46)
        _x51 = _x108**3
        _x52 = _x16*_x51
        _x53 = _x50*_x52
        _iF3 = _x10 - _x48 - _x49 + _x53
        _x54 = 2.0*_P3
        _pd__28 = _x52*_x54
        _x55 = math.sin(_Q3)
        _pd__29 = _x12*_x55
        _pd__30 = -_x108**4*_x22*_x50 - k_c
        _pd__31 = _x45 + l0
        _x56 = (0.5*_x10 - 0.582374038291501*_x13 - 0.582374038291501*_x14 + 0.582374038291501*_x19
            + 0.12383458041329967*_x26 + 0.12383458041329967*_x27 - 0.12383458041329967*_x31
            - 0.0575898635297681*_x37 - 0.0575898635297681*_x38 + 0.0575898635297681*_x42
            + 0.016129321407969507*_x48 + 0.016129321407969507*_x49 - 0.016129321407969507*_x53)
        _iPsi0 = _x56
        _x57 = (1.0/math.sqrt(_x56))
        _x58 = math.sqrt(_D)
        _x59 = math.sqrt(m)
        _x60 = _x58*_x59
        _ift0 = _x57*_x60
        _x61 = (0.5)/_x58
        _x62 = _x59*_x61
        _pd__32 = _x57*_x62
        _x63 = _x56**(-1.5)
        _x64 = (0.5)*_x60
        _pd__33 = -_x63*_x64
        _x65 = (1.0/_x59)
        _x66 = _x58*_x65
        _x67 = _x109**2
        _x68 = _x57*_x67
        _x69 = _x66*_x68
        _ifq0 = _P0*_x69
        _x70 = _x61*_x65
        _pd__34 = _P0*_x68*_x70
        _pd__35 = _x69
        _x71 = (0.5)*_x66
        _pd__36 = -_P0*_x63*_x67*_x71
        _pd__37 = -_x17*_x20*_x57*_x66
        _x72 = g_s*m**(1.5)
        _x73 = _x58*_x72
        _x74 = _x57*_x73
        _x75 = _x21*_x74
        _ifp0 = _x75*_x9
        _x76 = _x21*_x9
        _x77 = _x61*_x72
        _pd__38 = _x57*_x76*_x77
        _pd__39 = _x11*_x74*_x9
        _x78 = (0.5)*_x73
        _pd__40 = -_x63*_x76*_x78
        _pd__41 = _x75
        _x79 = (-0.16000937841634696*_x13 - 0.16000937841634696*_x14 + 0.16000937841634696*_x15*_x16*_x17
            + 0.39252437029865583*_x16*_x28*_x29 + 0.017475652789475504*_x16*_x50*_x51
            - 0.39252437029865583*_x26 - 0.39252437029865583*_x27 + 0.0700094015044783*_x35*k_c
            + 0.0700094015044783*_x36*g_s*m - 0.0700094015044783*_x42 - 0.017475652789475504*_x48
            - 0.017475652789475504*_x49 + 0.5*k_c*l0)
        _iPsi1 = _x79
        _x80 = (1.0/math.sqrt(_x79))
        _ift1 = _x60*_x80
        _pd__42 = _x62*_x80
        _x81 = _x79**(-1.5)
        _pd__43 = -_x64*_x81
        _x82 = _x106**2
        _x83 = _x80*_x82
        _x84 = _x66*_x83
        _ifq1 = _P1*_x84
        _pd__44 = _P1*_x70*_x83
        _pd__45 = _x84
        _pd__46 = -_P1*_x71*_x81*_x82
        _pd__47 = -_x29*_x32*_x66*_x80
        _x85 = _x73*_x80
        _x86 = _x33*_x85
        _ifp1 = _x24*_x86
        _x87 = _x24*_x33
        _pd__48 = _x77*_x80*_x87
        _pd__49 = _x24*_x25*_x85
        _pd__50 = -_x78*_x81*_x87
        _pd__51 = _x86
        _x88 = (-0.01613725546399532*_x13 - 0.01613725546399532*_x14 + 0.01613725546399532*_x15*_x16*_x17
            + 0.2848443432415939*_x16*_x28*_x29 + 0.21871326539550162*_x16*_x39*_x40 - 0.2848443432415939*_x26
            - 0.2848443432415939*_x27 - 0.21871326539550162*_x37 - 0.21871326539550162*_x38
            + 0.019694864101090868*_x46*k_c + 0.019694864101090868*_x47*g_s*m - 0.019694864101090868*_x53
            + 0.5*k_c*l0)
        _iPsi2 = _x88
        _x89 = (1.0/math.sqrt(_x88))
        _ift2 = _x60*_x89
        _pd__52 = _x62*_x89
        _x90 = _x88**(-1.5)
        _pd__53 = -_x64*_x90
        _x91 = _x107**2
        _x92 = _x89*_x91
        _x93 = _x66*_x92
        _ifq2 = _P2*_x93
        _pd__54 = _P2*_x70*_x92
        _pd__55 = _x93
        _pd__56 = -_P2*_x71*_x90*_x91
        _pd__57 = -_x40*_x43*_x66*_x89
        _x94 = _x73*_x89
        _x95 = _x44*_x94
        _ifp2 = _x35*_x95
        _x96 = _x35*_x44
        _pd__58 = _x77*_x89*_x96
        _pd__59 = _x35*_x36*_x94
        _pd__60 = -_x78*_x90*_x96
        _pd__61 = _x95
        _x97 = (-0.01796104633752054*_x13 - 0.01796104633752054*_x14 + 0.01796104633752054*_x15*_x16*_x17
            + 0.11000222456933441*_x16*_x28*_x29 + 0.2823150697454702*_x16*_x39*_x40
            + 0.08972165934767481*_x16*_x50*_x51 - 0.11000222456933441*_x26 - 0.11000222456933441*_x27
            - 0.2823150697454702*_x37 - 0.2823150697454702*_x38 - 0.08972165934767481*_x48
            - 0.08972165934767481*_x49 + 0.5*k_c*l0)
        _iPsi3 = _x97
        _x98 = (1.0/math.sqrt(_x97))
        _ift3 = _x60*_x98
        _pd__62 = _x62*_x98
        _x99 = _x97**(-1.5)
        _pd__63 = -_x64*_x99
        _x100 = _x108**2
        _x101 = _x100*_x98
        _x102 = _x101*_x66
        _ifq3 = _P3*_x102
        _pd__64 = _P3*_x101*_x70
        _pd__65 = _x102
        _pd__66 = -_P3*_x100*_x71*_x99
        _pd__67 = -_x51*_x54*_x66*_x98
        _x103 = _x73*_x98
        _x104 = _x103*_x55
        _ifp3 = _x104*_x46
        _x105 = _x46*_x55
        _pd__68 = _x105*_x77*_x98
        _pd__69 = _x103*_x46*_x47
        _pd__70 = -_x105*_x78*_x99
        _pd__71 = _x104
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_Q3__j = _T[12, _j1]
            _d_P0__j = _T[13, _j1]
            _d_P1__j = _T[14, _j1]
            _d_P2__j = _T[15, _j1]
            _d_P3__j = _T[16, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x110 = -d_q_r__j
            _d_isigma0__j = -0.9951792190105739*_d_D__j - _x110
            _d_iF0__j = _d_P0__j*_pd__16 + _d_Q0__j*_pd__17 + _d_isigma0__j*_pd__18 + _pd__19*d_k_c__j
            _d_isigma1__j = -0.8910937442931661*_d_D__j - _x110
            _d_iF1__j = _d_P1__j*_pd__20 + _d_Q1__j*_pd__21 + _d_isigma1__j*_pd__22 + _pd__23*d_k_c__j
            _d_isigma2__j = -0.5511127007083099*_d_D__j - _x110
            _d_iF2__j = _d_P2__j*_pd__24 + _d_Q2__j*_pd__25 + _d_isigma2__j*_pd__26 + _pd__27*d_k_c__j
            _d_isigma3__j = -0.13404290741652142*_d_D__j - _x110
            _d_iF3__j = _d_P3__j*_pd__28 + _d_Q3__j*_pd__29 + _d_isigma3__j*_pd__30 + _pd__31*d_k_c__j
            _d_iPsi0__j = (0.582374038291501*_d_iF0__j - 0.12383458041329967*_d_iF1__j
                + 0.0575898635297681*_d_iF2__j - 0.016129321407969507*_d_iF3__j)
            _d_ift0__j = _d_D__j*_pd__32 + _d_iPsi0__j*_pd__33
            _d_ifq0__j = _d_D__j*_pd__34 + _d_P0__j*_pd__35 + _d_iPsi0__j*_pd__36 + _d_isigma0__j*_pd__37
            _d_ifp0__j = _d_D__j*_pd__38 + _d_Q0__j*_pd__39 + _d_iPsi0__j*_pd__40 + _d_isigma0__j*_pd__41
            _d_iPsi1__j = (0.16000937841634696*_d_iF0__j + 0.39252437029865583*_d_iF1__j
                - 0.0700094015044783*_d_iF2__j + 0.017475652789475504*_d_iF3__j)
            _d_ift1__j = _d_D__j*_pd__42 + _d_iPsi1__j*_pd__43
            _d_ifq1__j = _d_D__j*_pd__44 + _d_P1__j*_pd__45 + _d_iPsi1__j*_pd__46 + _d_isigma1__j*_pd__47
            _d_ifp1__j = _d_D__j*_pd__48 + _d_Q1__j*_pd__49 + _d_iPsi1__j*_pd__50 + _d_isigma1__j*_pd__51
            _d_iPsi2__j = (0.01613725546399532*_d_iF0__j + 0.2848443432415939*_d_iF1__j
                + 0.21871326539550162*_d_iF2__j - 0.019694864101090868*_d_iF3__j)
            _d_ift2__j = _d_D__j*_pd__52 + _d_iPsi2__j*_pd__53
            _d_ifq2__j = _d_D__j*_pd__54 + _d_P2__j*_pd__55 + _d_iPsi2__j*_pd__56 + _d_isigma2__j*_pd__57
            _d_ifp2__j = _d_D__j*_pd__58 + _d_Q2__j*_pd__59 + _d_iPsi2__j*_pd__60 + _d_isigma2__j*_pd__61
            _d_iPsi3__j = (0.01796104633752054*_d_iF0__j + 0.11000222456933441*_d_iF1__j
                + 0.2823150697454702*_d_iF2__j + 0.08972165934767481*_d_iF3__j)
            _d_ift3__j = _d_D__j*_pd__62 + _d_iPsi3__j*_pd__63
            _d_ifq3__j = _d_D__j*_pd__64 + _d_P3__j*_pd__65 + _d_iPsi3__j*_pd__66 + _d_isigma3__j*_pd__67
            _d_ifp3__j = _d_D__j*_pd__68 + _d_Q3__j*_pd__69 + _d_iPsi3__j*_pd__70 + _d_isigma3__j*_pd__71
            _T[17, _j1] = _d_isigma0__j
            _T[18, _j1] = _d_iF0__j
            _T[19, _j1] = _d_isigma1__j
            _T[20, _j1] = _d_iF1__j
            _T[21, _j1] = _d_isigma2__j
            _T[22, _j1] = _d_iF2__j
            _T[23, _j1] = _d_isigma3__j
            _T[24, _j1] = _d_iF3__j
            _T[25, _j1] = _d_ift0__j
            _T[26, _j1] = _d_ifq0__j
            _T[27, _j1] = _d_ifp0__j
            _T[28, _j1] = _d_ift1__j
            _T[29, _j1] = _d_ifq1__j
            _T[30, _j1] = _d_ifp1__j
            _T[31, _j1] = _d_ift2__j
            _T[32, _j1] = _d_ifq2__j
            _T[33, _j1] = _d_ifp2__j
            _T[34, _j1] = _d_ift3__j
            _T[35, _j1] = _d_ifq3__j
            _T[36, _j1] = _d_ifp3__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x111 = m*q_rd**2
        _x112 = -q_r
        _x113 = k_c*(_x112 + l0)
        _x114 = -l0
        _x115 = -_isigma0 - _x114
        _x116 = 0.024152203412833244*k_c
        _x117 = -_isigma1 - _x114
        _x118 = 0.215214082271785*k_c
        _x119 = -_isigma2 - _x114
        _x120 = 0.43693107259076114*k_c
        _x121 = -_isigma3 - _x114
        _x122 = 0.3237026417246206*k_c
        _x123 = (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 + _x113 - _x115*_x116 - _x117*_x118 - _x119*_x120 - _x121*_x122)
        _x124 = math.sqrt(_x111*k_c + _x123**2)
        _x125 = _x123 + _x124
        _x126 = (1.0/_x125)
        _D__next = _x111*_x126
        _x127 = _x115*k_c
        _x128 = 0.0051978942923343804*k_c
        _x129 = _x119*k_c
        _x130 = _x121*k_c
        _x131 = (1.0/_x124)
        _x132 = _x126**2
        _x133 = _x111*_x132
        _pd__72 = (_x133*(-_x131*(0.0005833289296948737*_iF0 + 0.0051978942923343804*_iF1
            + 0.01055284814259947*_iF2 + 0.007818132048204519*_iF3 + 0.024152203412833244*_x113 - _x117*_x128
            - 0.0005833289296948737*_x127 - 0.01055284814259947*_x129 - 0.007818132048204519*_x130)
            - 0.024152203412833244))
        _x134 = _x117*k_c
        _pd__73 = (_x133*(-_x131*(0.0051978942923343804*_iF0 + 0.046317101208086645*_iF1
            + 0.09403371980364733*_iF2 + 0.06966536696771665*_iF3 + 0.215214082271785*_x113 - _x115*_x128
            - 0.09403371980364733*_x129 - 0.06966536696771665*_x130 - 0.046317101208086645*_x134)
            - 0.215214082271785))
        _pd__74 = (_x133*(-_x131*(0.01055284814259947*_iF0 + 0.09403371980364733*_iF1
            + 0.19090876219531297*_iF2 + 0.14143574244920135*_iF3 + 0.43693107259076114*_x113
            - 0.01055284814259947*_x127 - 0.19090876219531297*_x129 - 0.14143574244920135*_x130
            - 0.09403371980364733*_x134) - 0.43693107259076114))
        _pd__75 = (_x133*(-_x131*(0.007818132048204519*_iF0 + 0.06966536696771665*_iF1
            + 0.14143574244920135*_iF2 + 0.10478340025949809*_iF3 + 0.3237026417246206*_x113
            - 0.007818132048204519*_x127 - 0.14143574244920135*_x129 - 0.10478340025949809*_x130
            - 0.06966536696771665*_x134) - 0.3237026417246206))
        _x135 = _x123*_x131
        _pd__76 = _x133*(-_x116*_x135 - _x116)
        _pd__77 = _x133*(-_x118*_x135 - _x118)
        _pd__78 = _x133*(-_x120*_x135 - _x120)
        _pd__79 = _x133*(-_x122*_x135 - _x122)
        _x136 = 2.0*q_r
        _pd__80 = (_x133*(-0.024152203412833244*_isigma0 - 0.215214082271785*_isigma1
            - 0.43693107259076114*_isigma2 - 0.3237026417246206*_isigma3 - _x112 - _x131*((0.5)*_x111
            + (0.5)*_x123*(0.04830440682566649*_isigma0 + 0.43042816454357*_isigma1
            + 0.8738621451815223*_isigma2 + 0.6474052834492412*_isigma3 - _x136 - 8.470329472543003e-22*l0))
            + 4.235164736271502e-22*l0))
        _pd__81 = _x133*(_x135*k_c + k_c)
        _pd__82 = 2.0*_x126*m*q_rd - _x131*_x132*k_c*m**2*q_rd**3
        _Q0__next = (0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2
            + 0.1774825722545226*_ifq3 + q_th)
        _Q1__next = (-0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2
            + 0.16719192197418878*_ifq3 + q_th)
        _Q2__next = (0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2
            + 0.18811811749986806*_ifq3 + q_th)
        _Q3__next = (-0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _x137 = m*q_r**2
        _x138 = _x137*q_thd
        _P0__next = (0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2
            + 0.1774825722545226*_ifp3 + _x138)
        _x139 = _x136*m*q_thd
        _pd__83 = _x139
        _pd__84 = _x137
        _P1__next = (-0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2
            + 0.16719192197418878*_ifp3 + _x138)
        _pd__85 = _x139
        _pd__86 = _x137
        _P2__next = (0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2
            + 0.18811811749986806*_ifp3 + _x138)
        _pd__87 = _x139
        _pd__88 = _x137
        _P3__next = (-0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2
            + 0.08696371128436346*_ifp3 + _x138)
        _pd__89 = _x139
        _pd__90 = _x137
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[17, _j2]
            _d_iF0__j = _T[18, _j2]
            _d_isigma1__j = _T[19, _j2]
            _d_iF1__j = _T[20, _j2]
            _d_isigma2__j = _T[21, _j2]
            _d_iF2__j = _T[22, _j2]
            _d_isigma3__j = _T[23, _j2]
            _d_iF3__j = _T[24, _j2]
            _d_ifq0__j = _T[26, _j2]
            _d_ifp0__j = _T[27, _j2]
            _d_ifq1__j = _T[29, _j2]
            _d_ifp1__j = _T[30, _j2]
            _d_ifq2__j = _T[32, _j2]
            _d_ifp2__j = _T[33, _j2]
            _d_ifq3__j = _T[35, _j2]
            _d_ifp3__j = _T[36, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__72 + _d_iF1__j*_pd__73 + _d_iF2__j*_pd__74 + _d_iF3__j*_pd__75
                + _d_isigma0__j*_pd__76 + _d_isigma1__j*_pd__77 + _d_isigma2__j*_pd__78
                + _d_isigma3__j*_pd__79 + _pd__80*d_k_c__j + _pd__81*d_q_r__j + _pd__82*d_q_rd__j)
            _d_Q0__next__j = (0.08696371128436346*_d_ifq0__j + 0.35267675751627187*_d_ifq1__j
                + 0.31344511474186837*_d_ifq2__j + 0.1774825722545226*_d_ifq3__j + d_q_th__j)
            _d_Q1__next__j = (-0.014190694931141144*_d_ifq0__j + 0.16303628871563652*_d_ifq1__j
                + 0.35395300603374397*_d_ifq2__j + 0.16719192197418878*_d_ifq3__j + d_q_th__j)
            _d_Q2__next__j = (0.006735500594538156*_d_ifq0__j - 0.027880428602470895*_d_ifq1__j
                + 0.16303628871563652*_d_ifq2__j + 0.18811811749986806*_d_ifq3__j + d_q_th__j)
            _d_Q3__next__j = (-0.0035551496857956833*_d_ifq0__j + 0.012627462689404725*_d_ifq1__j
                - 0.026604180084998794*_d_ifq2__j + 0.08696371128436346*_d_ifq3__j + d_q_th__j)
            _d_P0__next__j = (0.08696371128436346*_d_ifp0__j + 0.35267675751627187*_d_ifp1__j
                + 0.31344511474186837*_d_ifp2__j + 0.1774825722545226*_d_ifp3__j + _pd__83*d_q_r__j
                + _pd__84*d_q_thd__j)
            _d_P1__next__j = (-0.014190694931141144*_d_ifp0__j + 0.16303628871563652*_d_ifp1__j
                + 0.35395300603374397*_d_ifp2__j + 0.16719192197418878*_d_ifp3__j + _pd__85*d_q_r__j
                + _pd__86*d_q_thd__j)
            _d_P2__next__j = (0.006735500594538156*_d_ifp0__j - 0.027880428602470895*_d_ifp1__j
                + 0.16303628871563652*_d_ifp2__j + 0.18811811749986806*_d_ifp3__j + _pd__87*d_q_r__j
                + _pd__88*d_q_thd__j)
            _d_P3__next__j = (-0.0035551496857956833*_d_ifp0__j + 0.012627462689404725*_d_ifp1__j
                - 0.026604180084998794*_d_ifp2__j + 0.08696371128436346*_d_ifp3__j + _pd__89*d_q_r__j
                + _pd__90*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_Q3__next__j
            _T[13, _j2] = _d_P0__next__j
            _T[14, _j2] = _d_P1__next__j
            _T[15, _j2] = _d_P2__next__j
            _T[16, _j2] = _d_P3__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _P0__next
        _n0_6 = _P1__next
        _n0_7 = _P2__next
        _n0_8 = _P3__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7
            - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    _x140 = -_D + q_r
    end_q_r = _x140
    end_q_rd = 0.0
    _x141 = q_r**2
    _x142 = (0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x141*m*q_thd)
    _x148 = (1.0/_x140)
    _x143 = _x148**2
    _x144 = (1.0/m)
    _x145 = _x143*_x144
    end_q_thd = _x142*_x145
    _x146 = 0.17392742256872692*_x145
    _pd__91 = _x146
    _x147 = 0.32607257743127305*_x145
    _pd__92 = _x147
    _pd__93 = _x147
    _pd__94 = _x146
    _pd__95 = -2.0*_x142*_x144*_x148**3
    _pd__96 = 2.0*_x143*q_r*q_thd
    _pd__97 = _x141*_x143
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN42 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[25, _j3]
        _d_ifq0__j = _T[26, _j3]
        _d_ifp0__j = _T[27, _j3]
        _d_ift1__j = _T[28, _j3]
        _d_ifq1__j = _T[29, _j3]
        _d_ifp1__j = _T[30, _j3]
        _d_ift2__j = _T[31, _j3]
        _d_ifq2__j = _T[32, _j3]
        _d_ifp2__j = _T[33, _j3]
        _d_ift3__j = _T[34, _j3]
        _d_ifq3__j = _T[35, _j3]
        _d_ifp3__j = _T[36, _j3]
        # bottom state
        d_t_half__j = (0.17392742256872692*_d_ift0__j + 0.32607257743127305*_d_ift1__j
            + 0.32607257743127305*_d_ift2__j + 0.17392742256872692*_d_ift3__j)
        d_end_q_th__j = (0.17392742256872692*_d_ifq0__j + 0.32607257743127305*_d_ifq1__j
            + 0.32607257743127305*_d_ifq2__j + 0.17392742256872692*_d_ifq3__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__91 + _d_ifp1__j*_pd__92 + _d_ifp2__j*_pd__93 + _d_ifp3__j*_pd__94
            + _pd__95*d_end_q_r__j + _pd__96*d_q_r__j + _pd__97*d_q_thd__j)
        _T[37, _j3] = d_t_half__j
        _T[38, _j3] = d_end_q_th__j
        _T[39, _j3] = d_end_q_r__j
        _T[40, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[37, 0], _T[37, 1],
        _T[37, 2], _T[37, 3], _T[37, 4], _T[37, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[38, 0],
        _T[38, 1], _T[38, 2], _T[38, 3], _T[38, 4], _T[38, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[39, 0],
        _T[39, 1], _T[39, 2], _T[39, 3], _T[39, 4], _T[39, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[40, 0], _T[40, 1], _T[40, 2], _T[40, 3], _T[40, 4], _T[40, 5], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression):
    """The code of iterative_stance_jacobian's kernels per choice after their choice's own calls, shared by
    the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 234
    # chain rule through schwind_decompression
    d_t_decompression__q_r_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_t_decompression__q_r*d_bottom_q_r__q_r_td
        + _j_t_decompression__q_th*d_bottom_q_th__q_r_td + _j_t_decompression__q_thd*d_bottom_q_thd__q_r_td)
    d_t_decompression__q_rd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_rd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_rd_td + _j_t_decompression__q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_rd_td)
    d_t_decompression__q_th_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_th_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_th_td + _j_t_decompression__q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_th_td)
    d_t_decompression__q_thd_td = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__q_thd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_thd_td + _j_t_decompression__q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_thd_td)
    d_t_decompression__k_c = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__k_c
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__k_c + _j_t_decompression__q_r*d_bottom_q_r__k_c
        + _j_t_decompression__q_th*d_bottom_q_th__k_c + _j_t_decompression__q_thd*d_bottom_q_thd__k_c)
    d_t_decompression__k_d = (_j_t_decompression__guess_q_th*_j_z_lo_q_th__k_d
        + _j_t_decompression__guess_q_thd*_j_z_lo_q_thd__k_d + _j_t_decompression__k_d
        + _j_t_decompression__q_r*d_bottom_q_r__k_d + _j_t_decompression__q_th*d_bottom_q_th__k_d
        + _j_t_decompression__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_rd__q_r_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_rd__q_rd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_rd__q_thd_td = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_rd__k_c = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__k_c
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__k_c + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_rd__k_d = (_j_liftoff_q_rd__guess_q_th*_j_z_lo_q_th__k_d
        + _j_liftoff_q_rd__guess_q_thd*_j_z_lo_q_thd__k_d + _j_liftoff_q_rd__k_d
        + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_d + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_th__q_r_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_th__q_thd_td = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_th__k_c = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__k_c
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__k_c + _j_liftoff_q_th__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_th__q_th*d_bottom_q_th__k_c + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_th__k_d = (_j_liftoff_q_th__guess_q_th*_j_z_lo_q_th__k_d
        + _j_liftoff_q_th__guess_q_thd*_j_z_lo_q_thd__k_d + _j_liftoff_q_th__k_d
        + _j_liftoff_q_th__q_r*d_bottom_q_r__k_d + _j_liftoff_q_th__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_thd__q_r_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_r_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_r_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_thd__q_rd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_rd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_rd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_th_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_th_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_thd__q_thd_td = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__q_thd_td
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__q_thd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_thd__k_c = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__k_c
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__k_c + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_thd__k_d = (_j_liftoff_q_thd__guess_q_th*_j_z_lo_q_th__k_d
        + _j_liftoff_q_thd__guess_q_thd*_j_z_lo_q_thd__k_d + _j_liftoff_q_thd__k_d
        + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_d + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_d)
    t_stance = t_bottom + t_decompression
    d_t_stance__q_r_td = d_t_bottom__q_r_td + d_t_decompression__q_r_td
    d_t_stance__q_rd_td = d_t_bottom__q_rd_td + d_t_decompression__q_rd_td
    d_t_stance__q_th_td = d_t_bottom__q_th_td + d_t_decompression__q_th_td
    d_t_stance__q_thd_td = d_t_bottom__q_thd_td + d_t_decompression__q_thd_td
    d_t_stance__k_c = d_t_bottom__k_c + d_t_decompression__k_c
    d_t_stance__k_d = d_t_bottom__k_d + d_t_decompression__k_d
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN77 + (STATUS_FALL,)
    # derivatives of the outputs
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_passes__q_r_td = 0.0
    d_passes__q_rd_td = 0.0
    d_passes__q_th_td = 0.0
    d_passes__q_thd_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN77 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
        d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td,
        d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td,
        d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td,
        d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN77 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4_jvp6_a742c3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k_c, _j_z_b_q_th__k_c, _j_z_b_q_thd__k_c,
        _j_z_b_q_r__k_d, _j_z_b_q_th__k_d, _j_z_b_q_thd__k_d))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_4_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_4_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_4_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_4_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_4_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_1_jvp5_408d60(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 5 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp5_408d60` (another choice of
    the same kernel).
    """
    # Total ops: 351
    # inputs: finite and inside their domains
    if not _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4):
        return _NAN36 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN36 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 1 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.5*guess_q_th + 0.5*q_th, 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd,
        1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2, -d_guess_q_r__3, -d_guess_q_r__4,
        0.5*d_guess_q_th__0, 0.5*d_guess_q_th__1, 0.5*d_guess_q_th__2 + 0.5, 0.5*d_guess_q_th__3,
        0.5*d_guess_q_th__4, 1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__0*guess_q_r**2*m
        + 1.0*m*q_r*q_thd, 1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__1*guess_q_r**2*m,
        1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__2*guess_q_r**2*m,
        1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__3*guess_q_r**2*m + 0.5*m*q_r**2,
        1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__4*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _P0, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_Q0__0, _d_Q0__1, _d_Q0__2, _d_Q0__3,
            _d_Q0__4, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN36 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.75*_D - q_r
        _x1 = -_x0
        _isigma0 = _x1
        _d_isigma0__0 = 1.0 - 0.75*_d_D__0
        _x2 = k_c*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_c
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x37 = (1.0/_x1)
        _x9 = _x37**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x37**4*_x7*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__0 + _d_Q0__0*_pd__1 + _d_isigma0__0*_pd__2
        _x14 = 0.75*_pd__2
        _d_iF0__1 = -_d_D__1*_x14 + _d_P0__1*_pd__0 + _d_Q0__1*_pd__1
        _d_iF0__2 = -_d_D__2*_x14 + _d_P0__2*_pd__0 + _d_Q0__2*_pd__1
        _d_iF0__3 = -_d_D__3*_x14 + _d_P0__3*_pd__0 + _d_Q0__3*_pd__1
        _d_iF0__4 = -_d_D__4*_x14 + _d_P0__4*_pd__0 + _d_Q0__4*_pd__1 + _x0 + l0
        _x15 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x15
        _x16 = math.sqrt(_D)
        _x17 = math.sqrt(m)
        _x18 = (1.0/math.sqrt(_x15))
        _x19 = _x17*_x18
        _ift0 = _x16*_x19
        _x20 = (0.5)/_x16
        _pd__3 = _x19*_x20
        _x21 = (0.5)*_x16/_x15**(1.5)
        _pd__4 = -_x17*_x21
        _x22 = 0.5*_pd__4
        _d_ift0__0 = _d_D__0*_pd__3 + _d_iF0__0*_x22
        _d_ift0__1 = _d_D__1*_pd__3 + _d_iF0__1*_x22
        _d_ift0__2 = _d_D__2*_pd__3 + _d_iF0__2*_x22
        _d_ift0__3 = _d_D__3*_pd__3 + _d_iF0__3*_x22
        _d_ift0__4 = _d_D__4*_pd__3 + _d_iF0__4*_x22
        _x23 = _x16*_x18
        _x24 = (1.0/_x17)
        _x25 = _x24*_x37**2
        _x26 = _x23*_x25
        _ifq0 = _P0*_x26
        _x27 = _P0*_x25
        _x28 = _x18*_x20
        _pd__5 = _x27*_x28
        _pd__6 = _x26
        _pd__7 = -_x21*_x27
        _pd__8 = -_x12*_x23*_x24*_x9
        _x29 = 0.5*_pd__7
        _d_ifq0__0 = _d_D__0*_pd__5 + _d_P0__0*_pd__6 + _d_iF0__0*_x29 + _d_isigma0__0*_pd__8
        _x30 = 0.75*_pd__8
        _d_ifq0__1 = _d_D__1*_pd__5 - _d_D__1*_x30 + _d_P0__1*_pd__6 + _d_iF0__1*_x29
        _d_ifq0__2 = _d_D__2*_pd__5 - _d_D__2*_x30 + _d_P0__2*_pd__6 + _d_iF0__2*_x29
        _d_ifq0__3 = _d_D__3*_pd__5 - _d_D__3*_x30 + _d_P0__3*_pd__6 + _d_iF0__3*_x29
        _d_ifq0__4 = _d_D__4*_pd__5 - _d_D__4*_x30 + _d_P0__4*_pd__6 + _d_iF0__4*_x29
        _x31 = m**(1.5)
        _x32 = _x23*_x31*g_s
        _x33 = _x13*_x32
        _ifp0 = _x1*_x33
        _x34 = _x1*_x13*_x31*g_s
        _pd__9 = _x28*_x34
        _pd__10 = _x1*_x3*_x32
        _pd__11 = -_x21*_x34
        _pd__12 = _x33
        _x35 = 0.5*_pd__11
        _d_ifp0__0 = _d_D__0*_pd__9 + _d_Q0__0*_pd__10 + _d_iF0__0*_x35 + _d_isigma0__0*_pd__12
        _x36 = 0.75*_pd__12
        _d_ifp0__1 = _d_D__1*_pd__9 - _d_D__1*_x36 + _d_Q0__1*_pd__10 + _d_iF0__1*_x35
        _d_ifp0__2 = _d_D__2*_pd__9 - _d_D__2*_x36 + _d_Q0__2*_pd__10 + _d_iF0__2*_x35
        _d_ifp0__3 = _d_D__3*_pd__9 - _d_D__3*_x36 + _d_Q0__3*_pd__10 + _d_iF0__3*_x35
        _d_ifp0__4 = _d_D__4*_pd__9 - _d_D__4*_x36 + _d_Q0__4*_pd__10 + _d_iF0__4*_x35
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x38 = m*q_rd**2
        _x39 = -q_r
        _x40 = k_c*(_x39 + l0)
        _x41 = 1.0*k_c
        _x42 = 1.0*_iF0 - _x41*(-_isigma0 + l0)
        _x43 = _x40 + _x42
        _x44 = math.sqrt(_x38*k_c + _x43**2)
        _x45 = _x43 + _x44
        _x46 = (1.0/_x45)
        _D__next = _x38*_x46
        _x47 = (1.0/_x44)
        _x48 = _x46**2
        _x49 = _x38*_x48
        _pd__13 = _x49*(-_x47*(1.0*_x40 + _x42) - 1.0)
        _x50 = _x43*_x47
        _pd__14 = _x49*(-_x41*_x50 - _x41)
        _d_D__next__0 = _d_iF0__0*_pd__13 + _d_isigma0__0*_pd__14 + _x49*(_x50*k_c + k_c)
        _x51 = 0.75*_pd__14
        _d_D__next__1 = -_d_D__1*_x51 + _d_iF0__1*_pd__13 + 2.0*_x46*m*q_rd - _x47*_x48*k_c*m**2*q_rd**3
        _d_D__next__2 = -_d_D__2*_x51 + _d_iF0__2*_pd__13
        _d_D__next__3 = -_d_D__3*_x51 + _d_iF0__3*_pd__13
        _x52 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x51 + _d_iF0__4*_pd__13 + _x49*(-1.0*_isigma0 - _x39 - _x47*((0.5)*_x38
            + (0.5)*_x43*(2.0*_isigma0 - _x52))))
        _Q0__next = 0.5*_ifq0 + q_th
        _d_Q0__next__2 = 0.5*_d_ifq0__2 + 1.0
        _x53 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x53*q_thd
        _d_P0__next__0 = 0.5*_d_ifp0__0 + _x52*m*q_thd
        _d_P0__next__3 = 0.5*_d_ifp0__3 + _x53
        _n0_8 = 0.5*_d_ifq0__0
        _n0_9 = 0.5*_d_ifq0__1
        _n0_11 = 0.5*_d_ifq0__3
        _n0_12 = 0.5*_d_ifq0__4
        _n0_14 = 0.5*_d_ifp0__1
        _n0_15 = 0.5*_d_ifp0__2
        _n0_17 = 0.5*_d_ifp0__4
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _P0__next, _d_D__next__0, _d_D__next__1, _d_D__next__2, _d_D__next__3,
            _d_D__next__4, _n0_8, _n0_9, _d_Q0__next__2, _n0_11, _n0_12, _d_P0__next__0, _n0_14, _n0_15,
            _d_P0__next__3, _n0_17, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    d_end_q_th__2 = 1.0*_d_ifq0__2 + 1.0
    _x54 = -_D + q_r
    end_q_r = _x54
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x55 = q_r**2
    _x56 = 1.0*_ifp0 + _x55*m*q_thd
    _x60 = (1.0/_x54)
    _x57 = _x60**2
    _x58 = (1.0/m)
    _x59 = _x57*_x58
    end_q_thd = _x56*_x59
    _pd__15 = 1.0*_x59
    _pd__16 = -2.0*_x56*_x58*_x60**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__15 + _pd__16*d_end_q_r__0 + 2.0*_x57*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__16 + _d_ifp0__1*_pd__15
    d_end_q_thd__2 = -_d_D__2*_pd__16 + _d_ifp0__2*_pd__15
    d_end_q_thd__3 = -_d_D__3*_pd__16 + _d_ifp0__3*_pd__15 + _x55*_x57
    d_end_q_thd__4 = -_d_D__4*_pd__16 + _d_ifp0__4*_pd__15
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN36 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_half__0 = 1.0*_d_ift0__0
    d_t_half__1 = 1.0*_d_ift0__1
    d_t_half__2 = 1.0*_d_ift0__2
    d_t_half__3 = 1.0*_d_ift0__3
    d_t_half__4 = 1.0*_d_ift0__4
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_th__0 = 1.0*_d_ifq0__0
    d_end_q_th__1 = 1.0*_d_ifq0__1
    d_end_q_th__3 = 1.0*_d_ifq0__3
    d_end_q_th__4 = 1.0*_d_ifq0__4
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4, d_end_q_th__0,
        d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_thd__0, d_end_q_thd__1,
        d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_passes__0, d_passes__1, d_passes__2, d_passes__3,
        d_passes__4, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0,
        k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: those of
    :func:`schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd` (another choice of the
    same kernel).
    """
    # Total ops: 306
    # inputs: finite and inside their domains
    if not _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
            iterations, tol):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    # Picard passes on the 1 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.5*guess_q_th + 0.5*q_th, 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd, -1.0,
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.5, 0.0, 1.0*m*q_r*q_thd, 0.0, 0.5*m*q_r**2, 0.0, 0.0,
        0.5*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _P0, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__guess_q_th, _d_D__guess_q_thd,
            _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d, _d_Q0__guess_q_th, _d_Q0__guess_q_thd,
            _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d, _d_P0__guess_q_th, _d_P0__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.25*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.25*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x37 = (1.0/_x1)
        _x9 = _x37**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x37**4*_x7*_x8 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__0 + _d_Q0__q_r*_pd__1 + _d_isigma0__q_r*_pd__2
        _x14 = 0.25*_pd__2
        _d_iF0__q_th = _d_D__q_th*_x14 + _d_P0__q_th*_pd__0 + _d_Q0__q_th*_pd__1
        _d_iF0__q_thd = _d_D__q_thd*_x14 + _d_P0__q_thd*_pd__0 + _d_Q0__q_thd*_pd__1
        _d_iF0__k_d = _d_D__k_d*_x14 + _d_P0__k_d*_pd__0 + _d_Q0__k_d*_pd__1 - _x0 + l0 - q_r
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x14 + _d_P0__guess_q_th*_pd__0 + _d_Q0__guess_q_th*_pd__1
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x14 + _d_P0__guess_q_thd*_pd__0 + _d_Q0__guess_q_thd*_pd__1
        _x15 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x15
        _x16 = math.sqrt(_D)
        _x17 = math.sqrt(m)
        _x18 = (1.0/math.sqrt(_x15))
        _x19 = _x17*_x18
        _ift0 = _x16*_x19
        _x20 = (0.5)/_x16
        _pd__3 = _x19*_x20
        _x21 = (0.5)*_x16/_x15**(1.5)
        _pd__4 = -_x17*_x21
        _x22 = 0.5*_pd__4
        _d_ift0__q_r = _d_D__q_r*_pd__3 + _d_iF0__q_r*_x22
        _d_ift0__q_th = _d_D__q_th*_pd__3 + _d_iF0__q_th*_x22
        _d_ift0__q_thd = _d_D__q_thd*_pd__3 + _d_iF0__q_thd*_x22
        _d_ift0__k_d = _d_D__k_d*_pd__3 + _d_iF0__k_d*_x22
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__3 + _d_iF0__guess_q_th*_x22
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__3 + _d_iF0__guess_q_thd*_x22
        _x23 = _x16*_x18
        _x24 = (1.0/_x17)
        _x25 = _x24*_x37**2
        _x26 = _x23*_x25
        _ifq0 = _P0*_x26
        _x27 = _P0*_x25
        _x28 = _x18*_x20
        _pd__5 = _x27*_x28
        _pd__6 = _x26
        _pd__7 = -_x21*_x27
        _pd__8 = -_x12*_x23*_x24*_x9
        _x29 = 0.5*_pd__7
        _d_ifq0__q_r = _d_D__q_r*_pd__5 + _d_P0__q_r*_pd__6 + _d_iF0__q_r*_x29 + _d_isigma0__q_r*_pd__8
        _x30 = 0.25*_pd__8
        _d_ifq0__q_th = _d_D__q_th*_pd__5 + _d_D__q_th*_x30 + _d_P0__q_th*_pd__6 + _d_iF0__q_th*_x29
        _d_ifq0__q_thd = _d_D__q_thd*_pd__5 + _d_D__q_thd*_x30 + _d_P0__q_thd*_pd__6 + _d_iF0__q_thd*_x29
        _d_ifq0__k_d = _d_D__k_d*_pd__5 + _d_D__k_d*_x30 + _d_P0__k_d*_pd__6 + _d_iF0__k_d*_x29
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__5 + _d_D__guess_q_th*_x30 + _d_P0__guess_q_th*_pd__6
            + _d_iF0__guess_q_th*_x29)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__5 + _d_D__guess_q_thd*_x30 + _d_P0__guess_q_thd*_pd__6
            + _d_iF0__guess_q_thd*_x29)
        _x31 = m**(1.5)
        _x32 = _x23*_x31*g_s
        _x33 = _x13*_x32
        _ifp0 = _x1*_x33
        _x34 = _x1*_x13*_x31*g_s
        _pd__9 = _x28*_x34
        _pd__10 = _x1*_x3*_x32
        _pd__11 = -_x21*_x34
        _pd__12 = _x33
        _x35 = 0.5*_pd__11
        _d_ifp0__q_r = _d_D__q_r*_pd__9 + _d_Q0__q_r*_pd__10 + _d_iF0__q_r*_x35 + _d_isigma0__q_r*_pd__12
        _x36 = 0.25*_pd__12
        _d_ifp0__q_th = _d_D__q_th*_pd__9 + _d_D__q_th*_x36 + _d_Q0__q_th*_pd__10 + _d_iF0__q_th*_x35
        _d_ifp0__q_thd = _d_D__q_thd*_pd__9 + _d_D__q_thd*_x36 + _d_Q0__q_thd*_pd__10 + _d_iF0__q_thd*_x35
        _d_ifp0__k_d = _d_D__k_d*_pd__9 + _d_D__k_d*_x36 + _d_Q0__k_d*_pd__10 + _d_iF0__k_d*_x35
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__9 + _d_D__guess_q_th*_x36 + _d_Q0__guess_q_th*_pd__10
            + _d_iF0__guess_q_th*_x35)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__9 + _d_D__guess_q_thd*_x36 + _d_Q0__guess_q_thd*_pd__10
            + _d_iF0__guess_q_thd*_x35)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.5*_ifq0 + q_th
        _d_Q0__next__q_th = 0.5*_d_ifq0__q_th + 1.0
        _x38 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x38*q_thd
        _d_P0__next__q_r = 0.5*_d_ifp0__q_r + 2.0*m*q_r*q_thd
        _d_P0__next__q_thd = 0.5*_d_ifp0__q_thd + _x38
        _n0_3 = _d_D__q_r
        _n0_4 = _d_D__q_th
        _n0_5 = _d_D__q_thd
        _n0_6 = _d_D__k_d
        _n0_7 = _d_D__guess_q_th
        _n0_8 = _d_D__guess_q_thd
        _n0_9 = 0.5*_d_ifq0__q_r
        _n0_11 = 0.5*_d_ifq0__q_thd
        _n0_12 = 0.5*_d_ifq0__k_d
        _n0_13 = 0.5*_d_ifq0__guess_q_th
        _n0_14 = 0.5*_d_ifq0__guess_q_thd
        _n0_16 = 0.5*_d_ifp0__q_th
        _n0_18 = 0.5*_d_ifp0__k_d
        _n0_19 = 0.5*_d_ifp0__guess_q_th
        _n0_20 = 0.5*_d_ifp0__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _P0__next, _n0_3, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            _d_Q0__next__q_th, _n0_11, _n0_12, _n0_13, _n0_14, _d_P0__next__q_r, _n0_16, _d_P0__next__q_thd,
            _n0_18, _n0_19, _n0_20, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = 0.5*_iF0
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    d_end_q_th__q_th = 1.0*_d_ifq0__q_th + 1.0
    end_q_r = q_r_lo
    _x39 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x39
    _pd__13 = _x39/_D
    _pd__14 = _x39/_work
    _x40 = 0.5*_pd__14
    d_end_q_rd__q_r = _d_D__q_r*_pd__13 + _d_iF0__q_r*_x40
    d_end_q_rd__q_th = _d_D__q_th*_pd__13 + _d_iF0__q_th*_x40
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__13 + _d_iF0__q_thd*_x40
    d_end_q_rd__k_d = _d_D__k_d*_pd__13 + _d_iF0__k_d*_x40
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__13 + _d_iF0__guess_q_th*_x40
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__13 + _d_iF0__guess_q_thd*_x40
    _x41 = q_r**2
    _x42 = q_r_lo**-2
    _x43 = _x42/m
    end_q_thd = _x43*(1.0*_ifp0 + _x41*m*q_thd)
    _pd__15 = 1.0*_x43
    d_end_q_thd__q_r = _d_ifp0__q_r*_pd__15 + 2.0*_x42*q_r*q_thd
    d_end_q_thd__q_th = _d_ifp0__q_th*_pd__15
    d_end_q_thd__q_thd = _d_ifp0__q_thd*_pd__15 + _x41*_x42
    d_end_q_thd__k_d = _d_ifp0__k_d*_pd__15
    d_end_q_thd__guess_q_th = _d_ifp0__guess_q_th*_pd__15
    d_end_q_thd__guess_q_thd = _d_ifp0__guess_q_thd*_pd__15
    passes = _passes
    # derivatives of the outputs
    d_t_half__q_r = 1.0*_d_ift0__q_r
    d_t_half__q_th = 1.0*_d_ift0__q_th
    d_t_half__q_thd = 1.0*_d_ift0__q_thd
    d_t_half__k_d = 1.0*_d_ift0__k_d
    d_t_half__guess_q_th = 1.0*_d_ift0__guess_q_th
    d_t_half__guess_q_thd = 1.0*_d_ift0__guess_q_thd
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_end_q_th__q_r = 1.0*_d_ifq0__q_r
    d_end_q_th__q_thd = 1.0*_d_ifq0__q_thd
    d_end_q_th__k_d = 1.0*_d_ifq0__k_d
    d_end_q_th__guess_q_th = 1.0*_d_ifq0__guess_q_th
    d_end_q_th__guess_q_thd = 1.0*_d_ifq0__guess_q_thd
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN77 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td, 0.0,
        _j_z_b_q_th__q_th_td, 0.0, _j_z_b_q_r__q_thd_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_geyer`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_geyer`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 122
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x6 = m*q_rd_td**2
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    z_b_q_r = _x11
    _x12 = (1.0/_x8)
    _x13 = (0.5)*_x7
    _x14 = _x10**2
    _x15 = _x14*_x6
    d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
    d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
    _x16 = _x2*math.sin(q_th_td)
    _x17 = _x12*_x7
    d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
    _x18 = 2.0*q_r_td
    _x19 = _x18*q_thd_td
    _x20 = _x19*m
    d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
    d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
    z_b_q_th = q_th_td
    _x21 = q_r_td**2
    _x24 = (1.0/_x11)
    _x22 = _x24**2
    _x23 = _x21*_x22
    z_b_q_thd = _x23*q_thd_td
    _pd__0 = -2.0*_x21*_x24**3*q_thd_td
    d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
    d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
    d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
    d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
    d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, d_z_b_q_r__q_r_td, 0.0, d_z_b_q_thd__q_r_td,
        d_z_b_q_r__q_rd_td, 0.0, d_z_b_q_thd__q_rd_td, d_z_b_q_r__q_th_td, 1.0, d_z_b_q_thd__q_th_td,
        d_z_b_q_r__q_thd_td, 0.0, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, 0.0, d_z_b_q_thd__k_c))
    if _c0[36] != STATUS_OK:
        return _NAN77 + (_c0[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c0
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x25 = q_r_lo**-2
    _x26 = _x25*bottom_q_r**2
    g_lo_q_thd = _x26*bottom_q_thd
    _pd__1 = 2.0*_x25*bottom_q_r*bottom_q_thd
    _pd__2 = _x26
    d_g_lo_q_thd__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _pd__2*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td + _pd__2*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__1*d_bottom_q_r__q_th_td + _pd__2*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td + _pd__2*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__1*d_bottom_q_r__k_c + _pd__2*d_bottom_q_thd__k_c
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c1
    # the code shared between choices
    return (iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_held`: arguments, out and status
    as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_held`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_1_jvp6_a742c3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5,
        d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp6_a742c3` (another choice of
    the same kernel).
    """
    # Total ops: 382
    # inputs: finite and inside their domains
    if not _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 1 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.5*guess_q_th + 0.5*q_th, 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd,
        1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2, -d_guess_q_r__3, -d_guess_q_r__4,
        -d_guess_q_r__5, 0.5*d_guess_q_th__0, 0.5*d_guess_q_th__1, 0.5*d_guess_q_th__2 + 0.5,
        0.5*d_guess_q_th__3, 0.5*d_guess_q_th__4, 0.5*d_guess_q_th__5,
        1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__0*guess_q_r**2*m + 1.0*m*q_r*q_thd,
        1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__1*guess_q_r**2*m,
        1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__2*guess_q_r**2*m,
        1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__3*guess_q_r**2*m + 0.5*m*q_r**2,
        1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__4*guess_q_r**2*m,
        1.0*d_guess_q_r__5*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _P0, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_Q0__0, _d_Q0__1, _d_Q0__2,
            _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.75*_D - q_r
        _x1 = -_x0
        _isigma0 = _x1
        _d_isigma0__0 = 1.0 - 0.75*_d_D__0
        _x2 = k_c*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_c
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x37 = (1.0/_x1)
        _x9 = _x37**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x37**4*_x7*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__0 + _d_Q0__0*_pd__1 + _d_isigma0__0*_pd__2
        _x14 = 0.75*_pd__2
        _d_iF0__1 = -_d_D__1*_x14 + _d_P0__1*_pd__0 + _d_Q0__1*_pd__1
        _d_iF0__2 = -_d_D__2*_x14 + _d_P0__2*_pd__0 + _d_Q0__2*_pd__1
        _d_iF0__3 = -_d_D__3*_x14 + _d_P0__3*_pd__0 + _d_Q0__3*_pd__1
        _d_iF0__4 = -_d_D__4*_x14 + _d_P0__4*_pd__0 + _d_Q0__4*_pd__1 + _x0 + l0
        _d_iF0__5 = -_d_D__5*_x14 + _d_P0__5*_pd__0 + _d_Q0__5*_pd__1
        _x15 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x15
        _x16 = math.sqrt(_D)
        _x17 = math.sqrt(m)
        _x18 = (1.0/math.sqrt(_x15))
        _x19 = _x17*_x18
        _ift0 = _x16*_x19
        _x20 = (0.5)/_x16
        _pd__3 = _x19*_x20
        _x21 = (0.5)*_x16/_x15**(1.5)
        _pd__4 = -_x17*_x21
        _x22 = 0.5*_pd__4
        _d_ift0__0 = _d_D__0*_pd__3 + _d_iF0__0*_x22
        _d_ift0__1 = _d_D__1*_pd__3 + _d_iF0__1*_x22
        _d_ift0__2 = _d_D__2*_pd__3 + _d_iF0__2*_x22
        _d_ift0__3 = _d_D__3*_pd__3 + _d_iF0__3*_x22
        _d_ift0__4 = _d_D__4*_pd__3 + _d_iF0__4*_x22
        _d_ift0__5 = _d_D__5*_pd__3 + _d_iF0__5*_x22
        _x23 = _x16*_x18
        _x24 = (1.0/_x17)
        _x25 = _x24*_x37**2
        _x26 = _x23*_x25
        _ifq0 = _P0*_x26
        _x27 = _P0*_x25
        _x28 = _x18*_x20
        _pd__5 = _x27*_x28
        _pd__6 = _x26
        _pd__7 = -_x21*_x27
        _pd__8 = -_x12*_x23*_x24*_x9
        _x29 = 0.5*_pd__7
        _d_ifq0__0 = _d_D__0*_pd__5 + _d_P0__0*_pd__6 + _d_iF0__0*_x29 + _d_isigma0__0*_pd__8
        _x30 = 0.75*_pd__8
        _d_ifq0__1 = _d_D__1*_pd__5 - _d_D__1*_x30 + _d_P0__1*_pd__6 + _d_iF0__1*_x29
        _d_ifq0__2 = _d_D__2*_pd__5 - _d_D__2*_x30 + _d_P0__2*_pd__6 + _d_iF0__2*_x29
        _d_ifq0__3 = _d_D__3*_pd__5 - _d_D__3*_x30 + _d_P0__3*_pd__6 + _d_iF0__3*_x29
        _d_ifq0__4 = _d_D__4*_pd__5 - _d_D__4*_x30 + _d_P0__4*_pd__6 + _d_iF0__4*_x29
        _d_ifq0__5 = _d_D__5*_pd__5 - _d_D__5*_x30 + _d_P0__5*_pd__6 + _d_iF0__5*_x29
        _x31 = m**(1.5)
        _x32 = _x23*_x31*g_s
        _x33 = _x13*_x32
        _ifp0 = _x1*_x33
        _x34 = _x1*_x13*_x31*g_s
        _pd__9 = _x28*_x34
        _pd__10 = _x1*_x3*_x32
        _pd__11 = -_x21*_x34
        _pd__12 = _x33
        _x35 = 0.5*_pd__11
        _d_ifp0__0 = _d_D__0*_pd__9 + _d_Q0__0*_pd__10 + _d_iF0__0*_x35 + _d_isigma0__0*_pd__12
        _x36 = 0.75*_pd__12
        _d_ifp0__1 = _d_D__1*_pd__9 - _d_D__1*_x36 + _d_Q0__1*_pd__10 + _d_iF0__1*_x35
        _d_ifp0__2 = _d_D__2*_pd__9 - _d_D__2*_x36 + _d_Q0__2*_pd__10 + _d_iF0__2*_x35
        _d_ifp0__3 = _d_D__3*_pd__9 - _d_D__3*_x36 + _d_Q0__3*_pd__10 + _d_iF0__3*_x35
        _d_ifp0__4 = _d_D__4*_pd__9 - _d_D__4*_x36 + _d_Q0__4*_pd__10 + _d_iF0__4*_x35
        _d_ifp0__5 = _d_D__5*_pd__9 - _d_D__5*_x36 + _d_Q0__5*_pd__10 + _d_iF0__5*_x35
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x38 = m*q_rd**2
        _x39 = -q_r
        _x40 = k_c*(_x39 + l0)
        _x41 = 1.0*k_c
        _x42 = 1.0*_iF0 - _x41*(-_isigma0 + l0)
        _x43 = _x40 + _x42
        _x44 = math.sqrt(_x38*k_c + _x43**2)
        _x45 = _x43 + _x44
        _x46 = (1.0/_x45)
        _D__next = _x38*_x46
        _x47 = (1.0/_x44)
        _x48 = _x46**2
        _x49 = _x38*_x48
        _pd__13 = _x49*(-_x47*(1.0*_x40 + _x42) - 1.0)
        _x50 = _x43*_x47
        _pd__14 = _x49*(-_x41*_x50 - _x41)
        _d_D__next__0 = _d_iF0__0*_pd__13 + _d_isigma0__0*_pd__14 + _x49*(_x50*k_c + k_c)
        _x51 = 0.75*_pd__14
        _d_D__next__1 = -_d_D__1*_x51 + _d_iF0__1*_pd__13 + 2.0*_x46*m*q_rd - _x47*_x48*k_c*m**2*q_rd**3
        _d_D__next__2 = -_d_D__2*_x51 + _d_iF0__2*_pd__13
        _d_D__next__3 = -_d_D__3*_x51 + _d_iF0__3*_pd__13
        _x52 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x51 + _d_iF0__4*_pd__13 + _x49*(-1.0*_isigma0 - _x39 - _x47*((0.5)*_x38
            + (0.5)*_x43*(2.0*_isigma0 - _x52))))
        _d_D__next__5 = -_d_D__5*_x51 + _d_iF0__5*_pd__13
        _Q0__next = 0.5*_ifq0 + q_th
        _d_Q0__next__2 = 0.5*_d_ifq0__2 + 1.0
        _x53 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x53*q_thd
        _d_P0__next__0 = 0.5*_d_ifp0__0 + _x52*m*q_thd
        _d_P0__next__3 = 0.5*_d_ifp0__3 + _x53
        _n0_9 = 0.5*_d_ifq0__0
        _n0_10 = 0.5*_d_ifq0__1
        _n0_12 = 0.5*_d_ifq0__3
        _n0_13 = 0.5*_d_ifq0__4
        _n0_14 = 0.5*_d_ifq0__5
        _n0_16 = 0.5*_d_ifp0__1
        _n0_17 = 0.5*_d_ifp0__2
        _n0_19 = 0.5*_d_ifp0__4
        _n0_20 = 0.5*_d_ifp0__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _P0__next, _d_D__next__0, _d_D__next__1, _d_D__next__2, _d_D__next__3,
            _d_D__next__4, _d_D__next__5, _n0_9, _n0_10, _d_Q0__next__2, _n0_12, _n0_13, _n0_14,
            _d_P0__next__0, _n0_16, _n0_17, _d_P0__next__3, _n0_19, _n0_20, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    d_end_q_th__2 = 1.0*_d_ifq0__2 + 1.0
    _x54 = -_D + q_r
    end_q_r = _x54
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x55 = q_r**2
    _x56 = 1.0*_ifp0 + _x55*m*q_thd
    _x60 = (1.0/_x54)
    _x57 = _x60**2
    _x58 = (1.0/m)
    _x59 = _x57*_x58
    end_q_thd = _x56*_x59
    _pd__15 = 1.0*_x59
    _pd__16 = -2.0*_x56*_x58*_x60**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__15 + _pd__16*d_end_q_r__0 + 2.0*_x57*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__16 + _d_ifp0__1*_pd__15
    d_end_q_thd__2 = -_d_D__2*_pd__16 + _d_ifp0__2*_pd__15
    d_end_q_thd__3 = -_d_D__3*_pd__16 + _d_ifp0__3*_pd__15 + _x55*_x57
    d_end_q_thd__4 = -_d_D__4*_pd__16 + _d_ifp0__4*_pd__15
    d_end_q_thd__5 = -_d_D__5*_pd__16 + _d_ifp0__5*_pd__15
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN42 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_half__0 = 1.0*_d_ift0__0
    d_t_half__1 = 1.0*_d_ift0__1
    d_t_half__2 = 1.0*_d_ift0__2
    d_t_half__3 = 1.0*_d_ift0__3
    d_t_half__4 = 1.0*_d_ift0__4
    d_t_half__5 = 1.0*_d_ift0__5
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_end_q_th__0 = 1.0*_d_ifq0__0
    d_end_q_th__1 = 1.0*_d_ifq0__1
    d_end_q_th__3 = 1.0*_d_ifq0__3
    d_end_q_th__4 = 1.0*_d_ifq0__4
    d_end_q_th__5 = 1.0*_d_ifq0__5
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN77 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1_jvp6_a742c3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k_c, _j_z_b_q_th__k_c, _j_z_b_q_thd__k_c,
        _j_z_b_q_r__k_d, _j_z_b_q_th__k_d, _j_z_b_q_thd__k_d))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_1_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_1_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_1_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_1_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_1_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_1_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_1_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_1_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_2_jvp5_408d60(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 5 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp5_408d60` (another choice of
    the same kernel).
    """
    # Total ops: 756
    # inputs: finite and inside their domains
    if not _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4):
        return _NAN36 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN36 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 2 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th,
        0.2113248654051871*guess_q_th + 0.7886751345948129*q_th, 0.7886751345948129*guess_q_r**2*guess_q_thd*m
        + 0.2113248654051871*m*q_r**2*q_thd, 0.2113248654051871*guess_q_r**2*guess_q_thd*m
        + 0.7886751345948129*m*q_r**2*q_thd, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2,
        -d_guess_q_r__3, -d_guess_q_r__4, 0.7886751345948129*d_guess_q_th__0,
        0.7886751345948129*d_guess_q_th__1, 0.7886751345948129*d_guess_q_th__2 + 0.2113248654051871,
        0.7886751345948129*d_guess_q_th__3, 0.7886751345948129*d_guess_q_th__4,
        0.2113248654051871*d_guess_q_th__0, 0.2113248654051871*d_guess_q_th__1,
        0.2113248654051871*d_guess_q_th__2 + 0.7886751345948129, 0.2113248654051871*d_guess_q_th__3,
        0.2113248654051871*d_guess_q_th__4, 1.5773502691896257*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__0*guess_q_r**2*m + 0.4226497308103742*m*q_r*q_thd,
        1.5773502691896257*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__1*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__2*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__3*guess_q_r**2*m + 0.2113248654051871*m*q_r**2,
        1.5773502691896257*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__4*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__0*guess_q_r**2*m + 1.5773502691896257*m*q_r*q_thd,
        0.4226497308103742*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__1*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__2*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__3*guess_q_r**2*m + 0.7886751345948129*m*q_r**2,
        0.4226497308103742*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__4*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _P0, _P1, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_Q0__0, _d_Q0__1, _d_Q0__2,
            _d_Q0__3, _d_Q0__4, _d_Q1__0, _d_Q1__1, _d_Q1__2, _d_Q1__3, _d_Q1__4, _d_P0__0, _d_P0__1,
            _d_P0__2, _d_P0__3, _d_P0__4, _d_P1__0, _d_P1__1, _d_P1__2, _d_P1__3, _d_P1__4, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN36 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9553418012614795*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9553418012614795*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x66 = (1.0/_x2)
        _x10 = _x66**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__0 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__1 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__2 = -_x15*_x66**4*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__0 + _d_Q0__0*_pd__1 + _d_isigma0__0*_pd__2
        _x16 = 0.9553418012614795*_pd__2
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__0 + _d_Q0__1*_pd__1
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__0 + _d_Q0__2*_pd__1
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__0 + _d_Q0__3*_pd__1
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__0 + _d_Q0__4*_pd__1 + _x1 + l0
        _x17 = 0.37799153207185376*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.37799153207185376*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x65 = (1.0/_x18)
        _x23 = _x65**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__3 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__4 = _x27*_x5
        _pd__5 = -_x15*_x22*_x65**4 - k_c
        _d_iF1__0 = _d_P1__0*_pd__3 + _d_Q1__0*_pd__4 + _d_isigma1__0*_pd__5
        _x28 = 0.37799153207185376*_pd__5
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__3 + _d_Q1__1*_pd__4
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__3 + _d_Q1__2*_pd__4
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__3 + _d_Q1__3*_pd__4
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__3 + _d_Q1__4*_pd__4 + _x17 + l0
        _x29 = (0.5610042339640731*_x12 + 0.06100423396407311*_x20 + 0.06100423396407311*_x21
            - 0.06100423396407311*_x25 + 0.5*_x3 - 0.5610042339640731*_x6 - 0.5610042339640731*_x7)
        _iPsi0 = _x29
        _d_iPsi0__0 = 0.5610042339640731*_d_iF0__0 - 0.06100423396407311*_d_iF1__0
        _d_iPsi0__1 = 0.5610042339640731*_d_iF0__1 - 0.06100423396407311*_d_iF1__1
        _d_iPsi0__2 = 0.5610042339640731*_d_iF0__2 - 0.06100423396407311*_d_iF1__2
        _d_iPsi0__3 = 0.5610042339640731*_d_iF0__3 - 0.06100423396407311*_d_iF1__3
        _d_iPsi0__4 = 0.5610042339640731*_d_iF0__4 - 0.06100423396407311*_d_iF1__4
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _ift0 = _x30*_x33
        _x34 = (0.5)/_x31
        _x35 = _x32*_x34
        _pd__6 = _x30*_x35
        _x36 = _x29**(-1.5)
        _x37 = (0.5)*_x33
        _pd__7 = -_x36*_x37
        _d_ift0__0 = _d_D__0*_pd__6 + _d_iPsi0__0*_pd__7
        _d_ift0__1 = _d_D__1*_pd__6 + _d_iPsi0__1*_pd__7
        _d_ift0__2 = _d_D__2*_pd__6 + _d_iPsi0__2*_pd__7
        _d_ift0__3 = _d_D__3*_pd__6 + _d_iPsi0__3*_pd__7
        _d_ift0__4 = _d_D__4*_pd__6 + _d_iPsi0__4*_pd__7
        _x38 = (1.0/_x32)
        _x39 = _x31*_x38
        _x40 = _x66**2
        _x41 = _x30*_x40
        _x42 = _x39*_x41
        _ifq0 = _P0*_x42
        _x43 = _x34*_x38
        _pd__8 = _P0*_x41*_x43
        _pd__9 = _x42
        _x44 = (0.5)*_x39
        _pd__10 = -_P0*_x36*_x40*_x44
        _pd__11 = -_x10*_x13*_x30*_x39
        _d_ifq0__0 = _d_D__0*_pd__8 + _d_P0__0*_pd__9 + _d_iPsi0__0*_pd__10 + _d_isigma0__0*_pd__11
        _x45 = 0.9553418012614795*_pd__11
        _d_ifq0__1 = _d_D__1*_pd__8 - _d_D__1*_x45 + _d_P0__1*_pd__9 + _d_iPsi0__1*_pd__10
        _d_ifq0__2 = _d_D__2*_pd__8 - _d_D__2*_x45 + _d_P0__2*_pd__9 + _d_iPsi0__2*_pd__10
        _d_ifq0__3 = _d_D__3*_pd__8 - _d_D__3*_x45 + _d_P0__3*_pd__9 + _d_iPsi0__3*_pd__10
        _d_ifq0__4 = _d_D__4*_pd__8 - _d_D__4*_x45 + _d_P0__4*_pd__9 + _d_iPsi0__4*_pd__10
        _x46 = g_s*m**(1.5)
        _x47 = _x31*_x46
        _x48 = _x30*_x47
        _x49 = _x14*_x48
        _ifp0 = _x2*_x49
        _x50 = _x14*_x2
        _x51 = _x34*_x46
        _pd__12 = _x30*_x50*_x51
        _pd__13 = _x2*_x4*_x48
        _x52 = (0.5)*_x47
        _pd__14 = -_x36*_x50*_x52
        _pd__15 = _x49
        _d_ifp0__0 = _d_D__0*_pd__12 + _d_Q0__0*_pd__13 + _d_iPsi0__0*_pd__14 + _d_isigma0__0*_pd__15
        _x53 = 0.9553418012614795*_pd__15
        _d_ifp0__1 = _d_D__1*_pd__12 - _d_D__1*_x53 + _d_Q0__1*_pd__13 + _d_iPsi0__1*_pd__14
        _d_ifp0__2 = _d_D__2*_pd__12 - _d_D__2*_x53 + _d_Q0__2*_pd__13 + _d_iPsi0__2*_pd__14
        _d_ifp0__3 = _d_D__3*_pd__12 - _d_D__3*_x53 + _d_Q0__3*_pd__13 + _d_iPsi0__3*_pd__14
        _d_ifp0__4 = _d_D__4*_pd__12 - _d_D__4*_x53 + _d_Q0__4*_pd__13 + _d_iPsi0__4*_pd__14
        _x54 = (0.22767090063073978*_x10*_x8*_x9 - 0.27232909936926025*_x20 - 0.27232909936926025*_x21
            + 0.27232909936926025*_x22*_x23*_x9 - 0.22767090063073978*_x6 - 0.22767090063073978*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x54
        _d_iPsi1__0 = 0.22767090063073978*_d_iF0__0 + 0.27232909936926025*_d_iF1__0
        _d_iPsi1__1 = 0.22767090063073978*_d_iF0__1 + 0.27232909936926025*_d_iF1__1
        _d_iPsi1__2 = 0.22767090063073978*_d_iF0__2 + 0.27232909936926025*_d_iF1__2
        _d_iPsi1__3 = 0.22767090063073978*_d_iF0__3 + 0.27232909936926025*_d_iF1__3
        _d_iPsi1__4 = 0.22767090063073978*_d_iF0__4 + 0.27232909936926025*_d_iF1__4
        _x55 = (1.0/math.sqrt(_x54))
        _ift1 = _x33*_x55
        _pd__16 = _x35*_x55
        _x56 = _x54**(-1.5)
        _pd__17 = -_x37*_x56
        _d_ift1__0 = _d_D__0*_pd__16 + _d_iPsi1__0*_pd__17
        _d_ift1__1 = _d_D__1*_pd__16 + _d_iPsi1__1*_pd__17
        _d_ift1__2 = _d_D__2*_pd__16 + _d_iPsi1__2*_pd__17
        _d_ift1__3 = _d_D__3*_pd__16 + _d_iPsi1__3*_pd__17
        _d_ift1__4 = _d_D__4*_pd__16 + _d_iPsi1__4*_pd__17
        _x57 = _x65**2
        _x58 = _x55*_x57
        _x59 = _x39*_x58
        _ifq1 = _P1*_x59
        _pd__18 = _P1*_x43*_x58
        _pd__19 = _x59
        _pd__20 = -_P1*_x44*_x56*_x57
        _pd__21 = -_x23*_x26*_x39*_x55
        _d_ifq1__0 = _d_D__0*_pd__18 + _d_P1__0*_pd__19 + _d_iPsi1__0*_pd__20 + _d_isigma1__0*_pd__21
        _x60 = 0.37799153207185376*_pd__21
        _d_ifq1__1 = _d_D__1*_pd__18 - _d_D__1*_x60 + _d_P1__1*_pd__19 + _d_iPsi1__1*_pd__20
        _d_ifq1__2 = _d_D__2*_pd__18 - _d_D__2*_x60 + _d_P1__2*_pd__19 + _d_iPsi1__2*_pd__20
        _d_ifq1__3 = _d_D__3*_pd__18 - _d_D__3*_x60 + _d_P1__3*_pd__19 + _d_iPsi1__3*_pd__20
        _d_ifq1__4 = _d_D__4*_pd__18 - _d_D__4*_x60 + _d_P1__4*_pd__19 + _d_iPsi1__4*_pd__20
        _x61 = _x47*_x55
        _x62 = _x27*_x61
        _ifp1 = _x18*_x62
        _x63 = _x18*_x27
        _pd__22 = _x51*_x55*_x63
        _pd__23 = _x18*_x19*_x61
        _pd__24 = -_x52*_x56*_x63
        _pd__25 = _x62
        _d_ifp1__0 = _d_D__0*_pd__22 + _d_Q1__0*_pd__23 + _d_iPsi1__0*_pd__24 + _d_isigma1__0*_pd__25
        _x64 = 0.37799153207185376*_pd__25
        _d_ifp1__1 = _d_D__1*_pd__22 - _d_D__1*_x64 + _d_Q1__1*_pd__23 + _d_iPsi1__1*_pd__24
        _d_ifp1__2 = _d_D__2*_pd__22 - _d_D__2*_x64 + _d_Q1__2*_pd__23 + _d_iPsi1__2*_pd__24
        _d_ifp1__3 = _d_D__3*_pd__22 - _d_D__3*_x64 + _d_Q1__3*_pd__23 + _d_iPsi1__3*_pd__24
        _d_ifp1__4 = _d_D__4*_pd__22 - _d_D__4*_x64 + _d_Q1__4*_pd__23 + _d_iPsi1__4*_pd__24
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x67 = m*q_rd**2
        _x68 = -q_r
        _x69 = k_c*(_x68 + l0)
        _x70 = -l0
        _x71 = -_isigma0 - _x70
        _x72 = 0.2113248654051871*k_c
        _x73 = -_isigma1 - _x70
        _x74 = 0.7886751345948129*k_c
        _x75 = 0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 + _x69 - _x71*_x72 - _x73*_x74
        _x76 = math.sqrt(_x67*k_c + _x75**2)
        _x77 = _x75 + _x76
        _x78 = (1.0/_x77)
        _D__next = _x67*_x78
        _x79 = _x71*k_c
        _x80 = _x73*k_c
        _x81 = (1.0/_x76)
        _x82 = _x78**2
        _x83 = _x67*_x82
        _pd__26 = (_x83*(-_x81*(0.04465819873852045*_iF0 + 0.16666666666666666*_iF1 + 0.2113248654051871*_x69
            - 0.04465819873852045*_x79 - 0.16666666666666666*_x80) - 0.2113248654051871))
        _pd__27 = (_x83*(-_x81*(0.16666666666666666*_iF0 + 0.6220084679281462*_iF1 + 0.7886751345948129*_x69
            - 0.16666666666666666*_x79 - 0.6220084679281462*_x80) - 0.7886751345948129))
        _x84 = _x75*_x81
        _pd__28 = _x83*(-_x72*_x84 - _x72)
        _pd__29 = _x83*(-_x74*_x84 - _x74)
        _d_D__next__0 = (_d_iF0__0*_pd__26 + _d_iF1__0*_pd__27 + _d_isigma0__0*_pd__28 + _d_isigma1__0*_pd__29
            + _x83*(_x84*k_c + k_c))
        _x85 = 0.9553418012614795*_pd__28
        _x86 = 0.37799153207185376*_pd__29
        _d_D__next__1 = (-_d_D__1*_x85 - _d_D__1*_x86 + _d_iF0__1*_pd__26 + _d_iF1__1*_pd__27
            + 2.0*_x78*m*q_rd - _x81*_x82*k_c*m**2*q_rd**3)
        _d_D__next__2 = -_d_D__2*_x85 - _d_D__2*_x86 + _d_iF0__2*_pd__26 + _d_iF1__2*_pd__27
        _d_D__next__3 = -_d_D__3*_x85 - _d_D__3*_x86 + _d_iF0__3*_pd__26 + _d_iF1__3*_pd__27
        _x87 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x85 - _d_D__4*_x86 + _d_iF0__4*_pd__26 + _d_iF1__4*_pd__27
            + _x83*(-0.2113248654051871*_isigma0 - 0.7886751345948129*_isigma1 - _x68 - _x81*((0.5)*_x67
            + (0.5)*_x75*(0.4226497308103742*_isigma0 + 1.5773502691896257*_isigma1 - _x87
            - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0))
        _Q0__next = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
        _d_Q0__next__0 = 0.25*_d_ifq0__0 + 0.5386751345948129*_d_ifq1__0
        _d_Q0__next__1 = 0.25*_d_ifq0__1 + 0.5386751345948129*_d_ifq1__1
        _d_Q0__next__2 = 0.25*_d_ifq0__2 + 0.5386751345948129*_d_ifq1__2 + 1.0
        _d_Q0__next__3 = 0.25*_d_ifq0__3 + 0.5386751345948129*_d_ifq1__3
        _d_Q0__next__4 = 0.25*_d_ifq0__4 + 0.5386751345948129*_d_ifq1__4
        _Q1__next = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
        _d_Q1__next__0 = -0.03867513459481288*_d_ifq0__0 + 0.25*_d_ifq1__0
        _d_Q1__next__1 = -0.03867513459481288*_d_ifq0__1 + 0.25*_d_ifq1__1
        _d_Q1__next__2 = -0.03867513459481288*_d_ifq0__2 + 0.25*_d_ifq1__2 + 1.0
        _d_Q1__next__3 = -0.03867513459481288*_d_ifq0__3 + 0.25*_d_ifq1__3
        _d_Q1__next__4 = -0.03867513459481288*_d_ifq0__4 + 0.25*_d_ifq1__4
        _x88 = m*q_r**2
        _x89 = _x88*q_thd
        _P0__next = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + _x89
        _x90 = _x87*m*q_thd
        _d_P0__next__0 = 0.25*_d_ifp0__0 + 0.5386751345948129*_d_ifp1__0 + _x90
        _d_P0__next__1 = 0.25*_d_ifp0__1 + 0.5386751345948129*_d_ifp1__1
        _d_P0__next__2 = 0.25*_d_ifp0__2 + 0.5386751345948129*_d_ifp1__2
        _d_P0__next__3 = 0.25*_d_ifp0__3 + 0.5386751345948129*_d_ifp1__3 + _x88
        _d_P0__next__4 = 0.25*_d_ifp0__4 + 0.5386751345948129*_d_ifp1__4
        _P1__next = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + _x89
        _d_P1__next__0 = -0.03867513459481288*_d_ifp0__0 + 0.25*_d_ifp1__0 + _x90
        _d_P1__next__1 = -0.03867513459481288*_d_ifp0__1 + 0.25*_d_ifp1__1
        _d_P1__next__2 = -0.03867513459481288*_d_ifp0__2 + 0.25*_d_ifp1__2
        _d_P1__next__3 = -0.03867513459481288*_d_ifp0__3 + 0.25*_d_ifp1__3 + _x88
        _d_P1__next__4 = -0.03867513459481288*_d_ifp0__4 + 0.25*_d_ifp1__4
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_P0__next - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _P0__next, _P1__next, _d_D__next__0, _d_D__next__1,
            _d_D__next__2, _d_D__next__3, _d_D__next__4, _d_Q0__next__0, _d_Q0__next__1, _d_Q0__next__2,
            _d_Q0__next__3, _d_Q0__next__4, _d_Q1__next__0, _d_Q1__next__1, _d_Q1__next__2, _d_Q1__next__3,
            _d_Q1__next__4, _d_P0__next__0, _d_P0__next__1, _d_P0__next__2, _d_P0__next__3, _d_P0__next__4,
            _d_P1__next__0, _d_P1__next__1, _d_P1__next__2, _d_P1__next__3, _d_P1__next__4, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 0.5*_ift0 + 0.5*_ift1
    d_t_half__0 = 0.5*_d_ift0__0 + 0.5*_d_ift1__0
    d_t_half__1 = 0.5*_d_ift0__1 + 0.5*_d_ift1__1
    d_t_half__2 = 0.5*_d_ift0__2 + 0.5*_d_ift1__2
    d_t_half__3 = 0.5*_d_ift0__3 + 0.5*_d_ift1__3
    d_t_half__4 = 0.5*_d_ift0__4 + 0.5*_d_ift1__4
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    d_end_q_th__0 = 0.5*_d_ifq0__0 + 0.5*_d_ifq1__0
    d_end_q_th__1 = 0.5*_d_ifq0__1 + 0.5*_d_ifq1__1
    d_end_q_th__2 = 0.5*_d_ifq0__2 + 0.5*_d_ifq1__2 + 1.0
    d_end_q_th__3 = 0.5*_d_ifq0__3 + 0.5*_d_ifq1__3
    d_end_q_th__4 = 0.5*_d_ifq0__4 + 0.5*_d_ifq1__4
    _x91 = -_D + q_r
    end_q_r = _x91
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x92 = q_r**2
    _x93 = 0.5*_ifp0 + 0.5*_ifp1 + _x92*m*q_thd
    _x98 = (1.0/_x91)
    _x94 = _x98**2
    _x95 = (1.0/m)
    _x96 = _x94*_x95
    end_q_thd = _x93*_x96
    _x97 = 0.5*_x96
    _pd__30 = _x97
    _pd__31 = _x97
    _pd__32 = -2.0*_x93*_x95*_x98**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__30 + _d_ifp1__0*_pd__31 + _pd__32*d_end_q_r__0 + 2.0*_x94*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__32 + _d_ifp0__1*_pd__30 + _d_ifp1__1*_pd__31
    d_end_q_thd__2 = -_d_D__2*_pd__32 + _d_ifp0__2*_pd__30 + _d_ifp1__2*_pd__31
    d_end_q_thd__3 = -_d_D__3*_pd__32 + _d_ifp0__3*_pd__30 + _d_ifp1__3*_pd__31 + _x92*_x94
    d_end_q_thd__4 = -_d_D__4*_pd__32 + _d_ifp0__4*_pd__30 + _d_ifp1__4*_pd__31
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN36 + (STATUS_FALL,)
    # derivatives of the outputs
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4, d_end_q_th__0,
        d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_thd__0, d_end_q_thd__1,
        d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_passes__0, d_passes__1, d_passes__2, d_passes__3,
        d_passes__4, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0,
        k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: those of
    :func:`schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd` (another choice of the
    same kernel).
    """
    # Total ops: 711
    # inputs: finite and inside their domains
    if not _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
            iterations, tol):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    # Picard passes on the 2 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th,
        0.7886751345948129*guess_q_th + 0.2113248654051871*q_th, 0.2113248654051871*guess_q_thd*m*q_r_lo**2
        + 0.7886751345948129*m*q_r**2*q_thd, 0.7886751345948129*guess_q_thd*m*q_r_lo**2
        + 0.2113248654051871*m*q_r**2*q_thd, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.7886751345948129, 0.0, 0.0,
        0.2113248654051871, 0.0, 0.0, 0.2113248654051871, 0.0, 0.0, 0.7886751345948129, 0.0,
        1.5773502691896257*m*q_r*q_thd, 0.0, 0.7886751345948129*m*q_r**2, 0.0, 0.0,
        0.2113248654051871*m*q_r_lo**2, 0.4226497308103742*m*q_r*q_thd, 0.0, 0.2113248654051871*m*q_r**2, 0.0,
        0.0, 0.7886751345948129*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _P0, _P1, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__guess_q_th,
            _d_D__guess_q_thd, _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d, _d_Q0__guess_q_th,
            _d_Q0__guess_q_thd, _d_Q1__q_r, _d_Q1__q_th, _d_Q1__q_thd, _d_Q1__k_d, _d_Q1__guess_q_th,
            _d_Q1__guess_q_thd, _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d, _d_P0__guess_q_th,
            _d_P0__guess_q_thd, _d_P1__q_r, _d_P1__q_th, _d_P1__q_thd, _d_P1__k_d, _d_P1__guess_q_th,
            _d_P1__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.04465819873852045*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.04465819873852045*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x65 = (1.0/_x1)
        _x9 = _x65**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _x14 = 3.0*_x8
        _pd__2 = -_x14*_x65**4*_x7 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__0 + _d_Q0__q_r*_pd__1 + _d_isigma0__q_r*_pd__2
        _x15 = 0.04465819873852045*_pd__2
        _d_iF0__q_th = _d_D__q_th*_x15 + _d_P0__q_th*_pd__0 + _d_Q0__q_th*_pd__1
        _d_iF0__q_thd = _d_D__q_thd*_x15 + _d_P0__q_thd*_pd__0 + _d_Q0__q_thd*_pd__1
        _x16 = l0 - q_r
        _d_iF0__k_d = _d_D__k_d*_x15 + _d_P0__k_d*_pd__0 + _d_Q0__k_d*_pd__1 - _x0 + _x16
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x15 + _d_P0__guess_q_th*_pd__0 + _d_Q0__guess_q_th*_pd__1
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x15 + _d_P0__guess_q_thd*_pd__0 + _d_Q0__guess_q_thd*_pd__1
        _x17 = 0.6220084679281462*_D
        _x18 = _x17 + q_r
        _isigma1 = _x18
        _d_isigma1__q_r = 0.6220084679281462*_d_D__q_r + 1.0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x4
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x66 = (1.0/_x18)
        _x23 = _x66**3
        _x24 = _x23*_x8
        _x25 = _x22*_x24
        _iF1 = _x2 - _x20 - _x21 + _x25
        _x26 = 2.0*_P1
        _pd__3 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__4 = _x27*_x4
        _pd__5 = -_x14*_x22*_x66**4 - k_d
        _d_iF1__q_r = _d_P1__q_r*_pd__3 + _d_Q1__q_r*_pd__4 + _d_isigma1__q_r*_pd__5
        _x28 = 0.6220084679281462*_pd__5
        _d_iF1__q_th = _d_D__q_th*_x28 + _d_P1__q_th*_pd__3 + _d_Q1__q_th*_pd__4
        _d_iF1__q_thd = _d_D__q_thd*_x28 + _d_P1__q_thd*_pd__3 + _d_Q1__q_thd*_pd__4
        _d_iF1__k_d = _d_D__k_d*_x28 + _d_P1__k_d*_pd__3 + _d_Q1__k_d*_pd__4 + _x16 - _x17
        _d_iF1__guess_q_th = _d_D__guess_q_th*_x28 + _d_P1__guess_q_th*_pd__3 + _d_Q1__guess_q_th*_pd__4
        _d_iF1__guess_q_thd = _d_D__guess_q_thd*_x28 + _d_P1__guess_q_thd*_pd__3 + _d_Q1__guess_q_thd*_pd__4
        _x29 = (0.5610042339640731*_x11 + 0.5*_x2 + 0.06100423396407311*_x20 + 0.06100423396407311*_x21
            - 0.06100423396407311*_x25 - 0.5610042339640731*_x5 - 0.5610042339640731*_x6)
        _iPsi0 = _x29
        _d_iPsi0__q_r = 0.5610042339640731*_d_iF0__q_r - 0.06100423396407311*_d_iF1__q_r
        _d_iPsi0__q_th = 0.5610042339640731*_d_iF0__q_th - 0.06100423396407311*_d_iF1__q_th
        _d_iPsi0__q_thd = 0.5610042339640731*_d_iF0__q_thd - 0.06100423396407311*_d_iF1__q_thd
        _d_iPsi0__k_d = 0.5610042339640731*_d_iF0__k_d - 0.06100423396407311*_d_iF1__k_d
        _d_iPsi0__guess_q_th = 0.5610042339640731*_d_iF0__guess_q_th - 0.06100423396407311*_d_iF1__guess_q_th
        _d_iPsi0__guess_q_thd = (0.5610042339640731*_d_iF0__guess_q_thd
            - 0.06100423396407311*_d_iF1__guess_q_thd)
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _ift0 = _x30*_x33
        _x34 = (0.5)/_x31
        _x35 = _x32*_x34
        _pd__6 = _x30*_x35
        _x36 = _x29**(-1.5)
        _x37 = (0.5)*_x33
        _pd__7 = -_x36*_x37
        _d_ift0__q_r = _d_D__q_r*_pd__6 + _d_iPsi0__q_r*_pd__7
        _d_ift0__q_th = _d_D__q_th*_pd__6 + _d_iPsi0__q_th*_pd__7
        _d_ift0__q_thd = _d_D__q_thd*_pd__6 + _d_iPsi0__q_thd*_pd__7
        _d_ift0__k_d = _d_D__k_d*_pd__6 + _d_iPsi0__k_d*_pd__7
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__6 + _d_iPsi0__guess_q_th*_pd__7
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__6 + _d_iPsi0__guess_q_thd*_pd__7
        _x38 = (1.0/_x32)
        _x39 = _x31*_x38
        _x40 = _x65**2
        _x41 = _x30*_x40
        _x42 = _x39*_x41
        _ifq0 = _P0*_x42
        _x43 = _x34*_x38
        _pd__8 = _P0*_x41*_x43
        _pd__9 = _x42
        _x44 = (0.5)*_x39
        _pd__10 = -_P0*_x36*_x40*_x44
        _pd__11 = -_x12*_x30*_x39*_x9
        _d_ifq0__q_r = _d_D__q_r*_pd__8 + _d_P0__q_r*_pd__9 + _d_iPsi0__q_r*_pd__10 + _d_isigma0__q_r*_pd__11
        _x45 = 0.04465819873852045*_pd__11
        _d_ifq0__q_th = _d_D__q_th*_pd__8 + _d_D__q_th*_x45 + _d_P0__q_th*_pd__9 + _d_iPsi0__q_th*_pd__10
        _d_ifq0__q_thd = _d_D__q_thd*_pd__8 + _d_D__q_thd*_x45 + _d_P0__q_thd*_pd__9 + _d_iPsi0__q_thd*_pd__10
        _d_ifq0__k_d = _d_D__k_d*_pd__8 + _d_D__k_d*_x45 + _d_P0__k_d*_pd__9 + _d_iPsi0__k_d*_pd__10
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__8 + _d_D__guess_q_th*_x45 + _d_P0__guess_q_th*_pd__9
            + _d_iPsi0__guess_q_th*_pd__10)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__8 + _d_D__guess_q_thd*_x45 + _d_P0__guess_q_thd*_pd__9
            + _d_iPsi0__guess_q_thd*_pd__10)
        _x46 = g_s*m**(1.5)
        _x47 = _x31*_x46
        _x48 = _x30*_x47
        _x49 = _x13*_x48
        _ifp0 = _x1*_x49
        _x50 = _x1*_x13
        _x51 = _x34*_x46
        _pd__12 = _x30*_x50*_x51
        _pd__13 = _x1*_x3*_x48
        _x52 = (0.5)*_x47
        _pd__14 = -_x36*_x50*_x52
        _pd__15 = _x49
        _d_ifp0__q_r = (_d_D__q_r*_pd__12 + _d_Q0__q_r*_pd__13 + _d_iPsi0__q_r*_pd__14
            + _d_isigma0__q_r*_pd__15)
        _x53 = 0.04465819873852045*_pd__15
        _d_ifp0__q_th = _d_D__q_th*_pd__12 + _d_D__q_th*_x53 + _d_Q0__q_th*_pd__13 + _d_iPsi0__q_th*_pd__14
        _d_ifp0__q_thd = (_d_D__q_thd*_pd__12 + _d_D__q_thd*_x53 + _d_Q0__q_thd*_pd__13
            + _d_iPsi0__q_thd*_pd__14)
        _d_ifp0__k_d = _d_D__k_d*_pd__12 + _d_D__k_d*_x53 + _d_Q0__k_d*_pd__13 + _d_iPsi0__k_d*_pd__14
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__12 + _d_D__guess_q_th*_x53 + _d_Q0__guess_q_th*_pd__13
            + _d_iPsi0__guess_q_th*_pd__14)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__12 + _d_D__guess_q_thd*_x53
            + _d_Q0__guess_q_thd*_pd__13 + _d_iPsi0__guess_q_thd*_pd__14)
        _x54 = (-0.27232909936926025*_x20 - 0.27232909936926025*_x21 + 0.27232909936926025*_x22*_x23*_x8
            - 0.22767090063073978*_x5 - 0.22767090063073978*_x6 + 0.22767090063073978*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi1 = _x54
        _d_iPsi1__q_r = 0.22767090063073978*_d_iF0__q_r + 0.27232909936926025*_d_iF1__q_r
        _d_iPsi1__q_th = 0.22767090063073978*_d_iF0__q_th + 0.27232909936926025*_d_iF1__q_th
        _d_iPsi1__q_thd = 0.22767090063073978*_d_iF0__q_thd + 0.27232909936926025*_d_iF1__q_thd
        _d_iPsi1__k_d = 0.22767090063073978*_d_iF0__k_d + 0.27232909936926025*_d_iF1__k_d
        _d_iPsi1__guess_q_th = 0.22767090063073978*_d_iF0__guess_q_th + 0.27232909936926025*_d_iF1__guess_q_th
        _d_iPsi1__guess_q_thd = (0.22767090063073978*_d_iF0__guess_q_thd
            + 0.27232909936926025*_d_iF1__guess_q_thd)
        _x55 = (1.0/math.sqrt(_x54))
        _ift1 = _x33*_x55
        _pd__16 = _x35*_x55
        _x56 = _x54**(-1.5)
        _pd__17 = -_x37*_x56
        _d_ift1__q_r = _d_D__q_r*_pd__16 + _d_iPsi1__q_r*_pd__17
        _d_ift1__q_th = _d_D__q_th*_pd__16 + _d_iPsi1__q_th*_pd__17
        _d_ift1__q_thd = _d_D__q_thd*_pd__16 + _d_iPsi1__q_thd*_pd__17
        _d_ift1__k_d = _d_D__k_d*_pd__16 + _d_iPsi1__k_d*_pd__17
        _d_ift1__guess_q_th = _d_D__guess_q_th*_pd__16 + _d_iPsi1__guess_q_th*_pd__17
        _d_ift1__guess_q_thd = _d_D__guess_q_thd*_pd__16 + _d_iPsi1__guess_q_thd*_pd__17
        _x57 = _x66**2
        _x58 = _x55*_x57
        _x59 = _x39*_x58
        _ifq1 = _P1*_x59
        _pd__18 = _P1*_x43*_x58
        _pd__19 = _x59
        _pd__20 = -_P1*_x44*_x56*_x57
        _pd__21 = -_x23*_x26*_x39*_x55
        _d_ifq1__q_r = (_d_D__q_r*_pd__18 + _d_P1__q_r*_pd__19 + _d_iPsi1__q_r*_pd__20
            + _d_isigma1__q_r*_pd__21)
        _x60 = 0.6220084679281462*_pd__21
        _d_ifq1__q_th = _d_D__q_th*_pd__18 + _d_D__q_th*_x60 + _d_P1__q_th*_pd__19 + _d_iPsi1__q_th*_pd__20
        _d_ifq1__q_thd = (_d_D__q_thd*_pd__18 + _d_D__q_thd*_x60 + _d_P1__q_thd*_pd__19
            + _d_iPsi1__q_thd*_pd__20)
        _d_ifq1__k_d = _d_D__k_d*_pd__18 + _d_D__k_d*_x60 + _d_P1__k_d*_pd__19 + _d_iPsi1__k_d*_pd__20
        _d_ifq1__guess_q_th = (_d_D__guess_q_th*_pd__18 + _d_D__guess_q_th*_x60 + _d_P1__guess_q_th*_pd__19
            + _d_iPsi1__guess_q_th*_pd__20)
        _d_ifq1__guess_q_thd = (_d_D__guess_q_thd*_pd__18 + _d_D__guess_q_thd*_x60
            + _d_P1__guess_q_thd*_pd__19 + _d_iPsi1__guess_q_thd*_pd__20)
        _x61 = _x47*_x55
        _x62 = _x27*_x61
        _ifp1 = _x18*_x62
        _x63 = _x18*_x27
        _pd__22 = _x51*_x55*_x63
        _pd__23 = _x18*_x19*_x61
        _pd__24 = -_x52*_x56*_x63
        _pd__25 = _x62
        _d_ifp1__q_r = (_d_D__q_r*_pd__22 + _d_Q1__q_r*_pd__23 + _d_iPsi1__q_r*_pd__24
            + _d_isigma1__q_r*_pd__25)
        _x64 = 0.6220084679281462*_pd__25
        _d_ifp1__q_th = _d_D__q_th*_pd__22 + _d_D__q_th*_x64 + _d_Q1__q_th*_pd__23 + _d_iPsi1__q_th*_pd__24
        _d_ifp1__q_thd = (_d_D__q_thd*_pd__22 + _d_D__q_thd*_x64 + _d_Q1__q_thd*_pd__23
            + _d_iPsi1__q_thd*_pd__24)
        _d_ifp1__k_d = _d_D__k_d*_pd__22 + _d_D__k_d*_x64 + _d_Q1__k_d*_pd__23 + _d_iPsi1__k_d*_pd__24
        _d_ifp1__guess_q_th = (_d_D__guess_q_th*_pd__22 + _d_D__guess_q_th*_x64 + _d_Q1__guess_q_th*_pd__23
            + _d_iPsi1__guess_q_th*_pd__24)
        _d_ifp1__guess_q_thd = (_d_D__guess_q_thd*_pd__22 + _d_D__guess_q_thd*_x64
            + _d_Q1__guess_q_thd*_pd__23 + _d_iPsi1__guess_q_thd*_pd__24)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
        _d_Q0__next__q_r = 0.25*_d_ifq0__q_r - 0.03867513459481288*_d_ifq1__q_r
        _d_Q0__next__q_th = 0.25*_d_ifq0__q_th - 0.03867513459481288*_d_ifq1__q_th + 1.0
        _d_Q0__next__q_thd = 0.25*_d_ifq0__q_thd - 0.03867513459481288*_d_ifq1__q_thd
        _d_Q0__next__k_d = 0.25*_d_ifq0__k_d - 0.03867513459481288*_d_ifq1__k_d
        _d_Q0__next__guess_q_th = 0.25*_d_ifq0__guess_q_th - 0.03867513459481288*_d_ifq1__guess_q_th
        _d_Q0__next__guess_q_thd = 0.25*_d_ifq0__guess_q_thd - 0.03867513459481288*_d_ifq1__guess_q_thd
        _Q1__next = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
        _d_Q1__next__q_r = 0.5386751345948129*_d_ifq0__q_r + 0.25*_d_ifq1__q_r
        _d_Q1__next__q_th = 0.5386751345948129*_d_ifq0__q_th + 0.25*_d_ifq1__q_th + 1.0
        _d_Q1__next__q_thd = 0.5386751345948129*_d_ifq0__q_thd + 0.25*_d_ifq1__q_thd
        _d_Q1__next__k_d = 0.5386751345948129*_d_ifq0__k_d + 0.25*_d_ifq1__k_d
        _d_Q1__next__guess_q_th = 0.5386751345948129*_d_ifq0__guess_q_th + 0.25*_d_ifq1__guess_q_th
        _d_Q1__next__guess_q_thd = 0.5386751345948129*_d_ifq0__guess_q_thd + 0.25*_d_ifq1__guess_q_thd
        _x67 = m*q_r**2
        _x68 = _x67*q_thd
        _P0__next = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + _x68
        _x69 = 2.0*m*q_r*q_thd
        _d_P0__next__q_r = 0.25*_d_ifp0__q_r - 0.03867513459481288*_d_ifp1__q_r + _x69
        _d_P0__next__q_th = 0.25*_d_ifp0__q_th - 0.03867513459481288*_d_ifp1__q_th
        _d_P0__next__q_thd = 0.25*_d_ifp0__q_thd - 0.03867513459481288*_d_ifp1__q_thd + _x67
        _d_P0__next__k_d = 0.25*_d_ifp0__k_d - 0.03867513459481288*_d_ifp1__k_d
        _d_P0__next__guess_q_th = 0.25*_d_ifp0__guess_q_th - 0.03867513459481288*_d_ifp1__guess_q_th
        _d_P0__next__guess_q_thd = 0.25*_d_ifp0__guess_q_thd - 0.03867513459481288*_d_ifp1__guess_q_thd
        _P1__next = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + _x68
        _d_P1__next__q_r = 0.5386751345948129*_d_ifp0__q_r + 0.25*_d_ifp1__q_r + _x69
        _d_P1__next__q_th = 0.5386751345948129*_d_ifp0__q_th + 0.25*_d_ifp1__q_th
        _d_P1__next__q_thd = 0.5386751345948129*_d_ifp0__q_thd + 0.25*_d_ifp1__q_thd + _x67
        _d_P1__next__k_d = 0.5386751345948129*_d_ifp0__k_d + 0.25*_d_ifp1__k_d
        _d_P1__next__guess_q_th = 0.5386751345948129*_d_ifp0__guess_q_th + 0.25*_d_ifp1__guess_q_th
        _d_P1__next__guess_q_thd = 0.5386751345948129*_d_ifp0__guess_q_thd + 0.25*_d_ifp1__guess_q_thd
        _n0_5 = _d_D__q_r
        _n0_6 = _d_D__q_th
        _n0_7 = _d_D__q_thd
        _n0_8 = _d_D__k_d
        _n0_9 = _d_D__guess_q_th
        _n0_10 = _d_D__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_P0__next - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _P0__next, _P1__next, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            _n0_10, _d_Q0__next__q_r, _d_Q0__next__q_th, _d_Q0__next__q_thd, _d_Q0__next__k_d,
            _d_Q0__next__guess_q_th, _d_Q0__next__guess_q_thd, _d_Q1__next__q_r, _d_Q1__next__q_th,
            _d_Q1__next__q_thd, _d_Q1__next__k_d, _d_Q1__next__guess_q_th, _d_Q1__next__guess_q_thd,
            _d_P0__next__q_r, _d_P0__next__q_th, _d_P0__next__q_thd, _d_P0__next__k_d,
            _d_P0__next__guess_q_th, _d_P0__next__guess_q_thd, _d_P1__next__q_r, _d_P1__next__q_th,
            _d_P1__next__q_thd, _d_P1__next__k_d, _d_P1__next__guess_q_th, _d_P1__next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = 0.10566243270259355*_iF0 + 0.39433756729740643*_iF1
    _d_work__q_r = 0.10566243270259355*_d_iF0__q_r + 0.39433756729740643*_d_iF1__q_r
    _d_work__q_th = 0.10566243270259355*_d_iF0__q_th + 0.39433756729740643*_d_iF1__q_th
    _d_work__q_thd = 0.10566243270259355*_d_iF0__q_thd + 0.39433756729740643*_d_iF1__q_thd
    _d_work__k_d = 0.10566243270259355*_d_iF0__k_d + 0.39433756729740643*_d_iF1__k_d
    _d_work__guess_q_th = 0.10566243270259355*_d_iF0__guess_q_th + 0.39433756729740643*_d_iF1__guess_q_th
    _d_work__guess_q_thd = 0.10566243270259355*_d_iF0__guess_q_thd + 0.39433756729740643*_d_iF1__guess_q_thd
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.5*_ift0 + 0.5*_ift1
    d_t_half__q_r = 0.5*_d_ift0__q_r + 0.5*_d_ift1__q_r
    d_t_half__q_th = 0.5*_d_ift0__q_th + 0.5*_d_ift1__q_th
    d_t_half__q_thd = 0.5*_d_ift0__q_thd + 0.5*_d_ift1__q_thd
    d_t_half__k_d = 0.5*_d_ift0__k_d + 0.5*_d_ift1__k_d
    d_t_half__guess_q_th = 0.5*_d_ift0__guess_q_th + 0.5*_d_ift1__guess_q_th
    d_t_half__guess_q_thd = 0.5*_d_ift0__guess_q_thd + 0.5*_d_ift1__guess_q_thd
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    d_end_q_th__q_r = 0.5*_d_ifq0__q_r + 0.5*_d_ifq1__q_r
    d_end_q_th__q_th = 0.5*_d_ifq0__q_th + 0.5*_d_ifq1__q_th + 1.0
    d_end_q_th__q_thd = 0.5*_d_ifq0__q_thd + 0.5*_d_ifq1__q_thd
    d_end_q_th__k_d = 0.5*_d_ifq0__k_d + 0.5*_d_ifq1__k_d
    d_end_q_th__guess_q_th = 0.5*_d_ifq0__guess_q_th + 0.5*_d_ifq1__guess_q_th
    d_end_q_th__guess_q_thd = 0.5*_d_ifq0__guess_q_thd + 0.5*_d_ifq1__guess_q_thd
    end_q_r = q_r_lo
    _x70 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x70
    _pd__26 = _x70/_D
    _pd__27 = _x70/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__26 + _d_work__q_r*_pd__27
    d_end_q_rd__q_th = _d_D__q_th*_pd__26 + _d_work__q_th*_pd__27
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__26 + _d_work__q_thd*_pd__27
    d_end_q_rd__k_d = _d_D__k_d*_pd__26 + _d_work__k_d*_pd__27
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__26 + _d_work__guess_q_th*_pd__27
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__26 + _d_work__guess_q_thd*_pd__27
    _x71 = q_r**2
    _x72 = q_r_lo**-2
    _x73 = _x72/m
    end_q_thd = _x73*(0.5*_ifp0 + 0.5*_ifp1 + _x71*m*q_thd)
    _x74 = 0.5*_x73
    _pd__28 = _x74
    _pd__29 = _x74
    d_end_q_thd__q_r = _d_ifp0__q_r*_pd__28 + _d_ifp1__q_r*_pd__29 + 2.0*_x72*q_r*q_thd
    d_end_q_thd__q_th = _d_ifp0__q_th*_pd__28 + _d_ifp1__q_th*_pd__29
    d_end_q_thd__q_thd = _d_ifp0__q_thd*_pd__28 + _d_ifp1__q_thd*_pd__29 + _x71*_x72
    d_end_q_thd__k_d = _d_ifp0__k_d*_pd__28 + _d_ifp1__k_d*_pd__29
    d_end_q_thd__guess_q_th = _d_ifp0__guess_q_th*_pd__28 + _d_ifp1__guess_q_th*_pd__29
    d_end_q_thd__guess_q_thd = _d_ifp0__guess_q_thd*_pd__28 + _d_ifp1__guess_q_thd*_pd__29
    passes = _passes
    # derivatives of the outputs
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN77 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td, 0.0,
        _j_z_b_q_th__q_th_td, 0.0, _j_z_b_q_r__q_thd_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_geyer`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_geyer`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 122
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x6 = m*q_rd_td**2
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    z_b_q_r = _x11
    _x12 = (1.0/_x8)
    _x13 = (0.5)*_x7
    _x14 = _x10**2
    _x15 = _x14*_x6
    d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
    d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
    _x16 = _x2*math.sin(q_th_td)
    _x17 = _x12*_x7
    d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
    _x18 = 2.0*q_r_td
    _x19 = _x18*q_thd_td
    _x20 = _x19*m
    d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
    d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
    z_b_q_th = q_th_td
    _x21 = q_r_td**2
    _x24 = (1.0/_x11)
    _x22 = _x24**2
    _x23 = _x21*_x22
    z_b_q_thd = _x23*q_thd_td
    _pd__0 = -2.0*_x21*_x24**3*q_thd_td
    d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
    d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
    d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
    d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
    d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, d_z_b_q_r__q_r_td, 0.0, d_z_b_q_thd__q_r_td,
        d_z_b_q_r__q_rd_td, 0.0, d_z_b_q_thd__q_rd_td, d_z_b_q_r__q_th_td, 1.0, d_z_b_q_thd__q_th_td,
        d_z_b_q_r__q_thd_td, 0.0, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, 0.0, d_z_b_q_thd__k_c))
    if _c0[36] != STATUS_OK:
        return _NAN77 + (_c0[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c0
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x25 = q_r_lo**-2
    _x26 = _x25*bottom_q_r**2
    g_lo_q_thd = _x26*bottom_q_thd
    _pd__1 = 2.0*_x25*bottom_q_r*bottom_q_thd
    _pd__2 = _x26
    d_g_lo_q_thd__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _pd__2*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td + _pd__2*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__1*d_bottom_q_r__q_th_td + _pd__2*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td + _pd__2*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__1*d_bottom_q_r__k_c + _pd__2*d_bottom_q_thd__k_c
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c1
    # the code shared between choices
    return (iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_held`: arguments, out and status
    as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_held`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_2_jvp6_a742c3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5,
        d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp6_a742c3` (another choice of
    the same kernel).
    """
    # Total ops: 837
    # inputs: finite and inside their domains
    if not _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # Picard passes on the 2 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th,
        0.2113248654051871*guess_q_th + 0.7886751345948129*q_th, 0.7886751345948129*guess_q_r**2*guess_q_thd*m
        + 0.2113248654051871*m*q_r**2*q_thd, 0.2113248654051871*guess_q_r**2*guess_q_thd*m
        + 0.7886751345948129*m*q_r**2*q_thd, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2,
        -d_guess_q_r__3, -d_guess_q_r__4, -d_guess_q_r__5, 0.7886751345948129*d_guess_q_th__0,
        0.7886751345948129*d_guess_q_th__1, 0.7886751345948129*d_guess_q_th__2 + 0.2113248654051871,
        0.7886751345948129*d_guess_q_th__3, 0.7886751345948129*d_guess_q_th__4,
        0.7886751345948129*d_guess_q_th__5, 0.2113248654051871*d_guess_q_th__0,
        0.2113248654051871*d_guess_q_th__1, 0.2113248654051871*d_guess_q_th__2 + 0.7886751345948129,
        0.2113248654051871*d_guess_q_th__3, 0.2113248654051871*d_guess_q_th__4,
        0.2113248654051871*d_guess_q_th__5, 1.5773502691896257*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__0*guess_q_r**2*m + 0.4226497308103742*m*q_r*q_thd,
        1.5773502691896257*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__1*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__2*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__3*guess_q_r**2*m + 0.2113248654051871*m*q_r**2,
        1.5773502691896257*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__4*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__5*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__0*guess_q_r**2*m + 1.5773502691896257*m*q_r*q_thd,
        0.4226497308103742*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__1*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__2*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__3*guess_q_r**2*m + 0.7886751345948129*m*q_r**2,
        0.4226497308103742*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__4*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _P0, _P1, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_Q0__0, _d_Q0__1,
            _d_Q0__2, _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_Q1__0, _d_Q1__1, _d_Q1__2, _d_Q1__3, _d_Q1__4,
            _d_Q1__5, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, _d_P1__0, _d_P1__1,
            _d_P1__2, _d_P1__3, _d_P1__4, _d_P1__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9553418012614795*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9553418012614795*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x66 = (1.0/_x2)
        _x10 = _x66**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__0 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__1 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__2 = -_x15*_x66**4*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__0 + _d_Q0__0*_pd__1 + _d_isigma0__0*_pd__2
        _x16 = 0.9553418012614795*_pd__2
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__0 + _d_Q0__1*_pd__1
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__0 + _d_Q0__2*_pd__1
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__0 + _d_Q0__3*_pd__1
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__0 + _d_Q0__4*_pd__1 + _x1 + l0
        _d_iF0__5 = -_d_D__5*_x16 + _d_P0__5*_pd__0 + _d_Q0__5*_pd__1
        _x17 = 0.37799153207185376*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.37799153207185376*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x65 = (1.0/_x18)
        _x23 = _x65**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__3 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__4 = _x27*_x5
        _pd__5 = -_x15*_x22*_x65**4 - k_c
        _d_iF1__0 = _d_P1__0*_pd__3 + _d_Q1__0*_pd__4 + _d_isigma1__0*_pd__5
        _x28 = 0.37799153207185376*_pd__5
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__3 + _d_Q1__1*_pd__4
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__3 + _d_Q1__2*_pd__4
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__3 + _d_Q1__3*_pd__4
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__3 + _d_Q1__4*_pd__4 + _x17 + l0
        _d_iF1__5 = -_d_D__5*_x28 + _d_P1__5*_pd__3 + _d_Q1__5*_pd__4
        _x29 = (0.5610042339640731*_x12 + 0.06100423396407311*_x20 + 0.06100423396407311*_x21
            - 0.06100423396407311*_x25 + 0.5*_x3 - 0.5610042339640731*_x6 - 0.5610042339640731*_x7)
        _iPsi0 = _x29
        _d_iPsi0__0 = 0.5610042339640731*_d_iF0__0 - 0.06100423396407311*_d_iF1__0
        _d_iPsi0__1 = 0.5610042339640731*_d_iF0__1 - 0.06100423396407311*_d_iF1__1
        _d_iPsi0__2 = 0.5610042339640731*_d_iF0__2 - 0.06100423396407311*_d_iF1__2
        _d_iPsi0__3 = 0.5610042339640731*_d_iF0__3 - 0.06100423396407311*_d_iF1__3
        _d_iPsi0__4 = 0.5610042339640731*_d_iF0__4 - 0.06100423396407311*_d_iF1__4
        _d_iPsi0__5 = 0.5610042339640731*_d_iF0__5 - 0.06100423396407311*_d_iF1__5
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _ift0 = _x30*_x33
        _x34 = (0.5)/_x31
        _x35 = _x32*_x34
        _pd__6 = _x30*_x35
        _x36 = _x29**(-1.5)
        _x37 = (0.5)*_x33
        _pd__7 = -_x36*_x37
        _d_ift0__0 = _d_D__0*_pd__6 + _d_iPsi0__0*_pd__7
        _d_ift0__1 = _d_D__1*_pd__6 + _d_iPsi0__1*_pd__7
        _d_ift0__2 = _d_D__2*_pd__6 + _d_iPsi0__2*_pd__7
        _d_ift0__3 = _d_D__3*_pd__6 + _d_iPsi0__3*_pd__7
        _d_ift0__4 = _d_D__4*_pd__6 + _d_iPsi0__4*_pd__7
        _d_ift0__5 = _d_D__5*_pd__6 + _d_iPsi0__5*_pd__7
        _x38 = (1.0/_x32)
        _x39 = _x31*_x38
        _x40 = _x66**2
        _x41 = _x30*_x40
        _x42 = _x39*_x41
        _ifq0 = _P0*_x42
        _x43 = _x34*_x38
        _pd__8 = _P0*_x41*_x43
        _pd__9 = _x42
        _x44 = (0.5)*_x39
        _pd__10 = -_P0*_x36*_x40*_x44
        _pd__11 = -_x10*_x13*_x30*_x39
        _d_ifq0__0 = _d_D__0*_pd__8 + _d_P0__0*_pd__9 + _d_iPsi0__0*_pd__10 + _d_isigma0__0*_pd__11
        _x45 = 0.9553418012614795*_pd__11
        _d_ifq0__1 = _d_D__1*_pd__8 - _d_D__1*_x45 + _d_P0__1*_pd__9 + _d_iPsi0__1*_pd__10
        _d_ifq0__2 = _d_D__2*_pd__8 - _d_D__2*_x45 + _d_P0__2*_pd__9 + _d_iPsi0__2*_pd__10
        _d_ifq0__3 = _d_D__3*_pd__8 - _d_D__3*_x45 + _d_P0__3*_pd__9 + _d_iPsi0__3*_pd__10
        _d_ifq0__4 = _d_D__4*_pd__8 - _d_D__4*_x45 + _d_P0__4*_pd__9 + _d_iPsi0__4*_pd__10
        _d_ifq0__5 = _d_D__5*_pd__8 - _d_D__5*_x45 + _d_P0__5*_pd__9 + _d_iPsi0__5*_pd__10
        _x46 = g_s*m**(1.5)
        _x47 = _x31*_x46
        _x48 = _x30*_x47
        _x49 = _x14*_x48
        _ifp0 = _x2*_x49
        _x50 = _x14*_x2
        _x51 = _x34*_x46
        _pd__12 = _x30*_x50*_x51
        _pd__13 = _x2*_x4*_x48
        _x52 = (0.5)*_x47
        _pd__14 = -_x36*_x50*_x52
        _pd__15 = _x49
        _d_ifp0__0 = _d_D__0*_pd__12 + _d_Q0__0*_pd__13 + _d_iPsi0__0*_pd__14 + _d_isigma0__0*_pd__15
        _x53 = 0.9553418012614795*_pd__15
        _d_ifp0__1 = _d_D__1*_pd__12 - _d_D__1*_x53 + _d_Q0__1*_pd__13 + _d_iPsi0__1*_pd__14
        _d_ifp0__2 = _d_D__2*_pd__12 - _d_D__2*_x53 + _d_Q0__2*_pd__13 + _d_iPsi0__2*_pd__14
        _d_ifp0__3 = _d_D__3*_pd__12 - _d_D__3*_x53 + _d_Q0__3*_pd__13 + _d_iPsi0__3*_pd__14
        _d_ifp0__4 = _d_D__4*_pd__12 - _d_D__4*_x53 + _d_Q0__4*_pd__13 + _d_iPsi0__4*_pd__14
        _d_ifp0__5 = _d_D__5*_pd__12 - _d_D__5*_x53 + _d_Q0__5*_pd__13 + _d_iPsi0__5*_pd__14
        _x54 = (0.22767090063073978*_x10*_x8*_x9 - 0.27232909936926025*_x20 - 0.27232909936926025*_x21
            + 0.27232909936926025*_x22*_x23*_x9 - 0.22767090063073978*_x6 - 0.22767090063073978*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x54
        _d_iPsi1__0 = 0.22767090063073978*_d_iF0__0 + 0.27232909936926025*_d_iF1__0
        _d_iPsi1__1 = 0.22767090063073978*_d_iF0__1 + 0.27232909936926025*_d_iF1__1
        _d_iPsi1__2 = 0.22767090063073978*_d_iF0__2 + 0.27232909936926025*_d_iF1__2
        _d_iPsi1__3 = 0.22767090063073978*_d_iF0__3 + 0.27232909936926025*_d_iF1__3
        _d_iPsi1__4 = 0.22767090063073978*_d_iF0__4 + 0.27232909936926025*_d_iF1__4
        _d_iPsi1__5 = 0.22767090063073978*_d_iF0__5 + 0.27232909936926025*_d_iF1__5
        _x55 = (1.0/math.sqrt(_x54))
        _ift1 = _x33*_x55
        _pd__16 = _x35*_x55
        _x56 = _x54**(-1.5)
        _pd__17 = -_x37*_x56
        _d_ift1__0 = _d_D__0*_pd__16 + _d_iPsi1__0*_pd__17
        _d_ift1__1 = _d_D__1*_pd__16 + _d_iPsi1__1*_pd__17
        _d_ift1__2 = _d_D__2*_pd__16 + _d_iPsi1__2*_pd__17
        _d_ift1__3 = _d_D__3*_pd__16 + _d_iPsi1__3*_pd__17
        _d_ift1__4 = _d_D__4*_pd__16 + _d_iPsi1__4*_pd__17
        _d_ift1__5 = _d_D__5*_pd__16 + _d_iPsi1__5*_pd__17
        _x57 = _x65**2
        _x58 = _x55*_x57
        _x59 = _x39*_x58
        _ifq1 = _P1*_x59
        _pd__18 = _P1*_x43*_x58
        _pd__19 = _x59
        _pd__20 = -_P1*_x44*_x56*_x57
        _pd__21 = -_x23*_x26*_x39*_x55
        _d_ifq1__0 = _d_D__0*_pd__18 + _d_P1__0*_pd__19 + _d_iPsi1__0*_pd__20 + _d_isigma1__0*_pd__21
        _x60 = 0.37799153207185376*_pd__21
        _d_ifq1__1 = _d_D__1*_pd__18 - _d_D__1*_x60 + _d_P1__1*_pd__19 + _d_iPsi1__1*_pd__20
        _d_ifq1__2 = _d_D__2*_pd__18 - _d_D__2*_x60 + _d_P1__2*_pd__19 + _d_iPsi1__2*_pd__20
        _d_ifq1__3 = _d_D__3*_pd__18 - _d_D__3*_x60 + _d_P1__3*_pd__19 + _d_iPsi1__3*_pd__20
        _d_ifq1__4 = _d_D__4*_pd__18 - _d_D__4*_x60 + _d_P1__4*_pd__19 + _d_iPsi1__4*_pd__20
        _d_ifq1__5 = _d_D__5*_pd__18 - _d_D__5*_x60 + _d_P1__5*_pd__19 + _d_iPsi1__5*_pd__20
        _x61 = _x47*_x55
        _x62 = _x27*_x61
        _ifp1 = _x18*_x62
        _x63 = _x18*_x27
        _pd__22 = _x51*_x55*_x63
        _pd__23 = _x18*_x19*_x61
        _pd__24 = -_x52*_x56*_x63
        _pd__25 = _x62
        _d_ifp1__0 = _d_D__0*_pd__22 + _d_Q1__0*_pd__23 + _d_iPsi1__0*_pd__24 + _d_isigma1__0*_pd__25
        _x64 = 0.37799153207185376*_pd__25
        _d_ifp1__1 = _d_D__1*_pd__22 - _d_D__1*_x64 + _d_Q1__1*_pd__23 + _d_iPsi1__1*_pd__24
        _d_ifp1__2 = _d_D__2*_pd__22 - _d_D__2*_x64 + _d_Q1__2*_pd__23 + _d_iPsi1__2*_pd__24
        _d_ifp1__3 = _d_D__3*_pd__22 - _d_D__3*_x64 + _d_Q1__3*_pd__23 + _d_iPsi1__3*_pd__24
        _d_ifp1__4 = _d_D__4*_pd__22 - _d_D__4*_x64 + _d_Q1__4*_pd__23 + _d_iPsi1__4*_pd__24
        _d_ifp1__5 = _d_D__5*_pd__22 - _d_D__5*_x64 + _d_Q1__5*_pd__23 + _d_iPsi1__5*_pd__24
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x67 = m*q_rd**2
        _x68 = -q_r
        _x69 = k_c*(_x68 + l0)
        _x70 = -l0
        _x71 = -_isigma0 - _x70
        _x72 = 0.2113248654051871*k_c
        _x73 = -_isigma1 - _x70
        _x74 = 0.7886751345948129*k_c
        _x75 = 0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 + _x69 - _x71*_x72 - _x73*_x74
        _x76 = math.sqrt(_x67*k_c + _x75**2)
        _x77 = _x75 + _x76
        _x78 = (1.0/_x77)
        _D__next = _x67*_x78
        _x79 = _x71*k_c
        _x80 = _x73*k_c
        _x81 = (1.0/_x76)
        _x82 = _x78**2
        _x83 = _x67*_x82
        _pd__26 = (_x83*(-_x81*(0.04465819873852045*_iF0 + 0.16666666666666666*_iF1 + 0.2113248654051871*_x69
            - 0.04465819873852045*_x79 - 0.16666666666666666*_x80) - 0.2113248654051871))
        _pd__27 = (_x83*(-_x81*(0.16666666666666666*_iF0 + 0.6220084679281462*_iF1 + 0.7886751345948129*_x69
            - 0.16666666666666666*_x79 - 0.6220084679281462*_x80) - 0.7886751345948129))
        _x84 = _x75*_x81
        _pd__28 = _x83*(-_x72*_x84 - _x72)
        _pd__29 = _x83*(-_x74*_x84 - _x74)
        _d_D__next__0 = (_d_iF0__0*_pd__26 + _d_iF1__0*_pd__27 + _d_isigma0__0*_pd__28 + _d_isigma1__0*_pd__29
            + _x83*(_x84*k_c + k_c))
        _x85 = 0.9553418012614795*_pd__28
        _x86 = 0.37799153207185376*_pd__29
        _d_D__next__1 = (-_d_D__1*_x85 - _d_D__1*_x86 + _d_iF0__1*_pd__26 + _d_iF1__1*_pd__27
            + 2.0*_x78*m*q_rd - _x81*_x82*k_c*m**2*q_rd**3)
        _d_D__next__2 = -_d_D__2*_x85 - _d_D__2*_x86 + _d_iF0__2*_pd__26 + _d_iF1__2*_pd__27
        _d_D__next__3 = -_d_D__3*_x85 - _d_D__3*_x86 + _d_iF0__3*_pd__26 + _d_iF1__3*_pd__27
        _x87 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x85 - _d_D__4*_x86 + _d_iF0__4*_pd__26 + _d_iF1__4*_pd__27
            + _x83*(-0.2113248654051871*_isigma0 - 0.7886751345948129*_isigma1 - _x68 - _x81*((0.5)*_x67
            + (0.5)*_x75*(0.4226497308103742*_isigma0 + 1.5773502691896257*_isigma1 - _x87
            - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0))
        _d_D__next__5 = -_d_D__5*_x85 - _d_D__5*_x86 + _d_iF0__5*_pd__26 + _d_iF1__5*_pd__27
        _Q0__next = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
        _d_Q0__next__0 = 0.25*_d_ifq0__0 + 0.5386751345948129*_d_ifq1__0
        _d_Q0__next__1 = 0.25*_d_ifq0__1 + 0.5386751345948129*_d_ifq1__1
        _d_Q0__next__2 = 0.25*_d_ifq0__2 + 0.5386751345948129*_d_ifq1__2 + 1.0
        _d_Q0__next__3 = 0.25*_d_ifq0__3 + 0.5386751345948129*_d_ifq1__3
        _d_Q0__next__4 = 0.25*_d_ifq0__4 + 0.5386751345948129*_d_ifq1__4
        _d_Q0__next__5 = 0.25*_d_ifq0__5 + 0.5386751345948129*_d_ifq1__5
        _Q1__next = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
        _d_Q1__next__0 = -0.03867513459481288*_d_ifq0__0 + 0.25*_d_ifq1__0
        _d_Q1__next__1 = -0.03867513459481288*_d_ifq0__1 + 0.25*_d_ifq1__1
        _d_Q1__next__2 = -0.03867513459481288*_d_ifq0__2 + 0.25*_d_ifq1__2 + 1.0
        _d_Q1__next__3 = -0.03867513459481288*_d_ifq0__3 + 0.25*_d_ifq1__3
        _d_Q1__next__4 = -0.03867513459481288*_d_ifq0__4 + 0.25*_d_ifq1__4
        _d_Q1__next__5 = -0.03867513459481288*_d_ifq0__5 + 0.25*_d_ifq1__5
        _x88 = m*q_r**2
        _x89 = _x88*q_thd
        _P0__next = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + _x89
        _x90 = _x87*m*q_thd
        _d_P0__next__0 = 0.25*_d_ifp0__0 + 0.5386751345948129*_d_ifp1__0 + _x90
        _d_P0__next__1 = 0.25*_d_ifp0__1 + 0.5386751345948129*_d_ifp1__1
        _d_P0__next__2 = 0.25*_d_ifp0__2 + 0.5386751345948129*_d_ifp1__2
        _d_P0__next__3 = 0.25*_d_ifp0__3 + 0.5386751345948129*_d_ifp1__3 + _x88
        _d_P0__next__4 = 0.25*_d_ifp0__4 + 0.5386751345948129*_d_ifp1__4
        _d_P0__next__5 = 0.25*_d_ifp0__5 + 0.5386751345948129*_d_ifp1__5
        _P1__next = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + _x89
        _d_P1__next__0 = -0.03867513459481288*_d_ifp0__0 + 0.25*_d_ifp1__0 + _x90
        _d_P1__next__1 = -0.03867513459481288*_d_ifp0__1 + 0.25*_d_ifp1__1
        _d_P1__next__2 = -0.03867513459481288*_d_ifp0__2 + 0.25*_d_ifp1__2
        _d_P1__next__3 = -0.03867513459481288*_d_ifp0__3 + 0.25*_d_ifp1__3 + _x88
        _d_P1__next__4 = -0.03867513459481288*_d_ifp0__4 + 0.25*_d_ifp1__4
        _d_P1__next__5 = -0.03867513459481288*_d_ifp0__5 + 0.25*_d_ifp1__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_P0__next - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _P0__next, _P1__next, _d_D__next__0, _d_D__next__1,
            _d_D__next__2, _d_D__next__3, _d_D__next__4, _d_D__next__5, _d_Q0__next__0, _d_Q0__next__1,
            _d_Q0__next__2, _d_Q0__next__3, _d_Q0__next__4, _d_Q0__next__5, _d_Q1__next__0, _d_Q1__next__1,
            _d_Q1__next__2, _d_Q1__next__3, _d_Q1__next__4, _d_Q1__next__5, _d_P0__next__0, _d_P0__next__1,
            _d_P0__next__2, _d_P0__next__3, _d_P0__next__4, _d_P0__next__5, _d_P1__next__0, _d_P1__next__1,
            _d_P1__next__2, _d_P1__next__3, _d_P1__next__4, _d_P1__next__5, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 0.5*_ift0 + 0.5*_ift1
    d_t_half__0 = 0.5*_d_ift0__0 + 0.5*_d_ift1__0
    d_t_half__1 = 0.5*_d_ift0__1 + 0.5*_d_ift1__1
    d_t_half__2 = 0.5*_d_ift0__2 + 0.5*_d_ift1__2
    d_t_half__3 = 0.5*_d_ift0__3 + 0.5*_d_ift1__3
    d_t_half__4 = 0.5*_d_ift0__4 + 0.5*_d_ift1__4
    d_t_half__5 = 0.5*_d_ift0__5 + 0.5*_d_ift1__5
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    d_end_q_th__0 = 0.5*_d_ifq0__0 + 0.5*_d_ifq1__0
    d_end_q_th__1 = 0.5*_d_ifq0__1 + 0.5*_d_ifq1__1
    d_end_q_th__2 = 0.5*_d_ifq0__2 + 0.5*_d_ifq1__2 + 1.0
    d_end_q_th__3 = 0.5*_d_ifq0__3 + 0.5*_d_ifq1__3
    d_end_q_th__4 = 0.5*_d_ifq0__4 + 0.5*_d_ifq1__4
    d_end_q_th__5 = 0.5*_d_ifq0__5 + 0.5*_d_ifq1__5
    _x91 = -_D + q_r
    end_q_r = _x91
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x92 = q_r**2
    _x93 = 0.5*_ifp0 + 0.5*_ifp1 + _x92*m*q_thd
    _x98 = (1.0/_x91)
    _x94 = _x98**2
    _x95 = (1.0/m)
    _x96 = _x94*_x95
    end_q_thd = _x93*_x96
    _x97 = 0.5*_x96
    _pd__30 = _x97
    _pd__31 = _x97
    _pd__32 = -2.0*_x93*_x95*_x98**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__30 + _d_ifp1__0*_pd__31 + _pd__32*d_end_q_r__0 + 2.0*_x94*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__32 + _d_ifp0__1*_pd__30 + _d_ifp1__1*_pd__31
    d_end_q_thd__2 = -_d_D__2*_pd__32 + _d_ifp0__2*_pd__30 + _d_ifp1__2*_pd__31
    d_end_q_thd__3 = -_d_D__3*_pd__32 + _d_ifp0__3*_pd__30 + _d_ifp1__3*_pd__31 + _x92*_x94
    d_end_q_thd__4 = -_d_D__4*_pd__32 + _d_ifp0__4*_pd__30 + _d_ifp1__4*_pd__31
    d_end_q_thd__5 = -_d_D__5*_pd__32 + _d_ifp0__5*_pd__30 + _d_ifp1__5*_pd__31
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN42 + (STATUS_FALL,)
    # derivatives of the outputs
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN77 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2_jvp6_a742c3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k_c, _j_z_b_q_th__k_c, _j_z_b_q_thd__k_c,
        _j_z_b_q_r__k_d, _j_z_b_q_th__k_d, _j_z_b_q_thd__k_d))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_2_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_2_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_2_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_2_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_2_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_2_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_2_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_2_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_3_jvp5_408d60(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 5 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp5_408d60` (another choice of
    the same kernel).
    """
    # Total ops: 716
    # inputs: finite and inside their domains
    if not _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4):
        return _NAN36 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((34, 5))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN36 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], ) = (d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
        d_guess_q_r__3, d_guess_q_r__4, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], ) = (d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
        d_guess_q_th__3, d_guess_q_th__4, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], ) = (0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], ) = (1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], ) = (0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], ) = (0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], ) = (0.0, 0.0, 0.0, 1.0, 0.0, )
    # the initial values
    _x0 = 1.7745966692414834*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.8872983346207417*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.22540333075851662*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.11270166537925831*_x5
    _x6 = _x1*m
    _pd__4 = 1.0*_x6
    _pd__5 = 0.5*_x2
    _pd__6 = 1.0*_x4
    _pd__7 = 0.5*_x5
    _pd__8 = 0.22540333075851662*_x6
    _pd__9 = 0.11270166537925831*_x2
    _pd__10 = _x0*_x3
    _pd__11 = 0.8872983346207417*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(5):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.8872983346207417*d_guess_q_th__j + 0.11270166537925831*d_q_th__j
        _d_Q1__start__j = 0.5*d_guess_q_th__j + 0.5*d_q_th__j
        _d_Q2__start__j = 0.11270166537925831*d_guess_q_th__j + 0.8872983346207417*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_P0__start__j
        _T[13, _j0] = _d_P1__start__j
        _T[14, _j0] = _d_P2__start__j
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
            return _NAN36 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9872983346207417*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x88 = (1.0/_x9)
        _x17 = _x88**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__12 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__13 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__14 = -_x15*_x22*_x88**4 - k_c
        _pd__15 = _x8 + l0
        _x23 = 0.75*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x86 = (1.0/_x24)
        _x29 = _x86**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__16 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__17 = _x12*_x33
        _pd__18 = -_x22*_x28*_x86**4 - k_c
        _pd__19 = _x23 + l0
        _x34 = 0.2127016653792583*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x87 = (1.0/_x35)
        _x40 = _x87**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__20 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__21 = _x12*_x44
        _pd__22 = -_x22*_x39*_x87**4 - k_c
        _pd__23 = _x34 + l0
        _x45 = (0.5*_x10 - 0.5762768525670787*_x13 - 0.5762768525670787*_x14 + 0.5762768525670787*_x19
            + 0.1040546303448565*_x26 + 0.1040546303448565*_x27 - 0.1040546303448565*_x31
            - 0.027777777777777776*_x37 - 0.027777777777777776*_x38 + 0.027777777777777776*_x42)
        _iPsi0 = _x45
        _x46 = (1.0/math.sqrt(_x45))
        _x47 = math.sqrt(_D)
        _x48 = math.sqrt(m)
        _x49 = _x47*_x48
        _ift0 = _x46*_x49
        _x50 = (0.5)/_x47
        _x51 = _x48*_x50
        _pd__24 = _x46*_x51
        _x52 = _x45**(-1.5)
        _x53 = (0.5)*_x49
        _pd__25 = -_x52*_x53
        _x54 = (1.0/_x48)
        _x55 = _x47*_x54
        _x56 = _x88**2
        _x57 = _x46*_x56
        _x58 = _x55*_x57
        _ifq0 = _P0*_x58
        _x59 = _x50*_x54
        _pd__26 = _P0*_x57*_x59
        _pd__27 = _x58
        _x60 = (0.5)*_x55
        _pd__28 = -_P0*_x52*_x56*_x60
        _pd__29 = -_x17*_x20*_x46*_x55
        _x61 = g_s*m**(1.5)
        _x62 = _x47*_x61
        _x63 = _x46*_x62
        _x64 = _x21*_x63
        _ifp0 = _x64*_x9
        _x65 = _x21*_x9
        _x66 = _x50*_x61
        _pd__30 = _x46*_x65*_x66
        _pd__31 = _x11*_x63*_x9
        _x67 = (0.5)*_x62
        _pd__32 = -_x52*_x65*_x67
        _pd__33 = _x64
        _x68 = (0.5*_x10 - 0.17702731517242826*_x13 - 0.17702731517242826*_x14 + 0.17702731517242826*_x19
            - 0.3611111111111111*_x26 - 0.3611111111111111*_x27 + 0.3611111111111111*_x31
            + 0.038138426283539355*_x37 + 0.038138426283539355*_x38 - 0.038138426283539355*_x42)
        _iPsi1 = _x68
        _x69 = (1.0/math.sqrt(_x68))
        _ift1 = _x49*_x69
        _pd__34 = _x51*_x69
        _x70 = _x68**(-1.5)
        _pd__35 = -_x53*_x70
        _x71 = _x86**2
        _x72 = _x69*_x71
        _x73 = _x55*_x72
        _ifq1 = _P1*_x73
        _pd__36 = _P1*_x59*_x72
        _pd__37 = _x73
        _pd__38 = -_P1*_x60*_x70*_x71
        _pd__39 = -_x29*_x32*_x55*_x69
        _x74 = _x62*_x69
        _x75 = _x33*_x74
        _ifp1 = _x24*_x75
        _x76 = _x24*_x33
        _pd__40 = _x66*_x69*_x76
        _pd__41 = _x24*_x25*_x74
        _pd__42 = -_x67*_x70*_x76
        _pd__43 = _x75
        _x77 = (-0.027777777777777776*_x13 - 0.027777777777777776*_x14 + 0.027777777777777776*_x15*_x16*_x17
            + 0.3262768525670787*_x16*_x28*_x29 + 0.14594536965514351*_x16*_x39*_x40 - 0.3262768525670787*_x26
            - 0.3262768525670787*_x27 - 0.14594536965514351*_x37 - 0.14594536965514351*_x38 + 0.5*k_c*l0)
        _iPsi2 = _x77
        _x78 = (1.0/math.sqrt(_x77))
        _ift2 = _x49*_x78
        _pd__44 = _x51*_x78
        _x79 = _x77**(-1.5)
        _pd__45 = -_x53*_x79
        _x80 = _x87**2
        _x81 = _x78*_x80
        _x82 = _x55*_x81
        _ifq2 = _P2*_x82
        _pd__46 = _P2*_x59*_x81
        _pd__47 = _x82
        _pd__48 = -_P2*_x60*_x79*_x80
        _pd__49 = -_x40*_x43*_x55*_x78
        _x83 = _x62*_x78
        _x84 = _x44*_x83
        _ifp2 = _x35*_x84
        _x85 = _x35*_x44
        _pd__50 = _x66*_x78*_x85
        _pd__51 = _x35*_x36*_x83
        _pd__52 = -_x67*_x79*_x85
        _pd__53 = _x84
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(5):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_P0__j = _T[12, _j1]
            _d_P1__j = _T[13, _j1]
            _d_P2__j = _T[14, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x89 = -d_q_r__j
            _d_isigma0__j = -0.9872983346207417*_d_D__j - _x89
            _d_iF0__j = _d_P0__j*_pd__12 + _d_Q0__j*_pd__13 + _d_isigma0__j*_pd__14 + _pd__15*d_k_c__j
            _d_isigma1__j = -0.75*_d_D__j - _x89
            _d_iF1__j = _d_P1__j*_pd__16 + _d_Q1__j*_pd__17 + _d_isigma1__j*_pd__18 + _pd__19*d_k_c__j
            _d_isigma2__j = -0.2127016653792583*_d_D__j - _x89
            _d_iF2__j = _d_P2__j*_pd__20 + _d_Q2__j*_pd__21 + _d_isigma2__j*_pd__22 + _pd__23*d_k_c__j
            _d_iPsi0__j = (0.5762768525670787*_d_iF0__j - 0.1040546303448565*_d_iF1__j
                + 0.027777777777777776*_d_iF2__j)
            _d_ift0__j = _d_D__j*_pd__24 + _d_iPsi0__j*_pd__25
            _d_ifq0__j = _d_D__j*_pd__26 + _d_P0__j*_pd__27 + _d_iPsi0__j*_pd__28 + _d_isigma0__j*_pd__29
            _d_ifp0__j = _d_D__j*_pd__30 + _d_Q0__j*_pd__31 + _d_iPsi0__j*_pd__32 + _d_isigma0__j*_pd__33
            _d_iPsi1__j = (0.17702731517242826*_d_iF0__j + 0.3611111111111111*_d_iF1__j
                - 0.038138426283539355*_d_iF2__j)
            _d_ift1__j = _d_D__j*_pd__34 + _d_iPsi1__j*_pd__35
            _d_ifq1__j = _d_D__j*_pd__36 + _d_P1__j*_pd__37 + _d_iPsi1__j*_pd__38 + _d_isigma1__j*_pd__39
            _d_ifp1__j = _d_D__j*_pd__40 + _d_Q1__j*_pd__41 + _d_iPsi1__j*_pd__42 + _d_isigma1__j*_pd__43
            _d_iPsi2__j = (0.027777777777777776*_d_iF0__j + 0.3262768525670787*_d_iF1__j
                + 0.14594536965514351*_d_iF2__j)
            _d_ift2__j = _d_D__j*_pd__44 + _d_iPsi2__j*_pd__45
            _d_ifq2__j = _d_D__j*_pd__46 + _d_P2__j*_pd__47 + _d_iPsi2__j*_pd__48 + _d_isigma2__j*_pd__49
            _d_ifp2__j = _d_D__j*_pd__50 + _d_Q2__j*_pd__51 + _d_iPsi2__j*_pd__52 + _d_isigma2__j*_pd__53
            _T[15, _j1] = _d_isigma0__j
            _T[16, _j1] = _d_iF0__j
            _T[17, _j1] = _d_isigma1__j
            _T[18, _j1] = _d_iF1__j
            _T[19, _j1] = _d_isigma2__j
            _T[20, _j1] = _d_iF2__j
            _T[21, _j1] = _d_ift0__j
            _T[22, _j1] = _d_ifq0__j
            _T[23, _j1] = _d_ifp0__j
            _T[24, _j1] = _d_ift1__j
            _T[25, _j1] = _d_ifq1__j
            _T[26, _j1] = _d_ifp1__j
            _T[27, _j1] = _d_ift2__j
            _T[28, _j1] = _d_ifq2__j
            _T[29, _j1] = _d_ifp2__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x90 = m*q_rd**2
        _x91 = -q_r
        _x92 = k_c*(_x91 + l0)
        _x93 = -l0
        _x94 = -_isigma0 - _x93
        _x95 = 0.06261203632181017*k_c
        _x96 = -_isigma1 - _x93
        _x97 = 0.4444444444444444*k_c
        _x98 = -_isigma2 - _x93
        _x99 = 0.4929435192337454*k_c
        _x100 = (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 + _x92
            - _x94*_x95 - _x96*_x97 - _x98*_x99)
        _x101 = math.sqrt(_x100**2 + _x90*k_c)
        _x102 = _x100 + _x101
        _x103 = (1.0/_x102)
        _D__next = _x103*_x90
        _x104 = _x94*k_c
        _x105 = _x96*k_c
        _x106 = _x98*k_c
        _x107 = (1.0/_x101)
        _x108 = _x103**2
        _x109 = _x108*_x90
        _pd__54 = (_x109*(-_x107*(0.0039202670923636765*_iF0 + 0.0278275716985823*_iF1
            + 0.030864197530864196*_iF2 - 0.0039202670923636765*_x104 - 0.0278275716985823*_x105
            - 0.030864197530864196*_x106 + 0.06261203632181017*_x92) - 0.06261203632181017))
        _pd__55 = (_x109*(-_x107*(0.0278275716985823*_iF0 + 0.19753086419753085*_iF1
            + 0.21908600854833127*_iF2 - 0.0278275716985823*_x104 - 0.19753086419753085*_x105
            - 0.21908600854833127*_x106 + 0.4444444444444444*_x92) - 0.4444444444444444))
        _pd__56 = (_x109*(-_x107*(0.030864197530864196*_iF0 + 0.21908600854833127*_iF1
            + 0.24299331315454992*_iF2 - 0.030864197530864196*_x104 - 0.21908600854833127*_x105
            - 0.24299331315454992*_x106 + 0.4929435192337454*_x92) - 0.4929435192337454))
        _x110 = _x100*_x107
        _pd__57 = _x109*(-_x110*_x95 - _x95)
        _pd__58 = _x109*(-_x110*_x97 - _x97)
        _pd__59 = _x109*(-_x110*_x99 - _x99)
        _x111 = 2.0*q_r
        _pd__60 = (_x109*(-0.06261203632181017*_isigma0 - 0.4444444444444444*_isigma1
            - 0.4929435192337454*_isigma2 - _x107*((0.5)*_x100*(0.12522407264362034*_isigma0
            + 0.8888888888888888*_isigma1 + 0.9858870384674908*_isigma2 - _x111) + (0.5)*_x90) - _x91))
        _pd__61 = _x109*(_x110*k_c + k_c)
        _pd__62 = 2.0*_x103*m*q_rd - _x107*_x108*k_c*m**2*q_rd**3
        _Q0__next = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
        _Q1__next = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
        _Q2__next = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _x112 = m*q_r**2
        _x113 = _x112*q_thd
        _P0__next = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + _x113
        _x114 = _x111*m*q_thd
        _pd__63 = _x114
        _pd__64 = _x112
        _P1__next = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + _x113
        _pd__65 = _x114
        _pd__66 = _x112
        _P2__next = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + _x113
        _pd__67 = _x114
        _pd__68 = _x112
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[15, _j2]
            _d_iF0__j = _T[16, _j2]
            _d_isigma1__j = _T[17, _j2]
            _d_iF1__j = _T[18, _j2]
            _d_isigma2__j = _T[19, _j2]
            _d_iF2__j = _T[20, _j2]
            _d_ifq0__j = _T[22, _j2]
            _d_ifp0__j = _T[23, _j2]
            _d_ifq1__j = _T[25, _j2]
            _d_ifp1__j = _T[26, _j2]
            _d_ifq2__j = _T[28, _j2]
            _d_ifp2__j = _T[29, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__54 + _d_iF1__j*_pd__55 + _d_iF2__j*_pd__56 + _d_isigma0__j*_pd__57
                + _d_isigma1__j*_pd__58 + _d_isigma2__j*_pd__59 + _pd__60*d_k_c__j + _pd__61*d_q_r__j
                + _pd__62*d_q_rd__j)
            _d_Q0__next__j = (0.1388888888888889*_d_ifq0__j + 0.48042111196938336*_d_ifq1__j
                + 0.26798833376246944*_d_ifq2__j + d_q_th__j)
            _d_Q1__next__j = (-0.022485417203086815*_d_ifq0__j + 0.2222222222222222*_d_ifq1__j
                + 0.30026319498086457*_d_ifq2__j + d_q_th__j)
            _d_Q2__next__j = (0.009789444015308325*_d_ifq0__j - 0.0359766675249389*_d_ifq1__j
                + 0.1388888888888889*_d_ifq2__j + d_q_th__j)
            _d_P0__next__j = (0.1388888888888889*_d_ifp0__j + 0.48042111196938336*_d_ifp1__j
                + 0.26798833376246944*_d_ifp2__j + _pd__63*d_q_r__j + _pd__64*d_q_thd__j)
            _d_P1__next__j = (-0.022485417203086815*_d_ifp0__j + 0.2222222222222222*_d_ifp1__j
                + 0.30026319498086457*_d_ifp2__j + _pd__65*d_q_r__j + _pd__66*d_q_thd__j)
            _d_P2__next__j = (0.009789444015308325*_d_ifp0__j - 0.0359766675249389*_d_ifp1__j
                + 0.1388888888888889*_d_ifp2__j + _pd__67*d_q_r__j + _pd__68*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_P0__next__j
            _T[13, _j2] = _d_P1__next__j
            _T[14, _j2] = _d_P2__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _P0__next
        _n0_5 = _P1__next
        _n0_6 = _P2__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    # bottom state
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    _x115 = -_D + q_r
    end_q_r = _x115
    end_q_rd = 0.0
    _x116 = q_r**2
    _x117 = 0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2 + _x116*m*q_thd
    _x122 = (1.0/_x115)
    _x118 = _x122**2
    _x119 = (1.0/m)
    _x120 = _x118*_x119
    end_q_thd = _x117*_x120
    _x121 = 0.2777777777777778*_x120
    _pd__69 = _x121
    _pd__70 = 0.4444444444444444*_x120
    _pd__71 = _x121
    _pd__72 = -2.0*_x117*_x119*_x122**3
    _pd__73 = 2.0*_x118*q_r*q_thd
    _pd__74 = _x116*_x118
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN36 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(5):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[21, _j3]
        _d_ifq0__j = _T[22, _j3]
        _d_ifp0__j = _T[23, _j3]
        _d_ift1__j = _T[24, _j3]
        _d_ifq1__j = _T[25, _j3]
        _d_ifp1__j = _T[26, _j3]
        _d_ift2__j = _T[27, _j3]
        _d_ifq2__j = _T[28, _j3]
        _d_ifp2__j = _T[29, _j3]
        # bottom state
        d_t_half__j = (0.2777777777777778*_d_ift0__j + 0.4444444444444444*_d_ift1__j
            + 0.2777777777777778*_d_ift2__j)
        d_end_q_th__j = (0.2777777777777778*_d_ifq0__j + 0.4444444444444444*_d_ifq1__j
            + 0.2777777777777778*_d_ifq2__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__69 + _d_ifp1__j*_pd__70 + _d_ifp2__j*_pd__71 + _pd__72*d_end_q_r__j
            + _pd__73*d_q_r__j + _pd__74*d_q_thd__j)
        _T[30, _j3] = d_t_half__j
        _T[31, _j3] = d_end_q_th__j
        _T[32, _j3] = d_end_q_r__j
        _T[33, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, ) = (_T[30, 0], _T[30, 1], _T[30, 2],
        _T[30, 3], _T[30, 4], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, ) = (_T[31, 0], _T[31, 1],
        _T[31, 2], _T[31, 3], _T[31, 4], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, ) = (_T[32, 0], _T[32, 1], _T[32,
        2], _T[32, 3], _T[32, 4], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, ) = (_T[33, 0], _T[33,
        1], _T[33, 2], _T[33, 3], _T[33, 4], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4, d_end_q_th__0,
        d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_thd__0, d_end_q_thd__1,
        d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_passes__0, d_passes__1, d_passes__2, d_passes__3,
        d_passes__4, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0,
        k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: those of
    :func:`schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd` (another choice of the
    same kernel).
    """
    # Total ops: 556
    # inputs: finite and inside their domains
    if not _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
            iterations, tol):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((29, 6))
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (0.0, 0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    # the initial values
    _x0 = m*q_r_lo**2
    _pd__0 = 0.11270166537925831*_x0
    _x1 = m*q_r*q_thd
    _pd__1 = 1.7745966692414834*_x1
    _x2 = m*q_r**2
    _pd__2 = 0.8872983346207417*_x2
    _pd__3 = 0.5*_x0
    _pd__4 = 1.0*_x1
    _pd__5 = 0.5*_x2
    _pd__6 = 0.8872983346207417*_x0
    _pd__7 = 0.22540333075851662*_x1
    _pd__8 = 0.11270166537925831*_x2
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_th__j = _T[0, _j0]
        d_guess_q_thd__j = _T[1, _j0]
        d_q_r__j = _T[3, _j0]
        d_q_th__j = _T[4, _j0]
        d_q_thd__j = _T[5, _j0]
        # the initial values
        _d_Q0__start__j = 0.11270166537925831*d_guess_q_th__j + 0.8872983346207417*d_q_th__j
        _d_Q1__start__j = 0.5*d_guess_q_th__j + 0.5*d_q_th__j
        _d_Q2__start__j = 0.8872983346207417*d_guess_q_th__j + 0.11270166537925831*d_q_th__j
        _d_P0__start__j = _pd__0*d_guess_q_thd__j + _pd__1*d_q_r__j + _pd__2*d_q_thd__j
        _d_P1__start__j = _pd__3*d_guess_q_thd__j + _pd__4*d_q_r__j + _pd__5*d_q_thd__j
        _d_P2__start__j = _pd__6*d_guess_q_thd__j + _pd__7*d_q_r__j + _pd__8*d_q_thd__j
        _T[6, _j0] = -d_q_r__j
        _T[7, _j0] = _d_Q0__start__j
        _T[8, _j0] = _d_Q1__start__j
        _T[9, _j0] = _d_Q2__start__j
        _T[10, _j0] = _d_P0__start__j
        _T[11, _j0] = _d_P1__start__j
        _T[12, _j0] = _d_P2__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x3 = 0.012701665379258311*_D + q_r
        _isigma0 = _x3
        _x4 = k_d*l0
        _x5 = math.cos(_Q0)
        _x6 = g_s*m
        _x7 = _x5*_x6
        _x8 = _x3*k_d
        _x9 = _P0**2
        _x10 = (1.0/m)
        _x81 = (1.0/_x3)
        _x11 = _x81**3
        _x12 = _x10*_x11
        _x13 = _x12*_x9
        _iF0 = _x13 + _x4 - _x7 - _x8
        _x14 = 2.0*_P0
        _pd__9 = _x12*_x14
        _x15 = math.sin(_Q0)
        _pd__10 = _x15*_x6
        _x16 = 3.0*_x10
        _pd__11 = -_x16*_x81**4*_x9 - k_d
        _x17 = -l0
        _pd__12 = -_x17 - _x3
        _x18 = 0.25*_D + q_r
        _isigma1 = _x18
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x6
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x79 = (1.0/_x18)
        _x23 = _x79**3
        _x24 = _x10*_x23
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x4
        _x26 = 2.0*_P1
        _pd__13 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__14 = _x27*_x6
        _pd__15 = -_x16*_x22*_x79**4 - k_d
        _pd__16 = -_x17 - _x18
        _x28 = 0.7872983346207417*_D + q_r
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x6
        _x31 = _x28*k_d
        _x32 = _P2**2
        _x80 = (1.0/_x28)
        _x33 = _x80**3
        _x34 = _x10*_x33
        _x35 = _x32*_x34
        _iF2 = -_x30 - _x31 + _x35 + _x4
        _x36 = 2.0*_P2
        _pd__17 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__18 = _x37*_x6
        _pd__19 = -_x16*_x32*_x80**4 - k_d
        _pd__20 = -_x17 - _x28
        _x38 = (0.5762768525670787*_x13 + 0.1040546303448565*_x20 + 0.1040546303448565*_x21
            - 0.1040546303448565*_x25 - 0.027777777777777776*_x30 - 0.027777777777777776*_x31
            + 0.027777777777777776*_x35 + 0.5*_x4 - 0.5762768525670787*_x7 - 0.5762768525670787*_x8)
        _iPsi0 = _x38
        _x39 = (1.0/math.sqrt(_x38))
        _x40 = math.sqrt(_D)
        _x41 = math.sqrt(m)
        _x42 = _x40*_x41
        _ift0 = _x39*_x42
        _x43 = (0.5)/_x40
        _x44 = _x41*_x43
        _pd__21 = _x39*_x44
        _x45 = _x38**(-1.5)
        _x46 = (0.5)*_x42
        _pd__22 = -_x45*_x46
        _x47 = (1.0/_x41)
        _x48 = _x40*_x47
        _x49 = _x81**2
        _x50 = _x39*_x49
        _x51 = _x48*_x50
        _ifq0 = _P0*_x51
        _x52 = _x43*_x47
        _pd__23 = _P0*_x50*_x52
        _pd__24 = _x51
        _x53 = (0.5)*_x48
        _pd__25 = -_P0*_x45*_x49*_x53
        _pd__26 = -_x11*_x14*_x39*_x48
        _x54 = g_s*m**(1.5)
        _x55 = _x40*_x54
        _x56 = _x39*_x55
        _x57 = _x15*_x56
        _ifp0 = _x3*_x57
        _x58 = _x15*_x3
        _x59 = _x43*_x54
        _pd__27 = _x39*_x58*_x59
        _pd__28 = _x3*_x5*_x56
        _x60 = (0.5)*_x55
        _pd__29 = -_x45*_x58*_x60
        _pd__30 = _x57
        _x61 = (0.17702731517242826*_x13 - 0.3611111111111111*_x20 - 0.3611111111111111*_x21
            + 0.3611111111111111*_x25 + 0.038138426283539355*_x30 + 0.038138426283539355*_x31
            - 0.038138426283539355*_x35 + 0.5*_x4 - 0.17702731517242826*_x7 - 0.17702731517242826*_x8)
        _iPsi1 = _x61
        _x62 = (1.0/math.sqrt(_x61))
        _ift1 = _x42*_x62
        _pd__31 = _x44*_x62
        _x63 = _x61**(-1.5)
        _pd__32 = -_x46*_x63
        _x64 = _x79**2
        _x65 = _x62*_x64
        _x66 = _x48*_x65
        _ifq1 = _P1*_x66
        _pd__33 = _P1*_x52*_x65
        _pd__34 = _x66
        _pd__35 = -_P1*_x53*_x63*_x64
        _pd__36 = -_x23*_x26*_x48*_x62
        _x67 = _x55*_x62
        _x68 = _x27*_x67
        _ifp1 = _x18*_x68
        _x69 = _x18*_x27
        _pd__37 = _x59*_x62*_x69
        _pd__38 = _x18*_x19*_x67
        _pd__39 = -_x60*_x63*_x69
        _pd__40 = _x68
        _x70 = (0.027777777777777776*_x10*_x11*_x9 + 0.3262768525670787*_x10*_x22*_x23
            + 0.14594536965514351*_x10*_x32*_x33 - 0.3262768525670787*_x20 - 0.3262768525670787*_x21
            - 0.14594536965514351*_x30 - 0.14594536965514351*_x31 - 0.027777777777777776*_x7
            - 0.027777777777777776*_x8 + 0.5*k_d*l0)
        _iPsi2 = _x70
        _x71 = (1.0/math.sqrt(_x70))
        _ift2 = _x42*_x71
        _pd__41 = _x44*_x71
        _x72 = _x70**(-1.5)
        _pd__42 = -_x46*_x72
        _x73 = _x80**2
        _x74 = _x71*_x73
        _x75 = _x48*_x74
        _ifq2 = _P2*_x75
        _pd__43 = _P2*_x52*_x74
        _pd__44 = _x75
        _pd__45 = -_P2*_x53*_x72*_x73
        _pd__46 = -_x33*_x36*_x48*_x71
        _x76 = _x55*_x71
        _x77 = _x37*_x76
        _ifp2 = _x28*_x77
        _x78 = _x28*_x37
        _pd__47 = _x59*_x71*_x78
        _pd__48 = _x28*_x29*_x76
        _pd__49 = -_x60*_x72*_x78
        _pd__50 = _x77
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_d__j = _T[2, _j1]
            d_q_r__j = _T[3, _j1]
            _d_D__j = _T[6, _j1]
            _d_Q0__j = _T[7, _j1]
            _d_Q1__j = _T[8, _j1]
            _d_Q2__j = _T[9, _j1]
            _d_P0__j = _T[10, _j1]
            _d_P1__j = _T[11, _j1]
            _d_P2__j = _T[12, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.012701665379258311*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__9 + _d_Q0__j*_pd__10 + _d_isigma0__j*_pd__11 + _pd__12*d_k_d__j
            _d_isigma1__j = 0.25*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__13 + _d_Q1__j*_pd__14 + _d_isigma1__j*_pd__15 + _pd__16*d_k_d__j
            _d_isigma2__j = 0.7872983346207417*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__17 + _d_Q2__j*_pd__18 + _d_isigma2__j*_pd__19 + _pd__20*d_k_d__j
            _d_iPsi0__j = (0.5762768525670787*_d_iF0__j - 0.1040546303448565*_d_iF1__j
                + 0.027777777777777776*_d_iF2__j)
            _d_ift0__j = _d_D__j*_pd__21 + _d_iPsi0__j*_pd__22
            _d_ifq0__j = _d_D__j*_pd__23 + _d_P0__j*_pd__24 + _d_iPsi0__j*_pd__25 + _d_isigma0__j*_pd__26
            _d_ifp0__j = _d_D__j*_pd__27 + _d_Q0__j*_pd__28 + _d_iPsi0__j*_pd__29 + _d_isigma0__j*_pd__30
            _d_iPsi1__j = (0.17702731517242826*_d_iF0__j + 0.3611111111111111*_d_iF1__j
                - 0.038138426283539355*_d_iF2__j)
            _d_ift1__j = _d_D__j*_pd__31 + _d_iPsi1__j*_pd__32
            _d_ifq1__j = _d_D__j*_pd__33 + _d_P1__j*_pd__34 + _d_iPsi1__j*_pd__35 + _d_isigma1__j*_pd__36
            _d_ifp1__j = _d_D__j*_pd__37 + _d_Q1__j*_pd__38 + _d_iPsi1__j*_pd__39 + _d_isigma1__j*_pd__40
            _d_iPsi2__j = (0.027777777777777776*_d_iF0__j + 0.3262768525670787*_d_iF1__j
                + 0.14594536965514351*_d_iF2__j)
            _d_ift2__j = _d_D__j*_pd__41 + _d_iPsi2__j*_pd__42
            _d_ifq2__j = _d_D__j*_pd__43 + _d_P2__j*_pd__44 + _d_iPsi2__j*_pd__45 + _d_isigma2__j*_pd__46
            _d_ifp2__j = _d_D__j*_pd__47 + _d_Q2__j*_pd__48 + _d_iPsi2__j*_pd__49 + _d_isigma2__j*_pd__50
            _T[13, _j1] = _d_iF0__j
            _T[14, _j1] = _d_iF1__j
            _T[15, _j1] = _d_iF2__j
            _T[16, _j1] = _d_ift0__j
            _T[17, _j1] = _d_ifq0__j
            _T[18, _j1] = _d_ifp0__j
            _T[19, _j1] = _d_ift1__j
            _T[20, _j1] = _d_ifq1__j
            _T[21, _j1] = _d_ifp1__j
            _T[22, _j1] = _d_ift2__j
            _T[23, _j1] = _d_ifq2__j
            _T[24, _j1] = _d_ifp2__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
        _Q1__next = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
        _Q2__next = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _x82 = m*q_r**2
        _x83 = _x82*q_thd
        _P0__next = 0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2 + _x83
        _x84 = 2.0*m*q_r*q_thd
        _pd__51 = _x84
        _pd__52 = _x82
        _P1__next = 0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2 + _x83
        _pd__53 = _x84
        _pd__54 = _x82
        _P2__next = 0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2 + _x83
        _pd__55 = _x84
        _pd__56 = _x82
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_q_r__j = _T[3, _j2]
            d_q_th__j = _T[4, _j2]
            d_q_thd__j = _T[5, _j2]
            _d_D__j = _T[6, _j2]
            _d_ifq0__j = _T[17, _j2]
            _d_ifp0__j = _T[18, _j2]
            _d_ifq1__j = _T[20, _j2]
            _d_ifp1__j = _T[21, _j2]
            _d_ifq2__j = _T[23, _j2]
            _d_ifp2__j = _T[24, _j2]
            # next values
            _d_Q0__next__j = (0.1388888888888889*_d_ifq0__j - 0.0359766675249389*_d_ifq1__j
                + 0.009789444015308325*_d_ifq2__j + d_q_th__j)
            _d_Q1__next__j = (0.30026319498086457*_d_ifq0__j + 0.2222222222222222*_d_ifq1__j
                - 0.022485417203086815*_d_ifq2__j + d_q_th__j)
            _d_Q2__next__j = (0.26798833376246944*_d_ifq0__j + 0.48042111196938336*_d_ifq1__j
                + 0.1388888888888889*_d_ifq2__j + d_q_th__j)
            _d_P0__next__j = (0.1388888888888889*_d_ifp0__j - 0.0359766675249389*_d_ifp1__j
                + 0.009789444015308325*_d_ifp2__j + _pd__51*d_q_r__j + _pd__52*d_q_thd__j)
            _d_P1__next__j = (0.30026319498086457*_d_ifp0__j + 0.2222222222222222*_d_ifp1__j
                - 0.022485417203086815*_d_ifp2__j + _pd__53*d_q_r__j + _pd__54*d_q_thd__j)
            _d_P2__next__j = (0.26798833376246944*_d_ifp0__j + 0.48042111196938336*_d_ifp1__j
                + 0.1388888888888889*_d_ifp2__j + _pd__55*d_q_r__j + _pd__56*d_q_thd__j)
            _T[6, _j2] = _d_D__j
            _T[7, _j2] = _d_Q0__next__j
            _T[8, _j2] = _d_Q1__next__j
            _T[9, _j2] = _d_Q2__next__j
            _T[10, _j2] = _d_P0__next__j
            _T[11, _j2] = _d_P1__next__j
            _T[12, _j2] = _d_P2__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _P0__next
        _n0_5 = _P1__next
        _n0_6 = _P2__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    end_q_r = q_r_lo
    _x85 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x85
    _pd__57 = _x85/_D
    _pd__58 = _x85/_work
    _x86 = q_r**2
    _x87 = q_r_lo**-2
    _x88 = _x87/m
    end_q_thd = (_x88*(0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2
        + _x86*m*q_thd))
    _x89 = 0.2777777777777778*_x88
    _pd__59 = _x89
    _pd__60 = 0.4444444444444444*_x88
    _pd__61 = _x89
    _pd__62 = 2.0*_x87*q_r*q_thd
    _pd__63 = _x86*_x87
    passes = _passes
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[3, _j3]
        d_q_th__j = _T[4, _j3]
        d_q_thd__j = _T[5, _j3]
        _d_D__j = _T[6, _j3]
        _d_iF0__j = _T[13, _j3]
        _d_iF1__j = _T[14, _j3]
        _d_iF2__j = _T[15, _j3]
        _d_ift0__j = _T[16, _j3]
        _d_ifq0__j = _T[17, _j3]
        _d_ifp0__j = _T[18, _j3]
        _d_ift1__j = _T[19, _j3]
        _d_ifq1__j = _T[20, _j3]
        _d_ifp1__j = _T[21, _j3]
        _d_ift2__j = _T[22, _j3]
        _d_ifq2__j = _T[23, _j3]
        _d_ifp2__j = _T[24, _j3]
        _d_work__j = (0.031306018160905086*_d_iF0__j + 0.2222222222222222*_d_iF1__j
            + 0.2464717596168727*_d_iF2__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.2777777777777778*_d_ift0__j + 0.4444444444444444*_d_ift1__j
            + 0.2777777777777778*_d_ift2__j)
        d_end_q_th__j = (0.2777777777777778*_d_ifq0__j + 0.4444444444444444*_d_ifq1__j
            + 0.2777777777777778*_d_ifq2__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__57 + _d_work__j*_pd__58
        d_end_q_thd__j = (_d_ifp0__j*_pd__59 + _d_ifp1__j*_pd__60 + _d_ifp2__j*_pd__61 + _pd__62*d_q_r__j
            + _pd__63*d_q_thd__j)
        _T[25, _j3] = d_t_half__j
        _T[26, _j3] = d_end_q_th__j
        _T[27, _j3] = d_end_q_rd__j
        _T[28, _j3] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[25, 0], _T[25, 1], _T[25, 2], _T[25, 3], _T[25, 4], _T[25, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[26, 0], _T[26, 1], _T[26, 2], _T[26, 3], _T[26, 4], _T[26, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[27, 0], _T[27, 1], _T[27, 2], _T[27, 3], _T[27, 4], _T[27, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[28, 0], _T[28, 1], _T[28, 2], _T[28, 3], _T[28, 4], _T[28, 5], )
    # derivatives of the outputs
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN77 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td, 0.0,
        _j_z_b_q_th__q_th_td, 0.0, _j_z_b_q_r__q_thd_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_geyer`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_geyer`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 122
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x6 = m*q_rd_td**2
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    z_b_q_r = _x11
    _x12 = (1.0/_x8)
    _x13 = (0.5)*_x7
    _x14 = _x10**2
    _x15 = _x14*_x6
    d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
    d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
    _x16 = _x2*math.sin(q_th_td)
    _x17 = _x12*_x7
    d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
    _x18 = 2.0*q_r_td
    _x19 = _x18*q_thd_td
    _x20 = _x19*m
    d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
    d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
    z_b_q_th = q_th_td
    _x21 = q_r_td**2
    _x24 = (1.0/_x11)
    _x22 = _x24**2
    _x23 = _x21*_x22
    z_b_q_thd = _x23*q_thd_td
    _pd__0 = -2.0*_x21*_x24**3*q_thd_td
    d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
    d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
    d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
    d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
    d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, d_z_b_q_r__q_r_td, 0.0, d_z_b_q_thd__q_r_td,
        d_z_b_q_r__q_rd_td, 0.0, d_z_b_q_thd__q_rd_td, d_z_b_q_r__q_th_td, 1.0, d_z_b_q_thd__q_th_td,
        d_z_b_q_r__q_thd_td, 0.0, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, 0.0, d_z_b_q_thd__k_c))
    if _c0[36] != STATUS_OK:
        return _NAN77 + (_c0[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c0
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x25 = q_r_lo**-2
    _x26 = _x25*bottom_q_r**2
    g_lo_q_thd = _x26*bottom_q_thd
    _pd__1 = 2.0*_x25*bottom_q_r*bottom_q_thd
    _pd__2 = _x26
    d_g_lo_q_thd__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _pd__2*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td + _pd__2*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__1*d_bottom_q_r__q_th_td + _pd__2*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td + _pd__2*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__1*d_bottom_q_r__k_c + _pd__2*d_bottom_q_thd__k_c
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c1
    # the code shared between choices
    return (iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_held`: arguments, out and status
    as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_held`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_3_jvp6_a742c3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5,
        d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp6_a742c3` (another choice of
    the same kernel).
    """
    # Total ops: 716
    # inputs: finite and inside their domains
    if not _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((34, 6))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (d_guess_q_r__0, d_guess_q_r__1,
        d_guess_q_r__2, d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (d_guess_q_th__0, d_guess_q_th__1,
        d_guess_q_th__2, d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], _T[6, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], _T[7, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    # the initial values
    _x0 = 1.7745966692414834*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.8872983346207417*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.22540333075851662*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.11270166537925831*_x5
    _x6 = _x1*m
    _pd__4 = 1.0*_x6
    _pd__5 = 0.5*_x2
    _pd__6 = 1.0*_x4
    _pd__7 = 0.5*_x5
    _pd__8 = 0.22540333075851662*_x6
    _pd__9 = 0.11270166537925831*_x2
    _pd__10 = _x0*_x3
    _pd__11 = 0.8872983346207417*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.8872983346207417*d_guess_q_th__j + 0.11270166537925831*d_q_th__j
        _d_Q1__start__j = 0.5*d_guess_q_th__j + 0.5*d_q_th__j
        _d_Q2__start__j = 0.11270166537925831*d_guess_q_th__j + 0.8872983346207417*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_P0__start__j
        _T[13, _j0] = _d_P1__start__j
        _T[14, _j0] = _d_P2__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9872983346207417*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x88 = (1.0/_x9)
        _x17 = _x88**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__12 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__13 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__14 = -_x15*_x22*_x88**4 - k_c
        _pd__15 = _x8 + l0
        _x23 = 0.75*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x86 = (1.0/_x24)
        _x29 = _x86**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__16 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__17 = _x12*_x33
        _pd__18 = -_x22*_x28*_x86**4 - k_c
        _pd__19 = _x23 + l0
        _x34 = 0.2127016653792583*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x87 = (1.0/_x35)
        _x40 = _x87**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__20 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__21 = _x12*_x44
        _pd__22 = -_x22*_x39*_x87**4 - k_c
        _pd__23 = _x34 + l0
        _x45 = (0.5*_x10 - 0.5762768525670787*_x13 - 0.5762768525670787*_x14 + 0.5762768525670787*_x19
            + 0.1040546303448565*_x26 + 0.1040546303448565*_x27 - 0.1040546303448565*_x31
            - 0.027777777777777776*_x37 - 0.027777777777777776*_x38 + 0.027777777777777776*_x42)
        _iPsi0 = _x45
        _x46 = (1.0/math.sqrt(_x45))
        _x47 = math.sqrt(_D)
        _x48 = math.sqrt(m)
        _x49 = _x47*_x48
        _ift0 = _x46*_x49
        _x50 = (0.5)/_x47
        _x51 = _x48*_x50
        _pd__24 = _x46*_x51
        _x52 = _x45**(-1.5)
        _x53 = (0.5)*_x49
        _pd__25 = -_x52*_x53
        _x54 = (1.0/_x48)
        _x55 = _x47*_x54
        _x56 = _x88**2
        _x57 = _x46*_x56
        _x58 = _x55*_x57
        _ifq0 = _P0*_x58
        _x59 = _x50*_x54
        _pd__26 = _P0*_x57*_x59
        _pd__27 = _x58
        _x60 = (0.5)*_x55
        _pd__28 = -_P0*_x52*_x56*_x60
        _pd__29 = -_x17*_x20*_x46*_x55
        _x61 = g_s*m**(1.5)
        _x62 = _x47*_x61
        _x63 = _x46*_x62
        _x64 = _x21*_x63
        _ifp0 = _x64*_x9
        _x65 = _x21*_x9
        _x66 = _x50*_x61
        _pd__30 = _x46*_x65*_x66
        _pd__31 = _x11*_x63*_x9
        _x67 = (0.5)*_x62
        _pd__32 = -_x52*_x65*_x67
        _pd__33 = _x64
        _x68 = (0.5*_x10 - 0.17702731517242826*_x13 - 0.17702731517242826*_x14 + 0.17702731517242826*_x19
            - 0.3611111111111111*_x26 - 0.3611111111111111*_x27 + 0.3611111111111111*_x31
            + 0.038138426283539355*_x37 + 0.038138426283539355*_x38 - 0.038138426283539355*_x42)
        _iPsi1 = _x68
        _x69 = (1.0/math.sqrt(_x68))
        _ift1 = _x49*_x69
        _pd__34 = _x51*_x69
        _x70 = _x68**(-1.5)
        _pd__35 = -_x53*_x70
        _x71 = _x86**2
        _x72 = _x69*_x71
        _x73 = _x55*_x72
        _ifq1 = _P1*_x73
        _pd__36 = _P1*_x59*_x72
        _pd__37 = _x73
        _pd__38 = -_P1*_x60*_x70*_x71
        _pd__39 = -_x29*_x32*_x55*_x69
        _x74 = _x62*_x69
        _x75 = _x33*_x74
        _ifp1 = _x24*_x75
        _x76 = _x24*_x33
        _pd__40 = _x66*_x69*_x76
        _pd__41 = _x24*_x25*_x74
        _pd__42 = -_x67*_x70*_x76
        _pd__43 = _x75
        _x77 = (-0.027777777777777776*_x13 - 0.027777777777777776*_x14 + 0.027777777777777776*_x15*_x16*_x17
            + 0.3262768525670787*_x16*_x28*_x29 + 0.14594536965514351*_x16*_x39*_x40 - 0.3262768525670787*_x26
            - 0.3262768525670787*_x27 - 0.14594536965514351*_x37 - 0.14594536965514351*_x38 + 0.5*k_c*l0)
        _iPsi2 = _x77
        _x78 = (1.0/math.sqrt(_x77))
        _ift2 = _x49*_x78
        _pd__44 = _x51*_x78
        _x79 = _x77**(-1.5)
        _pd__45 = -_x53*_x79
        _x80 = _x87**2
        _x81 = _x78*_x80
        _x82 = _x55*_x81
        _ifq2 = _P2*_x82
        _pd__46 = _P2*_x59*_x81
        _pd__47 = _x82
        _pd__48 = -_P2*_x60*_x79*_x80
        _pd__49 = -_x40*_x43*_x55*_x78
        _x83 = _x62*_x78
        _x84 = _x44*_x83
        _ifp2 = _x35*_x84
        _x85 = _x35*_x44
        _pd__50 = _x66*_x78*_x85
        _pd__51 = _x35*_x36*_x83
        _pd__52 = -_x67*_x79*_x85
        _pd__53 = _x84
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_P0__j = _T[12, _j1]
            _d_P1__j = _T[13, _j1]
            _d_P2__j = _T[14, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x89 = -d_q_r__j
            _d_isigma0__j = -0.9872983346207417*_d_D__j - _x89
            _d_iF0__j = _d_P0__j*_pd__12 + _d_Q0__j*_pd__13 + _d_isigma0__j*_pd__14 + _pd__15*d_k_c__j
            _d_isigma1__j = -0.75*_d_D__j - _x89
            _d_iF1__j = _d_P1__j*_pd__16 + _d_Q1__j*_pd__17 + _d_isigma1__j*_pd__18 + _pd__19*d_k_c__j
            _d_isigma2__j = -0.2127016653792583*_d_D__j - _x89
            _d_iF2__j = _d_P2__j*_pd__20 + _d_Q2__j*_pd__21 + _d_isigma2__j*_pd__22 + _pd__23*d_k_c__j
            _d_iPsi0__j = (0.5762768525670787*_d_iF0__j - 0.1040546303448565*_d_iF1__j
                + 0.027777777777777776*_d_iF2__j)
            _d_ift0__j = _d_D__j*_pd__24 + _d_iPsi0__j*_pd__25
            _d_ifq0__j = _d_D__j*_pd__26 + _d_P0__j*_pd__27 + _d_iPsi0__j*_pd__28 + _d_isigma0__j*_pd__29
            _d_ifp0__j = _d_D__j*_pd__30 + _d_Q0__j*_pd__31 + _d_iPsi0__j*_pd__32 + _d_isigma0__j*_pd__33
            _d_iPsi1__j = (0.17702731517242826*_d_iF0__j + 0.3611111111111111*_d_iF1__j
                - 0.038138426283539355*_d_iF2__j)
            _d_ift1__j = _d_D__j*_pd__34 + _d_iPsi1__j*_pd__35
            _d_ifq1__j = _d_D__j*_pd__36 + _d_P1__j*_pd__37 + _d_iPsi1__j*_pd__38 + _d_isigma1__j*_pd__39
            _d_ifp1__j = _d_D__j*_pd__40 + _d_Q1__j*_pd__41 + _d_iPsi1__j*_pd__42 + _d_isigma1__j*_pd__43
            _d_iPsi2__j = (0.027777777777777776*_d_iF0__j + 0.3262768525670787*_d_iF1__j
                + 0.14594536965514351*_d_iF2__j)
            _d_ift2__j = _d_D__j*_pd__44 + _d_iPsi2__j*_pd__45
            _d_ifq2__j = _d_D__j*_pd__46 + _d_P2__j*_pd__47 + _d_iPsi2__j*_pd__48 + _d_isigma2__j*_pd__49
            _d_ifp2__j = _d_D__j*_pd__50 + _d_Q2__j*_pd__51 + _d_iPsi2__j*_pd__52 + _d_isigma2__j*_pd__53
            _T[15, _j1] = _d_isigma0__j
            _T[16, _j1] = _d_iF0__j
            _T[17, _j1] = _d_isigma1__j
            _T[18, _j1] = _d_iF1__j
            _T[19, _j1] = _d_isigma2__j
            _T[20, _j1] = _d_iF2__j
            _T[21, _j1] = _d_ift0__j
            _T[22, _j1] = _d_ifq0__j
            _T[23, _j1] = _d_ifp0__j
            _T[24, _j1] = _d_ift1__j
            _T[25, _j1] = _d_ifq1__j
            _T[26, _j1] = _d_ifp1__j
            _T[27, _j1] = _d_ift2__j
            _T[28, _j1] = _d_ifq2__j
            _T[29, _j1] = _d_ifp2__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x90 = m*q_rd**2
        _x91 = -q_r
        _x92 = k_c*(_x91 + l0)
        _x93 = -l0
        _x94 = -_isigma0 - _x93
        _x95 = 0.06261203632181017*k_c
        _x96 = -_isigma1 - _x93
        _x97 = 0.4444444444444444*k_c
        _x98 = -_isigma2 - _x93
        _x99 = 0.4929435192337454*k_c
        _x100 = (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 + _x92
            - _x94*_x95 - _x96*_x97 - _x98*_x99)
        _x101 = math.sqrt(_x100**2 + _x90*k_c)
        _x102 = _x100 + _x101
        _x103 = (1.0/_x102)
        _D__next = _x103*_x90
        _x104 = _x94*k_c
        _x105 = _x96*k_c
        _x106 = _x98*k_c
        _x107 = (1.0/_x101)
        _x108 = _x103**2
        _x109 = _x108*_x90
        _pd__54 = (_x109*(-_x107*(0.0039202670923636765*_iF0 + 0.0278275716985823*_iF1
            + 0.030864197530864196*_iF2 - 0.0039202670923636765*_x104 - 0.0278275716985823*_x105
            - 0.030864197530864196*_x106 + 0.06261203632181017*_x92) - 0.06261203632181017))
        _pd__55 = (_x109*(-_x107*(0.0278275716985823*_iF0 + 0.19753086419753085*_iF1
            + 0.21908600854833127*_iF2 - 0.0278275716985823*_x104 - 0.19753086419753085*_x105
            - 0.21908600854833127*_x106 + 0.4444444444444444*_x92) - 0.4444444444444444))
        _pd__56 = (_x109*(-_x107*(0.030864197530864196*_iF0 + 0.21908600854833127*_iF1
            + 0.24299331315454992*_iF2 - 0.030864197530864196*_x104 - 0.21908600854833127*_x105
            - 0.24299331315454992*_x106 + 0.4929435192337454*_x92) - 0.4929435192337454))
        _x110 = _x100*_x107
        _pd__57 = _x109*(-_x110*_x95 - _x95)
        _pd__58 = _x109*(-_x110*_x97 - _x97)
        _pd__59 = _x109*(-_x110*_x99 - _x99)
        _x111 = 2.0*q_r
        _pd__60 = (_x109*(-0.06261203632181017*_isigma0 - 0.4444444444444444*_isigma1
            - 0.4929435192337454*_isigma2 - _x107*((0.5)*_x100*(0.12522407264362034*_isigma0
            + 0.8888888888888888*_isigma1 + 0.9858870384674908*_isigma2 - _x111) + (0.5)*_x90) - _x91))
        _pd__61 = _x109*(_x110*k_c + k_c)
        _pd__62 = 2.0*_x103*m*q_rd - _x107*_x108*k_c*m**2*q_rd**3
        _Q0__next = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
        _Q1__next = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
        _Q2__next = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _x112 = m*q_r**2
        _x113 = _x112*q_thd
        _P0__next = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + _x113
        _x114 = _x111*m*q_thd
        _pd__63 = _x114
        _pd__64 = _x112
        _P1__next = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + _x113
        _pd__65 = _x114
        _pd__66 = _x112
        _P2__next = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + _x113
        _pd__67 = _x114
        _pd__68 = _x112
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[15, _j2]
            _d_iF0__j = _T[16, _j2]
            _d_isigma1__j = _T[17, _j2]
            _d_iF1__j = _T[18, _j2]
            _d_isigma2__j = _T[19, _j2]
            _d_iF2__j = _T[20, _j2]
            _d_ifq0__j = _T[22, _j2]
            _d_ifp0__j = _T[23, _j2]
            _d_ifq1__j = _T[25, _j2]
            _d_ifp1__j = _T[26, _j2]
            _d_ifq2__j = _T[28, _j2]
            _d_ifp2__j = _T[29, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__54 + _d_iF1__j*_pd__55 + _d_iF2__j*_pd__56 + _d_isigma0__j*_pd__57
                + _d_isigma1__j*_pd__58 + _d_isigma2__j*_pd__59 + _pd__60*d_k_c__j + _pd__61*d_q_r__j
                + _pd__62*d_q_rd__j)
            _d_Q0__next__j = (0.1388888888888889*_d_ifq0__j + 0.48042111196938336*_d_ifq1__j
                + 0.26798833376246944*_d_ifq2__j + d_q_th__j)
            _d_Q1__next__j = (-0.022485417203086815*_d_ifq0__j + 0.2222222222222222*_d_ifq1__j
                + 0.30026319498086457*_d_ifq2__j + d_q_th__j)
            _d_Q2__next__j = (0.009789444015308325*_d_ifq0__j - 0.0359766675249389*_d_ifq1__j
                + 0.1388888888888889*_d_ifq2__j + d_q_th__j)
            _d_P0__next__j = (0.1388888888888889*_d_ifp0__j + 0.48042111196938336*_d_ifp1__j
                + 0.26798833376246944*_d_ifp2__j + _pd__63*d_q_r__j + _pd__64*d_q_thd__j)
            _d_P1__next__j = (-0.022485417203086815*_d_ifp0__j + 0.2222222222222222*_d_ifp1__j
                + 0.30026319498086457*_d_ifp2__j + _pd__65*d_q_r__j + _pd__66*d_q_thd__j)
            _d_P2__next__j = (0.009789444015308325*_d_ifp0__j - 0.0359766675249389*_d_ifp1__j
                + 0.1388888888888889*_d_ifp2__j + _pd__67*d_q_r__j + _pd__68*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_P0__next__j
            _T[13, _j2] = _d_P1__next__j
            _T[14, _j2] = _d_P2__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _P0__next
        _n0_5 = _P1__next
        _n0_6 = _P2__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    # bottom state
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    _x115 = -_D + q_r
    end_q_r = _x115
    end_q_rd = 0.0
    _x116 = q_r**2
    _x117 = 0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2 + _x116*m*q_thd
    _x122 = (1.0/_x115)
    _x118 = _x122**2
    _x119 = (1.0/m)
    _x120 = _x118*_x119
    end_q_thd = _x117*_x120
    _x121 = 0.2777777777777778*_x120
    _pd__69 = _x121
    _pd__70 = 0.4444444444444444*_x120
    _pd__71 = _x121
    _pd__72 = -2.0*_x117*_x119*_x122**3
    _pd__73 = 2.0*_x118*q_r*q_thd
    _pd__74 = _x116*_x118
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN42 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[21, _j3]
        _d_ifq0__j = _T[22, _j3]
        _d_ifp0__j = _T[23, _j3]
        _d_ift1__j = _T[24, _j3]
        _d_ifq1__j = _T[25, _j3]
        _d_ifp1__j = _T[26, _j3]
        _d_ift2__j = _T[27, _j3]
        _d_ifq2__j = _T[28, _j3]
        _d_ifp2__j = _T[29, _j3]
        # bottom state
        d_t_half__j = (0.2777777777777778*_d_ift0__j + 0.4444444444444444*_d_ift1__j
            + 0.2777777777777778*_d_ift2__j)
        d_end_q_th__j = (0.2777777777777778*_d_ifq0__j + 0.4444444444444444*_d_ifq1__j
            + 0.2777777777777778*_d_ifq2__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__69 + _d_ifp1__j*_pd__70 + _d_ifp2__j*_pd__71 + _pd__72*d_end_q_r__j
            + _pd__73*d_q_r__j + _pd__74*d_q_thd__j)
        _T[30, _j3] = d_t_half__j
        _T[31, _j3] = d_end_q_th__j
        _T[32, _j3] = d_end_q_r__j
        _T[33, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[30, 0], _T[30, 1],
        _T[30, 2], _T[30, 3], _T[30, 4], _T[30, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[31, 0],
        _T[31, 1], _T[31, 2], _T[31, 3], _T[31, 4], _T[31, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[32, 0],
        _T[32, 1], _T[32, 2], _T[32, 3], _T[32, 4], _T[32, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[33, 0], _T[33, 1], _T[33, 2], _T[33, 3], _T[33, 4], _T[33, 5], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN77 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3_jvp6_a742c3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k_c, _j_z_b_q_th__k_c, _j_z_b_q_thd__k_c,
        _j_z_b_q_r__k_d, _j_z_b_q_th__k_d, _j_z_b_q_thd__k_d))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_3_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_3_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_3_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_3_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_3_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_3_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_3_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_3_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_6_jvp5_408d60(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 5 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp5_408d60` (another choice of
    the same kernel).
    """
    # Total ops: 1740
    # inputs: finite and inside their domains
    if not _inputs_valid_0(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4):
        return _NAN36 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((55, 5))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN36 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], ) = (d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
        d_guess_q_r__3, d_guess_q_r__4, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], ) = (d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
        d_guess_q_th__3, d_guess_q_th__4, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], ) = (0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], ) = (1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], ) = (0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], ) = (0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], ) = (0.0, 0.0, 0.0, 1.0, 0.0, )
    # the initial values
    _x0 = 1.932469514203152*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.966234757101576*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.06753048579684798*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.03376524289842399*_x5
    _x6 = _x1*m
    _pd__4 = 1.6612093864662645*_x6
    _pd__5 = 0.8306046932331322*_x2
    _pd__6 = 0.33879061353373546*_x4
    _pd__7 = 0.16939530676686773*_x5
    _pd__8 = 1.238619186083197*_x6
    _pd__9 = 0.6193095930415985*_x2
    _pd__10 = 0.7613808139168031*_x4
    _pd__11 = 0.38069040695840156*_x5
    _pd__12 = 0.7613808139168031*_x6
    _pd__13 = 0.38069040695840156*_x2
    _pd__14 = 1.238619186083197*_x4
    _pd__15 = 0.6193095930415985*_x5
    _pd__16 = 0.33879061353373546*_x6
    _pd__17 = 0.16939530676686773*_x2
    _pd__18 = 1.6612093864662645*_x4
    _pd__19 = 0.8306046932331322*_x5
    _pd__20 = 0.06753048579684798*_x6
    _pd__21 = 0.03376524289842399*_x2
    _pd__22 = _x0*_x3
    _pd__23 = 0.966234757101576*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(5):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.966234757101576*d_guess_q_th__j + 0.03376524289842399*d_q_th__j
        _d_Q1__start__j = 0.8306046932331322*d_guess_q_th__j + 0.16939530676686773*d_q_th__j
        _d_Q2__start__j = 0.6193095930415985*d_guess_q_th__j + 0.38069040695840156*d_q_th__j
        _d_Q3__start__j = 0.38069040695840156*d_guess_q_th__j + 0.6193095930415985*d_q_th__j
        _d_Q4__start__j = 0.16939530676686773*d_guess_q_th__j + 0.8306046932331322*d_q_th__j
        _d_Q5__start__j = 0.03376524289842399*d_guess_q_th__j + 0.966234757101576*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _d_P3__start__j = (_pd__12*d_guess_q_r__j + _pd__13*d_guess_q_thd__j + _pd__14*d_q_r__j
            + _pd__15*d_q_thd__j)
        _d_P4__start__j = (_pd__16*d_guess_q_r__j + _pd__17*d_guess_q_thd__j + _pd__18*d_q_r__j
            + _pd__19*d_q_thd__j)
        _d_P5__start__j = (_pd__20*d_guess_q_r__j + _pd__21*d_guess_q_thd__j + _pd__22*d_q_r__j
            + _pd__23*d_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_Q3__start__j
        _T[13, _j0] = _d_Q4__start__j
        _T[14, _j0] = _d_Q5__start__j
        _T[15, _j0] = _d_P0__start__j
        _T[16, _j0] = _d_P1__start__j
        _T[17, _j0] = _d_P2__start__j
        _T[18, _j0] = _d_P3__start__j
        _T[19, _j0] = _d_P4__start__j
        _T[20, _j0] = _d_P5__start__j
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
            return _NAN36 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9988599083720104*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x153 = (1.0/_x9)
        _x17 = _x153**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__24 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__25 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__26 = -_x15*_x153**4*_x22 - k_c
        _pd__27 = _x8 + l0
        _x23 = 0.9713052300453587*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x148 = (1.0/_x24)
        _x29 = _x148**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__28 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__29 = _x12*_x33
        _pd__30 = -_x148**4*_x22*_x28 - k_c
        _pd__31 = _x23 + l0
        _x34 = 0.8550748140498466*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x149 = (1.0/_x35)
        _x40 = _x149**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__32 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__33 = _x12*_x44
        _pd__34 = -_x149**4*_x22*_x39 - k_c
        _pd__35 = _x34 + l0
        _x45 = 0.6164556279666497*_D + _x7
        _x46 = -_x45
        _isigma3 = _x46
        _x47 = math.cos(_Q3)
        _x48 = _x12*_x47
        _x49 = _x46*k_c
        _x50 = _P3**2
        _x150 = (1.0/_x46)
        _x51 = _x150**3
        _x52 = _x16*_x51
        _x53 = _x50*_x52
        _iF3 = _x10 - _x48 - _x49 + _x53
        _x54 = 2.0*_P3
        _pd__36 = _x52*_x54
        _x55 = math.sin(_Q3)
        _pd__37 = _x12*_x55
        _pd__38 = -_x150**4*_x22*_x50 - k_c
        _pd__39 = _x45 + l0
        _x56 = 0.31009584357909425*_D + _x7
        _x57 = -_x56
        _isigma4 = _x57
        _x58 = math.cos(_Q4)
        _x59 = _x12*_x58
        _x60 = _x57*k_c
        _x61 = _P4**2
        _x151 = (1.0/_x57)
        _x62 = _x151**3
        _x63 = _x16*_x62
        _x64 = _x61*_x63
        _iF4 = _x10 - _x59 - _x60 + _x64
        _x65 = 2.0*_P4
        _pd__40 = _x63*_x65
        _x66 = math.sin(_Q4)
        _pd__41 = _x12*_x66
        _pd__42 = -_x151**4*_x22*_x61 - k_c
        _pd__43 = _x56 + l0
        _x67 = 0.0663903941688584*_D + _x7
        _x68 = -_x67
        _isigma5 = _x68
        _x69 = math.cos(_Q5)
        _x70 = _x12*_x69
        _x71 = _x68*k_c
        _x72 = _P5**2
        _x152 = (1.0/_x68)
        _x73 = _x152**3
        _x74 = _x16*_x73
        _x75 = _x72*_x74
        _iF5 = _x10 - _x70 - _x71 + _x75
        _x76 = 2.0*_P5
        _pd__44 = _x74*_x76
        _x77 = math.sin(_Q5)
        _pd__45 = _x12*_x77
        _pd__46 = -_x152**4*_x22*_x72 - k_c
        _pd__47 = _x67 + l0
        _x78 = (0.5*_x10 - 0.5871580340658094*_x13 - 0.5871580340658094*_x14 + 0.5871580340658094*_x19
            + 0.140380692261653*_x26 + 0.140380692261653*_x27 - 0.140380692261653*_x31
            - 0.08683151831711133*_x37 - 0.08683151831711133*_x38 + 0.08683151831711133*_x42
            + 0.052466581536012566*_x48 + 0.052466581536012566*_x49 - 0.052466581536012566*_x53
            - 0.026354606039126004*_x59 - 0.026354606039126004*_x60 + 0.026354606039126004*_x64
            + 0.007496884624381081*_x70 + 0.007496884624381081*_x71 - 0.007496884624381081*_x75)
        _iPsi0 = _x78
        _x79 = (1.0/math.sqrt(_x78))
        _x80 = math.sqrt(_D)
        _x81 = math.sqrt(m)
        _x82 = _x80*_x81
        _ift0 = _x79*_x82
        _x83 = (0.5)/_x80
        _x84 = _x81*_x83
        _pd__48 = _x79*_x84
        _x85 = _x78**(-1.5)
        _x86 = (0.5)*_x82
        _pd__49 = -_x85*_x86
        _x87 = (1.0/_x81)
        _x88 = _x80*_x87
        _x89 = _x153**2
        _x90 = _x79*_x89
        _x91 = _x88*_x90
        _ifq0 = _P0*_x91
        _x92 = _x83*_x87
        _pd__50 = _P0*_x90*_x92
        _pd__51 = _x91
        _x93 = (0.5)*_x88
        _pd__52 = -_P0*_x85*_x89*_x93
        _pd__53 = -_x17*_x20*_x79*_x88
        _x94 = g_s*m**(1.5)
        _x95 = _x80*_x94
        _x96 = _x79*_x95
        _x97 = _x21*_x96
        _ifp0 = _x9*_x97
        _x98 = _x21*_x9
        _x99 = _x83*_x94
        _pd__54 = _x79*_x98*_x99
        _pd__55 = _x11*_x9*_x96
        _x100 = (0.5)*_x95
        _pd__56 = -_x100*_x85*_x98
        _pd__57 = _x97
        _x101 = -0.5*k_c*l0
        _x102 = (-_x101 - 0.147790320897128*_x13 - 0.147790320897128*_x14 + 0.147790320897128*_x15*_x16*_x17
            + 0.41567911405660357*_x16*_x28*_x29 + 0.05155355009455148*_x16*_x50*_x51
            + 0.006904529857608445*_x16*_x72*_x73 - 0.41567911405660357*_x26 - 0.41567911405660357*_x27
            + 0.09720828549085844*_x35*k_c + 0.09720828549085844*_x36*g_s*m - 0.09720828549085844*_x42
            - 0.05155355009455148*_x48 - 0.05155355009455148*_x49 + 0.024719229415033087*_x57*k_c
            + 0.024719229415033087*_x58*g_s*m - 0.024719229415033087*_x64 - 0.006904529857608445*_x70
            - 0.006904529857608445*_x71)
        _iPsi1 = _x102
        _x103 = (1.0/math.sqrt(_x102))
        _ift1 = _x103*_x82
        _pd__58 = _x103*_x84
        _x104 = _x102**(-1.5)
        _pd__59 = -_x104*_x86
        _x105 = _x148**2
        _x106 = _x103*_x105
        _x107 = _x106*_x88
        _ifq1 = _P1*_x107
        _pd__60 = _P1*_x106*_x92
        _pd__61 = _x107
        _pd__62 = -_P1*_x104*_x105*_x93
        _pd__63 = -_x103*_x29*_x32*_x88
        _x108 = _x103*_x95
        _x109 = _x108*_x33
        _ifp1 = _x109*_x24
        _x110 = _x24*_x33
        _pd__64 = _x103*_x110*_x99
        _pd__65 = _x108*_x24*_x25
        _pd__66 = -_x100*_x104*_x110
        _pd__67 = _x109
        _x111 = (-_x101 - 0.010443786721981197*_x13 - 0.010443786721981197*_x14
            + 0.010443786721981197*_x15*_x16*_x17 + 0.25540525119175433*_x16*_x28*_x29
            + 0.2685463444140672*_x16*_x39*_x40 + 0.01951903325298492*_x16*_x61*_x62
            - 0.25540525119175433*_x26 - 0.25540525119175433*_x27 - 0.2685463444140672*_x37
            - 0.2685463444140672*_x38 + 0.048794612428541204*_x46*k_c + 0.048794612428541204*_x47*g_s*m
            - 0.048794612428541204*_x53 - 0.01951903325298492*_x59 - 0.01951903325298492*_x60
            + 0.005119803152246505*_x68*k_c + 0.005119803152246505*_x69*g_s*m - 0.005119803152246505*_x75)
        _iPsi2 = _x111
        _x112 = (1.0/math.sqrt(_x111))
        _ift2 = _x112*_x82
        _pd__68 = _x112*_x84
        _x113 = _x111**(-1.5)
        _pd__69 = -_x113*_x86
        _x114 = _x149**2
        _x115 = _x112*_x114
        _x116 = _x115*_x88
        _ifq2 = _P2*_x116
        _pd__70 = _P2*_x115*_x92
        _pd__71 = _x116
        _pd__72 = -_P2*_x113*_x114*_x93
        _pd__73 = -_x112*_x40*_x43*_x88
        _x117 = _x112*_x95
        _x118 = _x117*_x44
        _ifp2 = _x118*_x35
        _x119 = _x35*_x44
        _pd__74 = _x112*_x119*_x99
        _pd__75 = _x117*_x35*_x36
        _pd__76 = -_x100*_x113*_x119
        _pd__77 = _x118
        _x120 = -0.5*k_c*l0
        _x121 = (-_x120 - 0.01101839635505667*_x13 - 0.01101839635505667*_x14
            + 0.01101839635505667*_x15*_x16*_x17 + 0.0662099828438604*_x16*_x28*_x29
            + 0.2671819482314443*_x16*_x39*_x40 + 0.1742495636223592*_x16*_x50*_x51
            + 0.00530703852813994*_x16*_x72*_x73 - 0.0662099828438604*_x26 - 0.0662099828438604*_x27
            - 0.2671819482314443*_x37 - 0.2671819482314443*_x38 - 0.1742495636223592*_x48
            - 0.1742495636223592*_x49 + 0.02396692958086051*_x57*k_c + 0.02396692958086051*_x58*g_s*m
            - 0.02396692958086051*_x64 - 0.00530703852813994*_x70 - 0.00530703852813994*_x71)
        _iPsi3 = _x121
        _x122 = (1.0/math.sqrt(_x121))
        _ift3 = _x122*_x82
        _pd__78 = _x122*_x84
        _x123 = _x121**(-1.5)
        _pd__79 = -_x123*_x86
        _x124 = _x150**2
        _x125 = _x122*_x124
        _x126 = _x125*_x88
        _ifq3 = _P3*_x126
        _pd__80 = _P3*_x125*_x92
        _pd__81 = _x126
        _pd__82 = -_P3*_x123*_x124*_x93
        _pd__83 = -_x122*_x51*_x54*_x88
        _x127 = _x122*_x95
        _x128 = _x127*_x55
        _ifp3 = _x128*_x46
        _x129 = _x46*_x55
        _pd__84 = _x122*_x129*_x99
        _pd__85 = _x127*_x46*_x47
        _pd__86 = -_x100*_x123*_x129
        _pd__87 = _x128
        _x130 = (-_x101 - 0.0025147977064533143*_x13 - 0.0025147977064533143*_x14
            + 0.0025147977064533143*_x15*_x16*_x17 + 0.050345455482979015*_x16*_x28*_x29
            + 0.11622097556712797*_x16*_x39*_x40 + 0.2353986790647292*_x16*_x50*_x51
            + 0.10372825048336794*_x16*_x61*_x62 - 0.050345455482979015*_x26 - 0.050345455482979015*_x27
            - 0.11622097556712797*_x37 - 0.11622097556712797*_x38 - 0.2353986790647292*_x48
            - 0.2353986790647292*_x49 - 0.10372825048336794*_x59 - 0.10372825048336794*_x60
            + 0.008208158304657426*_x68*k_c + 0.008208158304657426*_x69*g_s*m - 0.008208158304657426*_x75)
        _iPsi4 = _x130
        _x131 = (1.0/math.sqrt(_x130))
        _ift4 = _x131*_x82
        _pd__88 = _x131*_x84
        _x132 = _x130**(-1.5)
        _pd__89 = -_x132*_x86
        _x133 = _x151**2
        _x134 = _x131*_x133
        _x135 = _x134*_x88
        _ifq4 = _P4*_x135
        _pd__90 = _P4*_x134*_x92
        _pd__91 = _x135
        _pd__92 = -_P4*_x132*_x133*_x93
        _pd__93 = -_x131*_x62*_x65*_x88
        _x136 = _x131*_x95
        _x137 = _x136*_x66
        _ifp4 = _x137*_x57
        _x138 = _x57*_x66
        _pd__94 = _x131*_x138*_x99
        _pd__95 = _x136*_x57*_x58
        _pd__96 = -_x100*_x132*_x138
        _pd__97 = _x137
        _x139 = (-_x120 - 0.003959513229722528*_x13 - 0.003959513229722528*_x14
            + 0.003959513229722528*_x15*_x16*_x17 + 0.029703284805013122*_x16*_x28*_x29
            + 0.10140664131431479*_x16*_x39*_x40 + 0.14531313573962065*_x16*_x50*_x51
            + 0.17612158869639333*_x16*_x61*_x62 + 0.04349583621493557*_x16*_x72*_x73
            - 0.029703284805013122*_x26 - 0.029703284805013122*_x27 - 0.10140664131431479*_x37
            - 0.10140664131431479*_x38 - 0.14531313573962065*_x48 - 0.14531313573962065*_x49
            - 0.17612158869639333*_x59 - 0.17612158869639333*_x60 - 0.04349583621493557*_x70
            - 0.04349583621493557*_x71)
        _iPsi5 = _x139
        _x140 = (1.0/math.sqrt(_x139))
        _ift5 = _x140*_x82
        _pd__98 = _x140*_x84
        _x141 = _x139**(-1.5)
        _pd__99 = -_x141*_x86
        _x142 = _x152**2
        _x143 = _x140*_x142
        _x144 = _x143*_x88
        _ifq5 = _P5*_x144
        _pd__100 = _P5*_x143*_x92
        _pd__101 = _x144
        _pd__102 = -_P5*_x141*_x142*_x93
        _pd__103 = -_x140*_x73*_x76*_x88
        _x145 = _x140*_x95
        _x146 = _x145*_x77
        _ifp5 = _x146*_x68
        _x147 = _x68*_x77
        _pd__104 = _x140*_x147*_x99
        _pd__105 = _x145*_x68*_x69
        _pd__106 = -_x100*_x141*_x147
        _pd__107 = _x146
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN36 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(5):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_Q3__j = _T[12, _j1]
            _d_Q4__j = _T[13, _j1]
            _d_Q5__j = _T[14, _j1]
            _d_P0__j = _T[15, _j1]
            _d_P1__j = _T[16, _j1]
            _d_P2__j = _T[17, _j1]
            _d_P3__j = _T[18, _j1]
            _d_P4__j = _T[19, _j1]
            _d_P5__j = _T[20, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x154 = -d_q_r__j
            _d_isigma0__j = -0.9988599083720104*_d_D__j - _x154
            _d_iF0__j = _d_P0__j*_pd__24 + _d_Q0__j*_pd__25 + _d_isigma0__j*_pd__26 + _pd__27*d_k_c__j
            _d_isigma1__j = -0.9713052300453587*_d_D__j - _x154
            _d_iF1__j = _d_P1__j*_pd__28 + _d_Q1__j*_pd__29 + _d_isigma1__j*_pd__30 + _pd__31*d_k_c__j
            _d_isigma2__j = -0.8550748140498466*_d_D__j - _x154
            _d_iF2__j = _d_P2__j*_pd__32 + _d_Q2__j*_pd__33 + _d_isigma2__j*_pd__34 + _pd__35*d_k_c__j
            _d_isigma3__j = -0.6164556279666497*_d_D__j - _x154
            _d_iF3__j = _d_P3__j*_pd__36 + _d_Q3__j*_pd__37 + _d_isigma3__j*_pd__38 + _pd__39*d_k_c__j
            _d_isigma4__j = -0.31009584357909425*_d_D__j - _x154
            _d_iF4__j = _d_P4__j*_pd__40 + _d_Q4__j*_pd__41 + _d_isigma4__j*_pd__42 + _pd__43*d_k_c__j
            _d_isigma5__j = -0.0663903941688584*_d_D__j - _x154
            _d_iF5__j = _d_P5__j*_pd__44 + _d_Q5__j*_pd__45 + _d_isigma5__j*_pd__46 + _pd__47*d_k_c__j
            _d_iPsi0__j = (0.5871580340658094*_d_iF0__j - 0.140380692261653*_d_iF1__j
                + 0.08683151831711133*_d_iF2__j - 0.052466581536012566*_d_iF3__j
                + 0.026354606039126004*_d_iF4__j - 0.007496884624381081*_d_iF5__j)
            _d_ift0__j = _d_D__j*_pd__48 + _d_iPsi0__j*_pd__49
            _d_ifq0__j = _d_D__j*_pd__50 + _d_P0__j*_pd__51 + _d_iPsi0__j*_pd__52 + _d_isigma0__j*_pd__53
            _d_ifp0__j = _d_D__j*_pd__54 + _d_Q0__j*_pd__55 + _d_iPsi0__j*_pd__56 + _d_isigma0__j*_pd__57
            _d_iPsi1__j = (0.147790320897128*_d_iF0__j + 0.41567911405660357*_d_iF1__j
                - 0.09720828549085844*_d_iF2__j + 0.05155355009455148*_d_iF3__j
                - 0.024719229415033087*_d_iF4__j + 0.006904529857608445*_d_iF5__j)
            _d_ift1__j = _d_D__j*_pd__58 + _d_iPsi1__j*_pd__59
            _d_ifq1__j = _d_D__j*_pd__60 + _d_P1__j*_pd__61 + _d_iPsi1__j*_pd__62 + _d_isigma1__j*_pd__63
            _d_ifp1__j = _d_D__j*_pd__64 + _d_Q1__j*_pd__65 + _d_iPsi1__j*_pd__66 + _d_isigma1__j*_pd__67
            _d_iPsi2__j = (0.010443786721981197*_d_iF0__j + 0.25540525119175433*_d_iF1__j
                + 0.2685463444140672*_d_iF2__j - 0.048794612428541204*_d_iF3__j
                + 0.01951903325298492*_d_iF4__j - 0.005119803152246505*_d_iF5__j)
            _d_ift2__j = _d_D__j*_pd__68 + _d_iPsi2__j*_pd__69
            _d_ifq2__j = _d_D__j*_pd__70 + _d_P2__j*_pd__71 + _d_iPsi2__j*_pd__72 + _d_isigma2__j*_pd__73
            _d_ifp2__j = _d_D__j*_pd__74 + _d_Q2__j*_pd__75 + _d_iPsi2__j*_pd__76 + _d_isigma2__j*_pd__77
            _d_iPsi3__j = (0.01101839635505667*_d_iF0__j + 0.0662099828438604*_d_iF1__j
                + 0.2671819482314443*_d_iF2__j + 0.1742495636223592*_d_iF3__j - 0.02396692958086051*_d_iF4__j
                + 0.00530703852813994*_d_iF5__j)
            _d_ift3__j = _d_D__j*_pd__78 + _d_iPsi3__j*_pd__79
            _d_ifq3__j = _d_D__j*_pd__80 + _d_P3__j*_pd__81 + _d_iPsi3__j*_pd__82 + _d_isigma3__j*_pd__83
            _d_ifp3__j = _d_D__j*_pd__84 + _d_Q3__j*_pd__85 + _d_iPsi3__j*_pd__86 + _d_isigma3__j*_pd__87
            _d_iPsi4__j = (0.0025147977064533143*_d_iF0__j + 0.050345455482979015*_d_iF1__j
                + 0.11622097556712797*_d_iF2__j + 0.2353986790647292*_d_iF3__j + 0.10372825048336794*_d_iF4__j
                - 0.008208158304657426*_d_iF5__j)
            _d_ift4__j = _d_D__j*_pd__88 + _d_iPsi4__j*_pd__89
            _d_ifq4__j = _d_D__j*_pd__90 + _d_P4__j*_pd__91 + _d_iPsi4__j*_pd__92 + _d_isigma4__j*_pd__93
            _d_ifp4__j = _d_D__j*_pd__94 + _d_Q4__j*_pd__95 + _d_iPsi4__j*_pd__96 + _d_isigma4__j*_pd__97
            _d_iPsi5__j = (0.003959513229722528*_d_iF0__j + 0.029703284805013122*_d_iF1__j
                + 0.10140664131431479*_d_iF2__j + 0.14531313573962065*_d_iF3__j
                + 0.17612158869639333*_d_iF4__j + 0.04349583621493557*_d_iF5__j)
            _d_ift5__j = _d_D__j*_pd__98 + _d_iPsi5__j*_pd__99
            _d_ifq5__j = _d_D__j*_pd__100 + _d_P5__j*_pd__101 + _d_iPsi5__j*_pd__102 + _d_isigma5__j*_pd__103
            _d_ifp5__j = _d_D__j*_pd__104 + _d_Q5__j*_pd__105 + _d_iPsi5__j*_pd__106 + _d_isigma5__j*_pd__107
            _T[21, _j1] = _d_isigma0__j
            _T[22, _j1] = _d_iF0__j
            _T[23, _j1] = _d_isigma1__j
            _T[24, _j1] = _d_iF1__j
            _T[25, _j1] = _d_isigma2__j
            _T[26, _j1] = _d_iF2__j
            _T[27, _j1] = _d_isigma3__j
            _T[28, _j1] = _d_iF3__j
            _T[29, _j1] = _d_isigma4__j
            _T[30, _j1] = _d_iF4__j
            _T[31, _j1] = _d_isigma5__j
            _T[32, _j1] = _d_iF5__j
            _T[33, _j1] = _d_ift0__j
            _T[34, _j1] = _d_ifq0__j
            _T[35, _j1] = _d_ifp0__j
            _T[36, _j1] = _d_ift1__j
            _T[37, _j1] = _d_ifq1__j
            _T[38, _j1] = _d_ifp1__j
            _T[39, _j1] = _d_ift2__j
            _T[40, _j1] = _d_ifq2__j
            _T[41, _j1] = _d_ifp2__j
            _T[42, _j1] = _d_ift3__j
            _T[43, _j1] = _d_ifq3__j
            _T[44, _j1] = _d_ifp3__j
            _T[45, _j1] = _d_ift4__j
            _T[46, _j1] = _d_ifq4__j
            _T[47, _j1] = _d_ifp4__j
            _T[48, _j1] = _d_ift5__j
            _T[49, _j1] = _d_ifq5__j
            _T[50, _j1] = _d_ifp5__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x155 = m*q_rd**2
        _x156 = -q_r
        _x157 = k_c*(_x156 + l0)
        _x158 = -l0
        _x159 = -_isigma0 - _x158
        _x160 = 0.005784813099631875*k_c
        _x161 = -_isigma1 - _x158
        _x162 = 0.06111131733618721*k_c
        _x163 = -_isigma2 - _x158
        _x164 = 0.17813034617398463*k_c
        _x165 = -_isigma3 - _x158
        _x166 = 0.28978358839870644*k_c
        _x167 = -_isigma4 - _x158
        _x168 = 0.2996502557119514*k_c
        _x169 = -_isigma5 - _x158
        _x170 = 0.16553967927953847*k_c
        _x171 = (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2
            + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 + _x157
            - _x159*_x160 - _x161*_x162 - _x163*_x164 - _x165*_x166 - _x167*_x168 - _x169*_x170)
        _x172 = math.sqrt(_x155*k_c + _x171**2)
        _x173 = _x171 + _x172
        _x174 = (1.0/_x173)
        _D__next = _x155*_x174
        _x175 = _x159*k_c
        _x176 = _x161*k_c
        _x177 = _x163*k_c
        _x178 = _x165*k_c
        _x179 = _x167*k_c
        _x180 = _x169*k_c
        _x181 = (1.0/_x172)
        _x182 = _x174**2
        _x183 = _x155*_x182
        _pd__108 = (_x183*(-_x181*(3.346406259767255e-05*_iF0 + 0.0003535175490621363*_iF1
            + 0.0010304507599892272*_iF2 + 0.0016763438982271685*_iF3 + 0.001733420724550538*_iF4
            + 0.0009576161052051336*_iF5 + 0.005784813099631875*_x157 - 3.346406259767255e-05*_x175
            - 0.0003535175490621363*_x176 - 0.0010304507599892272*_x177 - 0.0016763438982271685*_x178
            - 0.001733420724550538*_x179 - 0.0009576161052051336*_x180) - 0.005784813099631875))
        _pd__109 = (_x183*(-_x181*(0.0003535175490621363*_iF0 + 0.003734593106564175*_iF1
            + 0.010885780112243256*_iF2 + 0.017709056829452403*_iF3 + 0.018312021866682706*_iF4
            + 0.010116347872182529*_iF5 + 0.06111131733618721*_x157 - 0.0003535175490621363*_x175
            - 0.003734593106564175*_x176 - 0.010885780112243256*_x177 - 0.017709056829452403*_x178
            - 0.018312021866682706*_x179 - 0.010116347872182529*_x180) - 0.06111131733618721))
        _pd__110 = (_x183*(-_x181*(0.0010304507599892272*_iF0 + 0.010885780112243256*_iF1
            + 0.0317304202280636*_iF2 + 0.05161925091700105*_iF3 + 0.05337680378109292*_iF4
            + 0.02948764037559458*_iF5 + 0.17813034617398463*_x157 - 0.0010304507599892272*_x175
            - 0.010885780112243256*_x176 - 0.0317304202280636*_x177 - 0.05161925091700105*_x178
            - 0.05337680378109292*_x179 - 0.02948764037559458*_x180) - 0.17813034617398463))
        _pd__111 = (_x183*(-_x181*(0.0016763438982271685*_iF0 + 0.017709056829452403*_iF1
            + 0.05161925091700105*_iF2 + 0.0839745281052309*_iF3 + 0.08683372636479925*_iF4
            + 0.04797068228399565*_iF5 + 0.28978358839870644*_x157 - 0.0016763438982271685*_x175
            - 0.017709056829452403*_x176 - 0.05161925091700105*_x177 - 0.0839745281052309*_x178
            - 0.08683372636479925*_x179 - 0.04797068228399565*_x180) - 0.28978358839870644))
        _pd__112 = (_x183*(-_x181*(0.001733420724550538*_iF0 + 0.018312021866682706*_iF1
            + 0.05337680378109292*_iF2 + 0.08683372636479925*_iF3 + 0.08979027574823786*_iF4
            + 0.04960400722658813*_iF5 + 0.2996502557119514*_x157 - 0.001733420724550538*_x175
            - 0.018312021866682706*_x176 - 0.05337680378109292*_x177 - 0.08683372636479925*_x178
            - 0.08979027574823786*_x179 - 0.04960400722658813*_x180) - 0.2996502557119514))
        _pd__113 = (_x183*(-_x181*(0.0009576161052051336*_iF0 + 0.010116347872182529*_iF1
            + 0.02948764037559458*_iF2 + 0.04797068228399565*_iF3 + 0.04960400722658813*_iF4
            + 0.027403385415972457*_iF5 + 0.16553967927953847*_x157 - 0.0009576161052051336*_x175
            - 0.010116347872182529*_x176 - 0.02948764037559458*_x177 - 0.04797068228399565*_x178
            - 0.04960400722658813*_x179 - 0.027403385415972457*_x180) - 0.16553967927953847))
        _x184 = _x171*_x181
        _pd__114 = _x183*(-_x160*_x184 - _x160)
        _pd__115 = _x183*(-_x162*_x184 - _x162)
        _pd__116 = _x183*(-_x164*_x184 - _x164)
        _pd__117 = _x183*(-_x166*_x184 - _x166)
        _pd__118 = _x183*(-_x168*_x184 - _x168)
        _pd__119 = _x183*(-_x170*_x184 - _x170)
        _x185 = 2.0*q_r
        _pd__120 = (_x183*(-0.005784813099631875*_isigma0 - 0.06111131733618721*_isigma1
            - 0.17813034617398463*_isigma2 - 0.28978358839870644*_isigma3 - 0.2996502557119514*_isigma4
            - 0.16553967927953847*_isigma5 - _x156 - _x181*((0.5)*_x155
            + (0.5)*_x171*(0.01156962619926375*_isigma0 + 0.12222263467237442*_isigma1
            + 0.35626069234796925*_isigma2 + 0.5795671767974129*_isigma3 + 0.5993005114239028*_isigma4
            + 0.33107935855907694*_isigma5 - _x185 - 1.164670302474663e-21*l0)) + 5.823351512373315e-22*l0))
        _pd__121 = _x183*(_x184*k_c + k_c)
        _pd__122 = 2.0*_x174*m*q_rd - _x181*_x182*k_c*m**2*q_rd**3
        _Q0__next = (0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2
            + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th)
        _Q1__next = (-0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2
            + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th)
        _Q2__next = (0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2
            + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th)
        _Q3__next = (-0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2
            + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th)
        _Q4__next = (0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2
            - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th)
        _Q5__next = (-0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2
            + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _x186 = m*q_r**2
        _x187 = _x186*q_thd
        _P0__next = (0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2
            + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + _x187)
        _x188 = _x185*m*q_thd
        _pd__123 = _x188
        _pd__124 = _x186
        _P1__next = (-0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2
            + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + _x187)
        _pd__125 = _x188
        _pd__126 = _x186
        _P2__next = (0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2
            + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + _x187)
        _pd__127 = _x188
        _pd__128 = _x186
        _P3__next = (-0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2
            + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + _x187)
        _pd__129 = _x188
        _pd__130 = _x186
        _P4__next = (0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2
            - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + _x187)
        _pd__131 = _x188
        _pd__132 = _x186
        _P5__next = (-0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2
            + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + _x187)
        _pd__133 = _x188
        _pd__134 = _x186
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[21, _j2]
            _d_iF0__j = _T[22, _j2]
            _d_isigma1__j = _T[23, _j2]
            _d_iF1__j = _T[24, _j2]
            _d_isigma2__j = _T[25, _j2]
            _d_iF2__j = _T[26, _j2]
            _d_isigma3__j = _T[27, _j2]
            _d_iF3__j = _T[28, _j2]
            _d_isigma4__j = _T[29, _j2]
            _d_iF4__j = _T[30, _j2]
            _d_isigma5__j = _T[31, _j2]
            _d_iF5__j = _T[32, _j2]
            _d_ifq0__j = _T[34, _j2]
            _d_ifp0__j = _T[35, _j2]
            _d_ifq1__j = _T[37, _j2]
            _d_ifp1__j = _T[38, _j2]
            _d_ifq2__j = _T[40, _j2]
            _d_ifp2__j = _T[41, _j2]
            _d_ifq3__j = _T[43, _j2]
            _d_ifp3__j = _T[44, _j2]
            _d_ifq4__j = _T[46, _j2]
            _d_ifp4__j = _T[47, _j2]
            _d_ifq5__j = _T[49, _j2]
            _d_ifp5__j = _T[50, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__108 + _d_iF1__j*_pd__109 + _d_iF2__j*_pd__110 + _d_iF3__j*_pd__111
                + _d_iF4__j*_pd__112 + _d_iF5__j*_pd__113 + _d_isigma0__j*_pd__114 + _d_isigma1__j*_pd__115
                + _d_isigma2__j*_pd__116 + _d_isigma3__j*_pd__117 + _d_isigma4__j*_pd__118
                + _d_isigma5__j*_pd__119 + _pd__120*d_k_c__j + _pd__121*d_q_r__j + _pd__122*d_q_rd__j)
            _d_Q0__next__j = (0.04283112309479259*_d_ifq0__j + 0.19514451252126672*_d_ifq1__j
                + 0.22463191657986778*_d_ifq2__j + 0.23962582533582905*_d_ifq3__j
                + 0.17752635320896998*_d_ifq4__j + 0.08647502636084993*_d_ifq5__j + d_q_th__j)
            _d_Q1__next__j = (-0.007011245240793691*_d_ifq0__j + 0.09019039326203465*_d_ifq1__j
                + 0.2542570695795851*_d_ifq2__j + 0.2235938110460991*_d_ifq3__j
                + 0.18526797945210696*_d_ifq4__j + 0.08430668513410011*_d_ifq5__j + d_q_th__j)
            _d_Q2__next__j = (0.0034143235767412987*_d_ifq0__j - 0.0156513758091757*_d_ifq1__j
                + 0.11697848364317276*_d_ifq2__j + 0.25443949503200164*_d_ifq3__j
                + 0.17239079462440696*_d_ifq4__j + 0.0877378719744515*_d_ifq5__j + d_q_th__j)
            _d_Q3__next__j = (-0.002075625784866334*_d_ifq0__j + 0.007989991899662336*_d_ifq1__j
                - 0.020482527745656096*_d_ifq2__j + 0.11697848364317276*_d_ifq3__j
                + 0.196032162333245*_d_ifq4__j + 0.08224792261284387*_d_ifq5__j + d_q_th__j)
            _d_Q4__next__j = (0.0013555610554850618*_d_ifq0__j - 0.004887192928037671*_d_ifq1__j
                + 0.010363156240246424*_d_ifq2__j - 0.020300102293239586*_d_ifq3__j
                + 0.09019039326203465*_d_ifq4__j + 0.09267349143037887*_d_ifq5__j + d_q_th__j)
            _d_Q5__next__j = (-0.0008127801712647621*_d_ifq0__j + 0.002854433315099335*_d_ifq1__j
                - 0.005668858049483512*_d_ifq2__j + 0.009325050706477751*_d_ifq3__j
                - 0.014763725997197413*_d_ifq4__j + 0.04283112309479259*_d_ifq5__j + d_q_th__j)
            _d_P0__next__j = (0.04283112309479259*_d_ifp0__j + 0.19514451252126672*_d_ifp1__j
                + 0.22463191657986778*_d_ifp2__j + 0.23962582533582905*_d_ifp3__j
                + 0.17752635320896998*_d_ifp4__j + 0.08647502636084993*_d_ifp5__j + _pd__123*d_q_r__j
                + _pd__124*d_q_thd__j)
            _d_P1__next__j = (-0.007011245240793691*_d_ifp0__j + 0.09019039326203465*_d_ifp1__j
                + 0.2542570695795851*_d_ifp2__j + 0.2235938110460991*_d_ifp3__j
                + 0.18526797945210696*_d_ifp4__j + 0.08430668513410011*_d_ifp5__j + _pd__125*d_q_r__j
                + _pd__126*d_q_thd__j)
            _d_P2__next__j = (0.0034143235767412987*_d_ifp0__j - 0.0156513758091757*_d_ifp1__j
                + 0.11697848364317276*_d_ifp2__j + 0.25443949503200164*_d_ifp3__j
                + 0.17239079462440696*_d_ifp4__j + 0.0877378719744515*_d_ifp5__j + _pd__127*d_q_r__j
                + _pd__128*d_q_thd__j)
            _d_P3__next__j = (-0.002075625784866334*_d_ifp0__j + 0.007989991899662336*_d_ifp1__j
                - 0.020482527745656096*_d_ifp2__j + 0.11697848364317276*_d_ifp3__j
                + 0.196032162333245*_d_ifp4__j + 0.08224792261284387*_d_ifp5__j + _pd__129*d_q_r__j
                + _pd__130*d_q_thd__j)
            _d_P4__next__j = (0.0013555610554850618*_d_ifp0__j - 0.004887192928037671*_d_ifp1__j
                + 0.010363156240246424*_d_ifp2__j - 0.020300102293239586*_d_ifp3__j
                + 0.09019039326203465*_d_ifp4__j + 0.09267349143037887*_d_ifp5__j + _pd__131*d_q_r__j
                + _pd__132*d_q_thd__j)
            _d_P5__next__j = (-0.0008127801712647621*_d_ifp0__j + 0.002854433315099335*_d_ifp1__j
                - 0.005668858049483512*_d_ifp2__j + 0.009325050706477751*_d_ifp3__j
                - 0.014763725997197413*_d_ifp4__j + 0.04283112309479259*_d_ifp5__j + _pd__133*d_q_r__j
                + _pd__134*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_Q3__next__j
            _T[13, _j2] = _d_Q4__next__j
            _T[14, _j2] = _d_Q5__next__j
            _T[15, _j2] = _d_P0__next__j
            _T[16, _j2] = _d_P1__next__j
            _T[17, _j2] = _d_P2__next__j
            _T[18, _j2] = _d_P3__next__j
            _T[19, _j2] = _d_P4__next__j
            _T[20, _j2] = _d_P5__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _Q4__next
        _n0_6 = _Q5__next
        _n0_7 = _P0__next
        _n0_8 = _P1__next
        _n0_9 = _P2__next
        _n0_10 = _P3__next
        _n0_11 = _P4__next
        _n0_12 = _P5__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8
            - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    _x189 = -_D + q_r
    end_q_r = _x189
    end_q_rd = 0.0
    _x190 = q_r**2
    _x191 = (0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x190*m*q_thd)
    _x198 = (1.0/_x189)
    _x192 = _x198**2
    _x193 = (1.0/m)
    _x194 = _x192*_x193
    end_q_thd = _x191*_x194
    _x195 = 0.08566224618958518*_x194
    _pd__135 = _x195
    _x196 = 0.1803807865240693*_x194
    _pd__136 = _x196
    _x197 = 0.23395696728634552*_x194
    _pd__137 = _x197
    _pd__138 = _x197
    _pd__139 = _x196
    _pd__140 = _x195
    _pd__141 = -2.0*_x191*_x193*_x198**3
    _pd__142 = 2.0*_x192*q_r*q_thd
    _pd__143 = _x190*_x192
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN36 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(5):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[33, _j3]
        _d_ifq0__j = _T[34, _j3]
        _d_ifp0__j = _T[35, _j3]
        _d_ift1__j = _T[36, _j3]
        _d_ifq1__j = _T[37, _j3]
        _d_ifp1__j = _T[38, _j3]
        _d_ift2__j = _T[39, _j3]
        _d_ifq2__j = _T[40, _j3]
        _d_ifp2__j = _T[41, _j3]
        _d_ift3__j = _T[42, _j3]
        _d_ifq3__j = _T[43, _j3]
        _d_ifp3__j = _T[44, _j3]
        _d_ift4__j = _T[45, _j3]
        _d_ifq4__j = _T[46, _j3]
        _d_ifp4__j = _T[47, _j3]
        _d_ift5__j = _T[48, _j3]
        _d_ifq5__j = _T[49, _j3]
        _d_ifp5__j = _T[50, _j3]
        # bottom state
        d_t_half__j = (0.08566224618958518*_d_ift0__j + 0.1803807865240693*_d_ift1__j
            + 0.23395696728634552*_d_ift2__j + 0.23395696728634552*_d_ift3__j + 0.1803807865240693*_d_ift4__j
            + 0.08566224618958518*_d_ift5__j)
        d_end_q_th__j = (0.08566224618958518*_d_ifq0__j + 0.1803807865240693*_d_ifq1__j
            + 0.23395696728634552*_d_ifq2__j + 0.23395696728634552*_d_ifq3__j + 0.1803807865240693*_d_ifq4__j
            + 0.08566224618958518*_d_ifq5__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__135 + _d_ifp1__j*_pd__136 + _d_ifp2__j*_pd__137
            + _d_ifp3__j*_pd__138 + _d_ifp4__j*_pd__139 + _d_ifp5__j*_pd__140 + _pd__141*d_end_q_r__j
            + _pd__142*d_q_r__j + _pd__143*d_q_thd__j)
        _T[51, _j3] = d_t_half__j
        _T[52, _j3] = d_end_q_th__j
        _T[53, _j3] = d_end_q_r__j
        _T[54, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, ) = (_T[51, 0], _T[51, 1], _T[51, 2],
        _T[51, 3], _T[51, 4], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, ) = (_T[52, 0], _T[52, 1],
        _T[52, 2], _T[52, 3], _T[52, 4], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, ) = (_T[53, 0], _T[53, 1], _T[53,
        2], _T[53, 3], _T[53, 4], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, ) = (_T[54, 0], _T[54,
        1], _T[54, 2], _T[54, 3], _T[54, 4], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4, d_end_q_th__0,
        d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_thd__0, d_end_q_thd__1,
        d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_passes__0, d_passes__1, d_passes__2, d_passes__3,
        d_passes__4, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0,
        k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Arguments, returns and status: those of
    :func:`schwind_decompression_nodes_4_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd` (another choice of the
    same kernel).
    """
    # Total ops: 1394
    # inputs: finite and inside their domains
    if not _inputs_valid_1(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd,
            iterations, tol):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((47, 6))
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (0.0, 0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    # the initial values
    _x0 = m*q_r_lo**2
    _pd__0 = 0.03376524289842399*_x0
    _x1 = m*q_r*q_thd
    _pd__1 = 1.932469514203152*_x1
    _x2 = m*q_r**2
    _pd__2 = 0.966234757101576*_x2
    _pd__3 = 0.16939530676686773*_x0
    _pd__4 = 1.6612093864662645*_x1
    _pd__5 = 0.8306046932331322*_x2
    _pd__6 = 0.38069040695840156*_x0
    _pd__7 = 1.238619186083197*_x1
    _pd__8 = 0.6193095930415985*_x2
    _pd__9 = 0.6193095930415985*_x0
    _pd__10 = 0.7613808139168031*_x1
    _pd__11 = 0.38069040695840156*_x2
    _pd__12 = 0.8306046932331322*_x0
    _pd__13 = 0.33879061353373546*_x1
    _pd__14 = 0.16939530676686773*_x2
    _pd__15 = 0.966234757101576*_x0
    _pd__16 = 0.06753048579684798*_x1
    _pd__17 = 0.03376524289842399*_x2
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_th__j = _T[0, _j0]
        d_guess_q_thd__j = _T[1, _j0]
        d_q_r__j = _T[3, _j0]
        d_q_th__j = _T[4, _j0]
        d_q_thd__j = _T[5, _j0]
        # the initial values
        _d_Q0__start__j = 0.03376524289842399*d_guess_q_th__j + 0.966234757101576*d_q_th__j
        _d_Q1__start__j = 0.16939530676686773*d_guess_q_th__j + 0.8306046932331322*d_q_th__j
        _d_Q2__start__j = 0.38069040695840156*d_guess_q_th__j + 0.6193095930415985*d_q_th__j
        _d_Q3__start__j = 0.6193095930415985*d_guess_q_th__j + 0.38069040695840156*d_q_th__j
        _d_Q4__start__j = 0.8306046932331322*d_guess_q_th__j + 0.16939530676686773*d_q_th__j
        _d_Q5__start__j = 0.966234757101576*d_guess_q_th__j + 0.03376524289842399*d_q_th__j
        _d_P0__start__j = _pd__0*d_guess_q_thd__j + _pd__1*d_q_r__j + _pd__2*d_q_thd__j
        _d_P1__start__j = _pd__3*d_guess_q_thd__j + _pd__4*d_q_r__j + _pd__5*d_q_thd__j
        _d_P2__start__j = _pd__6*d_guess_q_thd__j + _pd__7*d_q_r__j + _pd__8*d_q_thd__j
        _d_P3__start__j = _pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__9*d_guess_q_thd__j
        _d_P4__start__j = _pd__12*d_guess_q_thd__j + _pd__13*d_q_r__j + _pd__14*d_q_thd__j
        _d_P5__start__j = _pd__15*d_guess_q_thd__j + _pd__16*d_q_r__j + _pd__17*d_q_thd__j
        _T[6, _j0] = -d_q_r__j
        _T[7, _j0] = _d_Q0__start__j
        _T[8, _j0] = _d_Q1__start__j
        _T[9, _j0] = _d_Q2__start__j
        _T[10, _j0] = _d_Q3__start__j
        _T[11, _j0] = _d_Q4__start__j
        _T[12, _j0] = _d_Q5__start__j
        _T[13, _j0] = _d_P0__start__j
        _T[14, _j0] = _d_P1__start__j
        _T[15, _j0] = _d_P2__start__j
        _T[16, _j0] = _d_P3__start__j
        _T[17, _j0] = _d_P4__start__j
        _T[18, _j0] = _d_P5__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x3 = 0.0011400916279895713*_D + q_r
        _isigma0 = _x3
        _x4 = k_d*l0
        _x5 = math.cos(_Q0)
        _x6 = g_s*m
        _x7 = _x5*_x6
        _x8 = _x3*k_d
        _x9 = _P0**2
        _x10 = (1.0/m)
        _x140 = (1.0/_x3)
        _x11 = _x140**3
        _x12 = _x10*_x11
        _x13 = _x12*_x9
        _iF0 = _x13 + _x4 - _x7 - _x8
        _x14 = 2.0*_P0
        _pd__18 = _x12*_x14
        _x15 = math.sin(_Q0)
        _pd__19 = _x15*_x6
        _x16 = 3.0*_x10
        _pd__20 = -_x140**4*_x16*_x9 - k_d
        _x17 = -l0
        _pd__21 = -_x17 - _x3
        _x18 = 0.02869476995464123*_D + q_r
        _isigma1 = _x18
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x6
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x138 = (1.0/_x18)
        _x23 = _x138**3
        _x24 = _x10*_x23
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x4
        _x26 = 2.0*_P1
        _pd__22 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__23 = _x27*_x6
        _pd__24 = -_x138**4*_x16*_x22 - k_d
        _pd__25 = -_x17 - _x18
        _x28 = 0.14492518595015338*_D + q_r
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x6
        _x31 = _x28*k_d
        _x32 = _P2**2
        _x139 = (1.0/_x28)
        _x33 = _x139**3
        _x34 = _x10*_x33
        _x35 = _x32*_x34
        _iF2 = -_x30 - _x31 + _x35 + _x4
        _x36 = 2.0*_P2
        _pd__26 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__27 = _x37*_x6
        _pd__28 = -_x139**4*_x16*_x32 - k_d
        _pd__29 = -_x17 - _x28
        _x38 = 0.3835443720333503*_D + q_r
        _isigma3 = _x38
        _x39 = math.cos(_Q3)
        _x40 = _x39*_x6
        _x41 = _x38*k_d
        _x42 = _P3**2
        _x141 = (1.0/_x38)
        _x43 = _x141**3
        _x44 = _x10*_x43
        _x45 = _x42*_x44
        _iF3 = _x4 - _x40 - _x41 + _x45
        _x46 = 2.0*_P3
        _pd__30 = _x44*_x46
        _x47 = math.sin(_Q3)
        _pd__31 = _x47*_x6
        _pd__32 = -_x141**4*_x16*_x42 - k_d
        _pd__33 = -_x17 - _x38
        _x48 = 0.6899041564209057*_D + q_r
        _isigma4 = _x48
        _x49 = math.cos(_Q4)
        _x50 = _x49*_x6
        _x51 = _x48*k_d
        _x52 = _P4**2
        _x142 = (1.0/_x48)
        _x53 = _x142**3
        _x54 = _x10*_x53
        _x55 = _x52*_x54
        _iF4 = _x4 - _x50 - _x51 + _x55
        _x56 = 2.0*_P4
        _pd__34 = _x54*_x56
        _x57 = math.sin(_Q4)
        _pd__35 = _x57*_x6
        _pd__36 = -_x142**4*_x16*_x52 - k_d
        _pd__37 = -_x17 - _x48
        _x58 = 0.9336096058311416*_D + q_r
        _isigma5 = _x58
        _x59 = math.cos(_Q5)
        _x60 = _x59*_x6
        _x61 = _x58*k_d
        _x62 = _P5**2
        _x143 = (1.0/_x58)
        _x63 = _x143**3
        _x64 = _x10*_x63
        _x65 = _x62*_x64
        _iF5 = _x4 - _x60 - _x61 + _x65
        _x66 = 2.0*_P5
        _pd__38 = _x64*_x66
        _x67 = math.sin(_Q5)
        _pd__39 = _x6*_x67
        _pd__40 = -_x143**4*_x16*_x62 - k_d
        _pd__41 = -_x17 - _x58
        _x68 = (0.5871580340658094*_x13 + 0.140380692261653*_x20 + 0.140380692261653*_x21
            - 0.140380692261653*_x25 - 0.08683151831711133*_x30 - 0.08683151831711133*_x31
            + 0.08683151831711133*_x35 + 0.5*_x4 + 0.052466581536012566*_x40 + 0.052466581536012566*_x41
            - 0.052466581536012566*_x45 - 0.026354606039126004*_x50 - 0.026354606039126004*_x51
            + 0.026354606039126004*_x55 + 0.007496884624381081*_x60 + 0.007496884624381081*_x61
            - 0.007496884624381081*_x65 - 0.5871580340658094*_x7 - 0.5871580340658094*_x8)
        _iPsi0 = _x68
        _x69 = (1.0/math.sqrt(_x68))
        _x70 = math.sqrt(_D)
        _x71 = math.sqrt(m)
        _x72 = _x70*_x71
        _ift0 = _x69*_x72
        _x73 = (0.5)/_x70
        _x74 = _x71*_x73
        _pd__42 = _x69*_x74
        _x75 = _x68**(-1.5)
        _x76 = (0.5)*_x72
        _pd__43 = -_x75*_x76
        _x77 = (1.0/_x71)
        _x78 = _x70*_x77
        _x79 = _x140**2
        _x80 = _x69*_x79
        _x81 = _x78*_x80
        _ifq0 = _P0*_x81
        _x82 = _x73*_x77
        _pd__44 = _P0*_x80*_x82
        _pd__45 = _x81
        _x83 = (0.5)*_x78
        _pd__46 = -_P0*_x75*_x79*_x83
        _pd__47 = -_x11*_x14*_x69*_x78
        _x84 = g_s*m**(1.5)
        _x85 = _x70*_x84
        _x86 = _x69*_x85
        _x87 = _x15*_x86
        _ifp0 = _x3*_x87
        _x88 = _x15*_x3
        _x89 = _x73*_x84
        _pd__48 = _x69*_x88*_x89
        _pd__49 = _x3*_x5*_x86
        _x90 = (0.5)*_x85
        _pd__50 = -_x75*_x88*_x90
        _pd__51 = _x87
        _x91 = -0.5*k_d*l0
        _x92 = (0.147790320897128*_x10*_x11*_x9 + 0.41567911405660357*_x10*_x22*_x23
            + 0.05155355009455148*_x10*_x42*_x43 + 0.006904529857608445*_x10*_x62*_x63
            - 0.41567911405660357*_x20 - 0.41567911405660357*_x21 + 0.09720828549085844*_x28*k_d
            + 0.09720828549085844*_x29*g_s*m - 0.09720828549085844*_x35 - 0.05155355009455148*_x40
            - 0.05155355009455148*_x41 + 0.024719229415033087*_x48*k_d + 0.024719229415033087*_x49*g_s*m
            - 0.024719229415033087*_x55 - 0.006904529857608445*_x60 - 0.006904529857608445*_x61
            - 0.147790320897128*_x7 - 0.147790320897128*_x8 - _x91)
        _iPsi1 = _x92
        _x93 = (1.0/math.sqrt(_x92))
        _ift1 = _x72*_x93
        _pd__52 = _x74*_x93
        _x94 = _x92**(-1.5)
        _pd__53 = -_x76*_x94
        _x95 = _x138**2
        _x96 = _x93*_x95
        _x97 = _x78*_x96
        _ifq1 = _P1*_x97
        _pd__54 = _P1*_x82*_x96
        _pd__55 = _x97
        _pd__56 = -_P1*_x83*_x94*_x95
        _pd__57 = -_x23*_x26*_x78*_x93
        _x98 = _x85*_x93
        _x99 = _x27*_x98
        _ifp1 = _x18*_x99
        _x100 = _x18*_x27
        _pd__58 = _x100*_x89*_x93
        _pd__59 = _x18*_x19*_x98
        _pd__60 = -_x100*_x90*_x94
        _pd__61 = _x99
        _x101 = (0.010443786721981197*_x10*_x11*_x9 + 0.25540525119175433*_x10*_x22*_x23
            + 0.2685463444140672*_x10*_x32*_x33 + 0.01951903325298492*_x10*_x52*_x53
            - 0.25540525119175433*_x20 - 0.25540525119175433*_x21 - 0.2685463444140672*_x30
            - 0.2685463444140672*_x31 + 0.048794612428541204*_x38*k_d + 0.048794612428541204*_x39*g_s*m
            - 0.048794612428541204*_x45 - 0.01951903325298492*_x50 - 0.01951903325298492*_x51
            + 0.005119803152246505*_x58*k_d + 0.005119803152246505*_x59*g_s*m - 0.005119803152246505*_x65
            - 0.010443786721981197*_x7 - 0.010443786721981197*_x8 - _x91)
        _iPsi2 = _x101
        _x102 = (1.0/math.sqrt(_x101))
        _ift2 = _x102*_x72
        _pd__62 = _x102*_x74
        _x103 = _x101**(-1.5)
        _pd__63 = -_x103*_x76
        _x104 = _x139**2
        _x105 = _x102*_x104
        _x106 = _x105*_x78
        _ifq2 = _P2*_x106
        _pd__64 = _P2*_x105*_x82
        _pd__65 = _x106
        _pd__66 = -_P2*_x103*_x104*_x83
        _pd__67 = -_x102*_x33*_x36*_x78
        _x107 = _x102*_x85
        _x108 = _x107*_x37
        _ifp2 = _x108*_x28
        _x109 = _x28*_x37
        _pd__68 = _x102*_x109*_x89
        _pd__69 = _x107*_x28*_x29
        _pd__70 = -_x103*_x109*_x90
        _pd__71 = _x108
        _x110 = -0.5*k_d*l0
        _x111 = (0.01101839635505667*_x10*_x11*_x9 + 0.0662099828438604*_x10*_x22*_x23
            + 0.2671819482314443*_x10*_x32*_x33 + 0.1742495636223592*_x10*_x42*_x43
            + 0.00530703852813994*_x10*_x62*_x63 - _x110 - 0.0662099828438604*_x20 - 0.0662099828438604*_x21
            - 0.2671819482314443*_x30 - 0.2671819482314443*_x31 - 0.1742495636223592*_x40
            - 0.1742495636223592*_x41 + 0.02396692958086051*_x48*k_d + 0.02396692958086051*_x49*g_s*m
            - 0.02396692958086051*_x55 - 0.00530703852813994*_x60 - 0.00530703852813994*_x61
            - 0.01101839635505667*_x7 - 0.01101839635505667*_x8)
        _iPsi3 = _x111
        _x112 = (1.0/math.sqrt(_x111))
        _ift3 = _x112*_x72
        _pd__72 = _x112*_x74
        _x113 = _x111**(-1.5)
        _pd__73 = -_x113*_x76
        _x114 = _x141**2
        _x115 = _x112*_x114
        _x116 = _x115*_x78
        _ifq3 = _P3*_x116
        _pd__74 = _P3*_x115*_x82
        _pd__75 = _x116
        _pd__76 = -_P3*_x113*_x114*_x83
        _pd__77 = -_x112*_x43*_x46*_x78
        _x117 = _x112*_x85
        _x118 = _x117*_x47
        _ifp3 = _x118*_x38
        _x119 = _x38*_x47
        _pd__78 = _x112*_x119*_x89
        _pd__79 = _x117*_x38*_x39
        _pd__80 = -_x113*_x119*_x90
        _pd__81 = _x118
        _x120 = (0.0025147977064533143*_x10*_x11*_x9 + 0.050345455482979015*_x10*_x22*_x23
            + 0.11622097556712797*_x10*_x32*_x33 + 0.2353986790647292*_x10*_x42*_x43
            + 0.10372825048336794*_x10*_x52*_x53 - 0.050345455482979015*_x20 - 0.050345455482979015*_x21
            - 0.11622097556712797*_x30 - 0.11622097556712797*_x31 - 0.2353986790647292*_x40
            - 0.2353986790647292*_x41 - 0.10372825048336794*_x50 - 0.10372825048336794*_x51
            + 0.008208158304657426*_x58*k_d + 0.008208158304657426*_x59*g_s*m - 0.008208158304657426*_x65
            - 0.0025147977064533143*_x7 - 0.0025147977064533143*_x8 - _x91)
        _iPsi4 = _x120
        _x121 = (1.0/math.sqrt(_x120))
        _ift4 = _x121*_x72
        _pd__82 = _x121*_x74
        _x122 = _x120**(-1.5)
        _pd__83 = -_x122*_x76
        _x123 = _x142**2
        _x124 = _x121*_x123
        _x125 = _x124*_x78
        _ifq4 = _P4*_x125
        _pd__84 = _P4*_x124*_x82
        _pd__85 = _x125
        _pd__86 = -_P4*_x122*_x123*_x83
        _pd__87 = -_x121*_x53*_x56*_x78
        _x126 = _x121*_x85
        _x127 = _x126*_x57
        _ifp4 = _x127*_x48
        _x128 = _x48*_x57
        _pd__88 = _x121*_x128*_x89
        _pd__89 = _x126*_x48*_x49
        _pd__90 = -_x122*_x128*_x90
        _pd__91 = _x127
        _x129 = (0.003959513229722528*_x10*_x11*_x9 + 0.029703284805013122*_x10*_x22*_x23
            + 0.10140664131431479*_x10*_x32*_x33 + 0.14531313573962065*_x10*_x42*_x43
            + 0.17612158869639333*_x10*_x52*_x53 + 0.04349583621493557*_x10*_x62*_x63 - _x110
            - 0.029703284805013122*_x20 - 0.029703284805013122*_x21 - 0.10140664131431479*_x30
            - 0.10140664131431479*_x31 - 0.14531313573962065*_x40 - 0.14531313573962065*_x41
            - 0.17612158869639333*_x50 - 0.17612158869639333*_x51 - 0.04349583621493557*_x60
            - 0.04349583621493557*_x61 - 0.003959513229722528*_x7 - 0.003959513229722528*_x8)
        _iPsi5 = _x129
        _x130 = (1.0/math.sqrt(_x129))
        _ift5 = _x130*_x72
        _pd__92 = _x130*_x74
        _x131 = _x129**(-1.5)
        _pd__93 = -_x131*_x76
        _x132 = _x143**2
        _x133 = _x130*_x132
        _x134 = _x133*_x78
        _ifq5 = _P5*_x134
        _pd__94 = _P5*_x133*_x82
        _pd__95 = _x134
        _pd__96 = -_P5*_x131*_x132*_x83
        _pd__97 = -_x130*_x63*_x66*_x78
        _x135 = _x130*_x85
        _x136 = _x135*_x67
        _ifp5 = _x136*_x58
        _x137 = _x58*_x67
        _pd__98 = _x130*_x137*_x89
        _pd__99 = _x135*_x58*_x59
        _pd__100 = -_x131*_x137*_x90
        _pd__101 = _x136
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_d__j = _T[2, _j1]
            d_q_r__j = _T[3, _j1]
            _d_D__j = _T[6, _j1]
            _d_Q0__j = _T[7, _j1]
            _d_Q1__j = _T[8, _j1]
            _d_Q2__j = _T[9, _j1]
            _d_Q3__j = _T[10, _j1]
            _d_Q4__j = _T[11, _j1]
            _d_Q5__j = _T[12, _j1]
            _d_P0__j = _T[13, _j1]
            _d_P1__j = _T[14, _j1]
            _d_P2__j = _T[15, _j1]
            _d_P3__j = _T[16, _j1]
            _d_P4__j = _T[17, _j1]
            _d_P5__j = _T[18, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.0011400916279895713*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__18 + _d_Q0__j*_pd__19 + _d_isigma0__j*_pd__20 + _pd__21*d_k_d__j
            _d_isigma1__j = 0.02869476995464123*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__22 + _d_Q1__j*_pd__23 + _d_isigma1__j*_pd__24 + _pd__25*d_k_d__j
            _d_isigma2__j = 0.14492518595015338*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__26 + _d_Q2__j*_pd__27 + _d_isigma2__j*_pd__28 + _pd__29*d_k_d__j
            _d_isigma3__j = 0.3835443720333503*_d_D__j + d_q_r__j
            _d_iF3__j = _d_P3__j*_pd__30 + _d_Q3__j*_pd__31 + _d_isigma3__j*_pd__32 + _pd__33*d_k_d__j
            _d_isigma4__j = 0.6899041564209057*_d_D__j + d_q_r__j
            _d_iF4__j = _d_P4__j*_pd__34 + _d_Q4__j*_pd__35 + _d_isigma4__j*_pd__36 + _pd__37*d_k_d__j
            _d_isigma5__j = 0.9336096058311416*_d_D__j + d_q_r__j
            _d_iF5__j = _d_P5__j*_pd__38 + _d_Q5__j*_pd__39 + _d_isigma5__j*_pd__40 + _pd__41*d_k_d__j
            _d_iPsi0__j = (0.5871580340658094*_d_iF0__j - 0.140380692261653*_d_iF1__j
                + 0.08683151831711133*_d_iF2__j - 0.052466581536012566*_d_iF3__j
                + 0.026354606039126004*_d_iF4__j - 0.007496884624381081*_d_iF5__j)
            _d_ift0__j = _d_D__j*_pd__42 + _d_iPsi0__j*_pd__43
            _d_ifq0__j = _d_D__j*_pd__44 + _d_P0__j*_pd__45 + _d_iPsi0__j*_pd__46 + _d_isigma0__j*_pd__47
            _d_ifp0__j = _d_D__j*_pd__48 + _d_Q0__j*_pd__49 + _d_iPsi0__j*_pd__50 + _d_isigma0__j*_pd__51
            _d_iPsi1__j = (0.147790320897128*_d_iF0__j + 0.41567911405660357*_d_iF1__j
                - 0.09720828549085844*_d_iF2__j + 0.05155355009455148*_d_iF3__j
                - 0.024719229415033087*_d_iF4__j + 0.006904529857608445*_d_iF5__j)
            _d_ift1__j = _d_D__j*_pd__52 + _d_iPsi1__j*_pd__53
            _d_ifq1__j = _d_D__j*_pd__54 + _d_P1__j*_pd__55 + _d_iPsi1__j*_pd__56 + _d_isigma1__j*_pd__57
            _d_ifp1__j = _d_D__j*_pd__58 + _d_Q1__j*_pd__59 + _d_iPsi1__j*_pd__60 + _d_isigma1__j*_pd__61
            _d_iPsi2__j = (0.010443786721981197*_d_iF0__j + 0.25540525119175433*_d_iF1__j
                + 0.2685463444140672*_d_iF2__j - 0.048794612428541204*_d_iF3__j
                + 0.01951903325298492*_d_iF4__j - 0.005119803152246505*_d_iF5__j)
            _d_ift2__j = _d_D__j*_pd__62 + _d_iPsi2__j*_pd__63
            _d_ifq2__j = _d_D__j*_pd__64 + _d_P2__j*_pd__65 + _d_iPsi2__j*_pd__66 + _d_isigma2__j*_pd__67
            _d_ifp2__j = _d_D__j*_pd__68 + _d_Q2__j*_pd__69 + _d_iPsi2__j*_pd__70 + _d_isigma2__j*_pd__71
            _d_iPsi3__j = (0.01101839635505667*_d_iF0__j + 0.0662099828438604*_d_iF1__j
                + 0.2671819482314443*_d_iF2__j + 0.1742495636223592*_d_iF3__j - 0.02396692958086051*_d_iF4__j
                + 0.00530703852813994*_d_iF5__j)
            _d_ift3__j = _d_D__j*_pd__72 + _d_iPsi3__j*_pd__73
            _d_ifq3__j = _d_D__j*_pd__74 + _d_P3__j*_pd__75 + _d_iPsi3__j*_pd__76 + _d_isigma3__j*_pd__77
            _d_ifp3__j = _d_D__j*_pd__78 + _d_Q3__j*_pd__79 + _d_iPsi3__j*_pd__80 + _d_isigma3__j*_pd__81
            _d_iPsi4__j = (0.0025147977064533143*_d_iF0__j + 0.050345455482979015*_d_iF1__j
                + 0.11622097556712797*_d_iF2__j + 0.2353986790647292*_d_iF3__j + 0.10372825048336794*_d_iF4__j
                - 0.008208158304657426*_d_iF5__j)
            _d_ift4__j = _d_D__j*_pd__82 + _d_iPsi4__j*_pd__83
            _d_ifq4__j = _d_D__j*_pd__84 + _d_P4__j*_pd__85 + _d_iPsi4__j*_pd__86 + _d_isigma4__j*_pd__87
            _d_ifp4__j = _d_D__j*_pd__88 + _d_Q4__j*_pd__89 + _d_iPsi4__j*_pd__90 + _d_isigma4__j*_pd__91
            _d_iPsi5__j = (0.003959513229722528*_d_iF0__j + 0.029703284805013122*_d_iF1__j
                + 0.10140664131431479*_d_iF2__j + 0.14531313573962065*_d_iF3__j
                + 0.17612158869639333*_d_iF4__j + 0.04349583621493557*_d_iF5__j)
            _d_ift5__j = _d_D__j*_pd__92 + _d_iPsi5__j*_pd__93
            _d_ifq5__j = _d_D__j*_pd__94 + _d_P5__j*_pd__95 + _d_iPsi5__j*_pd__96 + _d_isigma5__j*_pd__97
            _d_ifp5__j = _d_D__j*_pd__98 + _d_Q5__j*_pd__99 + _d_iPsi5__j*_pd__100 + _d_isigma5__j*_pd__101
            _T[19, _j1] = _d_iF0__j
            _T[20, _j1] = _d_iF1__j
            _T[21, _j1] = _d_iF2__j
            _T[22, _j1] = _d_iF3__j
            _T[23, _j1] = _d_iF4__j
            _T[24, _j1] = _d_iF5__j
            _T[25, _j1] = _d_ift0__j
            _T[26, _j1] = _d_ifq0__j
            _T[27, _j1] = _d_ifp0__j
            _T[28, _j1] = _d_ift1__j
            _T[29, _j1] = _d_ifq1__j
            _T[30, _j1] = _d_ifp1__j
            _T[31, _j1] = _d_ift2__j
            _T[32, _j1] = _d_ifq2__j
            _T[33, _j1] = _d_ifp2__j
            _T[34, _j1] = _d_ift3__j
            _T[35, _j1] = _d_ifq3__j
            _T[36, _j1] = _d_ifp3__j
            _T[37, _j1] = _d_ift4__j
            _T[38, _j1] = _d_ifq4__j
            _T[39, _j1] = _d_ifp4__j
            _T[40, _j1] = _d_ift5__j
            _T[41, _j1] = _d_ifq5__j
            _T[42, _j1] = _d_ifp5__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2
            - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th)
        _Q1__next = (0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2
            + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th)
        _Q2__next = (0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2
            - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th)
        _Q3__next = (0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2
            + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th)
        _Q4__next = (0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2
            + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th)
        _Q5__next = (0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2
            + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _x144 = m*q_r**2
        _x145 = _x144*q_thd
        _P0__next = (0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2
            - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5 + _x145)
        _x146 = 2.0*m*q_r*q_thd
        _pd__102 = _x146
        _pd__103 = _x144
        _P1__next = (0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2
            + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5 + _x145)
        _pd__104 = _x146
        _pd__105 = _x144
        _P2__next = (0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2
            - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5 + _x145)
        _pd__106 = _x146
        _pd__107 = _x144
        _P3__next = (0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2
            + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5 + _x145)
        _pd__108 = _x146
        _pd__109 = _x144
        _P4__next = (0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2
            + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5 + _x145)
        _pd__110 = _x146
        _pd__111 = _x144
        _P5__next = (0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2
            + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5 + _x145)
        _pd__112 = _x146
        _pd__113 = _x144
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_q_r__j = _T[3, _j2]
            d_q_th__j = _T[4, _j2]
            d_q_thd__j = _T[5, _j2]
            _d_D__j = _T[6, _j2]
            _d_ifq0__j = _T[26, _j2]
            _d_ifp0__j = _T[27, _j2]
            _d_ifq1__j = _T[29, _j2]
            _d_ifp1__j = _T[30, _j2]
            _d_ifq2__j = _T[32, _j2]
            _d_ifp2__j = _T[33, _j2]
            _d_ifq3__j = _T[35, _j2]
            _d_ifp3__j = _T[36, _j2]
            _d_ifq4__j = _T[38, _j2]
            _d_ifp4__j = _T[39, _j2]
            _d_ifq5__j = _T[41, _j2]
            _d_ifp5__j = _T[42, _j2]
            # next values
            _d_Q0__next__j = (0.04283112309479259*_d_ifq0__j - 0.014763725997197413*_d_ifq1__j
                + 0.009325050706477751*_d_ifq2__j - 0.005668858049483512*_d_ifq3__j
                + 0.002854433315099335*_d_ifq4__j - 0.0008127801712647621*_d_ifq5__j + d_q_th__j)
            _d_Q1__next__j = (0.09267349143037887*_d_ifq0__j + 0.09019039326203465*_d_ifq1__j
                - 0.020300102293239586*_d_ifq2__j + 0.010363156240246424*_d_ifq3__j
                - 0.004887192928037671*_d_ifq4__j + 0.0013555610554850618*_d_ifq5__j + d_q_th__j)
            _d_Q2__next__j = (0.08224792261284387*_d_ifq0__j + 0.196032162333245*_d_ifq1__j
                + 0.11697848364317276*_d_ifq2__j - 0.020482527745656096*_d_ifq3__j
                + 0.007989991899662336*_d_ifq4__j - 0.002075625784866334*_d_ifq5__j + d_q_th__j)
            _d_Q3__next__j = (0.0877378719744515*_d_ifq0__j + 0.17239079462440696*_d_ifq1__j
                + 0.25443949503200164*_d_ifq2__j + 0.11697848364317276*_d_ifq3__j
                - 0.0156513758091757*_d_ifq4__j + 0.0034143235767412987*_d_ifq5__j + d_q_th__j)
            _d_Q4__next__j = (0.08430668513410011*_d_ifq0__j + 0.18526797945210696*_d_ifq1__j
                + 0.2235938110460991*_d_ifq2__j + 0.2542570695795851*_d_ifq3__j
                + 0.09019039326203465*_d_ifq4__j - 0.007011245240793691*_d_ifq5__j + d_q_th__j)
            _d_Q5__next__j = (0.08647502636084993*_d_ifq0__j + 0.17752635320896998*_d_ifq1__j
                + 0.23962582533582905*_d_ifq2__j + 0.22463191657986778*_d_ifq3__j
                + 0.19514451252126672*_d_ifq4__j + 0.04283112309479259*_d_ifq5__j + d_q_th__j)
            _d_P0__next__j = (0.04283112309479259*_d_ifp0__j - 0.014763725997197413*_d_ifp1__j
                + 0.009325050706477751*_d_ifp2__j - 0.005668858049483512*_d_ifp3__j
                + 0.002854433315099335*_d_ifp4__j - 0.0008127801712647621*_d_ifp5__j + _pd__102*d_q_r__j
                + _pd__103*d_q_thd__j)
            _d_P1__next__j = (0.09267349143037887*_d_ifp0__j + 0.09019039326203465*_d_ifp1__j
                - 0.020300102293239586*_d_ifp2__j + 0.010363156240246424*_d_ifp3__j
                - 0.004887192928037671*_d_ifp4__j + 0.0013555610554850618*_d_ifp5__j + _pd__104*d_q_r__j
                + _pd__105*d_q_thd__j)
            _d_P2__next__j = (0.08224792261284387*_d_ifp0__j + 0.196032162333245*_d_ifp1__j
                + 0.11697848364317276*_d_ifp2__j - 0.020482527745656096*_d_ifp3__j
                + 0.007989991899662336*_d_ifp4__j - 0.002075625784866334*_d_ifp5__j + _pd__106*d_q_r__j
                + _pd__107*d_q_thd__j)
            _d_P3__next__j = (0.0877378719744515*_d_ifp0__j + 0.17239079462440696*_d_ifp1__j
                + 0.25443949503200164*_d_ifp2__j + 0.11697848364317276*_d_ifp3__j
                - 0.0156513758091757*_d_ifp4__j + 0.0034143235767412987*_d_ifp5__j + _pd__108*d_q_r__j
                + _pd__109*d_q_thd__j)
            _d_P4__next__j = (0.08430668513410011*_d_ifp0__j + 0.18526797945210696*_d_ifp1__j
                + 0.2235938110460991*_d_ifp2__j + 0.2542570695795851*_d_ifp3__j
                + 0.09019039326203465*_d_ifp4__j - 0.007011245240793691*_d_ifp5__j + _pd__110*d_q_r__j
                + _pd__111*d_q_thd__j)
            _d_P5__next__j = (0.08647502636084993*_d_ifp0__j + 0.17752635320896998*_d_ifp1__j
                + 0.23962582533582905*_d_ifp2__j + 0.22463191657986778*_d_ifp3__j
                + 0.19514451252126672*_d_ifp4__j + 0.04283112309479259*_d_ifp5__j + _pd__112*d_q_r__j
                + _pd__113*d_q_thd__j)
            _T[6, _j2] = _d_D__j
            _T[7, _j2] = _d_Q0__next__j
            _T[8, _j2] = _d_Q1__next__j
            _T[9, _j2] = _d_Q2__next__j
            _T[10, _j2] = _d_Q3__next__j
            _T[11, _j2] = _d_Q4__next__j
            _T[12, _j2] = _d_Q5__next__j
            _T[13, _j2] = _d_P0__next__j
            _T[14, _j2] = _d_P1__next__j
            _T[15, _j2] = _d_P2__next__j
            _T[16, _j2] = _d_P3__next__j
            _T[17, _j2] = _d_P4__next__j
            _T[18, _j2] = _d_P5__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _Q4__next
        _n0_6 = _Q5__next
        _n0_7 = _P0__next
        _n0_8 = _P1__next
        _n0_9 = _P2__next
        _n0_10 = _P3__next
        _n0_11 = _P4__next
        _n0_12 = _P5__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8
            - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    end_q_r = q_r_lo
    _x147 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x147
    _pd__114 = _x147/_D
    _pd__115 = _x147/_work
    _x148 = q_r**2
    _x149 = q_r_lo**-2
    _x150 = _x149/m
    end_q_thd = (_x150*(0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x148*m*q_thd))
    _x151 = 0.08566224618958518*_x150
    _pd__116 = _x151
    _x152 = 0.1803807865240693*_x150
    _pd__117 = _x152
    _x153 = 0.23395696728634552*_x150
    _pd__118 = _x153
    _pd__119 = _x153
    _pd__120 = _x152
    _pd__121 = _x151
    _pd__122 = 2.0*_x149*q_r*q_thd
    _pd__123 = _x148*_x149
    passes = _passes
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[3, _j3]
        d_q_th__j = _T[4, _j3]
        d_q_thd__j = _T[5, _j3]
        _d_D__j = _T[6, _j3]
        _d_iF0__j = _T[19, _j3]
        _d_iF1__j = _T[20, _j3]
        _d_iF2__j = _T[21, _j3]
        _d_iF3__j = _T[22, _j3]
        _d_iF4__j = _T[23, _j3]
        _d_iF5__j = _T[24, _j3]
        _d_ift0__j = _T[25, _j3]
        _d_ifq0__j = _T[26, _j3]
        _d_ifp0__j = _T[27, _j3]
        _d_ift1__j = _T[28, _j3]
        _d_ifq1__j = _T[29, _j3]
        _d_ifp1__j = _T[30, _j3]
        _d_ift2__j = _T[31, _j3]
        _d_ifq2__j = _T[32, _j3]
        _d_ifp2__j = _T[33, _j3]
        _d_ift3__j = _T[34, _j3]
        _d_ifq3__j = _T[35, _j3]
        _d_ifp3__j = _T[36, _j3]
        _d_ift4__j = _T[37, _j3]
        _d_ifq4__j = _T[38, _j3]
        _d_ifp4__j = _T[39, _j3]
        _d_ift5__j = _T[40, _j3]
        _d_ifq5__j = _T[41, _j3]
        _d_ifp5__j = _T[42, _j3]
        _d_work__j = (0.0028924065498159377*_d_iF0__j + 0.030555658668093604*_d_iF1__j
            + 0.08906517308699231*_d_iF2__j + 0.14489179419935322*_d_iF3__j + 0.1498251278559757*_d_iF4__j
            + 0.08276983963976924*_d_iF5__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.08566224618958518*_d_ift0__j + 0.1803807865240693*_d_ift1__j
            + 0.23395696728634552*_d_ift2__j + 0.23395696728634552*_d_ift3__j + 0.1803807865240693*_d_ift4__j
            + 0.08566224618958518*_d_ift5__j)
        d_end_q_th__j = (0.08566224618958518*_d_ifq0__j + 0.1803807865240693*_d_ifq1__j
            + 0.23395696728634552*_d_ifq2__j + 0.23395696728634552*_d_ifq3__j + 0.1803807865240693*_d_ifq4__j
            + 0.08566224618958518*_d_ifq5__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__114 + _d_work__j*_pd__115
        d_end_q_thd__j = (_d_ifp0__j*_pd__116 + _d_ifp1__j*_pd__117 + _d_ifp2__j*_pd__118
            + _d_ifp3__j*_pd__119 + _d_ifp4__j*_pd__120 + _d_ifp5__j*_pd__121 + _pd__122*d_q_r__j
            + _pd__123*d_q_thd__j)
        _T[43, _j3] = d_t_half__j
        _T[44, _j3] = d_end_q_th__j
        _T[45, _j3] = d_end_q_rd__j
        _T[46, _j3] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[43, 0], _T[43, 1], _T[43, 2], _T[43, 3], _T[43, 4], _T[43, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[44, 0], _T[44, 1], _T[44, 2], _T[44, 3], _T[44, 4], _T[44, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[45, 0], _T[45, 1], _T[45, 2], _T[45, 3], _T[45, 4], _T[45, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[46, 0], _T[46, 1], _T[46, 2], _T[46, 3], _T[46, 4], _T[46, 5], )
    # derivatives of the outputs
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN77 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td, 0.0,
        _j_z_b_q_th__q_th_td, 0.0, _j_z_b_q_r__q_thd_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_02ae5f(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes,
        d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_geyer`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_geyer`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 122
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x6 = m*q_rd_td**2
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    z_b_q_r = _x11
    _x12 = (1.0/_x8)
    _x13 = (0.5)*_x7
    _x14 = _x10**2
    _x15 = _x14*_x6
    d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
    d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
    _x16 = _x2*math.sin(q_th_td)
    _x17 = _x12*_x7
    d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
    _x18 = 2.0*q_r_td
    _x19 = _x18*q_thd_td
    _x20 = _x19*m
    d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
    d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
    z_b_q_th = q_th_td
    _x21 = q_r_td**2
    _x24 = (1.0/_x11)
    _x22 = _x24**2
    _x23 = _x21*_x22
    z_b_q_thd = _x23*q_thd_td
    _pd__0 = -2.0*_x21*_x24**3*q_thd_td
    d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
    d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
    d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
    d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
    d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, d_z_b_q_r__q_r_td, 0.0, d_z_b_q_thd__q_r_td,
        d_z_b_q_r__q_rd_td, 0.0, d_z_b_q_thd__q_rd_td, d_z_b_q_r__q_th_td, 1.0, d_z_b_q_thd__q_th_td,
        d_z_b_q_r__q_thd_td, 0.0, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, 0.0, d_z_b_q_thd__k_c))
    if _c0[36] != STATUS_OK:
        return _NAN77 + (_c0[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c0
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x25 = q_r_lo**-2
    _x26 = _x25*bottom_q_r**2
    g_lo_q_thd = _x26*bottom_q_thd
    _pd__1 = 2.0*_x25*bottom_q_r*bottom_q_thd
    _pd__2 = _x26
    d_g_lo_q_thd__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _pd__2*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td + _pd__2*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__1*d_bottom_q_r__q_th_td + _pd__2*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td + _pd__2*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__1*d_bottom_q_r__k_c + _pd__2*d_bottom_q_thd__k_c
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c1
    # the code shared between choices
    return (iterative_stance_jacobian_tail_18d243(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_g_lo_q_thd__k_c, d_g_lo_q_thd__q_r_td, d_g_lo_q_thd__q_rd_td,
        d_g_lo_q_thd__q_th_td, d_g_lo_q_thd__q_thd_td, d_passes, d_t_bottom__k_c, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_held`: arguments, out and status
    as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_held`: arguments, out and
    status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN77 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp5_408d60(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k, _j_z_b_q_th__k, _j_z_b_q_thd__k))
    if _c1[36] != STATUS_OK:
        return _NAN77 + (_c1[36],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, _, _, _, _,
        _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_d06e2d(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td,
        _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td,
        _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
        c_passes, d_bottom_q_r__k_c, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__q_r_td,
        d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_passes, d_t_bottom__k_c,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)


@njit(cache=True, error_model="numpy")
def schwind_compression_nodes_6_jvp6_a742c3(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
        d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3,
        d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5,
        d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Arguments, returns and status: those of :func:`schwind_compression_nodes_4_jvp6_a742c3` (another choice of
    the same kernel).
    """
    # Total ops: 1740
    # inputs: finite and inside their domains
    if not _inputs_valid_4(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd,
            iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1,
            d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
            d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4,
            d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((55, 6))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], _T[0, 5], ) = (d_guess_q_r__0, d_guess_q_r__1,
        d_guess_q_r__2, d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], _T[1, 5], ) = (d_guess_q_th__0, d_guess_q_th__1,
        d_guess_q_th__2, d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], _T[2, 5], ) = (d_guess_q_thd__0, d_guess_q_thd__1,
        d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], _T[3, 5], ) = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], _T[4, 5], ) = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], _T[5, 5], ) = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[6, 0], _T[6, 1], _T[6, 2], _T[6, 3], _T[6, 4], _T[6, 5], ) = (0.0, 0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[7, 0], _T[7, 1], _T[7, 2], _T[7, 3], _T[7, 4], _T[7, 5], ) = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, )
    # the initial values
    _x0 = 1.932469514203152*m
    _x1 = guess_q_r*guess_q_thd
    _pd__0 = _x0*_x1
    _x2 = guess_q_r**2*m
    _pd__1 = 0.966234757101576*_x2
    _x3 = q_r*q_thd
    _x4 = _x3*m
    _pd__2 = 0.06753048579684798*_x4
    _x5 = m*q_r**2
    _pd__3 = 0.03376524289842399*_x5
    _x6 = _x1*m
    _pd__4 = 1.6612093864662645*_x6
    _pd__5 = 0.8306046932331322*_x2
    _pd__6 = 0.33879061353373546*_x4
    _pd__7 = 0.16939530676686773*_x5
    _pd__8 = 1.238619186083197*_x6
    _pd__9 = 0.6193095930415985*_x2
    _pd__10 = 0.7613808139168031*_x4
    _pd__11 = 0.38069040695840156*_x5
    _pd__12 = 0.7613808139168031*_x6
    _pd__13 = 0.38069040695840156*_x2
    _pd__14 = 1.238619186083197*_x4
    _pd__15 = 0.6193095930415985*_x5
    _pd__16 = 0.33879061353373546*_x6
    _pd__17 = 0.16939530676686773*_x2
    _pd__18 = 1.6612093864662645*_x4
    _pd__19 = 0.8306046932331322*_x5
    _pd__20 = 0.06753048579684798*_x6
    _pd__21 = 0.03376524289842399*_x2
    _pd__22 = _x0*_x3
    _pd__23 = 0.966234757101576*_x5
    # the initial values' tangents, once per direction
    for _j0 in range(6):
        d_guess_q_r__j = _T[0, _j0]
        d_guess_q_th__j = _T[1, _j0]
        d_guess_q_thd__j = _T[2, _j0]
        d_q_r__j = _T[4, _j0]
        d_q_th__j = _T[6, _j0]
        d_q_thd__j = _T[7, _j0]
        # the initial values
        _d_D__start__j = -d_guess_q_r__j + d_q_r__j
        _d_Q0__start__j = 0.966234757101576*d_guess_q_th__j + 0.03376524289842399*d_q_th__j
        _d_Q1__start__j = 0.8306046932331322*d_guess_q_th__j + 0.16939530676686773*d_q_th__j
        _d_Q2__start__j = 0.6193095930415985*d_guess_q_th__j + 0.38069040695840156*d_q_th__j
        _d_Q3__start__j = 0.38069040695840156*d_guess_q_th__j + 0.6193095930415985*d_q_th__j
        _d_Q4__start__j = 0.16939530676686773*d_guess_q_th__j + 0.8306046932331322*d_q_th__j
        _d_Q5__start__j = 0.03376524289842399*d_guess_q_th__j + 0.966234757101576*d_q_th__j
        _d_P0__start__j = (_pd__0*d_guess_q_r__j + _pd__1*d_guess_q_thd__j + _pd__2*d_q_r__j
            + _pd__3*d_q_thd__j)
        _d_P1__start__j = (_pd__4*d_guess_q_r__j + _pd__5*d_guess_q_thd__j + _pd__6*d_q_r__j
            + _pd__7*d_q_thd__j)
        _d_P2__start__j = (_pd__10*d_q_r__j + _pd__11*d_q_thd__j + _pd__8*d_guess_q_r__j
            + _pd__9*d_guess_q_thd__j)
        _d_P3__start__j = (_pd__12*d_guess_q_r__j + _pd__13*d_guess_q_thd__j + _pd__14*d_q_r__j
            + _pd__15*d_q_thd__j)
        _d_P4__start__j = (_pd__16*d_guess_q_r__j + _pd__17*d_guess_q_thd__j + _pd__18*d_q_r__j
            + _pd__19*d_q_thd__j)
        _d_P5__start__j = (_pd__20*d_guess_q_r__j + _pd__21*d_guess_q_thd__j + _pd__22*d_q_r__j
            + _pd__23*d_q_thd__j)
        _T[8, _j0] = _d_D__start__j
        _T[9, _j0] = _d_Q0__start__j
        _T[10, _j0] = _d_Q1__start__j
        _T[11, _j0] = _d_Q2__start__j
        _T[12, _j0] = _d_Q3__start__j
        _T[13, _j0] = _d_Q4__start__j
        _T[14, _j0] = _d_Q5__start__j
        _T[15, _j0] = _d_P0__start__j
        _T[16, _j0] = _d_P1__start__j
        _T[17, _j0] = _d_P2__start__j
        _T[18, _j0] = _d_P3__start__j
        _T[19, _j0] = _d_P4__start__j
        _T[20, _j0] = _d_P5__start__j
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
            return _NAN42 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x7 = -q_r
        _x8 = 0.9988599083720104*_D + _x7
        _x9 = -_x8
        _isigma0 = _x9
        _x10 = k_c*l0
        _x11 = math.cos(_Q0)
        _x12 = g_s*m
        _x13 = _x11*_x12
        _x14 = _x9*k_c
        _x15 = _P0**2
        _x16 = (1.0/m)
        _x153 = (1.0/_x9)
        _x17 = _x153**3
        _x18 = _x16*_x17
        _x19 = _x15*_x18
        _iF0 = _x10 - _x13 - _x14 + _x19
        _x20 = 2.0*_P0
        _pd__24 = _x18*_x20
        _x21 = math.sin(_Q0)
        _pd__25 = _x12*_x21
        _x22 = 3.0*_x16
        _pd__26 = -_x15*_x153**4*_x22 - k_c
        _pd__27 = _x8 + l0
        _x23 = 0.9713052300453587*_D + _x7
        _x24 = -_x23
        _isigma1 = _x24
        _x25 = math.cos(_Q1)
        _x26 = _x12*_x25
        _x27 = _x24*k_c
        _x28 = _P1**2
        _x148 = (1.0/_x24)
        _x29 = _x148**3
        _x30 = _x16*_x29
        _x31 = _x28*_x30
        _iF1 = _x10 - _x26 - _x27 + _x31
        _x32 = 2.0*_P1
        _pd__28 = _x30*_x32
        _x33 = math.sin(_Q1)
        _pd__29 = _x12*_x33
        _pd__30 = -_x148**4*_x22*_x28 - k_c
        _pd__31 = _x23 + l0
        _x34 = 0.8550748140498466*_D + _x7
        _x35 = -_x34
        _isigma2 = _x35
        _x36 = math.cos(_Q2)
        _x37 = _x12*_x36
        _x38 = _x35*k_c
        _x39 = _P2**2
        _x149 = (1.0/_x35)
        _x40 = _x149**3
        _x41 = _x16*_x40
        _x42 = _x39*_x41
        _iF2 = _x10 - _x37 - _x38 + _x42
        _x43 = 2.0*_P2
        _pd__32 = _x41*_x43
        _x44 = math.sin(_Q2)
        _pd__33 = _x12*_x44
        _pd__34 = -_x149**4*_x22*_x39 - k_c
        _pd__35 = _x34 + l0
        _x45 = 0.6164556279666497*_D + _x7
        _x46 = -_x45
        _isigma3 = _x46
        _x47 = math.cos(_Q3)
        _x48 = _x12*_x47
        _x49 = _x46*k_c
        _x50 = _P3**2
        _x150 = (1.0/_x46)
        _x51 = _x150**3
        _x52 = _x16*_x51
        _x53 = _x50*_x52
        _iF3 = _x10 - _x48 - _x49 + _x53
        _x54 = 2.0*_P3
        _pd__36 = _x52*_x54
        _x55 = math.sin(_Q3)
        _pd__37 = _x12*_x55
        _pd__38 = -_x150**4*_x22*_x50 - k_c
        _pd__39 = _x45 + l0
        _x56 = 0.31009584357909425*_D + _x7
        _x57 = -_x56
        _isigma4 = _x57
        _x58 = math.cos(_Q4)
        _x59 = _x12*_x58
        _x60 = _x57*k_c
        _x61 = _P4**2
        _x151 = (1.0/_x57)
        _x62 = _x151**3
        _x63 = _x16*_x62
        _x64 = _x61*_x63
        _iF4 = _x10 - _x59 - _x60 + _x64
        _x65 = 2.0*_P4
        _pd__40 = _x63*_x65
        _x66 = math.sin(_Q4)
        _pd__41 = _x12*_x66
        _pd__42 = -_x151**4*_x22*_x61 - k_c
        _pd__43 = _x56 + l0
        _x67 = 0.0663903941688584*_D + _x7
        _x68 = -_x67
        _isigma5 = _x68
        _x69 = math.cos(_Q5)
        _x70 = _x12*_x69
        _x71 = _x68*k_c
        _x72 = _P5**2
        _x152 = (1.0/_x68)
        _x73 = _x152**3
        _x74 = _x16*_x73
        _x75 = _x72*_x74
        _iF5 = _x10 - _x70 - _x71 + _x75
        _x76 = 2.0*_P5
        _pd__44 = _x74*_x76
        _x77 = math.sin(_Q5)
        _pd__45 = _x12*_x77
        _pd__46 = -_x152**4*_x22*_x72 - k_c
        _pd__47 = _x67 + l0
        _x78 = (0.5*_x10 - 0.5871580340658094*_x13 - 0.5871580340658094*_x14 + 0.5871580340658094*_x19
            + 0.140380692261653*_x26 + 0.140380692261653*_x27 - 0.140380692261653*_x31
            - 0.08683151831711133*_x37 - 0.08683151831711133*_x38 + 0.08683151831711133*_x42
            + 0.052466581536012566*_x48 + 0.052466581536012566*_x49 - 0.052466581536012566*_x53
            - 0.026354606039126004*_x59 - 0.026354606039126004*_x60 + 0.026354606039126004*_x64
            + 0.007496884624381081*_x70 + 0.007496884624381081*_x71 - 0.007496884624381081*_x75)
        _iPsi0 = _x78
        _x79 = (1.0/math.sqrt(_x78))
        _x80 = math.sqrt(_D)
        _x81 = math.sqrt(m)
        _x82 = _x80*_x81
        _ift0 = _x79*_x82
        _x83 = (0.5)/_x80
        _x84 = _x81*_x83
        _pd__48 = _x79*_x84
        _x85 = _x78**(-1.5)
        _x86 = (0.5)*_x82
        _pd__49 = -_x85*_x86
        _x87 = (1.0/_x81)
        _x88 = _x80*_x87
        _x89 = _x153**2
        _x90 = _x79*_x89
        _x91 = _x88*_x90
        _ifq0 = _P0*_x91
        _x92 = _x83*_x87
        _pd__50 = _P0*_x90*_x92
        _pd__51 = _x91
        _x93 = (0.5)*_x88
        _pd__52 = -_P0*_x85*_x89*_x93
        _pd__53 = -_x17*_x20*_x79*_x88
        _x94 = g_s*m**(1.5)
        _x95 = _x80*_x94
        _x96 = _x79*_x95
        _x97 = _x21*_x96
        _ifp0 = _x9*_x97
        _x98 = _x21*_x9
        _x99 = _x83*_x94
        _pd__54 = _x79*_x98*_x99
        _pd__55 = _x11*_x9*_x96
        _x100 = (0.5)*_x95
        _pd__56 = -_x100*_x85*_x98
        _pd__57 = _x97
        _x101 = -0.5*k_c*l0
        _x102 = (-_x101 - 0.147790320897128*_x13 - 0.147790320897128*_x14 + 0.147790320897128*_x15*_x16*_x17
            + 0.41567911405660357*_x16*_x28*_x29 + 0.05155355009455148*_x16*_x50*_x51
            + 0.006904529857608445*_x16*_x72*_x73 - 0.41567911405660357*_x26 - 0.41567911405660357*_x27
            + 0.09720828549085844*_x35*k_c + 0.09720828549085844*_x36*g_s*m - 0.09720828549085844*_x42
            - 0.05155355009455148*_x48 - 0.05155355009455148*_x49 + 0.024719229415033087*_x57*k_c
            + 0.024719229415033087*_x58*g_s*m - 0.024719229415033087*_x64 - 0.006904529857608445*_x70
            - 0.006904529857608445*_x71)
        _iPsi1 = _x102
        _x103 = (1.0/math.sqrt(_x102))
        _ift1 = _x103*_x82
        _pd__58 = _x103*_x84
        _x104 = _x102**(-1.5)
        _pd__59 = -_x104*_x86
        _x105 = _x148**2
        _x106 = _x103*_x105
        _x107 = _x106*_x88
        _ifq1 = _P1*_x107
        _pd__60 = _P1*_x106*_x92
        _pd__61 = _x107
        _pd__62 = -_P1*_x104*_x105*_x93
        _pd__63 = -_x103*_x29*_x32*_x88
        _x108 = _x103*_x95
        _x109 = _x108*_x33
        _ifp1 = _x109*_x24
        _x110 = _x24*_x33
        _pd__64 = _x103*_x110*_x99
        _pd__65 = _x108*_x24*_x25
        _pd__66 = -_x100*_x104*_x110
        _pd__67 = _x109
        _x111 = (-_x101 - 0.010443786721981197*_x13 - 0.010443786721981197*_x14
            + 0.010443786721981197*_x15*_x16*_x17 + 0.25540525119175433*_x16*_x28*_x29
            + 0.2685463444140672*_x16*_x39*_x40 + 0.01951903325298492*_x16*_x61*_x62
            - 0.25540525119175433*_x26 - 0.25540525119175433*_x27 - 0.2685463444140672*_x37
            - 0.2685463444140672*_x38 + 0.048794612428541204*_x46*k_c + 0.048794612428541204*_x47*g_s*m
            - 0.048794612428541204*_x53 - 0.01951903325298492*_x59 - 0.01951903325298492*_x60
            + 0.005119803152246505*_x68*k_c + 0.005119803152246505*_x69*g_s*m - 0.005119803152246505*_x75)
        _iPsi2 = _x111
        _x112 = (1.0/math.sqrt(_x111))
        _ift2 = _x112*_x82
        _pd__68 = _x112*_x84
        _x113 = _x111**(-1.5)
        _pd__69 = -_x113*_x86
        _x114 = _x149**2
        _x115 = _x112*_x114
        _x116 = _x115*_x88
        _ifq2 = _P2*_x116
        _pd__70 = _P2*_x115*_x92
        _pd__71 = _x116
        _pd__72 = -_P2*_x113*_x114*_x93
        _pd__73 = -_x112*_x40*_x43*_x88
        _x117 = _x112*_x95
        _x118 = _x117*_x44
        _ifp2 = _x118*_x35
        _x119 = _x35*_x44
        _pd__74 = _x112*_x119*_x99
        _pd__75 = _x117*_x35*_x36
        _pd__76 = -_x100*_x113*_x119
        _pd__77 = _x118
        _x120 = -0.5*k_c*l0
        _x121 = (-_x120 - 0.01101839635505667*_x13 - 0.01101839635505667*_x14
            + 0.01101839635505667*_x15*_x16*_x17 + 0.0662099828438604*_x16*_x28*_x29
            + 0.2671819482314443*_x16*_x39*_x40 + 0.1742495636223592*_x16*_x50*_x51
            + 0.00530703852813994*_x16*_x72*_x73 - 0.0662099828438604*_x26 - 0.0662099828438604*_x27
            - 0.2671819482314443*_x37 - 0.2671819482314443*_x38 - 0.1742495636223592*_x48
            - 0.1742495636223592*_x49 + 0.02396692958086051*_x57*k_c + 0.02396692958086051*_x58*g_s*m
            - 0.02396692958086051*_x64 - 0.00530703852813994*_x70 - 0.00530703852813994*_x71)
        _iPsi3 = _x121
        _x122 = (1.0/math.sqrt(_x121))
        _ift3 = _x122*_x82
        _pd__78 = _x122*_x84
        _x123 = _x121**(-1.5)
        _pd__79 = -_x123*_x86
        _x124 = _x150**2
        _x125 = _x122*_x124
        _x126 = _x125*_x88
        _ifq3 = _P3*_x126
        _pd__80 = _P3*_x125*_x92
        _pd__81 = _x126
        _pd__82 = -_P3*_x123*_x124*_x93
        _pd__83 = -_x122*_x51*_x54*_x88
        _x127 = _x122*_x95
        _x128 = _x127*_x55
        _ifp3 = _x128*_x46
        _x129 = _x46*_x55
        _pd__84 = _x122*_x129*_x99
        _pd__85 = _x127*_x46*_x47
        _pd__86 = -_x100*_x123*_x129
        _pd__87 = _x128
        _x130 = (-_x101 - 0.0025147977064533143*_x13 - 0.0025147977064533143*_x14
            + 0.0025147977064533143*_x15*_x16*_x17 + 0.050345455482979015*_x16*_x28*_x29
            + 0.11622097556712797*_x16*_x39*_x40 + 0.2353986790647292*_x16*_x50*_x51
            + 0.10372825048336794*_x16*_x61*_x62 - 0.050345455482979015*_x26 - 0.050345455482979015*_x27
            - 0.11622097556712797*_x37 - 0.11622097556712797*_x38 - 0.2353986790647292*_x48
            - 0.2353986790647292*_x49 - 0.10372825048336794*_x59 - 0.10372825048336794*_x60
            + 0.008208158304657426*_x68*k_c + 0.008208158304657426*_x69*g_s*m - 0.008208158304657426*_x75)
        _iPsi4 = _x130
        _x131 = (1.0/math.sqrt(_x130))
        _ift4 = _x131*_x82
        _pd__88 = _x131*_x84
        _x132 = _x130**(-1.5)
        _pd__89 = -_x132*_x86
        _x133 = _x151**2
        _x134 = _x131*_x133
        _x135 = _x134*_x88
        _ifq4 = _P4*_x135
        _pd__90 = _P4*_x134*_x92
        _pd__91 = _x135
        _pd__92 = -_P4*_x132*_x133*_x93
        _pd__93 = -_x131*_x62*_x65*_x88
        _x136 = _x131*_x95
        _x137 = _x136*_x66
        _ifp4 = _x137*_x57
        _x138 = _x57*_x66
        _pd__94 = _x131*_x138*_x99
        _pd__95 = _x136*_x57*_x58
        _pd__96 = -_x100*_x132*_x138
        _pd__97 = _x137
        _x139 = (-_x120 - 0.003959513229722528*_x13 - 0.003959513229722528*_x14
            + 0.003959513229722528*_x15*_x16*_x17 + 0.029703284805013122*_x16*_x28*_x29
            + 0.10140664131431479*_x16*_x39*_x40 + 0.14531313573962065*_x16*_x50*_x51
            + 0.17612158869639333*_x16*_x61*_x62 + 0.04349583621493557*_x16*_x72*_x73
            - 0.029703284805013122*_x26 - 0.029703284805013122*_x27 - 0.10140664131431479*_x37
            - 0.10140664131431479*_x38 - 0.14531313573962065*_x48 - 0.14531313573962065*_x49
            - 0.17612158869639333*_x59 - 0.17612158869639333*_x60 - 0.04349583621493557*_x70
            - 0.04349583621493557*_x71)
        _iPsi5 = _x139
        _x140 = (1.0/math.sqrt(_x139))
        _ift5 = _x140*_x82
        _pd__98 = _x140*_x84
        _x141 = _x139**(-1.5)
        _pd__99 = -_x141*_x86
        _x142 = _x152**2
        _x143 = _x140*_x142
        _x144 = _x143*_x88
        _ifq5 = _P5*_x144
        _pd__100 = _P5*_x143*_x92
        _pd__101 = _x144
        _pd__102 = -_P5*_x141*_x142*_x93
        _pd__103 = -_x140*_x73*_x76*_x88
        _x145 = _x140*_x95
        _x146 = _x145*_x77
        _ifp5 = _x146*_x68
        _x147 = _x68*_x77
        _pd__104 = _x140*_x147*_x99
        _pd__105 = _x145*_x68*_x69
        _pd__106 = -_x100*_x141*_x147
        _pd__107 = _x146
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN42 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[3, _j1]
            d_q_r__j = _T[4, _j1]
            _d_D__j = _T[8, _j1]
            _d_Q0__j = _T[9, _j1]
            _d_Q1__j = _T[10, _j1]
            _d_Q2__j = _T[11, _j1]
            _d_Q3__j = _T[12, _j1]
            _d_Q4__j = _T[13, _j1]
            _d_Q5__j = _T[14, _j1]
            _d_P0__j = _T[15, _j1]
            _d_P1__j = _T[16, _j1]
            _d_P2__j = _T[17, _j1]
            _d_P3__j = _T[18, _j1]
            _d_P4__j = _T[19, _j1]
            _d_P5__j = _T[20, _j1]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x154 = -d_q_r__j
            _d_isigma0__j = -0.9988599083720104*_d_D__j - _x154
            _d_iF0__j = _d_P0__j*_pd__24 + _d_Q0__j*_pd__25 + _d_isigma0__j*_pd__26 + _pd__27*d_k_c__j
            _d_isigma1__j = -0.9713052300453587*_d_D__j - _x154
            _d_iF1__j = _d_P1__j*_pd__28 + _d_Q1__j*_pd__29 + _d_isigma1__j*_pd__30 + _pd__31*d_k_c__j
            _d_isigma2__j = -0.8550748140498466*_d_D__j - _x154
            _d_iF2__j = _d_P2__j*_pd__32 + _d_Q2__j*_pd__33 + _d_isigma2__j*_pd__34 + _pd__35*d_k_c__j
            _d_isigma3__j = -0.6164556279666497*_d_D__j - _x154
            _d_iF3__j = _d_P3__j*_pd__36 + _d_Q3__j*_pd__37 + _d_isigma3__j*_pd__38 + _pd__39*d_k_c__j
            _d_isigma4__j = -0.31009584357909425*_d_D__j - _x154
            _d_iF4__j = _d_P4__j*_pd__40 + _d_Q4__j*_pd__41 + _d_isigma4__j*_pd__42 + _pd__43*d_k_c__j
            _d_isigma5__j = -0.0663903941688584*_d_D__j - _x154
            _d_iF5__j = _d_P5__j*_pd__44 + _d_Q5__j*_pd__45 + _d_isigma5__j*_pd__46 + _pd__47*d_k_c__j
            _d_iPsi0__j = (0.5871580340658094*_d_iF0__j - 0.140380692261653*_d_iF1__j
                + 0.08683151831711133*_d_iF2__j - 0.052466581536012566*_d_iF3__j
                + 0.026354606039126004*_d_iF4__j - 0.007496884624381081*_d_iF5__j)
            _d_ift0__j = _d_D__j*_pd__48 + _d_iPsi0__j*_pd__49
            _d_ifq0__j = _d_D__j*_pd__50 + _d_P0__j*_pd__51 + _d_iPsi0__j*_pd__52 + _d_isigma0__j*_pd__53
            _d_ifp0__j = _d_D__j*_pd__54 + _d_Q0__j*_pd__55 + _d_iPsi0__j*_pd__56 + _d_isigma0__j*_pd__57
            _d_iPsi1__j = (0.147790320897128*_d_iF0__j + 0.41567911405660357*_d_iF1__j
                - 0.09720828549085844*_d_iF2__j + 0.05155355009455148*_d_iF3__j
                - 0.024719229415033087*_d_iF4__j + 0.006904529857608445*_d_iF5__j)
            _d_ift1__j = _d_D__j*_pd__58 + _d_iPsi1__j*_pd__59
            _d_ifq1__j = _d_D__j*_pd__60 + _d_P1__j*_pd__61 + _d_iPsi1__j*_pd__62 + _d_isigma1__j*_pd__63
            _d_ifp1__j = _d_D__j*_pd__64 + _d_Q1__j*_pd__65 + _d_iPsi1__j*_pd__66 + _d_isigma1__j*_pd__67
            _d_iPsi2__j = (0.010443786721981197*_d_iF0__j + 0.25540525119175433*_d_iF1__j
                + 0.2685463444140672*_d_iF2__j - 0.048794612428541204*_d_iF3__j
                + 0.01951903325298492*_d_iF4__j - 0.005119803152246505*_d_iF5__j)
            _d_ift2__j = _d_D__j*_pd__68 + _d_iPsi2__j*_pd__69
            _d_ifq2__j = _d_D__j*_pd__70 + _d_P2__j*_pd__71 + _d_iPsi2__j*_pd__72 + _d_isigma2__j*_pd__73
            _d_ifp2__j = _d_D__j*_pd__74 + _d_Q2__j*_pd__75 + _d_iPsi2__j*_pd__76 + _d_isigma2__j*_pd__77
            _d_iPsi3__j = (0.01101839635505667*_d_iF0__j + 0.0662099828438604*_d_iF1__j
                + 0.2671819482314443*_d_iF2__j + 0.1742495636223592*_d_iF3__j - 0.02396692958086051*_d_iF4__j
                + 0.00530703852813994*_d_iF5__j)
            _d_ift3__j = _d_D__j*_pd__78 + _d_iPsi3__j*_pd__79
            _d_ifq3__j = _d_D__j*_pd__80 + _d_P3__j*_pd__81 + _d_iPsi3__j*_pd__82 + _d_isigma3__j*_pd__83
            _d_ifp3__j = _d_D__j*_pd__84 + _d_Q3__j*_pd__85 + _d_iPsi3__j*_pd__86 + _d_isigma3__j*_pd__87
            _d_iPsi4__j = (0.0025147977064533143*_d_iF0__j + 0.050345455482979015*_d_iF1__j
                + 0.11622097556712797*_d_iF2__j + 0.2353986790647292*_d_iF3__j + 0.10372825048336794*_d_iF4__j
                - 0.008208158304657426*_d_iF5__j)
            _d_ift4__j = _d_D__j*_pd__88 + _d_iPsi4__j*_pd__89
            _d_ifq4__j = _d_D__j*_pd__90 + _d_P4__j*_pd__91 + _d_iPsi4__j*_pd__92 + _d_isigma4__j*_pd__93
            _d_ifp4__j = _d_D__j*_pd__94 + _d_Q4__j*_pd__95 + _d_iPsi4__j*_pd__96 + _d_isigma4__j*_pd__97
            _d_iPsi5__j = (0.003959513229722528*_d_iF0__j + 0.029703284805013122*_d_iF1__j
                + 0.10140664131431479*_d_iF2__j + 0.14531313573962065*_d_iF3__j
                + 0.17612158869639333*_d_iF4__j + 0.04349583621493557*_d_iF5__j)
            _d_ift5__j = _d_D__j*_pd__98 + _d_iPsi5__j*_pd__99
            _d_ifq5__j = _d_D__j*_pd__100 + _d_P5__j*_pd__101 + _d_iPsi5__j*_pd__102 + _d_isigma5__j*_pd__103
            _d_ifp5__j = _d_D__j*_pd__104 + _d_Q5__j*_pd__105 + _d_iPsi5__j*_pd__106 + _d_isigma5__j*_pd__107
            _T[21, _j1] = _d_isigma0__j
            _T[22, _j1] = _d_iF0__j
            _T[23, _j1] = _d_isigma1__j
            _T[24, _j1] = _d_iF1__j
            _T[25, _j1] = _d_isigma2__j
            _T[26, _j1] = _d_iF2__j
            _T[27, _j1] = _d_isigma3__j
            _T[28, _j1] = _d_iF3__j
            _T[29, _j1] = _d_isigma4__j
            _T[30, _j1] = _d_iF4__j
            _T[31, _j1] = _d_isigma5__j
            _T[32, _j1] = _d_iF5__j
            _T[33, _j1] = _d_ift0__j
            _T[34, _j1] = _d_ifq0__j
            _T[35, _j1] = _d_ifp0__j
            _T[36, _j1] = _d_ift1__j
            _T[37, _j1] = _d_ifq1__j
            _T[38, _j1] = _d_ifp1__j
            _T[39, _j1] = _d_ift2__j
            _T[40, _j1] = _d_ifq2__j
            _T[41, _j1] = _d_ifp2__j
            _T[42, _j1] = _d_ift3__j
            _T[43, _j1] = _d_ifq3__j
            _T[44, _j1] = _d_ifp3__j
            _T[45, _j1] = _d_ift4__j
            _T[46, _j1] = _d_ifq4__j
            _T[47, _j1] = _d_ifp4__j
            _T[48, _j1] = _d_ift5__j
            _T[49, _j1] = _d_ifq5__j
            _T[50, _j1] = _d_ifp5__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x155 = m*q_rd**2
        _x156 = -q_r
        _x157 = k_c*(_x156 + l0)
        _x158 = -l0
        _x159 = -_isigma0 - _x158
        _x160 = 0.005784813099631875*k_c
        _x161 = -_isigma1 - _x158
        _x162 = 0.06111131733618721*k_c
        _x163 = -_isigma2 - _x158
        _x164 = 0.17813034617398463*k_c
        _x165 = -_isigma3 - _x158
        _x166 = 0.28978358839870644*k_c
        _x167 = -_isigma4 - _x158
        _x168 = 0.2996502557119514*k_c
        _x169 = -_isigma5 - _x158
        _x170 = 0.16553967927953847*k_c
        _x171 = (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2
            + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 + _x157
            - _x159*_x160 - _x161*_x162 - _x163*_x164 - _x165*_x166 - _x167*_x168 - _x169*_x170)
        _x172 = math.sqrt(_x155*k_c + _x171**2)
        _x173 = _x171 + _x172
        _x174 = (1.0/_x173)
        _D__next = _x155*_x174
        _x175 = _x159*k_c
        _x176 = _x161*k_c
        _x177 = _x163*k_c
        _x178 = _x165*k_c
        _x179 = _x167*k_c
        _x180 = _x169*k_c
        _x181 = (1.0/_x172)
        _x182 = _x174**2
        _x183 = _x155*_x182
        _pd__108 = (_x183*(-_x181*(3.346406259767255e-05*_iF0 + 0.0003535175490621363*_iF1
            + 0.0010304507599892272*_iF2 + 0.0016763438982271685*_iF3 + 0.001733420724550538*_iF4
            + 0.0009576161052051336*_iF5 + 0.005784813099631875*_x157 - 3.346406259767255e-05*_x175
            - 0.0003535175490621363*_x176 - 0.0010304507599892272*_x177 - 0.0016763438982271685*_x178
            - 0.001733420724550538*_x179 - 0.0009576161052051336*_x180) - 0.005784813099631875))
        _pd__109 = (_x183*(-_x181*(0.0003535175490621363*_iF0 + 0.003734593106564175*_iF1
            + 0.010885780112243256*_iF2 + 0.017709056829452403*_iF3 + 0.018312021866682706*_iF4
            + 0.010116347872182529*_iF5 + 0.06111131733618721*_x157 - 0.0003535175490621363*_x175
            - 0.003734593106564175*_x176 - 0.010885780112243256*_x177 - 0.017709056829452403*_x178
            - 0.018312021866682706*_x179 - 0.010116347872182529*_x180) - 0.06111131733618721))
        _pd__110 = (_x183*(-_x181*(0.0010304507599892272*_iF0 + 0.010885780112243256*_iF1
            + 0.0317304202280636*_iF2 + 0.05161925091700105*_iF3 + 0.05337680378109292*_iF4
            + 0.02948764037559458*_iF5 + 0.17813034617398463*_x157 - 0.0010304507599892272*_x175
            - 0.010885780112243256*_x176 - 0.0317304202280636*_x177 - 0.05161925091700105*_x178
            - 0.05337680378109292*_x179 - 0.02948764037559458*_x180) - 0.17813034617398463))
        _pd__111 = (_x183*(-_x181*(0.0016763438982271685*_iF0 + 0.017709056829452403*_iF1
            + 0.05161925091700105*_iF2 + 0.0839745281052309*_iF3 + 0.08683372636479925*_iF4
            + 0.04797068228399565*_iF5 + 0.28978358839870644*_x157 - 0.0016763438982271685*_x175
            - 0.017709056829452403*_x176 - 0.05161925091700105*_x177 - 0.0839745281052309*_x178
            - 0.08683372636479925*_x179 - 0.04797068228399565*_x180) - 0.28978358839870644))
        _pd__112 = (_x183*(-_x181*(0.001733420724550538*_iF0 + 0.018312021866682706*_iF1
            + 0.05337680378109292*_iF2 + 0.08683372636479925*_iF3 + 0.08979027574823786*_iF4
            + 0.04960400722658813*_iF5 + 0.2996502557119514*_x157 - 0.001733420724550538*_x175
            - 0.018312021866682706*_x176 - 0.05337680378109292*_x177 - 0.08683372636479925*_x178
            - 0.08979027574823786*_x179 - 0.04960400722658813*_x180) - 0.2996502557119514))
        _pd__113 = (_x183*(-_x181*(0.0009576161052051336*_iF0 + 0.010116347872182529*_iF1
            + 0.02948764037559458*_iF2 + 0.04797068228399565*_iF3 + 0.04960400722658813*_iF4
            + 0.027403385415972457*_iF5 + 0.16553967927953847*_x157 - 0.0009576161052051336*_x175
            - 0.010116347872182529*_x176 - 0.02948764037559458*_x177 - 0.04797068228399565*_x178
            - 0.04960400722658813*_x179 - 0.027403385415972457*_x180) - 0.16553967927953847))
        _x184 = _x171*_x181
        _pd__114 = _x183*(-_x160*_x184 - _x160)
        _pd__115 = _x183*(-_x162*_x184 - _x162)
        _pd__116 = _x183*(-_x164*_x184 - _x164)
        _pd__117 = _x183*(-_x166*_x184 - _x166)
        _pd__118 = _x183*(-_x168*_x184 - _x168)
        _pd__119 = _x183*(-_x170*_x184 - _x170)
        _x185 = 2.0*q_r
        _pd__120 = (_x183*(-0.005784813099631875*_isigma0 - 0.06111131733618721*_isigma1
            - 0.17813034617398463*_isigma2 - 0.28978358839870644*_isigma3 - 0.2996502557119514*_isigma4
            - 0.16553967927953847*_isigma5 - _x156 - _x181*((0.5)*_x155
            + (0.5)*_x171*(0.01156962619926375*_isigma0 + 0.12222263467237442*_isigma1
            + 0.35626069234796925*_isigma2 + 0.5795671767974129*_isigma3 + 0.5993005114239028*_isigma4
            + 0.33107935855907694*_isigma5 - _x185 - 1.164670302474663e-21*l0)) + 5.823351512373315e-22*l0))
        _pd__121 = _x183*(_x184*k_c + k_c)
        _pd__122 = 2.0*_x174*m*q_rd - _x181*_x182*k_c*m**2*q_rd**3
        _Q0__next = (0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2
            + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th)
        _Q1__next = (-0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2
            + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th)
        _Q2__next = (0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2
            + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th)
        _Q3__next = (-0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2
            + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th)
        _Q4__next = (0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2
            - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th)
        _Q5__next = (-0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2
            + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _x186 = m*q_r**2
        _x187 = _x186*q_thd
        _P0__next = (0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2
            + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + _x187)
        _x188 = _x185*m*q_thd
        _pd__123 = _x188
        _pd__124 = _x186
        _P1__next = (-0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2
            + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + _x187)
        _pd__125 = _x188
        _pd__126 = _x186
        _P2__next = (0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2
            + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + _x187)
        _pd__127 = _x188
        _pd__128 = _x186
        _P3__next = (-0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2
            + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + _x187)
        _pd__129 = _x188
        _pd__130 = _x186
        _P4__next = (0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2
            - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + _x187)
        _pd__131 = _x188
        _pd__132 = _x186
        _P5__next = (-0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2
            + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + _x187)
        _pd__133 = _x188
        _pd__134 = _x186
        # the next state's tangents, once per direction
        for _j2 in range(6):
            d_k_c__j = _T[3, _j2]
            d_q_r__j = _T[4, _j2]
            d_q_rd__j = _T[5, _j2]
            d_q_th__j = _T[6, _j2]
            d_q_thd__j = _T[7, _j2]
            _d_isigma0__j = _T[21, _j2]
            _d_iF0__j = _T[22, _j2]
            _d_isigma1__j = _T[23, _j2]
            _d_iF1__j = _T[24, _j2]
            _d_isigma2__j = _T[25, _j2]
            _d_iF2__j = _T[26, _j2]
            _d_isigma3__j = _T[27, _j2]
            _d_iF3__j = _T[28, _j2]
            _d_isigma4__j = _T[29, _j2]
            _d_iF4__j = _T[30, _j2]
            _d_isigma5__j = _T[31, _j2]
            _d_iF5__j = _T[32, _j2]
            _d_ifq0__j = _T[34, _j2]
            _d_ifp0__j = _T[35, _j2]
            _d_ifq1__j = _T[37, _j2]
            _d_ifp1__j = _T[38, _j2]
            _d_ifq2__j = _T[40, _j2]
            _d_ifp2__j = _T[41, _j2]
            _d_ifq3__j = _T[43, _j2]
            _d_ifp3__j = _T[44, _j2]
            _d_ifq4__j = _T[46, _j2]
            _d_ifp4__j = _T[47, _j2]
            _d_ifq5__j = _T[49, _j2]
            _d_ifp5__j = _T[50, _j2]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__108 + _d_iF1__j*_pd__109 + _d_iF2__j*_pd__110 + _d_iF3__j*_pd__111
                + _d_iF4__j*_pd__112 + _d_iF5__j*_pd__113 + _d_isigma0__j*_pd__114 + _d_isigma1__j*_pd__115
                + _d_isigma2__j*_pd__116 + _d_isigma3__j*_pd__117 + _d_isigma4__j*_pd__118
                + _d_isigma5__j*_pd__119 + _pd__120*d_k_c__j + _pd__121*d_q_r__j + _pd__122*d_q_rd__j)
            _d_Q0__next__j = (0.04283112309479259*_d_ifq0__j + 0.19514451252126672*_d_ifq1__j
                + 0.22463191657986778*_d_ifq2__j + 0.23962582533582905*_d_ifq3__j
                + 0.17752635320896998*_d_ifq4__j + 0.08647502636084993*_d_ifq5__j + d_q_th__j)
            _d_Q1__next__j = (-0.007011245240793691*_d_ifq0__j + 0.09019039326203465*_d_ifq1__j
                + 0.2542570695795851*_d_ifq2__j + 0.2235938110460991*_d_ifq3__j
                + 0.18526797945210696*_d_ifq4__j + 0.08430668513410011*_d_ifq5__j + d_q_th__j)
            _d_Q2__next__j = (0.0034143235767412987*_d_ifq0__j - 0.0156513758091757*_d_ifq1__j
                + 0.11697848364317276*_d_ifq2__j + 0.25443949503200164*_d_ifq3__j
                + 0.17239079462440696*_d_ifq4__j + 0.0877378719744515*_d_ifq5__j + d_q_th__j)
            _d_Q3__next__j = (-0.002075625784866334*_d_ifq0__j + 0.007989991899662336*_d_ifq1__j
                - 0.020482527745656096*_d_ifq2__j + 0.11697848364317276*_d_ifq3__j
                + 0.196032162333245*_d_ifq4__j + 0.08224792261284387*_d_ifq5__j + d_q_th__j)
            _d_Q4__next__j = (0.0013555610554850618*_d_ifq0__j - 0.004887192928037671*_d_ifq1__j
                + 0.010363156240246424*_d_ifq2__j - 0.020300102293239586*_d_ifq3__j
                + 0.09019039326203465*_d_ifq4__j + 0.09267349143037887*_d_ifq5__j + d_q_th__j)
            _d_Q5__next__j = (-0.0008127801712647621*_d_ifq0__j + 0.002854433315099335*_d_ifq1__j
                - 0.005668858049483512*_d_ifq2__j + 0.009325050706477751*_d_ifq3__j
                - 0.014763725997197413*_d_ifq4__j + 0.04283112309479259*_d_ifq5__j + d_q_th__j)
            _d_P0__next__j = (0.04283112309479259*_d_ifp0__j + 0.19514451252126672*_d_ifp1__j
                + 0.22463191657986778*_d_ifp2__j + 0.23962582533582905*_d_ifp3__j
                + 0.17752635320896998*_d_ifp4__j + 0.08647502636084993*_d_ifp5__j + _pd__123*d_q_r__j
                + _pd__124*d_q_thd__j)
            _d_P1__next__j = (-0.007011245240793691*_d_ifp0__j + 0.09019039326203465*_d_ifp1__j
                + 0.2542570695795851*_d_ifp2__j + 0.2235938110460991*_d_ifp3__j
                + 0.18526797945210696*_d_ifp4__j + 0.08430668513410011*_d_ifp5__j + _pd__125*d_q_r__j
                + _pd__126*d_q_thd__j)
            _d_P2__next__j = (0.0034143235767412987*_d_ifp0__j - 0.0156513758091757*_d_ifp1__j
                + 0.11697848364317276*_d_ifp2__j + 0.25443949503200164*_d_ifp3__j
                + 0.17239079462440696*_d_ifp4__j + 0.0877378719744515*_d_ifp5__j + _pd__127*d_q_r__j
                + _pd__128*d_q_thd__j)
            _d_P3__next__j = (-0.002075625784866334*_d_ifp0__j + 0.007989991899662336*_d_ifp1__j
                - 0.020482527745656096*_d_ifp2__j + 0.11697848364317276*_d_ifp3__j
                + 0.196032162333245*_d_ifp4__j + 0.08224792261284387*_d_ifp5__j + _pd__129*d_q_r__j
                + _pd__130*d_q_thd__j)
            _d_P4__next__j = (0.0013555610554850618*_d_ifp0__j - 0.004887192928037671*_d_ifp1__j
                + 0.010363156240246424*_d_ifp2__j - 0.020300102293239586*_d_ifp3__j
                + 0.09019039326203465*_d_ifp4__j + 0.09267349143037887*_d_ifp5__j + _pd__131*d_q_r__j
                + _pd__132*d_q_thd__j)
            _d_P5__next__j = (-0.0008127801712647621*_d_ifp0__j + 0.002854433315099335*_d_ifp1__j
                - 0.005668858049483512*_d_ifp2__j + 0.009325050706477751*_d_ifp3__j
                - 0.014763725997197413*_d_ifp4__j + 0.04283112309479259*_d_ifp5__j + _pd__133*d_q_r__j
                + _pd__134*d_q_thd__j)
            _T[8, _j2] = _d_D__next__j
            _T[9, _j2] = _d_Q0__next__j
            _T[10, _j2] = _d_Q1__next__j
            _T[11, _j2] = _d_Q2__next__j
            _T[12, _j2] = _d_Q3__next__j
            _T[13, _j2] = _d_Q4__next__j
            _T[14, _j2] = _d_Q5__next__j
            _T[15, _j2] = _d_P0__next__j
            _T[16, _j2] = _d_P1__next__j
            _T[17, _j2] = _d_P2__next__j
            _T[18, _j2] = _d_P3__next__j
            _T[19, _j2] = _d_P4__next__j
            _T[20, _j2] = _d_P5__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _Q4__next
        _n0_6 = _Q5__next
        _n0_7 = _P0__next
        _n0_8 = _P1__next
        _n0_9 = _P2__next
        _n0_10 = _P3__next
        _n0_11 = _P4__next
        _n0_12 = _P5__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8
            - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    _x189 = -_D + q_r
    end_q_r = _x189
    end_q_rd = 0.0
    _x190 = q_r**2
    _x191 = (0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x190*m*q_thd)
    _x198 = (1.0/_x189)
    _x192 = _x198**2
    _x193 = (1.0/m)
    _x194 = _x192*_x193
    end_q_thd = _x191*_x194
    _x195 = 0.08566224618958518*_x194
    _pd__135 = _x195
    _x196 = 0.1803807865240693*_x194
    _pd__136 = _x196
    _x197 = 0.23395696728634552*_x194
    _pd__137 = _x197
    _pd__138 = _x197
    _pd__139 = _x196
    _pd__140 = _x195
    _pd__141 = -2.0*_x191*_x193*_x198**3
    _pd__142 = 2.0*_x192*q_r*q_thd
    _pd__143 = _x190*_x192
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN42 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j3 in range(6):
        d_q_r__j = _T[4, _j3]
        d_q_th__j = _T[6, _j3]
        d_q_thd__j = _T[7, _j3]
        _d_D__j = _T[8, _j3]
        _d_ift0__j = _T[33, _j3]
        _d_ifq0__j = _T[34, _j3]
        _d_ifp0__j = _T[35, _j3]
        _d_ift1__j = _T[36, _j3]
        _d_ifq1__j = _T[37, _j3]
        _d_ifp1__j = _T[38, _j3]
        _d_ift2__j = _T[39, _j3]
        _d_ifq2__j = _T[40, _j3]
        _d_ifp2__j = _T[41, _j3]
        _d_ift3__j = _T[42, _j3]
        _d_ifq3__j = _T[43, _j3]
        _d_ifp3__j = _T[44, _j3]
        _d_ift4__j = _T[45, _j3]
        _d_ifq4__j = _T[46, _j3]
        _d_ifp4__j = _T[47, _j3]
        _d_ift5__j = _T[48, _j3]
        _d_ifq5__j = _T[49, _j3]
        _d_ifp5__j = _T[50, _j3]
        # bottom state
        d_t_half__j = (0.08566224618958518*_d_ift0__j + 0.1803807865240693*_d_ift1__j
            + 0.23395696728634552*_d_ift2__j + 0.23395696728634552*_d_ift3__j + 0.1803807865240693*_d_ift4__j
            + 0.08566224618958518*_d_ift5__j)
        d_end_q_th__j = (0.08566224618958518*_d_ifq0__j + 0.1803807865240693*_d_ifq1__j
            + 0.23395696728634552*_d_ifq2__j + 0.23395696728634552*_d_ifq3__j + 0.1803807865240693*_d_ifq4__j
            + 0.08566224618958518*_d_ifq5__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__135 + _d_ifp1__j*_pd__136 + _d_ifp2__j*_pd__137
            + _d_ifp3__j*_pd__138 + _d_ifp4__j*_pd__139 + _d_ifp5__j*_pd__140 + _pd__141*d_end_q_r__j
            + _pd__142*d_q_r__j + _pd__143*d_q_thd__j)
        _T[51, _j3] = d_t_half__j
        _T[52, _j3] = d_end_q_th__j
        _T[53, _j3] = d_end_q_r__j
        _T[54, _j3] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[51, 0], _T[51, 1],
        _T[51, 2], _T[51, 3], _T[51, 4], _T[51, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[52, 0],
        _T[52, 1], _T[52, 2], _T[52, 3], _T[52, 4], _T[52, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[53, 0],
        _T[53, 1], _T[53, 2], _T[53, 3], _T[53, 4], _T[53, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[54, 0], _T[54, 1], _T[54, 2], _T[54, 3], _T[54, 4], _T[54, 5], )
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, iterations, tol):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer` (another
    choice of the same kernel).
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not _inputs_valid_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN77 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6_jvp6_a742c3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        z_b_q_r, z_b_q_th, z_b_q_thd, iterations, tol, _j_z_b_q_r__q_r_td, _j_z_b_q_th__q_r_td,
        _j_z_b_q_thd__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_thd__q_rd_td,
        _j_z_b_q_r__q_th_td, _j_z_b_q_th__q_th_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_th__q_thd_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_r__k_c, _j_z_b_q_th__k_c, _j_z_b_q_thd__k_c,
        _j_z_b_q_r__k_d, _j_z_b_q_th__k_d, _j_z_b_q_thd__k_d))
    if _c1[42] != STATUS_OK:
        return _NAN77 + (_c1[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c1
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # decompression half, k_d (report 3.2, 5.2.2)
    _c2 = (schwind_decompression_nodes_6_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r,
        bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, iterations,
        tol))
    if _c2[42] != STATUS_OK:
        return _NAN77 + (_c2[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c2
    # the code shared between choices
    return (iterative_stance_jacobian_tail_ad0cfd(_j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd,
        _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_thd__guess_q_th,
        _j_liftoff_q_thd__guess_q_thd, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th,
        _j_liftoff_q_thd__q_thd, _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd,
        _j_t_decompression__k_d, _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd,
        _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_bottom_q_r__k_c, d_bottom_q_r__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_passes, d_t_bottom__k_c, d_t_bottom__k_d, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_bottom, t_decompression))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_nodes_6_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian_nodes_6_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_stance_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian_nodes_6_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, iterations, tol))
        _store_row_11_77(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Arguments, returns and status: those of :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer`
    (another choice of the same kernel).
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not _inputs_valid_3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
            iterations, tol):
        return _NAN91 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN91 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian_nodes_6_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, iterations, tol))
    if _c1[77] != STATUS_OK:
        return _NAN91 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # the code shared between choices
    return (iterative_apex_return_jacobian_tail_03c072(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_nodes_6_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian_nodes_6_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_apex_return_jacobian_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian_nodes_6_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, iterations, tol))
        _store_row_13_91(out, status, i, res)
