# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
#   geyer_jacobian.py sha256:a1c9347d955c37d0
#   geyer_vs_jacobian.py sha256:9f039010262c20f7
#   gravity_jacobian.py sha256:9448514800b822e7
#   gravity_type5_jacobian.py sha256:7aecd59038dc92eb
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative: JVP kernels, and for a
map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_stance_jacobian
from .geyer_vs_jacobian import geyer_vs_stance_jacobian
from .gravity_jacobian import (gravity_type0_stance_jacobian, gravity_type1_stance_jacobian,
    gravity_type2_stance_jacobian, gravity_type3_stance_jacobian, gravity_type4_stance_jacobian)
from .gravity_type5_jacobian import gravity_type5_stance_jacobian

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


@njit(cache=True, error_model="numpy")
def zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative.zeroth_geyer`, in its order.

    Writes into out:
        <output>: each output of :func:`iterative.zeroth_geyer`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    # stance: Geyer et al.'s approximate stance map
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(7), 7)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo,))
    _o0 = carray(stack(60), 60)
    _c0 = geyer_stance_jacobian(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_20, _o0_21, _o0_23, _o0_24, _o0_30, _o0_31, _o0_32, _o0_33,
        _o0_34, _o0_35, _o0_36, _o0_38, _o0_39, _o0_50, _o0_51, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56,
        _o0_58, _o0_59,) = (load(_o0, 2, 4, 5, 8, 9, 20, 21, 23, 24, 30, 31, 32, 33, 34, 35, 36, 38, 39, 50,
        51, 52, 53, 54, 55, 56, 58, 59))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_20, _o0_21, 0.0, _o0_23, _o0_24, 0.0, _o0_30, _o0_31,
        _o0_32, _o0_33, _o0_34, 0.0, _o0_35, _o0_36, 0.0, _o0_38, _o0_39, 0.0, _o0_50, _o0_51, _o0_52, _o0_53,
        _o0_54, 0.0, _o0_55, _o0_56, 0.0, _o0_58, _o0_59, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, out):
    """The zeroth iterate 'held': the touchdown state held, the bottom from the radial work, and the
    derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c, k_d.

    Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 99
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
    # (internal helper: its callers check that their outputs are finite)
    store(out, (z_b_q_r, z_b_q_th, z_b_q_thd, 0.0, 0.0, d_z_b_q_r__q_r_td, d_z_b_q_r__q_rd_td,
        d_z_b_q_r__q_th_td, d_z_b_q_r__q_thd_td, d_z_b_q_r__k_c, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,
        d_z_b_q_thd__q_r_td, d_z_b_q_thd__q_rd_td, d_z_b_q_thd__q_th_td, d_z_b_q_thd__q_thd_td,
        d_z_b_q_thd__k_c, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    # stance: Gravity correction type 0 (leg length l0)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 1.0, 0.0,))
    _o0 = carray(stack(72), 72)
    _c0 = gravity_type0_stance_jacobian(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, _o0_32, _o0_33, _o0_34,
        _o0_35, _o0_36, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56,
        _o0_57, _o0_58, _o0_59, _o0_60, _o0_61,) = (load(_o0, 2, 4, 5, 8, 9, 22, 23, 24, 25, 26, 32, 33, 34,
        35, 36, 37, 38, 39, 40, 41, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, 0.0, _o0_32,
        _o0_33, _o0_34, _o0_35, _o0_36, 0.0, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, 0.0, _o0_52, _o0_53,
        _o0_54, _o0_55, _o0_56, 0.0, _o0_57, _o0_58, _o0_59, _o0_60, _o0_61, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy", inline="always")
def zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out, gravity_stance):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    The body that 4 kernels share, each passing the kernel it calls as gravity_stance
    (derive/share.py): zeroth_gravity_{type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d}.

    Arguments, returns and status: those of the kernels, then gravity_stance.
    """
    # Total ops: 0
    # stance: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(13), 13)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 0.0, 2.0, 1.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(72), 72)
    _c0 = gravity_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, _o0_32, _o0_33, _o0_34,
        _o0_35, _o0_36, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56,
        _o0_57, _o0_58, _o0_59, _o0_60, _o0_61,) = (load(_o0, 2, 4, 5, 8, 9, 22, 23, 24, 25, 26, 32, 33, 34,
        35, 36, 37, 38, 39, 40, 41, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, 0.0, _o0_32,
        _o0_33, _o0_34, _o0_35, _o0_36, 0.0, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, 0.0, _o0_52, _o0_53,
        _o0_54, _o0_55, _o0_56, 0.0, _o0_57, _o0_58, _o0_59, _o0_60, _o0_61, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Runs the shared body
    :func:`zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared` with
    gravity_type1_stance_jacobian. Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    return (zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared(q_r_td, q_rd_td, q_th_td,
        q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, out, gravity_type1_stance_jacobian))


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Runs the shared body
    :func:`zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared` with
    gravity_type2_stance_jacobian. Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    return (zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared(q_r_td, q_rd_td, q_th_td,
        q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, out, gravity_type2_stance_jacobian))


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Runs the shared body
    :func:`zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared` with
    gravity_type3_stance_jacobian. Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    return (zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared(q_r_td, q_rd_td, q_th_td,
        q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, out, gravity_type3_stance_jacobian))


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Runs the shared body
    :func:`zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared` with
    gravity_type4_stance_jacobian. Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    return (zeroth_gravity_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_shared(q_r_td, q_rd_td, q_th_td,
        q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, out, gravity_type4_stance_jacobian))


@njit(cache=True, error_model="numpy")
def zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m,
        l0, k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    # stance: Gravity correction type 5 (time-varying momentum)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(9), 9)
    store(_p0, (m, l0, k_c, g_s, NAN, q_r_td, q_r_lo, 100.0, 1e-12,))
    _o0 = carray(stack(72), 72)
    _c0 = gravity_type5_stance_jacobian(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, _o0_32, _o0_33, _o0_34,
        _o0_35, _o0_36, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56,
        _o0_57, _o0_58, _o0_59, _o0_60, _o0_61,) = (load(_o0, 2, 4, 5, 8, 9, 22, 23, 24, 25, 26, 32, 33, 34,
        35, 36, 37, 38, 39, 40, 41, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, 0.0, _o0_32,
        _o0_33, _o0_34, _o0_35, _o0_36, 0.0, _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, 0.0, _o0_52, _o0_53,
        _o0_54, _o0_55, _o0_56, 0.0, _o0_57, _o0_58, _o0_59, _o0_60, _o0_61, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, out):
    """A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states with the
    stiffness k_c, and the derivatives of its outputs with respect to q_r_td, q_rd_td, q_th_td, q_thd_td, k_c,
    k_d.

    Arguments, returns and status: those of
    :func:`zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d`.
    """
    # Total ops: 0
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_td, q_rd_td, q_th_td, q_thd_td,))
    _p0 = carray(stack(12), 12)
    store(_p0, (m, l0, k_c, k_d, g_s, NAN, q_r_td, q_r_lo, 2.0, 0.0, 100.0, 1e-12,))
    _o0 = carray(stack(91), 91)
    _c0 = geyer_vs_stance_jacobian(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_25, _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_37, _o0_38,
        _o0_39, _o0_40, _o0_41, _o0_42, _o0_43, _o0_44, _o0_45, _o0_46, _o0_47, _o0_48, _o0_61, _o0_62,
        _o0_63, _o0_64, _o0_65, _o0_66, _o0_67, _o0_68, _o0_69, _o0_70, _o0_71, _o0_72,) = (load(_o0, 2, 4, 5,
        8, 9, 25, 26, 27, 28, 29, 30, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 61, 62, 63, 64, 65, 66,
        67, 68, 69, 70, 71, 72))
    # (internal helper: its callers check that their outputs are finite)
    store(out, (_o0_2, _o0_4, _o0_5, _o0_8, _o0_9, _o0_25, _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_37,
        _o0_38, _o0_39, _o0_40, _o0_41, _o0_42, _o0_43, _o0_44, _o0_45, _o0_46, _o0_47, _o0_48, _o0_61,
        _o0_62, _o0_63, _o0_64, _o0_65, _o0_66, _o0_67, _o0_68, _o0_69, _o0_70, _o0_71, _o0_72,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp7_65b25d(_a, out):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 7 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative.schwind_compression`, in its order; then the components
    d_<argument>__<j> of each direction j (0 to 6) along guess_q_r, guess_q_th, guess_q_thd.

    Writes into out:
        <output>: each output of :func:`iterative.schwind_compression`, in its order
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5,
            6 (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 370
    (q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, c, guess_q_r, guess_q_th, guess_q_thd, nodes, iterations, tol,
        d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0, d_guess_q_r__1, d_guess_q_th__1, d_guess_q_thd__1,
        d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2, d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3,
        d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4, d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23,
        24, 25, 26, 27, 28, 29, 30, 31, 32))
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, c, guess_q_r, guess_q_th, guess_q_thd, nodes,
            iterations, tol,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0))
            & ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # node arrays (the nodes' values of a collocation), on the stack
    (Q0, P0, d_Q0__0, d_Q0__1, d_Q0__2, d_Q0__3, d_Q0__4, d_Q0__5, d_P0__0, d_P0__1, d_P0__2, d_P0__3,
        d_P0__4, d_P0__5, Psr0, d_Q0__6, d_P0__6, d_Psr0__0, d_Psr0__1, d_Psr0__2, d_Psr0__3, d_Psr0__4,
        d_Psr0__5, d_Psr0__6, Q, P, Psr, d_Q__0, d_Q__1, d_Q__2, d_Q__3, d_Q__4, d_Q__5, d_Q__6, d_P__0,
        d_P__1, d_P__2, d_P__3, d_P__4, d_P__5, d_P__6, d_Psr__0, d_Psr__1, d_Psr__2, d_Psr__3, d_Psr__4,
        d_Psr__5, d_Psr__6, sigma, F, sinQ, d_sigma__0, d_sigma__1, d_sigma__2, d_sigma__3, d_sigma__4,
        d_sigma__5, d_sigma__6, d_F__0, d_F__1, d_F__2, d_F__3, d_F__4, d_F__5, d_F__6, d_sinQ__0, d_sinQ__1,
        d_sinQ__2, d_sinQ__3, d_sinQ__4, d_sinQ__5, d_sinQ__6, ft, fq, fp, Psi, d_ft__0, d_ft__1, d_ft__2,
        d_ft__3, d_ft__4, d_ft__5, d_ft__6, d_fq__0, d_fq__1, d_fq__2, d_fq__3, d_fq__4, d_fq__5, d_fq__6,
        d_fp__0, d_fp__1, d_fp__2, d_fp__3, d_fp__4, d_fp__5, d_fp__6, d_Psi__0, d_Psi__1, d_Psi__2, d_Psi__3,
        d_Psi__4, d_Psi__5, d_Psi__6, G, d_G__0, d_G__1, d_G__2, d_G__3, d_G__4, d_G__5, d_G__6, Q_next,
        P_next, d_Q_next__0, d_Q_next__1, d_Q_next__2, d_Q_next__3, d_Q_next__4, d_Q_next__5, d_Q_next__6,
        d_P_next__0, d_P_next__1, d_P_next__2, d_P_next__3, d_P_next__4, d_P_next__5, d_P_next__6, Shape,
        d_Shape__0, d_Shape__1, d_Shape__2, d_Shape__3, d_Shape__4, d_Shape__5, d_Shape__6,
        ) = (node_arrays(stack(1632), 136, 12))
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # the Gauss-Legendre rule of the node count: nodes u, weights, integration matrices
    _code = int(nodes)
    if not (_code == 0 or _code == 1 or _code == 2 or _code == 3 or _code == 4):
        return fail(out, STATUS_INVALID_INPUT)
    nq = _L893379fc[_code]
    u = _L447fd80c[_code]
    w = _Lbacdd133[_code]
    w1 = _L62015774[_code]
    S = _Lac198189[_code]
    S1 = _L8c0ca55d[_code]
    # the zeroth iterate at the nodes
    for _j1000 in range(int(nq)):
        _u = u[_j1000]
        Q0[_j1000] = _u*(-guess_q_th + q_th) + guess_q_th
        P0[_j1000] = _u*(-guess_q_r**2*guess_q_thd*m + m*q_r**2*q_thd) + guess_q_r**2*guess_q_thd*m
        d_Q0__0[_j1000] = d_guess_q_th__0*(1.0 - _u)
        d_Q0__1[_j1000] = d_guess_q_th__1*(1.0 - _u)
        d_Q0__2[_j1000] = _u + d_guess_q_th__2*(1.0 - _u)
        d_Q0__3[_j1000] = d_guess_q_th__3*(1.0 - _u)
        d_Q0__4[_j1000] = d_guess_q_th__4*(1.0 - _u)
        d_Q0__5[_j1000] = d_guess_q_th__5*(1.0 - _u)
        d_P0__0[_j1000] = (2.0*_u*m*q_r*q_thd + d_guess_q_r__0*(-2.0*_u*guess_q_r*guess_q_thd*m
            + 2.0*guess_q_r*guess_q_thd*m) + d_guess_q_thd__0*(-_u*guess_q_r**2*m + guess_q_r**2*m))
        d_P0__1[_j1000] = (d_guess_q_r__1*(-2.0*_u*guess_q_r*guess_q_thd*m + 2.0*guess_q_r*guess_q_thd*m)
            + d_guess_q_thd__1*(-_u*guess_q_r**2*m + guess_q_r**2*m))
        d_P0__2[_j1000] = (d_guess_q_r__2*(-2.0*_u*guess_q_r*guess_q_thd*m + 2.0*guess_q_r*guess_q_thd*m)
            + d_guess_q_thd__2*(-_u*guess_q_r**2*m + guess_q_r**2*m))
        d_P0__3[_j1000] = (_u*m*q_r**2 + d_guess_q_r__3*(-2.0*_u*guess_q_r*guess_q_thd*m
            + 2.0*guess_q_r*guess_q_thd*m) + d_guess_q_thd__3*(-_u*guess_q_r**2*m + guess_q_r**2*m))
        d_P0__4[_j1000] = (d_guess_q_r__4*(-2.0*_u*guess_q_r*guess_q_thd*m + 2.0*guess_q_r*guess_q_thd*m)
            + d_guess_q_thd__4*(-_u*guess_q_r**2*m + guess_q_r**2*m))
        d_P0__5[_j1000] = (d_guess_q_r__5*(-2.0*_u*guess_q_r*guess_q_thd*m + 2.0*guess_q_r*guess_q_thd*m)
            + d_guess_q_thd__5*(-_u*guess_q_r**2*m + guess_q_r**2*m))
    # Psi at the nodes, zeroth iterate
    for _j1002 in range(int(nq)):
        Psr0[_j1002] = 1.0
    # tangents that are 0
    for _j1004 in range(int(nq)):
        d_Q0__6[_j1004] = 0.0
        d_P0__6[_j1004] = 0.0
        d_Psr0__0[_j1004] = 0.0
        d_Psr0__1[_j1004] = 0.0
        d_Psr0__2[_j1004] = 0.0
        d_Psr0__3[_j1004] = 0.0
        d_Psr0__4[_j1004] = 0.0
        d_Psr0__5[_j1004] = 0.0
        d_Psr0__6[_j1004] = 0.0
    # Picard passes on the node values (collocation in u)
    for _j1048 in range(int(nq)):
        Q[_j1048] = Q0[_j1048]
        P[_j1048] = P0[_j1048]
        Psr[_j1048] = Psr0[_j1048]
        d_Q__0[_j1048] = d_Q0__0[_j1048]
        d_Q__1[_j1048] = d_Q0__1[_j1048]
        d_Q__2[_j1048] = d_Q0__2[_j1048]
        d_Q__3[_j1048] = d_Q0__3[_j1048]
        d_Q__4[_j1048] = d_Q0__4[_j1048]
        d_Q__5[_j1048] = d_Q0__5[_j1048]
        d_Q__6[_j1048] = d_Q0__6[_j1048]
        d_P__0[_j1048] = d_P0__0[_j1048]
        d_P__1[_j1048] = d_P0__1[_j1048]
        d_P__2[_j1048] = d_P0__2[_j1048]
        d_P__3[_j1048] = d_P0__3[_j1048]
        d_P__4[_j1048] = d_P0__4[_j1048]
        d_P__5[_j1048] = d_P0__5[_j1048]
        d_P__6[_j1048] = d_P0__6[_j1048]
        d_Psr__0[_j1048] = d_Psr0__0[_j1048]
        d_Psr__1[_j1048] = d_Psr0__1[_j1048]
        d_Psr__2[_j1048] = d_Psr0__2[_j1048]
        d_Psr__3[_j1048] = d_Psr0__3[_j1048]
        d_Psr__4[_j1048] = d_Psr0__4[_j1048]
        d_Psr__5[_j1048] = d_Psr0__5[_j1048]
        d_Psr__6[_j1048] = d_Psr0__6[_j1048]
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2, -d_guess_q_r__3,
        -d_guess_q_r__4, -d_guess_q_r__5, 0.0, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_D__6, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # node values of the pass: sigma, F_r (29) and the damper's force, sin Q
        for _j1006 in range(int(nq)):
            _Qj = Q[_j1006]
            _Pj = P[_j1006]
            _u = u[_j1006]
            _Psr = Psr[_j1006]
            _d_Qj__0 = d_Q__0[_j1006]
            _d_Qj__1 = d_Q__1[_j1006]
            _d_Qj__2 = d_Q__2[_j1006]
            _d_Qj__3 = d_Q__3[_j1006]
            _d_Qj__4 = d_Q__4[_j1006]
            _d_Qj__5 = d_Q__5[_j1006]
            _d_Qj__6 = d_Q__6[_j1006]
            _d_Pj__0 = d_P__0[_j1006]
            _d_Pj__1 = d_P__1[_j1006]
            _d_Pj__2 = d_P__2[_j1006]
            _d_Pj__3 = d_P__3[_j1006]
            _d_Pj__4 = d_P__4[_j1006]
            _d_Pj__5 = d_P__5[_j1006]
            _d_Pj__6 = d_P__6[_j1006]
            _d_Psr__0 = d_Psr__0[_j1006]
            _d_Psr__1 = d_Psr__1[_j1006]
            _d_Psr__2 = d_Psr__2[_j1006]
            _d_Psr__3 = d_Psr__3[_j1006]
            _d_Psr__4 = d_Psr__4[_j1006]
            _d_Psr__5 = d_Psr__5[_j1006]
            _d_Psr__6 = d_Psr__6[_j1006]
            _x0 = _u**2
            _x1 = _D*_x0
            _x2 = -_D + _x1 + q_r
            _sigma = _x2
            _pd__0 = _x0 - 1.0
            _d_sigma__0 = _d_D__0*_pd__0 + 1.0
            _d_sigma__1 = _d_D__1*_pd__0
            _d_sigma__2 = _d_D__2*_pd__0
            _d_sigma__3 = _d_D__3*_pd__0
            _d_sigma__4 = _d_D__4*_pd__0
            _d_sigma__5 = _d_D__5*_pd__0
            _d_sigma__6 = _d_D__6*_pd__0
            _x3 = math.cos(_Qj)
            _x4 = g_s*m
            _x5 = _Pj**2
            _x6 = (1.0/m)
            _x9 = (1.0/_x2)
            _x7 = _x6*_x9**3
            _F = -_x2*k_c - _x3*_x4 + _x5*_x7 + k_c*l0
            _pd__1 = 2.0*_Pj*_x7
            _x8 = math.sin(_Qj)
            _pd__2 = _x4*_x8
            _pd__3 = -3.0*_x5*_x6*_x9**4 - k_c
            _d_F__0 = _d_Pj__0*_pd__1 + _d_Qj__0*_pd__2 + _d_sigma__0*_pd__3
            _d_F__1 = _d_Pj__1*_pd__1 + _d_Qj__1*_pd__2 + _d_sigma__1*_pd__3
            _d_F__2 = _d_Pj__2*_pd__1 + _d_Qj__2*_pd__2 + _d_sigma__2*_pd__3
            _d_F__3 = _d_Pj__3*_pd__1 + _d_Qj__3*_pd__2 + _d_sigma__3*_pd__3
            _d_F__4 = _D + _d_Pj__4*_pd__1 + _d_Qj__4*_pd__2 + _d_sigma__4*_pd__3 - _x1 + l0 - q_r
            _d_F__5 = _d_Pj__5*_pd__1 + _d_Qj__5*_pd__2 + _d_sigma__5*_pd__3
            _d_F__6 = _d_Pj__6*_pd__1 + _d_Qj__6*_pd__2 + _d_sigma__6*_pd__3
            _sinQ = _x8
            _pd__4 = _x3
            _d_sinQ__0 = _d_Qj__0*_pd__4
            _d_sinQ__1 = _d_Qj__1*_pd__4
            _d_sinQ__2 = _d_Qj__2*_pd__4
            _d_sinQ__3 = _d_Qj__3*_pd__4
            _d_sinQ__4 = _d_Qj__4*_pd__4
            _d_sinQ__5 = _d_Qj__5*_pd__4
            _d_sinQ__6 = _d_Qj__6*_pd__4
            sigma[_j1006] = _sigma
            F[_j1006] = _F - math.sqrt(_Psr)*_u*c*q_rd
            sinQ[_j1006] = _sinQ
            d_sigma__0[_j1006] = _d_sigma__0
            d_sigma__1[_j1006] = _d_sigma__1
            d_sigma__2[_j1006] = _d_sigma__2
            d_sigma__3[_j1006] = _d_sigma__3
            d_sigma__4[_j1006] = _d_sigma__4
            d_sigma__5[_j1006] = _d_sigma__5
            d_sigma__6[_j1006] = _d_sigma__6
            d_F__0[_j1006] = _d_F__0 - 0.5*_d_Psr__0*_u*c*q_rd/math.sqrt(_Psr)
            d_F__1[_j1006] = -math.sqrt(_Psr)*_u*c + _d_F__1 - 0.5*_d_Psr__1*_u*c*q_rd/math.sqrt(_Psr)
            d_F__2[_j1006] = _d_F__2 - 0.5*_d_Psr__2*_u*c*q_rd/math.sqrt(_Psr)
            d_F__3[_j1006] = _d_F__3 - 0.5*_d_Psr__3*_u*c*q_rd/math.sqrt(_Psr)
            d_F__4[_j1006] = _d_F__4 - 0.5*_d_Psr__4*_u*c*q_rd/math.sqrt(_Psr)
            d_F__5[_j1006] = _d_F__5 - 0.5*_d_Psr__5*_u*c*q_rd/math.sqrt(_Psr)
            d_F__6[_j1006] = -math.sqrt(_Psr)*_u*q_rd + _d_F__6 - 0.5*_d_Psr__6*_u*c*q_rd/math.sqrt(_Psr)
            d_sinQ__0[_j1006] = _d_sinQ__0
            d_sinQ__1[_j1006] = _d_sinQ__1
            d_sinQ__2[_j1006] = _d_sinQ__2
            d_sinQ__3[_j1006] = _d_sinQ__3
            d_sinQ__4[_j1006] = _d_sinQ__4
            d_sinQ__5[_j1006] = _d_sinQ__5
            d_sinQ__6[_j1006] = _d_sinQ__6
        # Psi and the u-rates of (30)-(32) at the nodes
        for _j1008 in range(int(nq)):
            _Pj = P[_j1008]
            _u = u[_j1008]
            _sigma = sigma[_j1008]
            _sinQ = sinQ[_j1008]
            _d_Pj__0 = d_P__0[_j1008]
            _d_Pj__1 = d_P__1[_j1008]
            _d_Pj__2 = d_P__2[_j1008]
            _d_Pj__3 = d_P__3[_j1008]
            _d_Pj__4 = d_P__4[_j1008]
            _d_Pj__5 = d_P__5[_j1008]
            _d_Pj__6 = d_P__6[_j1008]
            _d_sigma__0 = d_sigma__0[_j1008]
            _d_sigma__1 = d_sigma__1[_j1008]
            _d_sigma__2 = d_sigma__2[_j1008]
            _d_sigma__3 = d_sigma__3[_j1008]
            _d_sigma__4 = d_sigma__4[_j1008]
            _d_sigma__5 = d_sigma__5[_j1008]
            _d_sigma__6 = d_sigma__6[_j1008]
            _d_sinQ__0 = d_sinQ__0[_j1008]
            _d_sinQ__1 = d_sinQ__1[_j1008]
            _d_sinQ__2 = d_sinQ__2[_j1008]
            _d_sinQ__3 = d_sinQ__3[_j1008]
            _d_sinQ__4 = d_sinQ__4[_j1008]
            _d_sinQ__5 = d_sinQ__5[_j1008]
            _d_sinQ__6 = d_sinQ__6[_j1008]
            _S1F = 0.0
            _d_S1F__0 = 0.0
            _d_S1F__1 = 0.0
            _d_S1F__2 = 0.0
            _d_S1F__3 = 0.0
            _d_S1F__4 = 0.0
            _d_S1F__5 = 0.0
            _d_S1F__6 = 0.0
            for _j1009 in range(int(nq)):
                _S1F += S1[_j1008, _j1009]*F[_j1009]
                _d_S1F__0 += S1[_j1008, _j1009]*d_F__0[_j1009]
                _d_S1F__1 += S1[_j1008, _j1009]*d_F__1[_j1009]
                _d_S1F__2 += S1[_j1008, _j1009]*d_F__2[_j1009]
                _d_S1F__3 += S1[_j1008, _j1009]*d_F__3[_j1009]
                _d_S1F__4 += S1[_j1008, _j1009]*d_F__4[_j1009]
                _d_S1F__5 += S1[_j1008, _j1009]*d_F__5[_j1009]
                _d_S1F__6 += S1[_j1008, _j1009]*d_F__6[_j1009]
            _x10 = _u**-2
            _x11 = _S1F*_x10
            _Psi = _x11
            _pd__5 = _x10
            _d_Psi__0 = _d_S1F__0*_pd__5
            _d_Psi__1 = _d_S1F__1*_pd__5
            _d_Psi__2 = _d_S1F__2*_pd__5
            _d_Psi__3 = _d_S1F__3*_pd__5
            _d_Psi__4 = _d_S1F__4*_pd__5
            _d_Psi__5 = _d_S1F__5*_pd__5
            _d_Psi__6 = _d_S1F__6*_pd__5
            _x12 = math.sqrt(_D)
            _x13 = math.sqrt(m)
            _x14 = (1.0/math.sqrt(_x11))
            _x15 = _x13*_x14
            _ft = _x12*_x15
            _x16 = (0.5)/_x12
            _pd__6 = _x15*_x16
            _x17 = (0.5)*_x12/(_x11*math.sqrt(_x11))
            _pd__7 = -_x13*_x17
            _d_ft__0 = _d_D__0*_pd__6 + _d_Psi__0*_pd__7
            _d_ft__1 = _d_D__1*_pd__6 + _d_Psi__1*_pd__7
            _d_ft__2 = _d_D__2*_pd__6 + _d_Psi__2*_pd__7
            _d_ft__3 = _d_D__3*_pd__6 + _d_Psi__3*_pd__7
            _d_ft__4 = _d_D__4*_pd__6 + _d_Psi__4*_pd__7
            _d_ft__5 = _d_D__5*_pd__6 + _d_Psi__5*_pd__7
            _d_ft__6 = _d_D__6*_pd__6 + _d_Psi__6*_pd__7
            _x18 = _x12*_x14
            _x19 = (1.0/_x13)
            _x28 = (1.0/_sigma)
            _x20 = _x19*_x28**2
            _x21 = _x18*_x20
            _fq = _Pj*_x21
            _x22 = _Pj*_x20
            _x23 = _x14*_x16
            _pd__8 = _x22*_x23
            _pd__9 = _x21
            _pd__10 = -_x17*_x22
            _pd__11 = -2.0*_Pj*_x18*_x19*_x28**3
            _d_fq__0 = _d_D__0*_pd__8 + _d_Pj__0*_pd__9 + _d_Psi__0*_pd__10 + _d_sigma__0*_pd__11
            _d_fq__1 = _d_D__1*_pd__8 + _d_Pj__1*_pd__9 + _d_Psi__1*_pd__10 + _d_sigma__1*_pd__11
            _d_fq__2 = _d_D__2*_pd__8 + _d_Pj__2*_pd__9 + _d_Psi__2*_pd__10 + _d_sigma__2*_pd__11
            _d_fq__3 = _d_D__3*_pd__8 + _d_Pj__3*_pd__9 + _d_Psi__3*_pd__10 + _d_sigma__3*_pd__11
            _d_fq__4 = _d_D__4*_pd__8 + _d_Pj__4*_pd__9 + _d_Psi__4*_pd__10 + _d_sigma__4*_pd__11
            _d_fq__5 = _d_D__5*_pd__8 + _d_Pj__5*_pd__9 + _d_Psi__5*_pd__10 + _d_sigma__5*_pd__11
            _d_fq__6 = _d_D__6*_pd__8 + _d_Pj__6*_pd__9 + _d_Psi__6*_pd__10 + _d_sigma__6*_pd__11
            _x24 = (m*math.sqrt(m))
            _x25 = _x18*_x24*g_s
            _x26 = _sinQ*_x25
            _fp = _sigma*_x26
            _x27 = _sigma*_sinQ*_x24*g_s
            _pd__12 = _x23*_x27
            _pd__13 = -_x17*_x27
            _pd__14 = _x26
            _pd__15 = _sigma*_x25
            _d_fp__0 = _d_D__0*_pd__12 + _d_Psi__0*_pd__13 + _d_sigma__0*_pd__14 + _d_sinQ__0*_pd__15
            _d_fp__1 = _d_D__1*_pd__12 + _d_Psi__1*_pd__13 + _d_sigma__1*_pd__14 + _d_sinQ__1*_pd__15
            _d_fp__2 = _d_D__2*_pd__12 + _d_Psi__2*_pd__13 + _d_sigma__2*_pd__14 + _d_sinQ__2*_pd__15
            _d_fp__3 = _d_D__3*_pd__12 + _d_Psi__3*_pd__13 + _d_sigma__3*_pd__14 + _d_sinQ__3*_pd__15
            _d_fp__4 = _d_D__4*_pd__12 + _d_Psi__4*_pd__13 + _d_sigma__4*_pd__14 + _d_sinQ__4*_pd__15
            _d_fp__5 = _d_D__5*_pd__12 + _d_Psi__5*_pd__13 + _d_sigma__5*_pd__14 + _d_sinQ__5*_pd__15
            _d_fp__6 = _d_D__6*_pd__12 + _d_Psi__6*_pd__13 + _d_sigma__6*_pd__14 + _d_sinQ__6*_pd__15
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_Psi > 0.0)):
                return fail(out, STATUS_IMAGINARY_MOMENTUM)
            ft[_j1008] = _ft
            fq[_j1008] = _fq
            fp[_j1008] = _fp
            Psi[_j1008] = _Psi
            d_ft__0[_j1008] = _d_ft__0
            d_ft__1[_j1008] = _d_ft__1
            d_ft__2[_j1008] = _d_ft__2
            d_ft__3[_j1008] = _d_ft__3
            d_ft__4[_j1008] = _d_ft__4
            d_ft__5[_j1008] = _d_ft__5
            d_ft__6[_j1008] = _d_ft__6
            d_fq__0[_j1008] = _d_fq__0
            d_fq__1[_j1008] = _d_fq__1
            d_fq__2[_j1008] = _d_fq__2
            d_fq__3[_j1008] = _d_fq__3
            d_fq__4[_j1008] = _d_fq__4
            d_fq__5[_j1008] = _d_fq__5
            d_fq__6[_j1008] = _d_fq__6
            d_fp__0[_j1008] = _d_fp__0
            d_fp__1[_j1008] = _d_fp__1
            d_fp__2[_j1008] = _d_fp__2
            d_fp__3[_j1008] = _d_fp__3
            d_fp__4[_j1008] = _d_fp__4
            d_fp__5[_j1008] = _d_fp__5
            d_fp__6[_j1008] = _d_fp__6
            d_Psi__0[_j1008] = _d_Psi__0
            d_Psi__1[_j1008] = _d_Psi__1
            d_Psi__2[_j1008] = _d_Psi__2
            d_Psi__3[_j1008] = _d_Psi__3
            d_Psi__4[_j1008] = _d_Psi__4
            d_Psi__5[_j1008] = _d_Psi__5
            d_Psi__6[_j1008] = _d_Psi__6
        if _conv0 or _it0 == _last0:
            break
        _wfq = 0.0
        _d_wfq__0 = 0.0
        _d_wfq__1 = 0.0
        _d_wfq__2 = 0.0
        _d_wfq__3 = 0.0
        _d_wfq__4 = 0.0
        _d_wfq__5 = 0.0
        _d_wfq__6 = 0.0
        _wfp = 0.0
        _d_wfp__0 = 0.0
        _d_wfp__1 = 0.0
        _d_wfp__2 = 0.0
        _d_wfp__3 = 0.0
        _d_wfp__4 = 0.0
        _d_wfp__5 = 0.0
        _d_wfp__6 = 0.0
        for _j1010 in range(int(nq)):
            _wfq += w[_j1010]*fq[_j1010]
            _d_wfq__0 += w[_j1010]*d_fq__0[_j1010]
            _d_wfq__1 += w[_j1010]*d_fq__1[_j1010]
            _d_wfq__2 += w[_j1010]*d_fq__2[_j1010]
            _d_wfq__3 += w[_j1010]*d_fq__3[_j1010]
            _d_wfq__4 += w[_j1010]*d_fq__4[_j1010]
            _d_wfq__5 += w[_j1010]*d_fq__5[_j1010]
            _d_wfq__6 += w[_j1010]*d_fq__6[_j1010]
            _wfp += w[_j1010]*fp[_j1010]
            _d_wfp__0 += w[_j1010]*d_fp__0[_j1010]
            _d_wfp__1 += w[_j1010]*d_fp__1[_j1010]
            _d_wfp__2 += w[_j1010]*d_fp__2[_j1010]
            _d_wfp__3 += w[_j1010]*d_fp__3[_j1010]
            _d_wfp__4 += w[_j1010]*d_fp__4[_j1010]
            _d_wfp__5 += w[_j1010]*d_fp__5[_j1010]
            _d_wfp__6 += w[_j1010]*d_fp__6[_j1010]
        # F_r minus its spring term
        for _j1026 in range(int(nq)):
            _F = F[_j1026]
            _sigma = sigma[_j1026]
            _d_F__0 = d_F__0[_j1026]
            _d_F__1 = d_F__1[_j1026]
            _d_F__2 = d_F__2[_j1026]
            _d_F__3 = d_F__3[_j1026]
            _d_F__4 = d_F__4[_j1026]
            _d_F__5 = d_F__5[_j1026]
            _d_F__6 = d_F__6[_j1026]
            _d_sigma__0 = d_sigma__0[_j1026]
            _d_sigma__1 = d_sigma__1[_j1026]
            _d_sigma__2 = d_sigma__2[_j1026]
            _d_sigma__3 = d_sigma__3[_j1026]
            _d_sigma__4 = d_sigma__4[_j1026]
            _d_sigma__5 = d_sigma__5[_j1026]
            _d_sigma__6 = d_sigma__6[_j1026]
            G[_j1026] = _F - k_c*(-_sigma + l0)
            d_G__0[_j1026] = _d_F__0 + _d_sigma__0*k_c
            d_G__1[_j1026] = _d_F__1 + _d_sigma__1*k_c
            d_G__2[_j1026] = _d_F__2 + _d_sigma__2*k_c
            d_G__3[_j1026] = _d_F__3 + _d_sigma__3*k_c
            d_G__4[_j1026] = _d_F__4 + _d_sigma__4*k_c + _sigma - l0
            d_G__5[_j1026] = _d_F__5 + _d_sigma__5*k_c
            d_G__6[_j1026] = _d_F__6 + _d_sigma__6*k_c
        _rbar = 0.0
        _d_rbar__0 = 0.0
        _d_rbar__1 = 0.0
        _d_rbar__2 = 0.0
        _d_rbar__3 = 0.0
        _d_rbar__4 = 0.0
        _d_rbar__5 = 0.0
        _d_rbar__6 = 0.0
        _Wpass = 0.0
        _d_Wpass__0 = 0.0
        _d_Wpass__1 = 0.0
        _d_Wpass__2 = 0.0
        _d_Wpass__3 = 0.0
        _d_Wpass__4 = 0.0
        _d_Wpass__5 = 0.0
        _d_Wpass__6 = 0.0
        for _j1028 in range(int(nq)):
            _rbar += w1[_j1028]*G[_j1028]
            _d_rbar__0 += w1[_j1028]*d_G__0[_j1028]
            _d_rbar__1 += w1[_j1028]*d_G__1[_j1028]
            _d_rbar__2 += w1[_j1028]*d_G__2[_j1028]
            _d_rbar__3 += w1[_j1028]*d_G__3[_j1028]
            _d_rbar__4 += w1[_j1028]*d_G__4[_j1028]
            _d_rbar__5 += w1[_j1028]*d_G__5[_j1028]
            _d_rbar__6 += w1[_j1028]*d_G__6[_j1028]
            _Wpass += w1[_j1028]*F[_j1028]
            _d_Wpass__0 += w1[_j1028]*d_F__0[_j1028]
            _d_Wpass__1 += w1[_j1028]*d_F__1[_j1028]
            _d_Wpass__2 += w1[_j1028]*d_F__2[_j1028]
            _d_Wpass__3 += w1[_j1028]*d_F__3[_j1028]
            _d_Wpass__4 += w1[_j1028]*d_F__4[_j1028]
            _d_Wpass__5 += w1[_j1028]*d_F__5[_j1028]
            _d_Wpass__6 += w1[_j1028]*d_F__6[_j1028]
        # the next iterate at the nodes
        for _j1044 in range(int(nq)):
            _Sfq = 0.0
            _Sfp = 0.0
            _d_Sfq__0 = 0.0
            _d_Sfq__1 = 0.0
            _d_Sfq__2 = 0.0
            _d_Sfq__3 = 0.0
            _d_Sfq__4 = 0.0
            _d_Sfq__5 = 0.0
            _d_Sfq__6 = 0.0
            _d_Sfp__0 = 0.0
            _d_Sfp__1 = 0.0
            _d_Sfp__2 = 0.0
            _d_Sfp__3 = 0.0
            _d_Sfp__4 = 0.0
            _d_Sfp__5 = 0.0
            _d_Sfp__6 = 0.0
            for _j1045 in range(int(nq)):
                _Sfq += S[_j1044, _j1045]*fq[_j1045]
                _Sfp += S[_j1044, _j1045]*fp[_j1045]
                _d_Sfq__0 += S[_j1044, _j1045]*d_fq__0[_j1045]
                _d_Sfq__1 += S[_j1044, _j1045]*d_fq__1[_j1045]
                _d_Sfq__2 += S[_j1044, _j1045]*d_fq__2[_j1045]
                _d_Sfq__3 += S[_j1044, _j1045]*d_fq__3[_j1045]
                _d_Sfq__4 += S[_j1044, _j1045]*d_fq__4[_j1045]
                _d_Sfq__5 += S[_j1044, _j1045]*d_fq__5[_j1045]
                _d_Sfq__6 += S[_j1044, _j1045]*d_fq__6[_j1045]
                _d_Sfp__0 += S[_j1044, _j1045]*d_fp__0[_j1045]
                _d_Sfp__1 += S[_j1044, _j1045]*d_fp__1[_j1045]
                _d_Sfp__2 += S[_j1044, _j1045]*d_fp__2[_j1045]
                _d_Sfp__3 += S[_j1044, _j1045]*d_fp__3[_j1045]
                _d_Sfp__4 += S[_j1044, _j1045]*d_fp__4[_j1045]
                _d_Sfp__5 += S[_j1044, _j1045]*d_fp__5[_j1045]
                _d_Sfp__6 += S[_j1044, _j1045]*d_fp__6[_j1045]
            Q_next[_j1044] = -_Sfq + _wfq + q_th
            P_next[_j1044] = -_Sfp + _wfp + m*q_r**2*q_thd
            d_Q_next__0[_j1044] = -_d_Sfq__0 + _d_wfq__0
            d_Q_next__1[_j1044] = -_d_Sfq__1 + _d_wfq__1
            d_Q_next__2[_j1044] = -_d_Sfq__2 + _d_wfq__2 + 1.0
            d_Q_next__3[_j1044] = -_d_Sfq__3 + _d_wfq__3
            d_Q_next__4[_j1044] = -_d_Sfq__4 + _d_wfq__4
            d_Q_next__5[_j1044] = -_d_Sfq__5 + _d_wfq__5
            d_Q_next__6[_j1044] = -_d_Sfq__6 + _d_wfq__6
            d_P_next__0[_j1044] = -_d_Sfp__0 + _d_wfp__0 + 2.0*m*q_r*q_thd
            d_P_next__1[_j1044] = -_d_Sfp__1 + _d_wfp__1
            d_P_next__2[_j1044] = -_d_Sfp__2 + _d_wfp__2
            d_P_next__3[_j1044] = -_d_Sfp__3 + _d_wfp__3 + m*q_r**2
            d_P_next__4[_j1044] = -_d_Sfp__4 + _d_wfp__4
            d_P_next__5[_j1044] = -_d_Sfp__5 + _d_wfp__5
            d_P_next__6[_j1044] = -_d_Sfp__6 + _d_wfp__6
        # D = q_r_td - q_r_b from the radial work
        _x29 = m*q_rd**2
        _x30 = l0 - q_r
        _x31 = _x30*k_c
        _x32 = 2.0*_rbar + _x31
        _x33 = math.sqrt(_x29*k_c + _x32**2)
        _x34 = _x32 + _x33
        _x35 = (1.0/_x34)
        _D_next = _x29*_x35
        _x36 = (1.0/_x33)
        _x37 = _x35**2
        _x38 = _x29*_x37
        _pd__16 = _x38*(-_x36*(4.0*_rbar + 2.0*_x31) - 2.0)
        _x39 = _x36*k_c
        _d_D_next__0 = _d_rbar__0*_pd__16 + _x38*(_x32*_x39 + k_c)
        _d_D_next__1 = _d_rbar__1*_pd__16 + 2.0*_x35*m*q_rd - _x37*_x39*m**2*q_rd**3
        _d_D_next__2 = _d_rbar__2*_pd__16
        _d_D_next__3 = _d_rbar__3*_pd__16
        _d_D_next__4 = _d_rbar__4*_pd__16 + _x38*(-_x30 - _x36*((0.5)*_x29 + (0.5)*_x32*(2.0*l0 - 2.0*q_r)))
        _d_D_next__5 = _d_rbar__5*_pd__16
        _d_D_next__6 = _d_rbar__6*_pd__16
        # the shape Psi/W
        for _j1046 in range(int(nq)):
            _Psi = Psi[_j1046]
            _d_Psi__0 = d_Psi__0[_j1046]
            _d_Psi__1 = d_Psi__1[_j1046]
            _d_Psi__2 = d_Psi__2[_j1046]
            _d_Psi__3 = d_Psi__3[_j1046]
            _d_Psi__4 = d_Psi__4[_j1046]
            _d_Psi__5 = d_Psi__5[_j1046]
            _d_Psi__6 = d_Psi__6[_j1046]
            Shape[_j1046] = _Psi/_Wpass
            d_Shape__0[_j1046] = -_Psi*_d_Wpass__0/_Wpass**2 + _d_Psi__0/_Wpass
            d_Shape__1[_j1046] = -_Psi*_d_Wpass__1/_Wpass**2 + _d_Psi__1/_Wpass
            d_Shape__2[_j1046] = -_Psi*_d_Wpass__2/_Wpass**2 + _d_Psi__2/_Wpass
            d_Shape__3[_j1046] = -_Psi*_d_Wpass__3/_Wpass**2 + _d_Psi__3/_Wpass
            d_Shape__4[_j1046] = -_Psi*_d_Wpass__4/_Wpass**2 + _d_Psi__4/_Wpass
            d_Shape__5[_j1046] = -_Psi*_d_Wpass__5/_Wpass**2 + _d_Psi__5/_Wpass
            d_Shape__6[_j1046] = -_Psi*_d_Wpass__6/_Wpass**2 + _d_Psi__6/_Wpass
        # next values
        _D__next = _D_next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_D__next - _D) <= tol*(l0))
        for _j1048 in range(int(nq)):
            _conv0 = _conv0 and abs(Q_next[_j1048] - Q[_j1048]) <= tol*(1.0)
            Q[_j1048] = Q_next[_j1048]
            _conv0 = (_conv0 and abs(P_next[_j1048] - P[_j1048]) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
                + m*q_r**2*abs(q_thd)))
            P[_j1048] = P_next[_j1048]
            Psr[_j1048] = Shape[_j1048]
            d_Q__0[_j1048] = d_Q_next__0[_j1048]
            d_Q__1[_j1048] = d_Q_next__1[_j1048]
            d_Q__2[_j1048] = d_Q_next__2[_j1048]
            d_Q__3[_j1048] = d_Q_next__3[_j1048]
            d_Q__4[_j1048] = d_Q_next__4[_j1048]
            d_Q__5[_j1048] = d_Q_next__5[_j1048]
            d_Q__6[_j1048] = d_Q_next__6[_j1048]
            d_P__0[_j1048] = d_P_next__0[_j1048]
            d_P__1[_j1048] = d_P_next__1[_j1048]
            d_P__2[_j1048] = d_P_next__2[_j1048]
            d_P__3[_j1048] = d_P_next__3[_j1048]
            d_P__4[_j1048] = d_P_next__4[_j1048]
            d_P__5[_j1048] = d_P_next__5[_j1048]
            d_P__6[_j1048] = d_P_next__6[_j1048]
            d_Psr__0[_j1048] = d_Shape__0[_j1048]
            d_Psr__1[_j1048] = d_Shape__1[_j1048]
            d_Psr__2[_j1048] = d_Shape__2[_j1048]
            d_Psr__3[_j1048] = d_Shape__3[_j1048]
            d_Psr__4[_j1048] = d_Shape__4[_j1048]
            d_Psr__5[_j1048] = d_Shape__5[_j1048]
            d_Psr__6[_j1048] = d_Shape__6[_j1048]
        _pkn0 = (_D__next, _d_D_next__0, _d_D_next__1, _d_D_next__2, _d_D_next__3, _d_D_next__4, _d_D_next__5,
            _d_D_next__6, )
        _pk0 = _pkn0
        _passes += 1.0
    _t_end = 0.0
    _d_t_end__0 = 0.0
    _d_t_end__1 = 0.0
    _d_t_end__2 = 0.0
    _d_t_end__3 = 0.0
    _d_t_end__4 = 0.0
    _d_t_end__5 = 0.0
    _d_t_end__6 = 0.0
    _q_end = 0.0
    _d_q_end__0 = 0.0
    _d_q_end__1 = 0.0
    _d_q_end__2 = 0.0
    _d_q_end__3 = 0.0
    _d_q_end__4 = 0.0
    _d_q_end__5 = 0.0
    _d_q_end__6 = 0.0
    _p_end = 0.0
    _d_p_end__0 = 0.0
    _d_p_end__1 = 0.0
    _d_p_end__2 = 0.0
    _d_p_end__3 = 0.0
    _d_p_end__4 = 0.0
    _d_p_end__5 = 0.0
    _d_p_end__6 = 0.0
    for _j1049 in range(int(nq)):
        _t_end += w[_j1049]*ft[_j1049]
        _d_t_end__0 += w[_j1049]*d_ft__0[_j1049]
        _d_t_end__1 += w[_j1049]*d_ft__1[_j1049]
        _d_t_end__2 += w[_j1049]*d_ft__2[_j1049]
        _d_t_end__3 += w[_j1049]*d_ft__3[_j1049]
        _d_t_end__4 += w[_j1049]*d_ft__4[_j1049]
        _d_t_end__5 += w[_j1049]*d_ft__5[_j1049]
        _d_t_end__6 += w[_j1049]*d_ft__6[_j1049]
        _q_end += w[_j1049]*fq[_j1049]
        _d_q_end__0 += w[_j1049]*d_fq__0[_j1049]
        _d_q_end__1 += w[_j1049]*d_fq__1[_j1049]
        _d_q_end__2 += w[_j1049]*d_fq__2[_j1049]
        _d_q_end__3 += w[_j1049]*d_fq__3[_j1049]
        _d_q_end__4 += w[_j1049]*d_fq__4[_j1049]
        _d_q_end__5 += w[_j1049]*d_fq__5[_j1049]
        _d_q_end__6 += w[_j1049]*d_fq__6[_j1049]
        _p_end += w[_j1049]*fp[_j1049]
        _d_p_end__0 += w[_j1049]*d_fp__0[_j1049]
        _d_p_end__1 += w[_j1049]*d_fp__1[_j1049]
        _d_p_end__2 += w[_j1049]*d_fp__2[_j1049]
        _d_p_end__3 += w[_j1049]*d_fp__3[_j1049]
        _d_p_end__4 += w[_j1049]*d_fp__4[_j1049]
        _d_p_end__5 += w[_j1049]*d_fp__5[_j1049]
        _d_p_end__6 += w[_j1049]*d_fp__6[_j1049]
    # bottom state
    t_half = _t_end
    end_q_th = _q_end + q_th
    d_end_q_th__2 = _d_q_end__2 + 1.0
    _x40 = -_D + q_r
    end_q_r = _x40
    d_end_q_r__0 = 1.0 - _d_D__0
    _x41 = q_r**2
    _x42 = _p_end + _x41*m*q_thd
    _x43 = (1.0/m)
    _x46 = (1.0/_x40)
    _x44 = _x46**2
    _x45 = _x43*_x44
    end_q_thd = _x42*_x45
    _pd__17 = _x45
    _pd__18 = -2.0*_x42*_x43*_x46**3
    d_end_q_thd__0 = _d_p_end__0*_pd__17 + _pd__18*d_end_q_r__0 + 2.0*_x44*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__18 + _d_p_end__1*_pd__17
    d_end_q_thd__2 = -_d_D__2*_pd__18 + _d_p_end__2*_pd__17
    d_end_q_thd__3 = -_d_D__3*_pd__18 + _d_p_end__3*_pd__17 + _x41*_x44
    d_end_q_thd__4 = -_d_D__4*_pd__18 + _d_p_end__4*_pd__17
    d_end_q_thd__5 = -_d_D__5*_pd__18 + _d_p_end__5*_pd__17
    d_end_q_thd__6 = -_d_D__6*_pd__18 + _d_p_end__6*_pd__17
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return fail(out, STATUS_FALL)
    # derivatives of the outputs
    d_t_half__0 = _d_t_end__0
    d_t_half__1 = _d_t_end__1
    d_t_half__2 = _d_t_end__2
    d_t_half__3 = _d_t_end__3
    d_t_half__4 = _d_t_end__4
    d_t_half__5 = _d_t_end__5
    d_t_half__6 = _d_t_end__6
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    d_end_q_r__6 = -_d_D__6
    d_end_q_th__0 = _d_q_end__0
    d_end_q_th__1 = _d_q_end__1
    d_end_q_th__3 = _d_q_end__3
    d_end_q_th__4 = _d_q_end__4
    d_end_q_th__5 = _d_q_end__5
    d_end_q_th__6 = _d_q_end__6
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_half, end_q_r, 0.0, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_t_half__6, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2,
        d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_r__6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5,
        d_end_q_th__6, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_end_q_thd__6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_c_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0, k_d,
        g_s, q_r_lo, c, guess_q_th, guess_q_thd, nodes, iterations, tol, liftoff, out):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, c, guess_q_th,
    guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative.schwind_decompression`, in its order.

    Writes into out:
        <output>: each output of :func:`iterative.schwind_decompression`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r, q_th, q_thd,
            k_d, c, guess_q_th, guess_q_thd (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 478
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, c, guess_q_th, guess_q_thd, nodes,
            iterations, tol, liftoff,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((c >= 0.0)) & ((nodes == 0.0) or (nodes == 1.0) or (nodes
            == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0) and (tol <= 1.0)) & ((liftoff
            == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # node arrays (the nodes' values of a collocation), on the stack
    (Q0, P0, d_Q0__q_th, d_Q0__guess_q_th, d_P0__q_r, d_P0__q_thd, d_P0__guess_q_thd, Psr0, d_Psr0__q_r,
        d_Psr0__q_th, d_Psr0__q_thd, d_Psr0__k_d, d_Q0__q_r, d_Q0__q_thd, d_Q0__k_d, d_Q0__c,
        d_Q0__guess_q_thd, d_P0__q_th, d_P0__k_d, d_P0__c, d_P0__guess_q_th, d_Psr0__c, d_Psr0__guess_q_th,
        d_Psr0__guess_q_thd, Q, P, Psr, d_Q__q_r, d_Q__q_th, d_Q__q_thd, d_Q__k_d, d_Q__c, d_Q__guess_q_th,
        d_Q__guess_q_thd, d_P__q_r, d_P__q_th, d_P__q_thd, d_P__k_d, d_P__c, d_P__guess_q_th,
        d_P__guess_q_thd, d_Psr__q_r, d_Psr__q_th, d_Psr__q_thd, d_Psr__k_d, d_Psr__c, d_Psr__guess_q_th,
        d_Psr__guess_q_thd, sigma, F, sinQ, d_sigma__q_r, d_sigma__q_th, d_sigma__q_thd, d_sigma__k_d,
        d_sigma__c, d_sigma__guess_q_th, d_sigma__guess_q_thd, d_F__q_r, d_F__q_th, d_F__q_thd, d_F__k_d,
        d_F__c, d_F__guess_q_th, d_F__guess_q_thd, d_sinQ__q_r, d_sinQ__q_th, d_sinQ__q_thd, d_sinQ__k_d,
        d_sinQ__c, d_sinQ__guess_q_th, d_sinQ__guess_q_thd, ft, fq, fp, Psi, d_ft__q_r, d_ft__q_th,
        d_ft__q_thd, d_ft__k_d, d_ft__c, d_ft__guess_q_th, d_ft__guess_q_thd, d_fq__q_r, d_fq__q_th,
        d_fq__q_thd, d_fq__k_d, d_fq__c, d_fq__guess_q_th, d_fq__guess_q_thd, d_fp__q_r, d_fp__q_th,
        d_fp__q_thd, d_fp__k_d, d_fp__c, d_fp__guess_q_th, d_fp__guess_q_thd, d_Psi__q_r, d_Psi__q_th,
        d_Psi__q_thd, d_Psi__k_d, d_Psi__c, d_Psi__guess_q_th, d_Psi__guess_q_thd, Q_next, P_next,
        d_Q_next__q_r, d_Q_next__q_th, d_Q_next__q_thd, d_Q_next__k_d, d_Q_next__c, d_Q_next__guess_q_th,
        d_Q_next__guess_q_thd, d_P_next__q_r, d_P_next__q_th, d_P_next__q_thd, d_P_next__k_d, d_P_next__c,
        d_P_next__guess_q_th, d_P_next__guess_q_thd,) = (node_arrays(stack(1440), 120, 12))
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return fail(out, STATUS_RECOMPRESSION)
    # the Gauss-Legendre rule of the node count: nodes u, weights, integration matrices
    _code = int(nodes)
    if not (_code == 0 or _code == 1 or _code == 2 or _code == 3 or _code == 4):
        return fail(out, STATUS_INVALID_INPUT)
    nq = _L893379fc[_code]
    u = _L447fd80c[_code]
    w = _Lbacdd133[_code]
    w1 = _L62015774[_code]
    S = _Lac198189[_code]
    S1 = _L8c0ca55d[_code]
    # the zeroth iterate at the nodes
    for _j1000 in range(int(nq)):
        _u = u[_j1000]
        Q0[_j1000] = _u*(guess_q_th - q_th) + q_th
        P0[_j1000] = _u*(guess_q_thd*m*q_r_lo**2 - m*q_r**2*q_thd) + m*q_r**2*q_thd
        d_Q0__q_th[_j1000] = 1.0 - _u
        d_Q0__guess_q_th[_j1000] = _u
        d_P0__q_r[_j1000] = -2.0*_u*m*q_r*q_thd + 2.0*m*q_r*q_thd
        d_P0__q_thd[_j1000] = -_u*m*q_r**2 + m*q_r**2
        d_P0__guess_q_thd[_j1000] = _u*m*q_r_lo**2
    # Psi at the nodes, zeroth iterate
    for _j1002 in range(int(nq)):
        Psr0[_j1002] = -0.5*g_s*m*math.cos(q_th) + (0.5)*k_d*l0 - 0.5*k_d*q_r + (0.5)*m*q_r*q_thd**2
        d_Psr0__q_r[_j1002] = -0.5*k_d + (0.5)*m*q_thd**2
        d_Psr0__q_th[_j1002] = (0.5)*g_s*m*math.sin(q_th)
        d_Psr0__q_thd[_j1002] = m*q_r*q_thd
        d_Psr0__k_d[_j1002] = (0.5)*l0 - 0.5*q_r
    # tangents that are 0
    for _j1004 in range(int(nq)):
        d_Q0__q_r[_j1004] = 0.0
        d_Q0__q_thd[_j1004] = 0.0
        d_Q0__k_d[_j1004] = 0.0
        d_Q0__c[_j1004] = 0.0
        d_Q0__guess_q_thd[_j1004] = 0.0
        d_P0__q_th[_j1004] = 0.0
        d_P0__k_d[_j1004] = 0.0
        d_P0__c[_j1004] = 0.0
        d_P0__guess_q_th[_j1004] = 0.0
        d_Psr0__c[_j1004] = 0.0
        d_Psr0__guess_q_th[_j1004] = 0.0
        d_Psr0__guess_q_thd[_j1004] = 0.0
    # Picard passes on the node values (collocation in u)
    for _j1020 in range(int(nq)):
        Q[_j1020] = Q0[_j1020]
        P[_j1020] = P0[_j1020]
        Psr[_j1020] = Psr0[_j1020]
        d_Q__q_r[_j1020] = d_Q0__q_r[_j1020]
        d_Q__q_th[_j1020] = d_Q0__q_th[_j1020]
        d_Q__q_thd[_j1020] = d_Q0__q_thd[_j1020]
        d_Q__k_d[_j1020] = d_Q0__k_d[_j1020]
        d_Q__c[_j1020] = d_Q0__c[_j1020]
        d_Q__guess_q_th[_j1020] = d_Q0__guess_q_th[_j1020]
        d_Q__guess_q_thd[_j1020] = d_Q0__guess_q_thd[_j1020]
        d_P__q_r[_j1020] = d_P0__q_r[_j1020]
        d_P__q_th[_j1020] = d_P0__q_th[_j1020]
        d_P__q_thd[_j1020] = d_P0__q_thd[_j1020]
        d_P__k_d[_j1020] = d_P0__k_d[_j1020]
        d_P__c[_j1020] = d_P0__c[_j1020]
        d_P__guess_q_th[_j1020] = d_P0__guess_q_th[_j1020]
        d_P__guess_q_thd[_j1020] = d_P0__guess_q_thd[_j1020]
        d_Psr__q_r[_j1020] = d_Psr0__q_r[_j1020]
        d_Psr__q_th[_j1020] = d_Psr0__q_th[_j1020]
        d_Psr__q_thd[_j1020] = d_Psr0__q_thd[_j1020]
        d_Psr__k_d[_j1020] = d_Psr0__k_d[_j1020]
        d_Psr__c[_j1020] = d_Psr0__c[_j1020]
        d_Psr__guess_q_th[_j1020] = d_Psr0__guess_q_th[_j1020]
        d_Psr__guess_q_thd[_j1020] = d_Psr0__guess_q_thd[_j1020]
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__c, _d_D__guess_q_th, _d_D__guess_q_thd,
            ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # node values of the pass: sigma, F_r (29) and the damper's force, sin Q
        for _j1006 in range(int(nq)):
            _Qj = Q[_j1006]
            _Pj = P[_j1006]
            _u = u[_j1006]
            _Psr = Psr[_j1006]
            _d_Qj__q_r = d_Q__q_r[_j1006]
            _d_Qj__q_th = d_Q__q_th[_j1006]
            _d_Qj__q_thd = d_Q__q_thd[_j1006]
            _d_Qj__k_d = d_Q__k_d[_j1006]
            _d_Qj__c = d_Q__c[_j1006]
            _d_Qj__guess_q_th = d_Q__guess_q_th[_j1006]
            _d_Qj__guess_q_thd = d_Q__guess_q_thd[_j1006]
            _d_Pj__q_r = d_P__q_r[_j1006]
            _d_Pj__q_th = d_P__q_th[_j1006]
            _d_Pj__q_thd = d_P__q_thd[_j1006]
            _d_Pj__k_d = d_P__k_d[_j1006]
            _d_Pj__c = d_P__c[_j1006]
            _d_Pj__guess_q_th = d_P__guess_q_th[_j1006]
            _d_Pj__guess_q_thd = d_P__guess_q_thd[_j1006]
            _d_Psr__q_r = d_Psr__q_r[_j1006]
            _d_Psr__q_th = d_Psr__q_th[_j1006]
            _d_Psr__q_thd = d_Psr__q_thd[_j1006]
            _d_Psr__k_d = d_Psr__k_d[_j1006]
            _d_Psr__c = d_Psr__c[_j1006]
            _d_Psr__guess_q_th = d_Psr__guess_q_th[_j1006]
            _d_Psr__guess_q_thd = d_Psr__guess_q_thd[_j1006]
            _x0 = _u**2
            _x1 = _D*_x0
            _x2 = _x1 + q_r
            _sigma = _x2
            _pd__0 = _x0
            _d_sigma__q_r = _d_D__q_r*_pd__0 + 1.0
            _d_sigma__q_th = _d_D__q_th*_pd__0
            _d_sigma__q_thd = _d_D__q_thd*_pd__0
            _d_sigma__k_d = _d_D__k_d*_pd__0
            _d_sigma__c = _d_D__c*_pd__0
            _d_sigma__guess_q_th = _d_D__guess_q_th*_pd__0
            _d_sigma__guess_q_thd = _d_D__guess_q_thd*_pd__0
            _x3 = math.cos(_Qj)
            _x4 = g_s*m
            _x5 = _Pj**2
            _x6 = (1.0/m)
            _x9 = (1.0/_x2)
            _x7 = _x6*_x9**3
            _F = -_x2*k_d - _x3*_x4 + _x5*_x7 + k_d*l0
            _pd__1 = 2.0*_Pj*_x7
            _x8 = math.sin(_Qj)
            _pd__2 = _x4*_x8
            _pd__3 = -3.0*_x5*_x6*_x9**4 - k_d
            _d_F__q_r = _d_Pj__q_r*_pd__1 + _d_Qj__q_r*_pd__2 + _d_sigma__q_r*_pd__3
            _d_F__q_th = _d_Pj__q_th*_pd__1 + _d_Qj__q_th*_pd__2 + _d_sigma__q_th*_pd__3
            _d_F__q_thd = _d_Pj__q_thd*_pd__1 + _d_Qj__q_thd*_pd__2 + _d_sigma__q_thd*_pd__3
            _d_F__k_d = _d_Pj__k_d*_pd__1 + _d_Qj__k_d*_pd__2 + _d_sigma__k_d*_pd__3 - _x1 + l0 - q_r
            _d_F__c = _d_Pj__c*_pd__1 + _d_Qj__c*_pd__2 + _d_sigma__c*_pd__3
            _d_F__guess_q_th = (_d_Pj__guess_q_th*_pd__1 + _d_Qj__guess_q_th*_pd__2
                + _d_sigma__guess_q_th*_pd__3)
            _d_F__guess_q_thd = (_d_Pj__guess_q_thd*_pd__1 + _d_Qj__guess_q_thd*_pd__2
                + _d_sigma__guess_q_thd*_pd__3)
            _sinQ = _x8
            _pd__4 = _x3
            _d_sinQ__q_r = _d_Qj__q_r*_pd__4
            _d_sinQ__q_th = _d_Qj__q_th*_pd__4
            _d_sinQ__q_thd = _d_Qj__q_thd*_pd__4
            _d_sinQ__k_d = _d_Qj__k_d*_pd__4
            _d_sinQ__c = _d_Qj__c*_pd__4
            _d_sinQ__guess_q_th = _d_Qj__guess_q_th*_pd__4
            _d_sinQ__guess_q_thd = _d_Qj__guess_q_thd*_pd__4
            sigma[_j1006] = _sigma
            F[_j1006] = _F - 2.0*_u*c*math.sqrt(_D*_Psr)/math.sqrt(m)
            sinQ[_j1006] = _sinQ
            d_sigma__q_r[_j1006] = _d_sigma__q_r
            d_sigma__q_th[_j1006] = _d_sigma__q_th
            d_sigma__q_thd[_j1006] = _d_sigma__q_thd
            d_sigma__k_d[_j1006] = _d_sigma__k_d
            d_sigma__c[_j1006] = _d_sigma__c
            d_sigma__guess_q_th[_j1006] = _d_sigma__guess_q_th
            d_sigma__guess_q_thd[_j1006] = _d_sigma__guess_q_thd
            d_F__q_r[_j1006] = (_d_F__q_r - _d_Psr__q_r*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__q_r*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__q_th[_j1006] = (_d_F__q_th - _d_Psr__q_th*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__q_th*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__q_thd[_j1006] = (_d_F__q_thd - _d_Psr__q_thd*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__q_thd*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__k_d[_j1006] = (_d_F__k_d - _d_Psr__k_d*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__k_d*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__c[_j1006] = (_d_F__c - 2.0*_u*math.sqrt(_D*_Psr)/math.sqrt(m)
                - _d_Psr__c*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__c*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__guess_q_th[_j1006] = (_d_F__guess_q_th
                - _d_Psr__guess_q_th*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__guess_q_th*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_F__guess_q_thd[_j1006] = (_d_F__guess_q_thd
                - _d_Psr__guess_q_thd*_u*c*math.sqrt(_D*_Psr)/(_Psr*math.sqrt(m))
                - _d_D__guess_q_thd*_u*c*math.sqrt(_D*_Psr)/(_D*math.sqrt(m)))
            d_sinQ__q_r[_j1006] = _d_sinQ__q_r
            d_sinQ__q_th[_j1006] = _d_sinQ__q_th
            d_sinQ__q_thd[_j1006] = _d_sinQ__q_thd
            d_sinQ__k_d[_j1006] = _d_sinQ__k_d
            d_sinQ__c[_j1006] = _d_sinQ__c
            d_sinQ__guess_q_th[_j1006] = _d_sinQ__guess_q_th
            d_sinQ__guess_q_thd[_j1006] = _d_sinQ__guess_q_thd
        # Psi and the u-rates of (30)-(32) at the nodes
        for _j1008 in range(int(nq)):
            _Pj = P[_j1008]
            _u = u[_j1008]
            _sigma = sigma[_j1008]
            _sinQ = sinQ[_j1008]
            _d_Pj__q_r = d_P__q_r[_j1008]
            _d_Pj__q_th = d_P__q_th[_j1008]
            _d_Pj__q_thd = d_P__q_thd[_j1008]
            _d_Pj__k_d = d_P__k_d[_j1008]
            _d_Pj__c = d_P__c[_j1008]
            _d_Pj__guess_q_th = d_P__guess_q_th[_j1008]
            _d_Pj__guess_q_thd = d_P__guess_q_thd[_j1008]
            _d_sigma__q_r = d_sigma__q_r[_j1008]
            _d_sigma__q_th = d_sigma__q_th[_j1008]
            _d_sigma__q_thd = d_sigma__q_thd[_j1008]
            _d_sigma__k_d = d_sigma__k_d[_j1008]
            _d_sigma__c = d_sigma__c[_j1008]
            _d_sigma__guess_q_th = d_sigma__guess_q_th[_j1008]
            _d_sigma__guess_q_thd = d_sigma__guess_q_thd[_j1008]
            _d_sinQ__q_r = d_sinQ__q_r[_j1008]
            _d_sinQ__q_th = d_sinQ__q_th[_j1008]
            _d_sinQ__q_thd = d_sinQ__q_thd[_j1008]
            _d_sinQ__k_d = d_sinQ__k_d[_j1008]
            _d_sinQ__c = d_sinQ__c[_j1008]
            _d_sinQ__guess_q_th = d_sinQ__guess_q_th[_j1008]
            _d_sinQ__guess_q_thd = d_sinQ__guess_q_thd[_j1008]
            _S1F = 0.0
            _d_S1F__q_r = 0.0
            _d_S1F__q_th = 0.0
            _d_S1F__q_thd = 0.0
            _d_S1F__k_d = 0.0
            _d_S1F__c = 0.0
            _d_S1F__guess_q_th = 0.0
            _d_S1F__guess_q_thd = 0.0
            for _j1009 in range(int(nq)):
                _S1F += S1[_j1008, _j1009]*F[_j1009]
                _d_S1F__q_r += S1[_j1008, _j1009]*d_F__q_r[_j1009]
                _d_S1F__q_th += S1[_j1008, _j1009]*d_F__q_th[_j1009]
                _d_S1F__q_thd += S1[_j1008, _j1009]*d_F__q_thd[_j1009]
                _d_S1F__k_d += S1[_j1008, _j1009]*d_F__k_d[_j1009]
                _d_S1F__c += S1[_j1008, _j1009]*d_F__c[_j1009]
                _d_S1F__guess_q_th += S1[_j1008, _j1009]*d_F__guess_q_th[_j1009]
                _d_S1F__guess_q_thd += S1[_j1008, _j1009]*d_F__guess_q_thd[_j1009]
            _x10 = _u**-2
            _x11 = _S1F*_x10
            _Psi = _x11
            _pd__5 = _x10
            _d_Psi__q_r = _d_S1F__q_r*_pd__5
            _d_Psi__q_th = _d_S1F__q_th*_pd__5
            _d_Psi__q_thd = _d_S1F__q_thd*_pd__5
            _d_Psi__k_d = _d_S1F__k_d*_pd__5
            _d_Psi__c = _d_S1F__c*_pd__5
            _d_Psi__guess_q_th = _d_S1F__guess_q_th*_pd__5
            _d_Psi__guess_q_thd = _d_S1F__guess_q_thd*_pd__5
            _x12 = math.sqrt(_D)
            _x13 = math.sqrt(m)
            _x14 = (1.0/math.sqrt(_x11))
            _x15 = _x13*_x14
            _ft = _x12*_x15
            _x16 = (0.5)/_x12
            _pd__6 = _x15*_x16
            _x17 = (0.5)*_x12/(_x11*math.sqrt(_x11))
            _pd__7 = -_x13*_x17
            _d_ft__q_r = _d_D__q_r*_pd__6 + _d_Psi__q_r*_pd__7
            _d_ft__q_th = _d_D__q_th*_pd__6 + _d_Psi__q_th*_pd__7
            _d_ft__q_thd = _d_D__q_thd*_pd__6 + _d_Psi__q_thd*_pd__7
            _d_ft__k_d = _d_D__k_d*_pd__6 + _d_Psi__k_d*_pd__7
            _d_ft__c = _d_D__c*_pd__6 + _d_Psi__c*_pd__7
            _d_ft__guess_q_th = _d_D__guess_q_th*_pd__6 + _d_Psi__guess_q_th*_pd__7
            _d_ft__guess_q_thd = _d_D__guess_q_thd*_pd__6 + _d_Psi__guess_q_thd*_pd__7
            _x18 = _x12*_x14
            _x19 = (1.0/_x13)
            _x28 = (1.0/_sigma)
            _x20 = _x19*_x28**2
            _x21 = _x18*_x20
            _fq = _Pj*_x21
            _x22 = _Pj*_x20
            _x23 = _x14*_x16
            _pd__8 = _x22*_x23
            _pd__9 = _x21
            _pd__10 = -_x17*_x22
            _pd__11 = -2.0*_Pj*_x18*_x19*_x28**3
            _d_fq__q_r = _d_D__q_r*_pd__8 + _d_Pj__q_r*_pd__9 + _d_Psi__q_r*_pd__10 + _d_sigma__q_r*_pd__11
            _d_fq__q_th = (_d_D__q_th*_pd__8 + _d_Pj__q_th*_pd__9 + _d_Psi__q_th*_pd__10
                + _d_sigma__q_th*_pd__11)
            _d_fq__q_thd = (_d_D__q_thd*_pd__8 + _d_Pj__q_thd*_pd__9 + _d_Psi__q_thd*_pd__10
                + _d_sigma__q_thd*_pd__11)
            _d_fq__k_d = _d_D__k_d*_pd__8 + _d_Pj__k_d*_pd__9 + _d_Psi__k_d*_pd__10 + _d_sigma__k_d*_pd__11
            _d_fq__c = _d_D__c*_pd__8 + _d_Pj__c*_pd__9 + _d_Psi__c*_pd__10 + _d_sigma__c*_pd__11
            _d_fq__guess_q_th = (_d_D__guess_q_th*_pd__8 + _d_Pj__guess_q_th*_pd__9
                + _d_Psi__guess_q_th*_pd__10 + _d_sigma__guess_q_th*_pd__11)
            _d_fq__guess_q_thd = (_d_D__guess_q_thd*_pd__8 + _d_Pj__guess_q_thd*_pd__9
                + _d_Psi__guess_q_thd*_pd__10 + _d_sigma__guess_q_thd*_pd__11)
            _x24 = (m*math.sqrt(m))
            _x25 = _x18*_x24*g_s
            _x26 = _sinQ*_x25
            _fp = _sigma*_x26
            _x27 = _sigma*_sinQ*_x24*g_s
            _pd__12 = _x23*_x27
            _pd__13 = -_x17*_x27
            _pd__14 = _x26
            _pd__15 = _sigma*_x25
            _d_fp__q_r = (_d_D__q_r*_pd__12 + _d_Psi__q_r*_pd__13 + _d_sigma__q_r*_pd__14
                + _d_sinQ__q_r*_pd__15)
            _d_fp__q_th = (_d_D__q_th*_pd__12 + _d_Psi__q_th*_pd__13 + _d_sigma__q_th*_pd__14
                + _d_sinQ__q_th*_pd__15)
            _d_fp__q_thd = (_d_D__q_thd*_pd__12 + _d_Psi__q_thd*_pd__13 + _d_sigma__q_thd*_pd__14
                + _d_sinQ__q_thd*_pd__15)
            _d_fp__k_d = (_d_D__k_d*_pd__12 + _d_Psi__k_d*_pd__13 + _d_sigma__k_d*_pd__14
                + _d_sinQ__k_d*_pd__15)
            _d_fp__c = _d_D__c*_pd__12 + _d_Psi__c*_pd__13 + _d_sigma__c*_pd__14 + _d_sinQ__c*_pd__15
            _d_fp__guess_q_th = (_d_D__guess_q_th*_pd__12 + _d_Psi__guess_q_th*_pd__13
                + _d_sigma__guess_q_th*_pd__14 + _d_sinQ__guess_q_th*_pd__15)
            _d_fp__guess_q_thd = (_d_D__guess_q_thd*_pd__12 + _d_Psi__guess_q_thd*_pd__13
                + _d_sigma__guess_q_thd*_pd__14 + _d_sinQ__guess_q_thd*_pd__15)
            # p_r^2 = 2 m int F_r > 0 at every node
            if not ((_Psi > 0.0)):
                return fail(out, STATUS_IMAGINARY_MOMENTUM)
            ft[_j1008] = _ft
            fq[_j1008] = _fq
            fp[_j1008] = _fp
            Psi[_j1008] = _Psi
            d_ft__q_r[_j1008] = _d_ft__q_r
            d_ft__q_th[_j1008] = _d_ft__q_th
            d_ft__q_thd[_j1008] = _d_ft__q_thd
            d_ft__k_d[_j1008] = _d_ft__k_d
            d_ft__c[_j1008] = _d_ft__c
            d_ft__guess_q_th[_j1008] = _d_ft__guess_q_th
            d_ft__guess_q_thd[_j1008] = _d_ft__guess_q_thd
            d_fq__q_r[_j1008] = _d_fq__q_r
            d_fq__q_th[_j1008] = _d_fq__q_th
            d_fq__q_thd[_j1008] = _d_fq__q_thd
            d_fq__k_d[_j1008] = _d_fq__k_d
            d_fq__c[_j1008] = _d_fq__c
            d_fq__guess_q_th[_j1008] = _d_fq__guess_q_th
            d_fq__guess_q_thd[_j1008] = _d_fq__guess_q_thd
            d_fp__q_r[_j1008] = _d_fp__q_r
            d_fp__q_th[_j1008] = _d_fp__q_th
            d_fp__q_thd[_j1008] = _d_fp__q_thd
            d_fp__k_d[_j1008] = _d_fp__k_d
            d_fp__c[_j1008] = _d_fp__c
            d_fp__guess_q_th[_j1008] = _d_fp__guess_q_th
            d_fp__guess_q_thd[_j1008] = _d_fp__guess_q_thd
            d_Psi__q_r[_j1008] = _d_Psi__q_r
            d_Psi__q_th[_j1008] = _d_Psi__q_th
            d_Psi__q_thd[_j1008] = _d_Psi__q_thd
            d_Psi__k_d[_j1008] = _d_Psi__k_d
            d_Psi__c[_j1008] = _d_Psi__c
            d_Psi__guess_q_th[_j1008] = _d_Psi__guess_q_th
            d_Psi__guess_q_thd[_j1008] = _d_Psi__guess_q_thd
        if _conv0 or _it0 == _last0:
            break
        _Wpass = 0.0
        _d_Wpass__q_r = 0.0
        _d_Wpass__q_th = 0.0
        _d_Wpass__q_thd = 0.0
        _d_Wpass__k_d = 0.0
        _d_Wpass__c = 0.0
        _d_Wpass__guess_q_th = 0.0
        _d_Wpass__guess_q_thd = 0.0
        for _j1010 in range(int(nq)):
            _Wpass += w1[_j1010]*F[_j1010]
            _d_Wpass__q_r += w1[_j1010]*d_F__q_r[_j1010]
            _d_Wpass__q_th += w1[_j1010]*d_F__q_th[_j1010]
            _d_Wpass__q_thd += w1[_j1010]*d_F__q_thd[_j1010]
            _d_Wpass__k_d += w1[_j1010]*d_F__k_d[_j1010]
            _d_Wpass__c += w1[_j1010]*d_F__c[_j1010]
            _d_Wpass__guess_q_th += w1[_j1010]*d_F__guess_q_th[_j1010]
            _d_Wpass__guess_q_thd += w1[_j1010]*d_F__guess_q_thd[_j1010]
        # the next iterate at the nodes
        for _j1018 in range(int(nq)):
            _Sfq = 0.0
            _Sfp = 0.0
            _d_Sfq__q_r = 0.0
            _d_Sfq__q_th = 0.0
            _d_Sfq__q_thd = 0.0
            _d_Sfq__k_d = 0.0
            _d_Sfq__c = 0.0
            _d_Sfq__guess_q_th = 0.0
            _d_Sfq__guess_q_thd = 0.0
            _d_Sfp__q_r = 0.0
            _d_Sfp__q_th = 0.0
            _d_Sfp__q_thd = 0.0
            _d_Sfp__k_d = 0.0
            _d_Sfp__c = 0.0
            _d_Sfp__guess_q_th = 0.0
            _d_Sfp__guess_q_thd = 0.0
            for _j1019 in range(int(nq)):
                _Sfq += S[_j1018, _j1019]*fq[_j1019]
                _Sfp += S[_j1018, _j1019]*fp[_j1019]
                _d_Sfq__q_r += S[_j1018, _j1019]*d_fq__q_r[_j1019]
                _d_Sfq__q_th += S[_j1018, _j1019]*d_fq__q_th[_j1019]
                _d_Sfq__q_thd += S[_j1018, _j1019]*d_fq__q_thd[_j1019]
                _d_Sfq__k_d += S[_j1018, _j1019]*d_fq__k_d[_j1019]
                _d_Sfq__c += S[_j1018, _j1019]*d_fq__c[_j1019]
                _d_Sfq__guess_q_th += S[_j1018, _j1019]*d_fq__guess_q_th[_j1019]
                _d_Sfq__guess_q_thd += S[_j1018, _j1019]*d_fq__guess_q_thd[_j1019]
                _d_Sfp__q_r += S[_j1018, _j1019]*d_fp__q_r[_j1019]
                _d_Sfp__q_th += S[_j1018, _j1019]*d_fp__q_th[_j1019]
                _d_Sfp__q_thd += S[_j1018, _j1019]*d_fp__q_thd[_j1019]
                _d_Sfp__k_d += S[_j1018, _j1019]*d_fp__k_d[_j1019]
                _d_Sfp__c += S[_j1018, _j1019]*d_fp__c[_j1019]
                _d_Sfp__guess_q_th += S[_j1018, _j1019]*d_fp__guess_q_th[_j1019]
                _d_Sfp__guess_q_thd += S[_j1018, _j1019]*d_fp__guess_q_thd[_j1019]
            Q_next[_j1018] = _Sfq + q_th
            P_next[_j1018] = _Sfp + m*q_r**2*q_thd
            d_Q_next__q_r[_j1018] = _d_Sfq__q_r
            d_Q_next__q_th[_j1018] = _d_Sfq__q_th + 1.0
            d_Q_next__q_thd[_j1018] = _d_Sfq__q_thd
            d_Q_next__k_d[_j1018] = _d_Sfq__k_d
            d_Q_next__c[_j1018] = _d_Sfq__c
            d_Q_next__guess_q_th[_j1018] = _d_Sfq__guess_q_th
            d_Q_next__guess_q_thd[_j1018] = _d_Sfq__guess_q_thd
            d_P_next__q_r[_j1018] = _d_Sfp__q_r + 2.0*m*q_r*q_thd
            d_P_next__q_th[_j1018] = _d_Sfp__q_th
            d_P_next__q_thd[_j1018] = _d_Sfp__q_thd + m*q_r**2
            d_P_next__k_d[_j1018] = _d_Sfp__k_d
            d_P_next__c[_j1018] = _d_Sfp__c
            d_P_next__guess_q_th[_j1018] = _d_Sfp__guess_q_th
            d_P_next__guess_q_thd[_j1018] = _d_Sfp__guess_q_thd
        # D = q_r_lo - q_r_b, or to the leg force's zero (liftoff force)
        _x29 = k_d*l0
        _x30 = k_d*q_r
        _x31 = 2.0*_x29 - 2.0*_x30
        _x32 = _x31**2
        _x33 = math.sqrt(_Wpass)
        _x34 = (1.0/math.sqrt(m))
        _x35 = _x33*_x34
        _x36 = 2.0*c
        _x37 = _x35*_x36
        _x38 = (1.0/m)
        _x39 = _Wpass*_x38
        _x40 = 4.0*c**2
        _x41 = 4.0*k_d
        _x42 = math.sqrt(_x39*_x40 + _x41*(_x29 - _x30))
        _x43 = _x37 + _x42
        _x52 = (1.0/_x43)
        _x44 = _x52**2
        _x45 = -q_r_lo
        _x46 = -_x45 - q_r
        _x47 = (liftoff == 0.0) and (_x37*math.sqrt(_x46) - k_d*(_x45 + l0) > 0.0)
        _D_next = ((_x32*_x44) if _x47 else (_x46))
        _x48 = (1.0/_x42)
        _x49 = _x32*_x52**3
        _pd__16 = ((_x49*(-_x38*_x40*_x48 - _x34*_x36/_x33)) if _x47 else (0.0))
        _x50 = _x31*_x44
        _x51 = _x48*_x49
        _d_D_next__q_r = _d_Wpass__q_r*_pd__16 + ((-_x41*_x50 + 4.0*_x51*k_d**2) if _x47 else (-1.0))
        _d_D_next__q_th = _d_Wpass__q_th*_pd__16
        _d_D_next__q_thd = _d_Wpass__q_thd*_pd__16
        _d_D_next__k_d = (_d_Wpass__k_d*_pd__16 + ((_x50*(4.0*l0 - 4.0*q_r) - 2.0*_x51*(_x31 + 2.0*k_d*(l0
            - q_r))) if _x47 else (0.0)))
        _d_D_next__c = _d_Wpass__c*_pd__16 + ((_x49*(-4.0*_x35 - 8.0*_x39*_x48*c)) if _x47 else (0.0))
        _d_D_next__guess_q_th = _d_Wpass__guess_q_th*_pd__16
        _d_D_next__guess_q_thd = _d_Wpass__guess_q_thd*_pd__16
        # next values
        _D__next = _D_next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_D__next - _D) <= tol*(l0))
        for _j1020 in range(int(nq)):
            _conv0 = _conv0 and abs(Q_next[_j1020] - Q[_j1020]) <= tol*(1.0)
            Q[_j1020] = Q_next[_j1020]
            _conv0 = (_conv0 and abs(P_next[_j1020] - P[_j1020]) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
                + m*q_r**2*abs(q_thd)))
            P[_j1020] = P_next[_j1020]
            Psr[_j1020] = Psi[_j1020]
            d_Q__q_r[_j1020] = d_Q_next__q_r[_j1020]
            d_Q__q_th[_j1020] = d_Q_next__q_th[_j1020]
            d_Q__q_thd[_j1020] = d_Q_next__q_thd[_j1020]
            d_Q__k_d[_j1020] = d_Q_next__k_d[_j1020]
            d_Q__c[_j1020] = d_Q_next__c[_j1020]
            d_Q__guess_q_th[_j1020] = d_Q_next__guess_q_th[_j1020]
            d_Q__guess_q_thd[_j1020] = d_Q_next__guess_q_thd[_j1020]
            d_P__q_r[_j1020] = d_P_next__q_r[_j1020]
            d_P__q_th[_j1020] = d_P_next__q_th[_j1020]
            d_P__q_thd[_j1020] = d_P_next__q_thd[_j1020]
            d_P__k_d[_j1020] = d_P_next__k_d[_j1020]
            d_P__c[_j1020] = d_P_next__c[_j1020]
            d_P__guess_q_th[_j1020] = d_P_next__guess_q_th[_j1020]
            d_P__guess_q_thd[_j1020] = d_P_next__guess_q_thd[_j1020]
            d_Psr__q_r[_j1020] = d_Psi__q_r[_j1020]
            d_Psr__q_th[_j1020] = d_Psi__q_th[_j1020]
            d_Psr__q_thd[_j1020] = d_Psi__q_thd[_j1020]
            d_Psr__k_d[_j1020] = d_Psi__k_d[_j1020]
            d_Psr__c[_j1020] = d_Psi__c[_j1020]
            d_Psr__guess_q_th[_j1020] = d_Psi__guess_q_th[_j1020]
            d_Psr__guess_q_thd[_j1020] = d_Psi__guess_q_thd[_j1020]
        _pkn0 = (_D__next, _d_D_next__q_r, _d_D_next__q_th, _d_D_next__q_thd, _d_D_next__k_d, _d_D_next__c,
            _d_D_next__guess_q_th, _d_D_next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _t_end = 0.0
    _d_t_end__q_r = 0.0
    _d_t_end__q_th = 0.0
    _d_t_end__q_thd = 0.0
    _d_t_end__k_d = 0.0
    _d_t_end__c = 0.0
    _d_t_end__guess_q_th = 0.0
    _d_t_end__guess_q_thd = 0.0
    _q_end = 0.0
    _d_q_end__q_r = 0.0
    _d_q_end__q_th = 0.0
    _d_q_end__q_thd = 0.0
    _d_q_end__k_d = 0.0
    _d_q_end__c = 0.0
    _d_q_end__guess_q_th = 0.0
    _d_q_end__guess_q_thd = 0.0
    _p_end = 0.0
    _d_p_end__q_r = 0.0
    _d_p_end__q_th = 0.0
    _d_p_end__q_thd = 0.0
    _d_p_end__k_d = 0.0
    _d_p_end__c = 0.0
    _d_p_end__guess_q_th = 0.0
    _d_p_end__guess_q_thd = 0.0
    _work = 0.0
    _d_work__q_r = 0.0
    _d_work__q_th = 0.0
    _d_work__q_thd = 0.0
    _d_work__k_d = 0.0
    _d_work__c = 0.0
    _d_work__guess_q_th = 0.0
    _d_work__guess_q_thd = 0.0
    for _j1021 in range(int(nq)):
        _t_end += w[_j1021]*ft[_j1021]
        _d_t_end__q_r += w[_j1021]*d_ft__q_r[_j1021]
        _d_t_end__q_th += w[_j1021]*d_ft__q_th[_j1021]
        _d_t_end__q_thd += w[_j1021]*d_ft__q_thd[_j1021]
        _d_t_end__k_d += w[_j1021]*d_ft__k_d[_j1021]
        _d_t_end__c += w[_j1021]*d_ft__c[_j1021]
        _d_t_end__guess_q_th += w[_j1021]*d_ft__guess_q_th[_j1021]
        _d_t_end__guess_q_thd += w[_j1021]*d_ft__guess_q_thd[_j1021]
        _q_end += w[_j1021]*fq[_j1021]
        _d_q_end__q_r += w[_j1021]*d_fq__q_r[_j1021]
        _d_q_end__q_th += w[_j1021]*d_fq__q_th[_j1021]
        _d_q_end__q_thd += w[_j1021]*d_fq__q_thd[_j1021]
        _d_q_end__k_d += w[_j1021]*d_fq__k_d[_j1021]
        _d_q_end__c += w[_j1021]*d_fq__c[_j1021]
        _d_q_end__guess_q_th += w[_j1021]*d_fq__guess_q_th[_j1021]
        _d_q_end__guess_q_thd += w[_j1021]*d_fq__guess_q_thd[_j1021]
        _p_end += w[_j1021]*fp[_j1021]
        _d_p_end__q_r += w[_j1021]*d_fp__q_r[_j1021]
        _d_p_end__q_th += w[_j1021]*d_fp__q_th[_j1021]
        _d_p_end__q_thd += w[_j1021]*d_fp__q_thd[_j1021]
        _d_p_end__k_d += w[_j1021]*d_fp__k_d[_j1021]
        _d_p_end__c += w[_j1021]*d_fp__c[_j1021]
        _d_p_end__guess_q_th += w[_j1021]*d_fp__guess_q_th[_j1021]
        _d_p_end__guess_q_thd += w[_j1021]*d_fp__guess_q_thd[_j1021]
        _work += w1[_j1021]*F[_j1021]
        _d_work__q_r += w1[_j1021]*d_F__q_r[_j1021]
        _d_work__q_th += w1[_j1021]*d_F__q_th[_j1021]
        _d_work__q_thd += w1[_j1021]*d_F__q_thd[_j1021]
        _d_work__k_d += w1[_j1021]*d_F__k_d[_j1021]
        _d_work__c += w1[_j1021]*d_F__c[_j1021]
        _d_work__guess_q_th += w1[_j1021]*d_F__guess_q_th[_j1021]
        _d_work__guess_q_thd += w1[_j1021]*d_F__guess_q_thd[_j1021]
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = _t_end
    end_q_th = _q_end + q_th
    d_end_q_th__q_th = _d_q_end__q_th + 1.0
    _x53 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x53
    _pd__17 = _x53/_D
    _pd__18 = _x53/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__17 + _d_work__q_r*_pd__18
    d_end_q_rd__q_th = _d_D__q_th*_pd__17 + _d_work__q_th*_pd__18
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__17 + _d_work__q_thd*_pd__18
    d_end_q_rd__k_d = _d_D__k_d*_pd__17 + _d_work__k_d*_pd__18
    d_end_q_rd__c = _d_D__c*_pd__17 + _d_work__c*_pd__18
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__17 + _d_work__guess_q_th*_pd__18
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__17 + _d_work__guess_q_thd*_pd__18
    _x54 = q_r**2
    _x55 = q_r_lo**-2
    _x56 = _x55/m
    _lo_q_thd = _x56*(_p_end + _x54*m*q_thd)
    _pd__19 = _x56
    _d_lo_q_thd__q_r = _d_p_end__q_r*_pd__19 + 2.0*_x55*q_r*q_thd
    _d_lo_q_thd__q_th = _d_p_end__q_th*_pd__19
    _d_lo_q_thd__q_thd = _d_p_end__q_thd*_pd__19 + _x54*_x55
    _d_lo_q_thd__k_d = _d_p_end__k_d*_pd__19
    _d_lo_q_thd__c = _d_p_end__c*_pd__19
    _d_lo_q_thd__guess_q_th = _d_p_end__guess_q_th*_pd__19
    _d_lo_q_thd__guess_q_thd = _d_p_end__guess_q_thd*_pd__19
    passes = _passes
    # liftoff at q_r_lo, or at q_r_b + D short of it
    _x57 = _D + q_r
    _x58 = (_D < -q_r + q_r_lo)
    end_q_r = ((_x57) if _x58 else (q_r_lo))
    _x59 = ((1.0) if _x58 else (0.0))
    _pd__20 = _x59
    d_end_q_r__q_r = _d_D__q_r*_pd__20 + _x59
    d_end_q_r__q_th = _d_D__q_th*_pd__20
    d_end_q_r__q_thd = _d_D__q_thd*_pd__20
    d_end_q_r__k_d = _d_D__k_d*_pd__20
    d_end_q_r__c = _d_D__c*_pd__20
    d_end_q_r__guess_q_th = _d_D__guess_q_th*_pd__20
    d_end_q_r__guess_q_thd = _d_D__guess_q_thd*_pd__20
    _x60 = q_r**2
    _x61 = _p_end + _x60*m*q_thd
    _x62 = (1.0/m)
    _x66 = (1.0/_x57)
    _x63 = _x66**2
    _x64 = _x62*_x63
    end_q_thd = ((_x61*_x64) if _x58 else (_lo_q_thd))
    _x65 = -2.0*_x61*_x62*_x66**3
    _pd__21 = ((_x65) if _x58 else (0.0))
    _pd__22 = ((0.0) if _x58 else (1.0))
    _pd__23 = ((_x64) if _x58 else (0.0))
    d_end_q_thd__q_r = (_d_D__q_r*_pd__21 + _d_lo_q_thd__q_r*_pd__22 + _d_p_end__q_r*_pd__23
        + ((2.0*_x63*q_r*q_thd + _x65) if _x58 else (0.0)))
    d_end_q_thd__q_th = _d_D__q_th*_pd__21 + _d_lo_q_thd__q_th*_pd__22 + _d_p_end__q_th*_pd__23
    d_end_q_thd__q_thd = (_d_D__q_thd*_pd__21 + _d_lo_q_thd__q_thd*_pd__22 + _d_p_end__q_thd*_pd__23
        + ((_x60*_x63) if _x58 else (0.0)))
    d_end_q_thd__k_d = _d_D__k_d*_pd__21 + _d_lo_q_thd__k_d*_pd__22 + _d_p_end__k_d*_pd__23
    d_end_q_thd__c = _d_D__c*_pd__21 + _d_lo_q_thd__c*_pd__22 + _d_p_end__c*_pd__23
    d_end_q_thd__guess_q_th = (_d_D__guess_q_th*_pd__21 + _d_lo_q_thd__guess_q_th*_pd__22
        + _d_p_end__guess_q_th*_pd__23)
    d_end_q_thd__guess_q_thd = (_d_D__guess_q_thd*_pd__21 + _d_lo_q_thd__guess_q_thd*_pd__22
        + _d_p_end__guess_q_thd*_pd__23)
    # derivatives of the outputs
    d_t_half__q_r = _d_t_end__q_r
    d_t_half__q_th = _d_t_end__q_th
    d_t_half__q_thd = _d_t_end__q_thd
    d_t_half__k_d = _d_t_end__k_d
    d_t_half__c = _d_t_end__c
    d_t_half__guess_q_th = _d_t_end__guess_q_th
    d_t_half__guess_q_thd = _d_t_end__guess_q_thd
    d_end_q_th__q_r = _d_q_end__q_r
    d_end_q_th__q_thd = _d_q_end__q_thd
    d_end_q_th__k_d = _d_q_end__k_d
    d_end_q_th__c = _d_q_end__c
    d_end_q_th__guess_q_th = _d_q_end__guess_q_th
    d_end_q_th__guess_q_thd = _d_q_end__guess_q_thd
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__c, d_t_half__guess_q_th, d_t_half__guess_q_thd,
        d_end_q_r__q_r, d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__c,
        d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd,
        d_end_q_rd__k_d, d_end_q_rd__c, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__c, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__c, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        ))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_core_jvp7_443a9c(_a, out):
    """Schwind and Koditschek's iteration, converging form: the stance from the touchdown state and a zeroth
    iterate, and the derivatives of its outputs along 7 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative.iterative_core`, in its order; then the components
    d_<argument>__<j> of each direction j (0 to 6) along z_b_q_r, z_b_q_th, z_b_q_thd, z_lo_q_th,
    z_lo_q_thd.

    Writes into out:
        <output>: each output of :func:`iterative.iterative_core`, in its order
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5,
            6 (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 407
    (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, c, z_b_q_r, z_b_q_th, z_b_q_thd,
        z_lo_q_th, z_lo_q_thd, held, nodes, iterations, tol, liftoff, d_z_b_q_r__0, d_z_b_q_th__0,
        d_z_b_q_thd__0, d_z_lo_q_th__0, d_z_lo_q_thd__0, d_z_b_q_r__1, d_z_b_q_th__1, d_z_b_q_thd__1,
        d_z_lo_q_th__1, d_z_lo_q_thd__1, d_z_b_q_r__2, d_z_b_q_th__2, d_z_b_q_thd__2, d_z_lo_q_th__2,
        d_z_lo_q_thd__2, d_z_b_q_r__3, d_z_b_q_th__3, d_z_b_q_thd__3, d_z_lo_q_th__3, d_z_lo_q_thd__3,
        d_z_b_q_r__4, d_z_b_q_th__4, d_z_b_q_thd__4, d_z_lo_q_th__4, d_z_lo_q_thd__4, d_z_b_q_r__5,
        d_z_b_q_th__5, d_z_b_q_thd__5, d_z_lo_q_th__5, d_z_lo_q_thd__5,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7,
        8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
        34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50))
    # compression half, k_c (report 5.2.1)
    _a0 = carray(stack(33), 33)
    store(_a0, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, c, z_b_q_r, z_b_q_th, z_b_q_thd, nodes,
        iterations, tol, d_z_b_q_r__0, d_z_b_q_th__0, d_z_b_q_thd__0, d_z_b_q_r__1, d_z_b_q_th__1,
        d_z_b_q_thd__1, d_z_b_q_r__2, d_z_b_q_th__2, d_z_b_q_thd__2, d_z_b_q_r__3, d_z_b_q_th__3,
        d_z_b_q_thd__3, d_z_b_q_r__4, d_z_b_q_th__4, d_z_b_q_thd__4, d_z_b_q_r__5, d_z_b_q_th__5,
        d_z_b_q_thd__5,))
    _o0 = carray(stack(48), 48)
    _c0 = schwind_compression_jvp7_65b25d(_a0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__0, d_t_bottom__1,
        d_t_bottom__2, d_t_bottom__3, d_t_bottom__4, d_t_bottom__5, d_t_bottom__6, d_bottom_q_r__0,
        d_bottom_q_r__1, d_bottom_q_r__2, d_bottom_q_r__3, d_bottom_q_r__4, d_bottom_q_r__5, d_bottom_q_r__6,
        d_bottom_q_th__0, d_bottom_q_th__1, d_bottom_q_th__2, d_bottom_q_th__3, d_bottom_q_th__4,
        d_bottom_q_th__5, d_bottom_q_th__6, d_bottom_q_thd__0, d_bottom_q_thd__1, d_bottom_q_thd__2,
        d_bottom_q_thd__3, d_bottom_q_thd__4, d_bottom_q_thd__5, d_bottom_q_thd__6,) = (load(_o0, 0, 1, 2, 3,
        4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37,
        38, 39, 40))
    # zeroth iterate at liftoff
    _x0 = (held == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x0 else (z_lo_q_th))
    _pd__0 = ((1.0) if _x0 else (0.0))
    _x1 = ((0.0) if _x0 else (1.0))
    _pd__1 = _x1
    d_g_lo_q_th__0 = _pd__0*d_bottom_q_th__0 + _pd__1*d_z_lo_q_th__0
    d_g_lo_q_th__1 = _pd__0*d_bottom_q_th__1 + _pd__1*d_z_lo_q_th__1
    d_g_lo_q_th__2 = _pd__0*d_bottom_q_th__2 + _pd__1*d_z_lo_q_th__2
    d_g_lo_q_th__3 = _pd__0*d_bottom_q_th__3 + _pd__1*d_z_lo_q_th__3
    d_g_lo_q_th__4 = _pd__0*d_bottom_q_th__4 + _pd__1*d_z_lo_q_th__4
    d_g_lo_q_th__5 = _pd__0*d_bottom_q_th__5 + _pd__1*d_z_lo_q_th__5
    d_g_lo_q_th__6 = _pd__0*d_bottom_q_th__6
    _x2 = q_r_lo**-2
    _x3 = _x2*bottom_q_r**2
    g_lo_q_thd = ((_x3*bottom_q_thd) if _x0 else (z_lo_q_thd))
    _pd__2 = ((2.0*_x2*bottom_q_r*bottom_q_thd) if _x0 else (0.0))
    _pd__3 = ((_x3) if _x0 else (0.0))
    _pd__4 = _x1
    d_g_lo_q_thd__0 = _pd__2*d_bottom_q_r__0 + _pd__3*d_bottom_q_thd__0 + _pd__4*d_z_lo_q_thd__0
    d_g_lo_q_thd__1 = _pd__2*d_bottom_q_r__1 + _pd__3*d_bottom_q_thd__1 + _pd__4*d_z_lo_q_thd__1
    d_g_lo_q_thd__2 = _pd__2*d_bottom_q_r__2 + _pd__3*d_bottom_q_thd__2 + _pd__4*d_z_lo_q_thd__2
    d_g_lo_q_thd__3 = _pd__2*d_bottom_q_r__3 + _pd__3*d_bottom_q_thd__3 + _pd__4*d_z_lo_q_thd__3
    d_g_lo_q_thd__4 = _pd__2*d_bottom_q_r__4 + _pd__3*d_bottom_q_thd__4 + _pd__4*d_z_lo_q_thd__4
    d_g_lo_q_thd__5 = _pd__2*d_bottom_q_r__5 + _pd__3*d_bottom_q_thd__5 + _pd__4*d_z_lo_q_thd__5
    d_g_lo_q_thd__6 = _pd__2*d_bottom_q_r__6 + _pd__3*d_bottom_q_thd__6
    # decompression half, k_d (report 3.2, 5.2.2)
    _o1 = carray(stack(48), 48)
    _c1 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_c_guess_q_th_guess_q_thd(bottom_q_r, bottom_q_rd,
        bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, c, g_lo_q_th, g_lo_q_thd, nodes, iterations, tol,
        liftoff, _o1))
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (t_decompression, _o1_1, _o1_2, liftoff_q_th, _o1_4, d_passes, _j_t_decompression__q_r,
        _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d, _j_t_decompression__c,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _j_liftoff_q_r__q_r,
        _j_liftoff_q_r__q_th, _j_liftoff_q_r__q_thd, _j_liftoff_q_r__k_d, _j_liftoff_q_r__c,
        _j_liftoff_q_r__guess_q_th, _j_liftoff_q_r__guess_q_thd, _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th,
        _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__c, _j_liftoff_q_rd__guess_q_th,
        _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r, _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__c, _j_liftoff_q_th__guess_q_th, _j_liftoff_q_th__guess_q_thd,
        _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd, _j_liftoff_q_thd__k_d,
        _j_liftoff_q_thd__c, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd,) = (load(_o1, 0, 1,
        2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
        29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40))
    # chain rule through schwind_decompression
    d_t_decompression__0 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__0
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__0 + _j_t_decompression__q_r*d_bottom_q_r__0
        + _j_t_decompression__q_th*d_bottom_q_th__0 + _j_t_decompression__q_thd*d_bottom_q_thd__0)
    d_t_decompression__1 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__1
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__1 + _j_t_decompression__q_r*d_bottom_q_r__1
        + _j_t_decompression__q_th*d_bottom_q_th__1 + _j_t_decompression__q_thd*d_bottom_q_thd__1)
    d_t_decompression__2 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__2
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__2 + _j_t_decompression__q_r*d_bottom_q_r__2
        + _j_t_decompression__q_th*d_bottom_q_th__2 + _j_t_decompression__q_thd*d_bottom_q_thd__2)
    d_t_decompression__3 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__3
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__3 + _j_t_decompression__q_r*d_bottom_q_r__3
        + _j_t_decompression__q_th*d_bottom_q_th__3 + _j_t_decompression__q_thd*d_bottom_q_thd__3)
    d_t_decompression__4 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__4
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__4 + _j_t_decompression__q_r*d_bottom_q_r__4
        + _j_t_decompression__q_th*d_bottom_q_th__4 + _j_t_decompression__q_thd*d_bottom_q_thd__4)
    d_t_decompression__5 = (_j_t_decompression__guess_q_th*d_g_lo_q_th__5
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__5 + _j_t_decompression__k_d
        + _j_t_decompression__q_r*d_bottom_q_r__5 + _j_t_decompression__q_th*d_bottom_q_th__5
        + _j_t_decompression__q_thd*d_bottom_q_thd__5)
    d_t_decompression__6 = (_j_t_decompression__c + _j_t_decompression__guess_q_th*d_g_lo_q_th__6
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__6 + _j_t_decompression__q_r*d_bottom_q_r__6
        + _j_t_decompression__q_th*d_bottom_q_th__6 + _j_t_decompression__q_thd*d_bottom_q_thd__6)
    d_liftoff_q_r__0 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__0
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__0 + _j_liftoff_q_r__q_r*d_bottom_q_r__0
        + _j_liftoff_q_r__q_th*d_bottom_q_th__0 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__0)
    d_liftoff_q_r__1 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__1
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__1 + _j_liftoff_q_r__q_r*d_bottom_q_r__1
        + _j_liftoff_q_r__q_th*d_bottom_q_th__1 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__1)
    d_liftoff_q_r__2 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__2
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__2 + _j_liftoff_q_r__q_r*d_bottom_q_r__2
        + _j_liftoff_q_r__q_th*d_bottom_q_th__2 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__2)
    d_liftoff_q_r__3 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__3
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__3 + _j_liftoff_q_r__q_r*d_bottom_q_r__3
        + _j_liftoff_q_r__q_th*d_bottom_q_th__3 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__3)
    d_liftoff_q_r__4 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__4
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__4 + _j_liftoff_q_r__q_r*d_bottom_q_r__4
        + _j_liftoff_q_r__q_th*d_bottom_q_th__4 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__4)
    d_liftoff_q_r__5 = (_j_liftoff_q_r__guess_q_th*d_g_lo_q_th__5
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__5 + _j_liftoff_q_r__k_d
        + _j_liftoff_q_r__q_r*d_bottom_q_r__5 + _j_liftoff_q_r__q_th*d_bottom_q_th__5
        + _j_liftoff_q_r__q_thd*d_bottom_q_thd__5)
    d_liftoff_q_r__6 = (_j_liftoff_q_r__c + _j_liftoff_q_r__guess_q_th*d_g_lo_q_th__6
        + _j_liftoff_q_r__guess_q_thd*d_g_lo_q_thd__6 + _j_liftoff_q_r__q_r*d_bottom_q_r__6
        + _j_liftoff_q_r__q_th*d_bottom_q_th__6 + _j_liftoff_q_r__q_thd*d_bottom_q_thd__6)
    d_liftoff_q_rd__0 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__0
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__0 + _j_liftoff_q_rd__q_r*d_bottom_q_r__0
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__0 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__0)
    d_liftoff_q_rd__1 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__1
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__1 + _j_liftoff_q_rd__q_r*d_bottom_q_r__1
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__1 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__1)
    d_liftoff_q_rd__2 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__2
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__2 + _j_liftoff_q_rd__q_r*d_bottom_q_r__2
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__2 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__2)
    d_liftoff_q_rd__3 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__3
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__3 + _j_liftoff_q_rd__q_r*d_bottom_q_r__3
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__3 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__3)
    d_liftoff_q_rd__4 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__4
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__4 + _j_liftoff_q_rd__q_r*d_bottom_q_r__4
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__4 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__4)
    d_liftoff_q_rd__5 = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__5
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__5 + _j_liftoff_q_rd__k_d
        + _j_liftoff_q_rd__q_r*d_bottom_q_r__5 + _j_liftoff_q_rd__q_th*d_bottom_q_th__5
        + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__5)
    d_liftoff_q_rd__6 = (_j_liftoff_q_rd__c + _j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__6
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__6 + _j_liftoff_q_rd__q_r*d_bottom_q_r__6
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__6 + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__6)
    d_liftoff_q_th__0 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__0
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__0 + _j_liftoff_q_th__q_r*d_bottom_q_r__0
        + _j_liftoff_q_th__q_th*d_bottom_q_th__0 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__0)
    d_liftoff_q_th__1 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__1
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__1 + _j_liftoff_q_th__q_r*d_bottom_q_r__1
        + _j_liftoff_q_th__q_th*d_bottom_q_th__1 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__1)
    d_liftoff_q_th__2 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__2
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__2 + _j_liftoff_q_th__q_r*d_bottom_q_r__2
        + _j_liftoff_q_th__q_th*d_bottom_q_th__2 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__2)
    d_liftoff_q_th__3 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__3
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__3 + _j_liftoff_q_th__q_r*d_bottom_q_r__3
        + _j_liftoff_q_th__q_th*d_bottom_q_th__3 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__3)
    d_liftoff_q_th__4 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__4
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__4 + _j_liftoff_q_th__q_r*d_bottom_q_r__4
        + _j_liftoff_q_th__q_th*d_bottom_q_th__4 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__4)
    d_liftoff_q_th__5 = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__5
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__5 + _j_liftoff_q_th__k_d
        + _j_liftoff_q_th__q_r*d_bottom_q_r__5 + _j_liftoff_q_th__q_th*d_bottom_q_th__5
        + _j_liftoff_q_th__q_thd*d_bottom_q_thd__5)
    d_liftoff_q_th__6 = (_j_liftoff_q_th__c + _j_liftoff_q_th__guess_q_th*d_g_lo_q_th__6
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__6 + _j_liftoff_q_th__q_r*d_bottom_q_r__6
        + _j_liftoff_q_th__q_th*d_bottom_q_th__6 + _j_liftoff_q_th__q_thd*d_bottom_q_thd__6)
    d_liftoff_q_thd__0 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__0
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__0 + _j_liftoff_q_thd__q_r*d_bottom_q_r__0
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__0 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__0)
    d_liftoff_q_thd__1 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__1
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__1 + _j_liftoff_q_thd__q_r*d_bottom_q_r__1
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__1 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__1)
    d_liftoff_q_thd__2 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__2
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__2 + _j_liftoff_q_thd__q_r*d_bottom_q_r__2
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__2 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__2)
    d_liftoff_q_thd__3 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__3
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__3 + _j_liftoff_q_thd__q_r*d_bottom_q_r__3
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__3 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__3)
    d_liftoff_q_thd__4 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__4
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__4 + _j_liftoff_q_thd__q_r*d_bottom_q_r__4
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__4 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__4)
    d_liftoff_q_thd__5 = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__5
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__5 + _j_liftoff_q_thd__k_d
        + _j_liftoff_q_thd__q_r*d_bottom_q_r__5 + _j_liftoff_q_thd__q_th*d_bottom_q_th__5
        + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__5)
    d_liftoff_q_thd__6 = (_j_liftoff_q_thd__c + _j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__6
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__6 + _j_liftoff_q_thd__q_r*d_bottom_q_r__6
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__6 + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__6)
    t_stance = t_bottom + t_decompression
    d_t_stance__0 = d_t_bottom__0 + d_t_decompression__0
    d_t_stance__1 = d_t_bottom__1 + d_t_decompression__1
    d_t_stance__2 = d_t_bottom__2 + d_t_decompression__2
    d_t_stance__3 = d_t_bottom__3 + d_t_decompression__3
    d_t_stance__4 = d_t_bottom__4 + d_t_decompression__4
    d_t_stance__5 = d_t_bottom__5 + d_t_decompression__5
    d_t_stance__6 = d_t_bottom__6 + d_t_decompression__6
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, _o1_1, _o1_2,
        liftoff_q_th, _o1_4, passes, d_t_bottom__0, d_t_bottom__1, d_t_bottom__2, d_t_bottom__3,
        d_t_bottom__4, d_t_bottom__5, d_t_bottom__6, d_t_stance__0, d_t_stance__1, d_t_stance__2,
        d_t_stance__3, d_t_stance__4, d_t_stance__5, d_t_stance__6, d_bottom_q_r__0, d_bottom_q_r__1,
        d_bottom_q_r__2, d_bottom_q_r__3, d_bottom_q_r__4, d_bottom_q_r__5, d_bottom_q_r__6, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.0, d_bottom_q_th__0, d_bottom_q_th__1, d_bottom_q_th__2, d_bottom_q_th__3,
        d_bottom_q_th__4, d_bottom_q_th__5, d_bottom_q_th__6, d_bottom_q_thd__0, d_bottom_q_thd__1,
        d_bottom_q_thd__2, d_bottom_q_thd__3, d_bottom_q_thd__4, d_bottom_q_thd__5, d_bottom_q_thd__6,
        d_liftoff_q_r__0, d_liftoff_q_r__1, d_liftoff_q_r__2, d_liftoff_q_r__3, d_liftoff_q_r__4,
        d_liftoff_q_r__5, d_liftoff_q_r__6, d_liftoff_q_rd__0, d_liftoff_q_rd__1, d_liftoff_q_rd__2,
        d_liftoff_q_rd__3, d_liftoff_q_rd__4, d_liftoff_q_rd__5, d_liftoff_q_rd__6, d_liftoff_q_th__0,
        d_liftoff_q_th__1, d_liftoff_q_th__2, d_liftoff_q_th__3, d_liftoff_q_th__4, d_liftoff_q_th__5,
        d_liftoff_q_th__6, d_liftoff_q_thd__0, d_liftoff_q_thd__1, d_liftoff_q_thd__2, d_liftoff_q_thd__3,
        d_liftoff_q_thd__4, d_liftoff_q_thd__5, d_liftoff_q_thd__6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy", inline="always")
def iterative_stance_jacobian_zeroth_shared(x, p, out, zeroth_jac, constant0):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    The body that 9 kernels share, each passing the kernel it calls as zeroth_jac and its
    constant as constant0 (derive/share.py): iterative_stance_jacobian_zeroth_{geyer, held,
    gravity_type0, gravity_type1, gravity_type2, gravity_type3, gravity_type4, gravity_type5,
    geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth_jac, constant0.
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
    _o0 = carray(stack(35), 35)
    _c0 = zeroth_jac(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_6, _o0_7, _o0_8, _o0_9, _o0_10, _o0_11, _o0_12, _o0_13,
        _o0_14, _o0_15, _o0_16, _o0_17, _o0_18, _o0_19, _o0_20, _o0_21, _o0_22, _o0_23, _o0_24, _o0_25,
        _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32, _o0_33, _o0_34,) = (load(_o0, 0, 1, 2, 3, 4,
        5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31,
        32, 33, 34))
    # the iteration from the zeroth iterate
    _a1 = carray(stack(51), 51)
    store(_a1, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, c, _o0_0, _o0_1, _o0_2,
        _o0_3, _o0_4, constant0, nodes, iterations, tol, liftoff, _o0_5, _o0_11, _o0_17, _o0_23, _o0_29,
        _o0_6, _o0_12, _o0_18, _o0_24, _o0_30, _o0_7, _o0_13, _o0_19, _o0_25, _o0_31, _o0_8, _o0_14, _o0_20,
        _o0_26, _o0_32, _o0_9, _o0_15, _o0_21, _o0_27, _o0_33, _o0_10, _o0_16, _o0_22, _o0_28, _o0_34,))
    _o1 = carray(stack(88), 88)
    _c1 = iterative_core_jvp7_443a9c(_a1, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_0, _o1_1, _o1_2, _o1_3, _o1_4, _o1_5, _o1_6, _o1_7, _o1_8, _o1_9, _o1_10, _o1_11, _o1_12, _o1_13,
        _o1_14, _o1_15, _o1_16, _o1_17, _o1_18, _o1_19, _o1_20, _o1_21, _o1_22, _o1_23, _o1_24, _o1_25,
        _o1_26, _o1_27, _o1_28, _o1_29, _o1_30, _o1_31, _o1_39, _o1_40, _o1_41, _o1_42, _o1_43, _o1_44,
        _o1_45, _o1_46, _o1_47, _o1_48, _o1_49, _o1_50, _o1_51, _o1_52, _o1_53, _o1_54, _o1_55, _o1_56,
        _o1_57, _o1_58, _o1_59, _o1_60, _o1_61, _o1_62, _o1_63, _o1_64, _o1_65, _o1_66, _o1_67, _o1_68,
        _o1_69, _o1_70, _o1_71, _o1_72, _o1_73, _o1_74, _o1_75, _o1_76, _o1_77, _o1_78, _o1_79, _o1_80,
        ) = (load(_o1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23,
        24, 25, 26, 27, 28, 29, 30, 31, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55,
        56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80))
    # every output finite, or the inputs were far outside a physical range
    store(out, (_o1_0, _o1_1, _o1_2, _o1_3, _o1_4, _o1_5, _o1_6, _o1_7, _o1_8, _o1_9, _o1_10, _o1_11, _o1_12,
        _o1_13, _o1_14, _o1_15, _o1_16, _o1_17, _o1_18, _o1_19, _o1_20, _o1_21, _o1_22, _o1_23, _o1_24,
        _o1_25, _o1_26, _o1_27, _o1_28, _o1_29, _o1_30, _o1_31, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, _o1_39,
        _o1_40, _o1_41, _o1_42, _o1_43, _o1_44, _o1_45, _o1_46, _o1_47, _o1_48, _o1_49, _o1_50, _o1_51,
        _o1_52, _o1_53, _o1_54, _o1_55, _o1_56, _o1_57, _o1_58, _o1_59, _o1_60, _o1_61, _o1_62, _o1_63,
        _o1_64, _o1_65, _o1_66, _o1_67, _o1_68, _o1_69, _o1_70, _o1_71, _o1_72, _o1_73, _o1_74, _o1_75,
        _o1_76, _o1_77, _o1_78, _o1_79, _o1_80, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_geyer(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`iterative.iterative_stance_zeroth_geyer`, in its order.

    Writes into out:
        <output>: each output of :func:`iterative.iterative_stance_zeroth_geyer`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_tail_a4def6(_a, out):
    """The code of iterative_apex_return_jacobian's kernels per choice after their choice's own calls, shared
    by the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

    Writes into out:
        <output>: each output of :func:`iterative.iterative_apex_return_zeroth_geyer`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 347
    (_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex, _j_foot_x__ground, _j_foot_x__q_th_td,
        _j_foot_x__retraction_rate, _j_liftoff_q_r__c, _j_liftoff_q_r__k_c, _j_liftoff_q_r__k_d,
        _j_liftoff_q_r__q_rd_td, _j_liftoff_q_r__q_th_td, _j_liftoff_q_r__q_thd_td, _j_liftoff_q_rd__c,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td,
        _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__c, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d,
        _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_thd__c,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_descent__retraction_rate, _j_t_stance__c, _j_t_stance__k_c, _j_t_stance__k_d,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_td_q_rd__b_xd_apex,
        _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td, _j_td_q_rd__retraction_rate,
        _j_td_q_th__b_y_apex, _j_td_q_th__ground, _j_td_q_th__q_th_td, _j_td_q_th__retraction_rate,
        _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground, _j_td_q_thd__q_th_td,
        _j_td_q_thd__retraction_rate, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, t_descent, t_stance, td_q_th,) = (load(_a, 0, 1, 2, 3, 4, 5, 6,
        7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32,
        33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57,
        58, 59, 60, 61, 62, 63, 64, 65))
    # chain rule through iterative_stance
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
    # liftoff -> next apex: exact ballistic ascent
    _o0 = carray(stack(25), 25)
    _c0 = (liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        g_f, direction, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, next_apex_x, _j_apex_height__q_r, _j_apex_height__q_rd, _j_apex_height__q_th,
        _j_apex_height__q_thd, _j_apex_speed__q_r, _j_apex_speed__q_rd, _j_apex_speed__q_th,
        _j_apex_speed__q_thd, _j_t_ascent__q_r, _j_t_ascent__q_rd, _j_t_ascent__q_th, _j_t_ascent__q_thd,
        _j_next_apex_x__q_r, _j_next_apex_x__q_rd, _j_next_apex_x__q_th, _j_next_apex_x__q_thd,) = (load(_o0,
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
    touchdown_q_th = td_q_th
    # derivatives of the outputs
    d_t_descent__b_y_apex = _j_t_descent__b_y_apex
    d_t_descent__q_th_td = _j_t_descent__q_th_td
    d_t_descent__ground = _j_t_descent__ground
    d_t_descent__retraction_rate = _j_t_descent__retraction_rate
    d_t_stance__k_c = _j_t_stance__k_c
    d_t_stance__k_d = _j_t_stance__k_d
    d_t_stance__c = _j_t_stance__c
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
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by the role kernels that return them)
    if not (all_finite((_o0_0, _o0_1, t_descent, t_stance, _o0_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
            liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (_o0_0, _o0_1, t_descent, t_stance, _o0_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, passes, d_apex_height__b_y_apex,
        d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground,
        d_apex_height__retraction_rate, d_apex_height__k_c, d_apex_height__k_d, d_apex_height__c,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__retraction_rate, d_apex_speed__k_c, d_apex_speed__k_d, d_apex_speed__c,
        d_t_descent__b_y_apex, 0.0, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__retraction_rate,
        0.0, 0.0, 0.0, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, d_t_stance__k_c, d_t_stance__k_d, d_t_stance__c, d_t_ascent__b_y_apex,
        d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__retraction_rate,
        d_t_ascent__k_c, d_t_ascent__k_d, d_t_ascent__c, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex,
        d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__retraction_rate, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_r__c, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex,
        d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c,
        d_liftoff_q_rd__k_d, d_liftoff_q_rd__c, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex,
        d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_th__c, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex,
        d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__retraction_rate,
        d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_liftoff_q_thd__c, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d, d_step_length__c,
        d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground,
        d_foot_x__retraction_rate, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0,
        d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td, d_touchdown_q_th__ground,
        d_touchdown_q_th__retraction_rate, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy", inline="always")
def iterative_apex_return_jacobian_zeroth_shared(x, p, out, iterative_stance_jacobian_zeroth):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    The body that 9 kernels share, each passing the kernel it calls as
    iterative_stance_jacobian_zeroth (derive/share.py):
    iterative_apex_return_jacobian_zeroth_{geyer, held, gravity_type0, gravity_type1,
    gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then iterative_stance_jacobian_zeroth.
    """
    # Total ops: 1
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
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_11, _o0_12, _o0_13, _o0_14, _o0_15, _o0_16, _o0_18, _o0_19,
        _o0_20, _o0_21, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32,
        _o0_33, _o0_34, _o0_35,) = (load(_o0, 0, 1, 2, 3, 4, 5, 11, 12, 13, 14, 15, 16, 18, 19, 20, 21, 22,
        23, 24, 25, 26, 28, 29, 30, 31, 32, 33, 34, 35))
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(88), 88)
    _c1 = iterative_stance_jacobian_zeroth(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, _o1_6, _o1_7, _o1_8, _o1_9, _o1_10, _o1_19, _o1_20, _o1_21, _o1_22, _o1_23, _o1_24, _o1_54,
        _o1_55, _o1_56, _o1_57, _o1_58, _o1_59, _o1_61, _o1_62, _o1_63, _o1_64, _o1_65, _o1_66, _o1_68,
        _o1_69, _o1_70, _o1_71, _o1_72, _o1_73, _o1_75, _o1_76, _o1_77, _o1_78, _o1_79, _o1_80,) = (load(_o1,
        1, 6, 7, 8, 9, 10, 19, 20, 21, 22, 23, 24, 54, 55, 56, 57, 58, 59, 61, 62, 63, 64, 65, 66, 68, 69, 70,
        71, 72, 73, 75, 76, 77, 78, 79, 80))
    # the code shared between choices
    _a2 = carray(stack(66), 66)
    store(_a2, (_o0_32, _o0_31, _o0_34, _o0_33, _o0_35, _o1_59, _o1_57, _o1_58, _o1_54, _o1_55, _o1_56,
        _o1_66, _o1_64, _o1_65, _o1_61, _o1_62, _o1_63, _o1_73, _o1_71, _o1_72, _o1_68, _o1_69, _o1_70,
        _o1_80, _o1_78, _o1_79, _o1_75, _o1_76, _o1_77, _o0_26, _o0_29, _o0_28, _o0_30, _o1_24, _o1_22,
        _o1_23, _o1_19, _o1_20, _o1_21, _o0_12, _o0_11, _o0_14, _o0_13, _o0_15, _o0_16, _o0_19, _o0_18,
        _o0_20, _o0_22, _o0_21, _o0_24, _o0_23, _o0_25, b_y_apex, direction, _o0_5, g_f, ground, _o1_6, _o1_7,
        _o1_8, _o1_9, _o1_10, _o0_4, _o1_1, _o0_2,))
    _status = iterative_apex_return_jacobian_tail_a4def6(_a2, out)
    if _status == STATUS_OK and not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return _status


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_geyer(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_geyer.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`iterative.iterative_apex_return_zeroth_geyer`, in its order.

    Writes into out:
        <output>: each output of :func:`iterative.iterative_apex_return_zeroth_geyer`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_apex_return_jacobian_zeroth_shared(x, p, out, iterative_stance_jacobian_zeroth_geyer)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_held(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 1.0. Equations, arguments, returns
    and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 1.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_held(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_held. Equations, arguments, returns and status: those of
    :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_jacobian_zeroth_shared(x, p, out, iterative_stance_jacobian_zeroth_held)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type0(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type0(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type0. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type1(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type1(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type1. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type1))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type2(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type2(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type2. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type2))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type3(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type3(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type3. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type3))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type4(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type4(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type4. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type4))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type5(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type5(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_gravity_type5. Equations, arguments, returns and status:
    those of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_stance_jacobian_zeroth_gravity_type5))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_geyer_vs(x, p, out):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_stance_jacobian_zeroth_shared` with
    zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_stance_jacobian_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_stance_jacobian_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_stance_jacobian_zeroth_geyer_vs(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_geyer_vs(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_apex_return_jacobian_zeroth_shared` with
    iterative_stance_jacobian_zeroth_geyer_vs. Equations, arguments, returns and status: those
    of :func:`iterative_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_apex_return_jacobian_zeroth_shared(x, p, out, iterative_stance_jacobian_zeroth_geyer_vs)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_apex_return_jacobian_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_apex_return_jacobian_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_apex_return_jacobian_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
