# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer.py sha256:110e83efcc6593e2
#   geyer_vs.py sha256:ef01b987d9b927b3
#   gravity.py sha256:a143b1a44c6e8a1e
#   gravity_type5.py sha256:bbb19eaf7f21c7a4
# ----------------------------------------------------------------------------------------------
"""Iterative stance map (Schwind and Koditschek, converging form) (report section 5.2): stance, state-at-time
and apex-return kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_stance
from .geyer_vs import geyer_vs_stance
from .gravity import (gravity_type0_stance, gravity_type1_stance, gravity_type2_stance, gravity_type3_stance,
    gravity_type4_stance)
from .gravity_type5 import gravity_type5_stance

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED,
    STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_L447fd80c = (np.array([[0.5, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.2113248654051871,
    0.7886751345948129, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.11270166537925831, 0.5,
    0.8872983346207417, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.06943184420297371,
    0.33000947820757187, 0.6699905217924281, 0.9305681557970263, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [0.03376524289842399, 0.16939530676686773, 0.38069040695840156, 0.6193095930415985, 0.8306046932331322,
    0.966234757101576, NAN, NAN, NAN, NAN, NAN, NAN]]))
_L62015774 = (np.array([[0.5, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.10566243270259355,
    0.39433756729740643, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.031306018160905086,
    0.2222222222222222, 0.2464717596168727, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [0.012076101706416622, 0.1076070411358925, 0.21846553629538057, 0.1618513208623103, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [0.0028924065498159377, 0.030555658668093604, 0.08906517308699231,
    0.14489179419935322, 0.1498251278559757, 0.08276983963976924, NAN, NAN, NAN, NAN, NAN, NAN]]))
_L893379fc = np.array([1.0, 2.0, 3.0, 4.0, 6.0])
_L8c0ca55d = (np.array([[[0.125, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]], [[0.025053438573519, -0.0027243392042587762, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN], [0.14161322809314766, 0.16939100587092545, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN]], [[0.00731967574711921, -0.001321667095802785, 0.00035282403831273087, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN], [0.044256828793107064, 0.09027777777777778, -0.009534606570884839, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.02186939818390949, 0.2568772226513583, 0.114902546475103, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]],
    [[0.002807497692530926, -0.0005969793910899821, 0.0002776281192879446, -7.775592601588144e-05, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN], [0.017426022281302224, 0.04274835944290935, -0.007624461782129112,
    0.0019032079113344635, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.00724380902321293, 0.1278630079562343,
    0.09817760702265338, -0.00884077435625554, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.015553495466196424,
    0.09525720656577571, 0.24447273698928937, 0.07769510727047776, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]],
    [[0.0006694139589452448, -0.00016004685197889103, 9.899588707896176e-05, -5.981671035844016e-05,
    3.0046665704170957e-05, -8.547135396260614e-06, NAN, NAN, NAN, NAN, NAN, NAN], [0.004240809259665694,
    0.011927816552803313, -0.002789369389845272, 0.0014793172603082274, -0.0007093126015203751,
    0.00019812389590902608, NAN, NAN, NAN, NAN, NAN, NAN], [0.001513567732706868, 0.03701465352161063,
    0.03891912890044263, -0.0070715682795719995, 0.002828799523756067, -0.0007419884238675063, NAN, NAN, NAN,
    NAN, NAN, NAN], [0.004226043910814766, 0.025394466292187334, 0.10247613255307642, 0.06683243945662308,
    -0.009192380955658672, 0.002035484759632229, NAN, NAN, NAN, NAN, NAN, NAN], [0.0017349693902399023,
    0.0347335389946109, 0.08018133410705412, 0.16240252710274752, 0.07156255114674437, -0.005662842530943934,
    NAN, NAN, NAN, NAN, NAN, NAN], [0.0036966395856844396, 0.02773127201869844, 0.09467421442611738,
    0.1356657393799544, 0.16442880700119422, 0.040608130503921896, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]]]))
_Lac198189 = (np.array([[[0.5, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]], [[0.25, -0.03867513459481288, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN], [0.5386751345948129, 0.25, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]],
    [[0.1388888888888889, -0.0359766675249389, 0.009789444015308325, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN], [0.30026319498086457, 0.2222222222222222, -0.022485417203086815, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN], [0.26798833376246944, 0.48042111196938336, 0.1388888888888889, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]], [[0.08696371128436346, -0.026604180084998794,
    0.012627462689404725, -0.0035551496857956833, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [0.18811811749986806, 0.16303628871563652, -0.027880428602470895, 0.006735500594538156, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN], [0.16719192197418878, 0.35395300603374397, 0.16303628871563652,
    -0.014190694931141144, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.1774825722545226, 0.31344511474186837,
    0.35267675751627187, 0.08696371128436346, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN],
    [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN]], [[0.04283112309479259,
    -0.014763725997197413, 0.009325050706477751, -0.005668858049483512, 0.002854433315099335,
    -0.0008127801712647621, NAN, NAN, NAN, NAN, NAN, NAN], [0.09267349143037887, 0.09019039326203465,
    -0.020300102293239586, 0.010363156240246424, -0.004887192928037671, 0.0013555610554850618, NAN, NAN, NAN,
    NAN, NAN, NAN], [0.08224792261284387, 0.196032162333245, 0.11697848364317276, -0.020482527745656096,
    0.007989991899662336, -0.002075625784866334, NAN, NAN, NAN, NAN, NAN, NAN], [0.0877378719744515,
    0.17239079462440696, 0.25443949503200164, 0.11697848364317276, -0.0156513758091757, 0.0034143235767412987,
    NAN, NAN, NAN, NAN, NAN, NAN], [0.08430668513410011, 0.18526797945210696, 0.2235938110460991,
    0.2542570695795851, 0.09019039326203465, -0.007011245240793691, NAN, NAN, NAN, NAN, NAN, NAN],
    [0.08647502636084993, 0.17752635320896998, 0.23962582533582905, 0.22463191657986778, 0.19514451252126672,
    0.04283112309479259, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN,
    NAN]]]))
_Lbacdd133 = (np.array([[1.0, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.5, 0.5, NAN, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.2777777777777778, 0.4444444444444444, 0.2777777777777778, NAN,
    NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.17392742256872692, 0.32607257743127305, 0.32607257743127305,
    0.17392742256872692, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN], [0.08566224618958518, 0.1803807865240693,
    0.23395696728634552, 0.23395696728634552, 0.1803807865240693, 0.08566224618958518, NAN, NAN, NAN, NAN,
    NAN, NAN]]))
_NAN5 = (NAN,) * 5
_NAN6 = (NAN,) * 6
_NAN11 = (NAN,) * 11


@njit(cache=True, error_model="numpy")
def schwind_compression(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, c, guess_q_r, guess_q_th, guess_q_thd, nodes,
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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        guess_q_r: zeroth iterate's bottom q_r
        guess_q_th: zeroth iterate's bottom q_th
        guess_q_thd: zeroth iterate's bottom q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
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
    # Total ops: 59
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, c, guess_q_r, guess_q_th, guess_q_thd, nodes,
            iterations, tol,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0))
            & ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            & ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # node arrays (the nodes' values of a collocation), on the stack
    (Q0, P0, Psr0, Q, P, Psr, sigma, F, sinQ, ft, fq, fp, Psi, G, Q_next, P_next, Shape,
        ) = (node_arrays(stack(204), 17, 12))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # the Gauss-Legendre rule of the node count: nodes u, weights, integration matrices
    _code = int(nodes)
    if not (_code == 0 or _code == 1 or _code == 2 or _code == 3 or _code == 4):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    nq = _L893379fc[_code]
    u = _L447fd80c[_code]
    w = _Lbacdd133[_code]
    w1 = _L62015774[_code]
    S = _Lac198189[_code]
    S1 = _L8c0ca55d[_code]
    # the zeroth iterate at the nodes
    for _j1000 in range(6):
        if _j1000 >= nq:
            break
        _u = u[_j1000]
        Q0[_j1000] = _u*(-guess_q_th + q_th) + guess_q_th
        P0[_j1000] = _u*(-guess_q_r**2*guess_q_thd*m + m*q_r**2*q_thd) + guess_q_r**2*guess_q_thd*m
    # Psi at the nodes, zeroth iterate
    for _j1002 in range(6):
        if _j1002 >= nq:
            break
        Psr0[_j1002] = 1.0
    # Picard passes on the node values (collocation in u)
    for _j1018 in range(6):
        if _j1018 >= nq:
            break
        Q[_j1018] = Q0[_j1018]
        P[_j1018] = P0[_j1018]
        Psr[_j1018] = Psr0[_j1018]
    _D = -guess_q_r + q_r
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values of the pass: sigma, F_r (29) and the damper's force, sin Q
        for _j1004 in range(6):
            if _j1004 >= nq:
                break
            _Qj = Q[_j1004]
            _Pj = P[_j1004]
            _u = u[_j1004]
            _Psr = Psr[_j1004]
            _x0 = _D*_u**2 - _D + q_r
            _sigma = _x0
            _F = _Pj**2/(_x0**3*m) - _x0*k_c - g_s*m*math.cos(_Qj) + k_c*l0
            _sinQ = math.sin(_Qj)
            sigma[_j1004] = _sigma
            F[_j1004] = _F - math.sqrt(_Psr)*_u*c*q_rd
            sinQ[_j1004] = _sinQ
        # Psi and the u-rates of (30)-(32) at the nodes
        for _j1006 in range(6):
            if _j1006 >= nq:
                break
            _Qj = Q[_j1006]
            _Pj = P[_j1006]
            _u = u[_j1006]
            _sigma = sigma[_j1006]
            _sinQ = sinQ[_j1006]
            _S1F = 0.0
            for _j1007 in range(6):
                if _j1007 >= nq:
                    break
                _S1F += S1[_j1006, _j1007]*F[_j1007]
            _x1 = _S1F/_u**2
            _x2 = math.sqrt(m)
            _x3 = math.sqrt(_D)/math.sqrt(_x1)
            _Psi = _x1
            _ft = _x2*_x3
            _fq = _Pj*_x3/(_sigma**2*_x2)
            _fp = _sigma*_sinQ*_x3*g_s*(m*math.sqrt(m))
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_Psi > 0.0)):
                return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
            ft[_j1006] = _ft
            fq[_j1006] = _fq
            fp[_j1006] = _fp
            Psi[_j1006] = _Psi
        if _conv0 or _it0 == _last0:
            break
        _wfq = 0.0
        _wfp = 0.0
        for _j1008 in range(6):
            if _j1008 >= nq:
                break
            _wfq += w[_j1008]*fq[_j1008]
            _wfp += w[_j1008]*fp[_j1008]
        # F_r minus its spring term
        for _j1010 in range(6):
            if _j1010 >= nq:
                break
            _F = F[_j1010]
            _sigma = sigma[_j1010]
            G[_j1010] = _F - k_c*(-_sigma + l0)
        _rbar = 0.0
        _Wpass = 0.0
        for _j1012 in range(6):
            if _j1012 >= nq:
                break
            _rbar += w1[_j1012]*G[_j1012]
            _Wpass += w1[_j1012]*F[_j1012]
        # the next iterate at the nodes
        for _j1014 in range(6):
            if _j1014 >= nq:
                break
            _Sfq = 0.0
            _Sfp = 0.0
            for _j1015 in range(6):
                if _j1015 >= nq:
                    break
                _Sfq += S[_j1014, _j1015]*fq[_j1015]
                _Sfp += S[_j1014, _j1015]*fp[_j1015]
            Q_next[_j1014] = -_Sfq + _wfq + q_th
            P_next[_j1014] = -_Sfp + _wfp + m*q_r**2*q_thd
        # D = q_r_td - q_r_b from the radial work
        _x4 = m*q_rd**2
        _x5 = 2.0*_rbar + k_c*(l0 - q_r)
        _D_next = _x4/(_x5 + math.sqrt(_x4*k_c + _x5**2))
        # the shape Psi/W
        for _j1016 in range(6):
            if _j1016 >= nq:
                break
            _Psi = Psi[_j1016]
            Shape[_j1016] = _Psi/_Wpass
        _n0_0 = _D_next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0))
        for _j1018 in range(6):
            if _j1018 >= nq:
                break
            _conv0 = _conv0 and abs(Q_next[_j1018] - Q[_j1018]) <= tol*(1.0)
            Q[_j1018] = Q_next[_j1018]
            _conv0 = (_conv0 and abs(P_next[_j1018] - P[_j1018]) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
                + m*q_r**2*abs(q_thd)))
            P[_j1018] = P_next[_j1018]
            Psr[_j1018] = Shape[_j1018]
        _D = _n0_0
        _passes += 1.0
    _t_end = 0.0
    _q_end = 0.0
    _p_end = 0.0
    for _j1019 in range(6):
        if _j1019 >= nq:
            break
        _t_end += w[_j1019]*ft[_j1019]
        _q_end += w[_j1019]*fq[_j1019]
        _p_end += w[_j1019]*fp[_j1019]
    # bottom state
    _x6 = -_D + q_r
    t_half = _t_end
    end_q_th = _q_end + q_th
    end_q_r = _x6
    end_q_thd = (_p_end + m*q_r**2*q_thd)/(_x6**2*m)
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_th, end_q_thd, passes,))):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, 0.0, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, c, guess_q_th, guess_q_thd, nodes,
        iterations, tol, liftoff):
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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        guess_q_th: zeroth iterate's liftoff q_th
        guess_q_thd: zeroth iterate's liftoff q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Returns a tuple:
        t_half: time of the decompression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 100
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, c, guess_q_th, guess_q_thd, nodes,
            iterations, tol, liftoff,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((c >= 0.0)) & ((nodes == 0.0) or (nodes == 1.0) or (nodes
            == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0) and (tol <= 1.0)) & ((liftoff
            == 0.0) or (liftoff == 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # node arrays (the nodes' values of a collocation), on the stack
    (Q0, P0, Psr0, Q, P, Psr, sigma, F, sinQ, ft, fq, fp, Psi, Q_next, P_next,) = (node_arrays(stack(180), 15,
        12))
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN6 + (STATUS_RECOMPRESSION,)
    # the Gauss-Legendre rule of the node count: nodes u, weights, integration matrices
    _code = int(nodes)
    if not (_code == 0 or _code == 1 or _code == 2 or _code == 3 or _code == 4):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    nq = _L893379fc[_code]
    u = _L447fd80c[_code]
    w = _Lbacdd133[_code]
    w1 = _L62015774[_code]
    S = _Lac198189[_code]
    S1 = _L8c0ca55d[_code]
    # the zeroth iterate at the nodes
    for _j1000 in range(6):
        if _j1000 >= nq:
            break
        _u = u[_j1000]
        Q0[_j1000] = _u*(guess_q_th - q_th) + q_th
        P0[_j1000] = _u*(guess_q_thd*m*q_r_lo**2 - m*q_r**2*q_thd) + m*q_r**2*q_thd
    # Psi at the nodes, zeroth iterate
    for _j1002 in range(6):
        if _j1002 >= nq:
            break
        Psr0[_j1002] = -0.5*g_s*m*math.cos(q_th) + (0.5)*k_d*l0 - 0.5*k_d*q_r + (0.5)*m*q_r*q_thd**2
    # Picard passes on the node values (collocation in u)
    for _j1013 in range(6):
        if _j1013 >= nq:
            break
        Q[_j1013] = Q0[_j1013]
        P[_j1013] = P0[_j1013]
        Psr[_j1013] = Psr0[_j1013]
    _D = -q_r + q_r_lo
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN6 + (STATUS_NOT_CONVERGED,)
        # node values of the pass: sigma, F_r (29) and the damper's force, sin Q
        for _j1004 in range(6):
            if _j1004 >= nq:
                break
            _Qj = Q[_j1004]
            _Pj = P[_j1004]
            _u = u[_j1004]
            _Psr = Psr[_j1004]
            _x0 = _D*_u**2 + q_r
            _sigma = _x0
            _F = _Pj**2/(_x0**3*m) - _x0*k_d - g_s*m*math.cos(_Qj) + k_d*l0
            _sinQ = math.sin(_Qj)
            sigma[_j1004] = _sigma
            F[_j1004] = _F - 2.0*_u*c*math.sqrt(_D*_Psr)/math.sqrt(m)
            sinQ[_j1004] = _sinQ
        # Psi and the u-rates of (30)-(32) at the nodes
        for _j1006 in range(6):
            if _j1006 >= nq:
                break
            _Qj = Q[_j1006]
            _Pj = P[_j1006]
            _u = u[_j1006]
            _sigma = sigma[_j1006]
            _sinQ = sinQ[_j1006]
            _S1F = 0.0
            for _j1007 in range(6):
                if _j1007 >= nq:
                    break
                _S1F += S1[_j1006, _j1007]*F[_j1007]
            _x1 = _S1F/_u**2
            _x2 = math.sqrt(m)
            _x3 = math.sqrt(_D)/math.sqrt(_x1)
            _Psi = _x1
            _ft = _x2*_x3
            _fq = _Pj*_x3/(_sigma**2*_x2)
            _fp = _sigma*_sinQ*_x3*g_s*(m*math.sqrt(m))
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_Psi > 0.0)):
                return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
            ft[_j1006] = _ft
            fq[_j1006] = _fq
            fp[_j1006] = _fp
            Psi[_j1006] = _Psi
        if _conv0 or _it0 == _last0:
            break
        _wfq = 0.0
        _wfp = 0.0
        _Wpass = 0.0
        for _j1008 in range(6):
            if _j1008 >= nq:
                break
            _wfq += w[_j1008]*fq[_j1008]
            _wfp += w[_j1008]*fp[_j1008]
            _Wpass += w1[_j1008]*F[_j1008]
        # the next iterate at the nodes
        for _j1011 in range(6):
            if _j1011 >= nq:
                break
            _Sfq = 0.0
            _Sfp = 0.0
            for _j1012 in range(6):
                if _j1012 >= nq:
                    break
                _Sfq += S[_j1011, _j1012]*fq[_j1012]
                _Sfp += S[_j1011, _j1012]*fp[_j1012]
            Q_next[_j1011] = _Sfq + q_th
            P_next[_j1011] = _Sfp + m*q_r**2*q_thd
        # D = q_r_lo - q_r_b, or to the leg force's zero (liftoff force)
        _x4 = k_d*l0
        _x5 = k_d*q_r
        _x6 = 2.0*math.sqrt(_Wpass)*c/math.sqrt(m)
        _x7 = -q_r_lo
        _x8 = -_x7 - q_r
        _D_next = (((2.0*_x4 - 2.0*_x5)**2/(_x6 + math.sqrt(4.0*_Wpass*c**2/m + 4.0*k_d*(_x4 - _x5)))**2)
            if (liftoff == 0.0) and (_x6*math.sqrt(_x8) - k_d*(_x7 + l0) > 0.0) else (_x8))
        _n0_0 = _D_next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0))
        for _j1013 in range(6):
            if _j1013 >= nq:
                break
            _conv0 = _conv0 and abs(Q_next[_j1013] - Q[_j1013]) <= tol*(1.0)
            Q[_j1013] = Q_next[_j1013]
            _conv0 = (_conv0 and abs(P_next[_j1013] - P[_j1013]) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
                + m*q_r**2*abs(q_thd)))
            P[_j1013] = P_next[_j1013]
            Psr[_j1013] = Psi[_j1013]
        _D = _n0_0
        _passes += 1.0
    _t_end = 0.0
    _q_end = 0.0
    _p_end = 0.0
    _work = 0.0
    for _j1014 in range(6):
        if _j1014 >= nq:
            break
        _t_end += w[_j1014]*ft[_j1014]
        _q_end += w[_j1014]*fq[_j1014]
        _p_end += w[_j1014]*fp[_j1014]
        _work += w1[_j1014]*F[_j1014]
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = _t_end
    end_q_th = _q_end + q_th
    end_q_rd = 2.0*math.sqrt(_D*_work)/math.sqrt(m)
    _lo_q_thd = (_p_end + m*q_r**2*q_thd)/(m*q_r_lo**2)
    passes = _passes
    # liftoff at q_r_lo, or at q_r_b + D short of it
    _x9 = _D + q_r
    _x10 = (_D < -q_r + q_r_lo)
    end_q_r = ((_x9) if _x10 else (q_r_lo))
    end_q_thd = (((_p_end + m*q_r**2*q_thd)/(_x9**2*m)) if _x10 else (_lo_q_thd))
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes,))):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

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

    Returns a tuple:
        z_b_q_r: zeroth iterate: z_b_q_r
        z_b_q_th: zeroth iterate: z_b_q_th
        z_b_q_thd: zeroth iterate: z_b_q_thd
        z_lo_q_th: zeroth iterate: z_lo_q_th
        z_lo_q_thd: zeroth iterate: z_lo_q_thd
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # stance: Geyer et al.'s approximate stance map
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(7), 7)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo,))
    _o0 = carray(stack(10), 10)
    _c0 = geyer_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_core(_a):
    """Schwind and Koditschek's iteration, converging form: the stance from the touchdown state and a zeroth
    iterate.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        z_b_q_r: zeroth iterate: z_b_q_r
        z_b_q_th: zeroth iterate: z_b_q_th
        z_b_q_thd: zeroth iterate: z_b_q_thd
        z_lo_q_th: zeroth iterate: z_lo_q_th
        z_lo_q_thd: zeroth iterate: z_lo_q_thd
        held: 1 when the zeroth iterate is the held touchdown state, else 0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

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
    # Total ops: 15
    (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, c, z_b_q_r, z_b_q_th, z_b_q_thd,
        z_lo_q_th, z_lo_q_thd, held, nodes, iterations, tol, liftoff,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8,
        9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20))
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, c, z_b_q_r, z_b_q_th,
        z_b_q_thd, nodes, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN11 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    c_passes = _c0[5]
    # zeroth iterate at liftoff
    _x0 = (held == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x0 else (z_lo_q_th))
    g_lo_q_thd = ((bottom_q_r**2*bottom_q_thd/q_r_lo**2) if _x0 else (z_lo_q_thd))
    # decompression half, k_d (report 3.2, 5.2.2)
    _c1 = (schwind_decompression(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo,
        c, g_lo_q_th, g_lo_q_thd, nodes, iterations, tol, liftoff))
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
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes,))):
        return _NAN11 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """The zeroth iterate 'held': the touchdown state held, the bottom from the radial work.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 31
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
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_th, z_b_q_thd, 0.0, 0.0, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 0 (leg length l0)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 1.0, 0.0,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type0_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type1_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 2 (average leg length)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type2_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type3_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 4 (average leg length on [t_i, t_f])
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type4_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Gravity correction type 5 (time-varying momentum)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(9), 9)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 100.0, 1e-12,))
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type5_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c.

    Arguments, returns and status: those of :func:`zeroth_geyer`.
    """
    # Total ops: 0
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(12), 12)
    store(_p0, (m, l0, k_c, k_d, g_s, NAN, q_r_td, q_r_lo, 2.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(13), 13)
    _c0 = geyer_vs_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return _NAN5 + (_c0,)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9,) = load(_o0, 2, 4, 5, 8, 9)
    # (internal helper: its callers check that their outputs are finite)
    return (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def iterative_stance_zeroth_shared(x, p, out, zeroth, constant0):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    The body that 9 kernels share, each passing the kernel it calls as zeroth and its constant
    as constant0 (derive/share.py): iterative_stance_zeroth_{geyer, held, gravity_type0,
    gravity_type1, gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth, constant0.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, nodes, iterations, tol, liftoff,) = (load(p, 0, 1, 2, 3, 4, 8, 7, 9, 10,
        11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, nodes,
            iterations, tol, liftoff,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((c >= 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((nodes == 0.0) or (nodes == 1.0) or (nodes
            == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0) and (tol <= 1.0)) & ((liftoff
            == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate (option zeroth)
    _c0 = zeroth(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    z_b_q_r = _c0[0]
    z_b_q_th = _c0[1]
    z_b_q_thd = _c0[2]
    z_lo_q_th = _c0[3]
    z_lo_q_thd = _c0[4]
    # the iteration from the zeroth iterate
    _a1 = carray(stack(21), 21)
    store(_a1, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, c, z_b_q_r, z_b_q_th,
        z_b_q_thd, z_lo_q_th, z_lo_q_thd, constant0, nodes, iterations, tol, liftoff,))
    _c1 = iterative_core(_a1)
    if _c1[11] != STATUS_OK:
        return fail(out, _c1[11])
    t_bottom = _c1[0]
    t_stance = _c1[1]
    bottom_q_r = _c1[2]
    bottom_q_rd = _c1[3]
    bottom_q_th = _c1[4]
    bottom_q_thd = _c1[5]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_geyer(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_geyer, 0.0.

    Converging form of (30)-(45) and (116)-(151): p_r^2 = 2 m int F_r (work form) instead of
    (33); N Gauss-Legendre nodes in u (N = 1 is the mean value (41)); bottom leg length from
    p_r_td^2 = 2 m int F_r.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Writes into out:
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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_geyer, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    The body that 9 kernels share, each passing the kernel it calls as iterative_stance_zeroth
    (derive/share.py): iterative_apex_return_zeroth_{geyer, held, gravity_type0, gravity_type1,
    gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then iterative_stance_zeroth.
    """
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, g_f, q_r_td, q_r_lo, nodes, iterations, tol, liftoff,) = (load(p, 0, 1, 2, 3, 4,
        8, 5, 6, 7, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, c, g_f,
            q_r_td, q_r_lo, nodes, iterations, tol, liftoff,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((c >= 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo
            > 0.0)) & ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            & ((tol >= 0.0) and (tol <= 1.0)) & ((liftoff == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate)
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(11), 11)
    _c1 = iterative_stance_zeroth(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10,) = load(_o1, 1, 6, 7, 8, 9, 10)
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return fail(out, _c2[5])
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    touchdown_q_th = td_q_th
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd,
            liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_geyer(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_geyer.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward
            +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]
        retraction_rate: swing-leg retraction rate: after the apex the leg angle is touchdown_angle +
            retraction_rate * t (counterclockwise positive like the angle: a forward runner's retracting leg
            has a negative rate; Seyfarth, Geyer and Herr 2003); 0 holds the leg at touchdown_angle
            retraction_rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Writes into out:
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
        touchdown_q_th: leg angle the foot touched down with: touchdown_angle + retraction_rate * t_descent
            [rad]
        passes: Picard passes run (the larger of the two halves) [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_geyer)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_held(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_held, 1.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_held, 1.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_held(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_held. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_held)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type0(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type0, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type0, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type0(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type0. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type1(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type1, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type1, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type1(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type1. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type2(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type2, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type2, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type2(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type2. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type3(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type3, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type3, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type3(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type3. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type4(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type4, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type4, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type4(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type4. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type5(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_gravity_type5, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_gravity_type5, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type5(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_gravity_type5. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_gravity_type5)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_zeroth_geyer_vs(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_stance_zeroth_shared` with zeroth_geyer_vs, 0.0.
    Equations, arguments, returns and status: those of :func:`iterative_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_stance_zeroth_shared(x, p, out, zeroth_geyer_vs, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_zeroth_geyer_vs(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_zeroth_geyer_vs(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging
    form).

    Runs the shared body :func:`iterative_apex_return_zeroth_shared` with
    iterative_stance_zeroth_geyer_vs. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_zeroth_shared(x, p, out, iterative_stance_zeroth_geyer_vs)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
