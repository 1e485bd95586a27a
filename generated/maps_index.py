# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/mapspec.py
# Template:  derive/templates/maps_index.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""The index of every declared map and of the names the kernels share (plain data, no numba).

The runtime API (``slipmaps.maps()``, ``slipmaps.stance`` ...), the command line, the tests that
run over every map and the benchmark read this module; nothing else lists the maps or the output
layouts. ``MAPS`` rows: name, title, report section, equations, requirements, parameters,
options (kind, default, choices), generated module and kernel names, argument orders, extras.
A list or dict the tables repeat (a layout, an option) is written once, as
``_repeated<i>`` before its first use, and named where it recurs (derive/wrap.py,
``intern_repeats``): the same object, which no reader modifies.
"""

STANCE_OUTPUTS = [{'name': 't_bottom', 'doc': 'time from touchdown to the bottom', 'unit': 's', 'odd': False},
    {'name': 't_stance', 'doc': 'stance time, touchdown to liftoff', 'unit': 's', 'odd': False}, {'name':
    'bottom_q_r', 'doc': 'leg length', 'unit': 'm', 'odd': False}, {'name': 'bottom_q_rd', 'doc':
    'leg length rate', 'unit': 'm/s', 'odd': False}, {'name': 'bottom_q_th', 'doc':
    'leg angle from the vertical, counterclockwise positive', 'unit': 'rad', 'odd': True}, {'name':
    'bottom_q_thd', 'doc': 'leg angle rate', 'unit': 'rad/s', 'odd': True}, {'name': 'liftoff_q_r', 'doc':
    'leg length', 'unit': 'm', 'odd': False}, {'name': 'liftoff_q_rd', 'doc': 'leg length rate', 'unit':
    'm/s', 'odd': False}, {'name': 'liftoff_q_th', 'doc':
    'leg angle from the vertical, counterclockwise positive', 'unit': 'rad', 'odd': True}, {'name':
    'liftoff_q_thd', 'doc': 'leg angle rate', 'unit': 'rad/s', 'odd': True}]

APEX_OUTPUTS = [{'name': 'apex_height', 'doc': 'next apex height above the ground the foot stood on', 'unit':
    'm', 'odd': False}, {'name': 'apex_speed', 'doc': 'next apex horizontal speed (signed)', 'unit': 'm/s',
    'odd': True}, {'name': 't_descent', 'doc': 'flight time from the apex to touchdown', 'unit': 's', 'odd':
    False}, {'name': 't_stance', 'doc': 'stance time, touchdown to liftoff', 'unit': 's', 'odd': False}, {
    'name': 't_ascent', 'doc': 'flight time from liftoff to the next apex', 'unit': 's', 'odd': False}, {
    'name': 'liftoff_q_r', 'doc': 'leg length', 'unit': 'm', 'odd': False}, {'name': 'liftoff_q_rd', 'doc':
    'leg length rate', 'unit': 'm/s', 'odd': False}, {'name': 'liftoff_q_th', 'doc':
    'leg angle from the vertical, counterclockwise positive', 'unit': 'rad', 'odd': True}, {'name':
    'liftoff_q_thd', 'doc': 'leg angle rate', 'unit': 'rad/s', 'odd': True}, {'name': 'step_length', 'doc':
    'horizontal distance from the apex to the next apex (signed)', 'unit': 'm', 'odd': True}, {'name':
    'foot_x', 'doc': 'horizontal position of the foot at touchdown relative to the apex', 'unit': 'm', 'odd':
    True}, {'name': 'foot_y', 'doc':
    'height of the foot (the touchdown ground) relative to the apex: ground - apex height', 'unit': 'm',
    'odd': False}, {'name': 'touchdown_q_th', 'doc':
    'leg angle the foot touched down with: touchdown_angle + retraction_rate * t_descent', 'unit': 'rad',
    'odd': True}]

TRAJECTORY_OUTPUTS = [{'name': 'q_r', 'doc': 'leg length', 'unit': 'm', 'odd': False}, {'name': 'q_rd', 'doc':
    'leg length rate', 'unit': 'm/s', 'odd': False}, {'name': 'q_th', 'doc':
    'leg angle from the vertical, counterclockwise positive', 'unit': 'rad', 'odd': True}, {'name': 'q_thd',
    'doc': 'leg angle rate', 'unit': 'rad/s', 'odd': True}]

HALF_OUTPUTS = [{'name': 't_half', 'doc': 'time from the start state to the end state', 'unit': 's', 'odd':
    False}, {'name': 'end_q_r', 'doc': 'leg length', 'unit': 'm', 'odd': False}, {'name': 'end_q_rd', 'doc':
    'leg length rate', 'unit': 'm/s', 'odd': False}, {'name': 'end_q_th', 'doc':
    'leg angle from the vertical, counterclockwise positive', 'unit': 'rad', 'odd': True}, {'name':
    'end_q_thd', 'doc': 'leg angle rate', 'unit': 'rad/s', 'odd': True}]

GROUPS = {'bottom': ('bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd'), 'liftoff': ('liftoff_q_r',
    'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd'), 'end': ('end_q_r', 'end_q_rd', 'end_q_th', 'end_q_thd')}

TOUCHDOWN = ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td']

APEX_PUBLIC = {'b_y_apex': 'apex_height', 'b_xd_apex': 'apex_speed', 'q_th_td': 'touchdown_angle', 'ground':
    'ground', 'retraction_rate': 'retraction_rate'}

_repeated0 = ['t_bottom', 't_stance', 'bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd',
    'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd']

_repeated1 = ['apex_height', 'apex_speed', 't_descent', 't_stance', 't_ascent', 'liftoff_q_r', 'liftoff_q_rd',
    'liftoff_q_th', 'liftoff_q_thd', 'step_length', 'foot_x', 'foot_y', 'touchdown_q_th']

_repeated2 = [{'value': 'force', 'doc':
    'where the leg force k_d (l0 - q_r) - c q_rd falls to 0, or at q_r = q_r_lo if first'}, {'value':
    'length', 'doc': "at q_r = q_r_lo (the leg's pull on the ground ignored)"}]

_repeated3 = {'name': 'liftoff', 'kind': 'choice', 'default': 'force', 'doc':
    'where a damped leg lifts off (the same liftoff at c = 0)', 'choices': _repeated2, 'low': None, 'high':
    None, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': []}

_repeated4 = {'name': 'tol', 'kind': 'float', 'default': 1e-12, 'doc':
    'stop when P_c moves by at most tol times the momentum scale; 0: run all passes', 'choices': [], 'low':
    0.0, 'high': 1.0, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'tolerance']}

_repeated5 = {'name': 'P_c_compression', 'doc': 'virtual gravity effect of the first half (0 unless gravity)',
    'unit': 'N m s', 'odd': True}

_repeated6 = [_repeated5, {'name': 'P_c_decompression', 'doc': 'virtual gravity effect of the second half',
    'unit': 'N m s', 'odd': True}, {'name': 'passes', 'doc': 'fixed-point passes run (0 unless gravity)',
    'unit': '', 'odd': False}]

_repeated7 = ['t_bottom', 't_stance', 'bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd',
    'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd', 'P_c_compression', 'P_c_decompression',
    'passes']

_repeated8 = ['apex_height', 'apex_speed', 't_descent', 't_stance', 't_ascent', 'liftoff_q_r', 'liftoff_q_rd',
    'liftoff_q_th', 'liftoff_q_thd', 'step_length', 'foot_x', 'foot_y', 'touchdown_q_th', 'P_c_compression',
    'P_c_decompression', 'passes']

_repeated9 = {'value': 'factor', 'doc':
    'only 1/H^{-1} at the point, the weights 1/sigma^2 and sigma integrated exactly: (133)-(135), '
    '(148)-(150), with (134)/(149) keeping p_th' }

_repeated10 = [{'value': 'integrand', 'doc':
    'the whole integrand at the point: (42)-(44), (124)-(126), (139)-(141)'}, _repeated9]

_repeated11 = {'name': 'variant', 'kind': 'choice', 'default': 'integrand', 'doc':
    'which mean-value form each step uses', 'choices': _repeated10, 'low': None, 'high': None,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-variants',
    'convergence-series']}

_repeated12 = {'name': 'iterations', 'kind': 'int', 'default': 1, 'doc':
    "iterations n of each half's chain (0 = the zeroth iterate)", 'choices': [], 'low': 0, 'high': 100,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-passes',
    'convergence-passes']}

_repeated13 = {'value': 'gravity-type4', 'doc':
    'Gravity correction type 4 (average leg length on [t_i, t_f]) (section 4.5) with k_c'}

_repeated14 = [{'value': 'geyer', 'doc': "Geyer et al.'s map (section 3.1) with k_c"}, {'value': 'held',
    'doc': 'the touchdown state held (q_th, p_th constant), bottom from the radial work at touchdown'}, {
    'value': 'gravity-type0', 'doc': 'Gravity correction type 0 (leg length l0) (section 4.1) with k_c'}, {
    'value': 'gravity-type1', 'doc':
    'Gravity correction type 1 (leg length (l0 + q_r_b)/2) (section 4.2) with k_c'}, {'value':
    'gravity-type2', 'doc': 'Gravity correction type 2 (average leg length) (section 4.3) with k_c'}, {
    'value': 'gravity-type3', 'doc':
    'Gravity correction type 3 (trapezoid on [t_i, t_f]) (section 4.4) with k_c'}, _repeated13, {'value':
    'gravity-type5', 'doc': 'Gravity correction type 5 (time-varying momentum) (section 4.6) with k_c'}, {
    'value': 'geyer-vs', 'doc':
    'Simple variable-stiffness map (Geyer et al. per half) (section 5.1) with k_c, k_d'}]

_repeated15 = {'name': 'zeroth', 'kind': 'choice', 'default': 'geyer', 'doc':
    "zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), "
    "linear in u between the half's ends", 'choices': _repeated14, 'low': None, 'high': None,
    'at_rest_length': [], 'kernel': False, 'specialize': True, 'backends': {}, 'roles': ['accuracy-variants']}

_repeated16 = [{'value': 'zeroth', 'doc':
    "the zeroth iterate's bottom (with Geyer's map: (154), l0 (1 + a_ab - b_ab))"}, {'value': 'eq153', 'doc':
    "the quartic (153) of a vertical bottom with the touchdown's energy and momentum"}]

_repeated17 = {'name': 'bottom_length', 'kind': 'choice', 'default': 'zeroth', 'doc':
    'the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates)', 'choices':
    _repeated16, 'low': None, 'high': None, 'at_rest_length': [], 'kernel': True, 'specialize': False,
    'backends': {}, 'roles': ['accuracy-variants']}

_repeated18 = [_repeated11, _repeated12, _repeated15, _repeated17]

_repeated19 = {'geyer': '_zeroth_geyer', 'held': '_zeroth_held', 'gravity-type0': '_zeroth_gravity_type0',
    'gravity-type1': '_zeroth_gravity_type1', 'gravity-type2': '_zeroth_gravity_type2', 'gravity-type3':
    '_zeroth_gravity_type3', 'gravity-type4': '_zeroth_gravity_type4', 'gravity-type5':
    '_zeroth_gravity_type5', 'geyer-vs': '_zeroth_geyer_vs'}

_repeated20 = {'value': 'mean', 'doc':
    'trajectory with the stance-mean momentum p_th + P_c/2 (constant torque of (48)), rates from '
    'the momentum at that instant, liftoff radial speed from the exact energy (27)' }

_repeated21 = [_repeated20, {'value': 'report', 'doc':
    "p_th + P_c everywhere in Geyer's formulas, liftoff radial speed from Geyer's (11)"}]

_repeated22 = {'name': 'reading', 'kind': 'choice', 'default': 'mean', 'doc':
    "how P_c enters Geyer's formulas, eq (50)", 'choices': _repeated21, 'low': None, 'high': None,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-readings']}

_repeated23 = {'name': 'samples', 'kind': 'int', 'default': 2, 'doc':
    'number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the bottom)', 'choices': [], 'low': 2,
    'high': 3, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'accuracy-variants']}

_repeated24 = [{'name': 'P_c', 'doc': 'virtual gravity effect: the stance impulse added to p_th', 'unit':
    'N m s', 'odd': True}, {'name': 'passes', 'doc': 'fixed-point passes run', 'unit': '', 'odd': False}]

_repeated25 = ['t_bottom', 't_stance', 'bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd',
    'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd', 'P_c', 'passes']

_repeated26 = ['apex_height', 'apex_speed', 't_descent', 't_stance', 't_ascent', 'liftoff_q_r',
    'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd', 'step_length', 'foot_x', 'foot_y', 'touchdown_q_th',
    'P_c', 'passes']

_repeated27 = {'name': 'iterations', 'kind': 'int', 'default': 100, 'doc':
    "passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map)", 'choices': [], 'low': 0, 'high': 1000,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-passes']}

_repeated28 = [{'value': 'eq11', 'doc':
    '(11), eqs (55)-(57) and (67)-(68) (their printed forms lack an l0 on the b term)'}, {'value': 'eq21',
    'doc': '(21), eqs (58)-(59) and (70)-(72); touchdown at l0 only'}, {'value': 'eq23', 'doc':
    '(23), eqs (60)-(61) and (73)-(75); touchdown at l0 only'}]

_repeated29 = {'name': 'leg_length', 'kind': 'choice', 'default': 'eq11', 'doc':
    'the stance solution the average leg length is taken from', 'choices': _repeated28, 'low': None, 'high':
    None, 'at_rest_length': ['eq21', 'eq23'], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'accuracy-variants']}

_repeated30 = {'value': 'halves', 'doc':
    "touchdown to bottom and bottom to liftoff, summed (the report's suggestion for the split "
    'maps of section 5)' }

_repeated31 = [{'value': 'stance', 'doc': 'one interval, touchdown to liftoff'}, _repeated30]

_repeated32 = {'name': 'interval', 'kind': 'choice', 'default': 'halves', 'doc':
    'the intervals [t_i, t_f] of the correction', 'choices': _repeated31, 'low': None, 'high': None,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-variants']}

_repeated33 = [{'value': '1', 'doc': '1 node'}, {'value': '2', 'doc': '2 nodes'}, {'value': '3', 'doc':
    '3 nodes'}, {'value': '4', 'doc': '4 nodes'}, {'value': '6', 'doc': '6 nodes'}]

_repeated34 = {'name': 'nodes', 'kind': 'choice', 'default': '4', 'doc':
    "Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41))", 'choices':
    _repeated33, 'low': None, 'high': None, 'at_rest_length': [], 'kernel': True, 'specialize': False,
    'backends': {}, 'roles': ['accuracy-variants']}

_repeated35 = {'name': 'iterations', 'kind': 'int', 'default': 6, 'doc':
    'Picard passes per half-stance (0 = the zeroth iterate)', 'choices': [], 'low': 0, 'high': 100,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-passes',
    'convergence-passes']}

_repeated36 = {'name': 'tol', 'kind': 'float', 'default': 0.0, 'doc':
    'stop when no node value moves by more than tol (relative; 0 = run every pass)', 'choices': [], 'low':
    0.0, 'high': 1.0, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'tolerance']}

_repeated37 = ['t_bottom', 't_stance', 'bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd',
    'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd', 'passes']

_repeated38 = ['apex_height', 'apex_speed', 't_descent', 't_stance', 't_ascent', 'liftoff_q_r',
    'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd', 'step_length', 'foot_x', 'foot_y', 'touchdown_q_th',
    'passes']

MAPS = [{'name': 'geyer', 'title': "Geyer et al.'s approximate stance map", 'section': '3.1', 'equations': [
    '7', '8', '9', '10', '11', '12', '13', '14', '17', '18', '19', '20'], 'params': ['m', 'l0', 'k', 'g_s'],
    'options': [], 'module': 'geyer', 'summary':
    'angular momentum conserved (small sweep), 1/(1+rho)^2 by its Taylor polynomial (small compression)',
    'roles': ['baseline', 'accuracy-figure', 'region', 'default'], 'specialized': [], 'choices': {}, 'extras':
    [], 'requires': ['constant_stiffness'], 'as_printed': False, 'approximation_statuses': [], 'kernels': {
    'stance': {'module': 'geyer', 'name': 'geyer_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'],
    'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo'], 'out': _repeated0}, 'apex_return': {'module':
    'geyer', 'name': 'geyer_apex_return', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo'], 'out': _repeated1},
    'state_at': {'module': 'geyer', 'name': 'geyer_state_at', 'x': ['t', 'q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo'], 'out': ['q_r', 'q_rd', 'q_th',
    'q_thd']}, 'stance_jacobian': {'module': 'geyer_jacobian', 'name': 'geyer_stance_jacobian', 'x': [
    'q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo'],
    'out': _repeated0, 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {
    'module': 'geyer_jacobian', 'name': 'geyer_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo'], 'out':
    _repeated1, 'wrt': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {}},
    {'name': 'geyer-damped', 'title':
    "Geyer et al.'s map with leg damping (damped radial oscillator per half)", 'section': '3.1', 'equations':
    ['4', '7', '17', '18', '19', '48', '65', '76'], 'params': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'c'],
    'options': [_repeated3, {'name': 'gravity', 'kind': 'choice', 'default': 'none', 'doc':
    'virtual gravity effect on p_th per half (report section 4 on [t_td, t_b] and [t_b, t_lo], as '
    "geyer-vs's types 3-4): (48) from the torque at each half's two ends with the type's leg length; "
    'each half runs with its mean momentum, the rates with the momentum at that instant', 'choices': [{
    'value': 'none', 'doc': 'p_th conserved (Assumption 1; the damper exerts no torque about the toe)'}, {
    'value': 'type0', 'doc': '(48) per half with the leg length l0 (type 0, (49))'}, {'value': 'type1', 'doc':
    '(48) per half with the leg length (l0 + q_r_b)/2 (type 1, (52))'}, {'value': 'type2', 'doc':
    '(48) per half with the stance-average leg length of the damped rho(t) (type 2, (62))'}, {'value':
    'type3', 'doc': "(65) per half: the trapezoid rule on the torque at the half's ends"}, {'value': 'type4',
    'doc': "(76) per half: the torque at the half's average leg length of the damped rho(t)"}], 'low': None,
    'high': None, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'accuracy-variants']}, {'name': 'iterations', 'kind': 'int', 'default': 100, 'doc':
    "passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map)", 'choices': [], 'low': 0, 'high': 1000,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': []}, _repeated4],
    'module': 'geyer_damped', 'summary':
    'Assumption 1 (angular momentum conserved), 1/(1+rho)^3 by its Taylor polynomial: a damped linear '
    'oscillator per half (k_c, then k_d); liftoff a safeguarded Halley root; optionally a gravity '
    'correction per half', 'roles': [], 'specialized': [], 'choices': {}, 'extras': _repeated6, 'requires': [
    ], 'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'geyer_damped',
    'name': 'geyer_damped_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c',
    'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'liftoff', 'gravity', 'iterations', 'tol'], 'out':
    _repeated7}, 'apex_return': {'module': 'geyer_damped', 'name': 'geyer_damped_apex_return', 'x': [
    'b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'c', 'liftoff', 'gravity', 'iterations', 'tol'], 'out': _repeated8},
    'state_at': {'module': 'geyer_damped', 'name': 'geyer_damped_state_at', 'x': ['t', 'q_r_td', 'q_rd_td',
    'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'liftoff',
    'gravity', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']}, 'stance_jacobian': {'module':
    'geyer_damped_jacobian', 'name': 'geyer_damped_stance_jacobian', 'x': ['q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'liftoff', 'gravity',
    'iterations', 'tol'], 'out': _repeated7, 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k_c', 'k_d',
    'c']}, 'apex_return_jacobian': {'module': 'geyer_damped_jacobian', 'name':
    'geyer_damped_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'liftoff',
    'gravity', 'iterations', 'tol'], 'out': _repeated8, 'wrt': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate', 'k_c', 'k_d', 'c']}}, 'fixed': {}}, {'name': 'iterative-report', 'title':
    'Iterative stance map (Schwind and Koditschek, as printed)', 'section': '3.2', 'equations': ['27', '29',
    '30', '31', '32', '33', '35', '37', '38', '39', '40', '41', '42', '43', '44', '45', '98', '114', '115',
    '116', '117', '118', '119', '120', '121', '122', '123', '124', '125', '126', '128', '129', '130', '131',
    '132', '133', '134', '135', '137', '138', '139', '140', '141', '143', '144', '145', '146', '147', '148',
    '149', '150', '154'], 'params': ['m', 'l0', 'k_c', 'k_d', 'g_s'], 'options': _repeated18, 'module':
    'iterative_report', 'summary':
    "the report's iteration: n-th iterate at the end of each half from the zeroth at the n-fold "
    'mean-value point, stepping outward; compression anchored at touchdown (123), decompression at the '
    'bottom (41); bottom leg length of the zeroth iterate', 'roles': ['accuracy-figure'], 'specialized': [
    'zeroth'], 'choices': _repeated19, 'extras': [], 'requires': [], 'as_printed': True,
    'approximation_statuses': ['IMAGINARY_MOMENTUM', 'LIFTOFF_BACKWARD', 'LIFTOFF_DOWNWARD'], 'kernels': {
    'stance': {'module': 'iterative_report', 'name': 'iterative_report_stance_zeroth_geyer', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo',
    'variant', 'iterations', 'bottom_length'], 'out': _repeated0, 'base': 'iterative_report_stance'},
    'apex_return': {'module': 'iterative_report', 'name': 'iterative_report_apex_return_zeroth_geyer', 'x': [
    'b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'variant', 'iterations', 'bottom_length'], 'out': _repeated1, 'base':
    'iterative_report_apex_return'}, 'stance_jacobian': {'module': 'iterative_report_jacobian', 'name':
    'iterative_report_stance_jacobian_zeroth_geyer', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': [
    'm', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'variant', 'iterations', 'bottom_length'],
    'out': _repeated0, 'base': 'iterative_report_stance_jacobian', 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td', 'k_c', 'k_d']}, 'apex_return_jacobian': {'module': 'iterative_report_jacobian', 'name':
    'iterative_report_apex_return_jacobian_zeroth_geyer', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'variant',
    'iterations', 'bottom_length'], 'out': _repeated1, 'base': 'iterative_report_apex_return_jacobian', 'wrt':
    ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate', 'k_c', 'k_d']}}, 'fixed': {}}, {'name':
    'gravity-type0', 'title': 'Gravity correction type 0 (leg length l0)', 'section': '4.1', 'equations': [
    '46', '47', '48', '49', '50', '51'], 'params': ['m', 'l0', 'k', 'g_s'], 'options': [_repeated22,
    _repeated23, {'name': 'iterations', 'kind': 'int', 'default': 1, 'doc':
    "passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map)", 'choices': [], 'low': 0, 'high': 1000,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-passes']},
    {'name': 'tol', 'kind': 'float', 'default': 0.0, 'doc':
    'stop when P_c moves by at most tol times the momentum scale; 0: run all passes', 'choices': [], 'low':
    0.0, 'high': 1.0, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'tolerance']}], 'module': 'gravity', 'summary':
    'P_c from the torque at l0 sampled at touchdown and liftoff (49) or also the bottom (51)', 'roles': [
    'yu-target'], 'specialized': [], 'choices': {}, 'extras': _repeated24, 'requires': ['constant_stiffness'],
    'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'gravity', 'name':
    'gravity_type0_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out':
    _repeated25}, 'apex_return': {'module': 'gravity', 'name': 'gravity_type0_apex_return', 'x': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td',
    'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26},
    'state_at': {'module': 'gravity', 'name': 'gravity_type0_state_at', 'x': ['t', 'q_r_td', 'q_rd_td',
    'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'gravity_jacobian', 'name': 'gravity_type0_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated25, 'wrt': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module': 'gravity_jacobian', 'name':
    'gravity_type0_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {'leg_length': 0.0, 'interval': 1.0}}, {'name':
    'gravity-type1', 'title': 'Gravity correction type 1 (leg length (l0 + q_r_b)/2)', 'section': '4.2',
    'equations': ['46', '47', '48', '50', '52', '53', '54'], 'params': ['m', 'l0', 'k', 'g_s'], 'options': [
    _repeated22, _repeated23, _repeated27, _repeated4], 'module': 'gravity', 'summary':
    'P_c from the torque at the mean of the rest and bottom leg lengths (52), (54)', 'roles': ['yu-target'],
    'specialized': [], 'choices': {}, 'extras': _repeated24, 'requires': ['constant_stiffness'], 'as_printed':
    False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'gravity', 'name':
    'gravity_type1_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out':
    _repeated25}, 'apex_return': {'module': 'gravity', 'name': 'gravity_type1_apex_return', 'x': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td',
    'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26},
    'state_at': {'module': 'gravity', 'name': 'gravity_type1_state_at', 'x': ['t', 'q_r_td', 'q_rd_td',
    'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'gravity_jacobian', 'name': 'gravity_type1_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated25, 'wrt': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module': 'gravity_jacobian', 'name':
    'gravity_type1_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {'leg_length': 0.0, 'interval': 1.0}}, {'name':
    'gravity-type2', 'title': 'Gravity correction type 2 (average leg length)', 'section': '4.3', 'equations':
    ['46', '47', '48', '50', '55', '56', '57', '58', '59', '60', '61', '62', '63', '64'], 'params': ['m',
    'l0', 'k', 'g_s'], 'options': [_repeated22, _repeated23, _repeated29, _repeated27, _repeated4], 'module':
    'gravity', 'summary': 'P_c from the torque at the stance-average leg length (62), (64)', 'roles': [
    'yu-target', 'accuracy-figure'], 'specialized': [], 'choices': {}, 'extras': _repeated24, 'requires': [
    'constant_stiffness'], 'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module':
    'gravity', 'name': 'gravity_type2_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m',
    'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations',
    'tol'], 'out': _repeated25}, 'apex_return': {'module': 'gravity', 'name': 'gravity_type2_apex_return',
    'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out':
    _repeated26}, 'state_at': {'module': 'gravity', 'name': 'gravity_type2_state_at', 'x': ['t', 'q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'gravity_jacobian', 'name': 'gravity_type2_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated25, 'wrt': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module': 'gravity_jacobian', 'name':
    'gravity_type2_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {'interval': 1.0}}, {'name': 'gravity-type3',
    'title': 'Gravity correction type 3 (trapezoid on [t_i, t_f])', 'section': '4.4', 'equations': ['46',
    '47', '48', '50', '65', '66'], 'params': ['m', 'l0', 'k', 'g_s'], 'options': [_repeated22, _repeated32,
    _repeated27, _repeated4], 'module': 'gravity', 'summary':
    'P_c by the trapezoid rule on the torque with the true leg lengths (65), whole stance or halves', 'roles':
    ['yu-target'], 'specialized': [], 'choices': {}, 'extras': _repeated24, 'requires': [
    'constant_stiffness'], 'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module':
    'gravity', 'name': 'gravity_type3_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m',
    'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations',
    'tol'], 'out': _repeated25}, 'apex_return': {'module': 'gravity', 'name': 'gravity_type3_apex_return',
    'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out':
    _repeated26}, 'state_at': {'module': 'gravity', 'name': 'gravity_type3_state_at', 'x': ['t', 'q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'gravity_jacobian', 'name': 'gravity_type3_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated25, 'wrt': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module': 'gravity_jacobian', 'name':
    'gravity_type3_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {'samples': 2.0, 'leg_length': 0.0}}, {'name':
    'gravity-type4', 'title': 'Gravity correction type 4 (average leg length on [t_i, t_f])', 'section':
    '4.5', 'equations': ['46', '47', '48', '50', '67', '68', '69', '70', '71', '72', '73', '74', '75', '76',
    '77'], 'params': ['m', 'l0', 'k', 'g_s'], 'options': [_repeated22, _repeated32, _repeated29, _repeated27,
    _repeated4], 'module': 'gravity', 'summary':
    'P_c from the torque at the average leg length of each interval (76), whole stance or halves', 'roles': [
    'yu-target'], 'specialized': [], 'choices': {}, 'extras': _repeated24, 'requires': ['constant_stiffness'],
    'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'gravity', 'name':
    'gravity_type4_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s',
    'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out':
    _repeated25}, 'apex_return': {'module': 'gravity', 'name': 'gravity_type4_apex_return', 'x': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td',
    'q_r_lo', 'reading', 'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26},
    'state_at': {'module': 'gravity', 'name': 'gravity_type4_state_at', 'x': ['t', 'q_r_td', 'q_rd_td',
    'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'gravity_jacobian', 'name': 'gravity_type4_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading',
    'samples', 'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated25, 'wrt': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module': 'gravity_jacobian', 'name':
    'gravity_type4_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'reading', 'samples',
    'interval', 'leg_length', 'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate', 'k']}}, 'fixed': {'samples': 2.0}}, {'name': 'gravity-type5',
    'title': 'Gravity correction type 5 (time-varying momentum)', 'section': '4.6', 'equations': ['46', '47',
    '48'], 'params': ['m', 'l0', 'k', 'g_s'], 'options': [{'name': 'iterations', 'kind': 'int', 'default':
    100, 'doc': "fixed-point passes T5.8 from Geyer's map", 'choices': [], 'low': 0, 'high': 1000,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': ['accuracy-passes',
    'convergence-passes']}, {'name': 'tol', 'kind': 'float', 'default': 1e-12, 'doc':
    'stop when every state moved by at most tol times its scale; 0: run all passes', 'choices': [], 'low':
    0.0, 'high': 1.0, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'tolerance']}], 'module': 'gravity_type5', 'summary':
    'the gravity torque at the 3 Gauss-Legendre nodes of the stance, interpolated: a cubic momentum '
    'P(t); radial solution about the mean compression; leg angle in closed form (docs/type5.md)', 'roles': [
    'yu-target', 'accuracy-figure', 'region'], 'specialized': [], 'choices': {}, 'extras': [{'name': 'P_c',
    'doc': 'stance impulse of the gravity torque P(t_lo) - p_td', 'unit': 'N m s', 'odd': True}, {'name':
    'passes', 'doc': 'fixed-point passes run', 'unit': '', 'odd': False}], 'requires': ['constant_stiffness'],
    'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'gravity_type5',
    'name': 'gravity_type5_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k',
    'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'iterations', 'tol'], 'out': _repeated25}, 'apex_return': {'module':
    'gravity_type5', 'name': 'gravity_type5_apex_return', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'iterations', 'tol'], 'out':
    _repeated26}, 'state_at': {'module': 'gravity_type5', 'name': 'gravity_type5_state_at', 'x': ['t',
    'q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo',
    'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']}, 'stance_jacobian': {'module':
    'gravity_type5_jacobian', 'name': 'gravity_type5_stance_jacobian', 'x': ['q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'iterations', 'tol'], 'out':
    _repeated25, 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k']}, 'apex_return_jacobian': {'module':
    'gravity_type5_jacobian', 'name': 'gravity_type5_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex',
    'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k', 'g_s', 'g_f', 'q_r_td', 'q_r_lo',
    'iterations', 'tol'], 'out': _repeated26, 'wrt': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate', 'k']}}, 'fixed': {}}, {'name': 'geyer-vs', 'title':
    'Simple variable-stiffness map (Geyer et al. per half)', 'section': '5.1', 'equations': ['78', '79', '80',
    '81', '82', '83', '84', '85', '86', '87', '88', '89', '90', '91', '92', '93', '94', '96', '97', '98',
    '99', '100', '101', '102', '103', '104', '105', '106', '107', '108', '109', '110', '111', '112', '113'],
    'params': ['m', 'l0', 'k_c', 'k_d', 'g_s'], 'options': [{'name': 'continuity', 'kind': 'choice',
    'default': 'energy', 'doc': "the second half's a_ba, b_ba: how the leg length joins at the bottom",
    'choices': [{'value': 'report', 'doc':
    "(103)-(104) with E_ab the touchdown's total energy (27): q_r jumps at the bottom"}, {'value':
    'constrained', 'doc': 'b_ba of (104) as in report, a_ba from the continuity constraint (111)'}, {'value':
    'energy', 'doc': '(103)-(104) with E_ab the energy the first half conserves: continuous, (110) holds'}],
    'low': None, 'high': None, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {},
    'roles': ['accuracy-variants', 'stiffness-variants']}, {'name': 'gravity', 'kind': 'choice', 'default':
    'none', 'doc':
    'virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half '
    'runs with its mean momentum, the rates with the momentum at that instant', 'choices': [{'value': 'none',
    'doc': 'p_th conserved (Remark 2)'}, {'value': 'type3', 'doc':
    "(65) per half: the trapezoid rule on the torque at the half's ends"}, {'value': 'type4', 'doc':
    "(76) per half: the torque at the half's average leg length from (11), at its ends"}], 'low': None,
    'high': None, 'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'accuracy-variants', 'stiffness-variants']}, {'name': 'iterations', 'kind': 'int', 'default': 100, 'doc':
    "passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map)", 'choices': [], 'low': 0, 'high': 1000,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': [
    'convergence-passes']}, _repeated4], 'module': 'geyer_vs', 'summary':
    "Geyer et al.'s map with k_c to the bottom, the energy jump (97)-(98), again with k_d to liftoff; "
    'optionally a gravity correction per half', 'roles': ['default'], 'specialized': [], 'choices': {},
    'extras': _repeated6, 'requires': [], 'as_printed': False, 'approximation_statuses': [], 'kernels': {
    'stance': {'module': 'geyer_vs', 'name': 'geyer_vs_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'continuity', 'gravity',
    'iterations', 'tol'], 'out': _repeated7}, 'apex_return': {'module': 'geyer_vs', 'name':
    'geyer_vs_apex_return', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m',
    'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'continuity', 'gravity', 'iterations', 'tol'],
    'out': _repeated8}, 'state_at': {'module': 'geyer_vs', 'name': 'geyer_vs_state_at', 'x': ['t', 'q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo',
    'continuity', 'gravity', 'iterations', 'tol'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'geyer_vs_jacobian', 'name': 'geyer_vs_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo',
    'continuity', 'gravity', 'iterations', 'tol'], 'out': _repeated7, 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td',
    'q_thd_td', 'k_c', 'k_d']}, 'apex_return_jacobian': {'module': 'geyer_vs_jacobian', 'name':
    'geyer_vs_apex_return_jacobian', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'],
    'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'continuity', 'gravity', 'iterations',
    'tol'], 'out': _repeated8, 'wrt': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate', 'k_c',
    'k_d']}}, 'fixed': {}}, {'name': 'iterative', 'title':
    'Iterative stance map (Schwind and Koditschek, converging form)', 'section': '5.2', 'equations': ['27',
    '29', '30', '31', '32', '33', '35', '37', '41', '114', '115', '116', '117', '118', '137'], 'params': ['m',
    'l0', 'k_c', 'k_d', 'g_s', 'c'], 'options': [_repeated34, _repeated35, _repeated36, _repeated15,
    _repeated3], 'module': 'iterative', 'summary':
    'both halves by Picard passes on Gauss nodes in u = sqrt(q_r - q_r_b); p_r from the radial work; '
    'k_c before the bottom, k_d after', 'roles': ['region', 'accuracy-figure'], 'specialized': ['zeroth'],
    'choices': _repeated19, 'extras': [{'name': 'passes', 'doc':
    'Picard passes run (the larger of the two halves)', 'unit': '1', 'odd': False}], 'requires': [],
    'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module': 'iterative', 'name':
    'iterative_stance_zeroth_geyer', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0',
    'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'nodes', 'iterations', 'tol', 'liftoff'], 'out':
    _repeated37, 'base': 'iterative_stance'}, 'apex_return': {'module': 'iterative', 'name':
    'iterative_apex_return_zeroth_geyer', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground',
    'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'nodes',
    'iterations', 'tol', 'liftoff'], 'out': _repeated38, 'base': 'iterative_apex_return'}, 'stance_jacobian':
    {'module': 'iterative_jacobian', 'name': 'iterative_stance_jacobian_zeroth_geyer', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c',
    'nodes', 'iterations', 'tol', 'liftoff'], 'out': _repeated37, 'base': 'iterative_stance_jacobian', 'wrt':
    ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k_c', 'k_d', 'c']}, 'apex_return_jacobian': {'module':
    'iterative_jacobian', 'name': 'iterative_apex_return_jacobian_zeroth_geyer', 'x': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f',
    'q_r_td', 'q_r_lo', 'c', 'nodes', 'iterations', 'tol', 'liftoff'], 'out': _repeated38, 'base':
    'iterative_apex_return_jacobian', 'wrt': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate',
    'k_c', 'k_d', 'c']}}, 'fixed': {}}]

_repeated39 = {'name': 'rtol', 'kind': 'float', 'default': 1e-11, 'doc':
    'relative tolerance of the DOP853 integration', 'choices': [], 'low': 1e-14, 'high': 0.001,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': []}

_repeated40 = {'name': 'atol', 'kind': 'float', 'default': 1e-12, 'doc':
    'absolute tolerance of the DOP853 integration', 'choices': [], 'low': 1e-16, 'high': 0.001,
    'at_rest_length': [], 'kernel': True, 'specialize': False, 'backends': {}, 'roles': []}

HALVES = [{'name': 'exact-compression', 'title':
    'Exact compression half (touchdown to bottom, k_c; DOP853 integration)', 'section': '2.2', 'equations': [
    '2', '3'], 'params': ['m', 'l0', 'k_c', 'g_s', 'q_r_lo', 'c'], 'options': [_repeated39, _repeated40],
    'module': 'exact_compression', 'summary':
    "the exact stance's compression half, the same integration split at the bottom", 'roles': [],
    'specialized': [], 'choices': {}, 'extras': [], 'whole': 'exact', 'start': 'touchdown', 'end': 'bottom',
    'requires': [], 'kernels': {'half': {'module': 'exact_compression', 'name': 'exact_compression', 'x': [
    'q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'g_s', 'q_r_lo', 'c', 'rtol',
    'atol'], 'out': ['t_half', 'end_q_r', 'end_q_rd', 'end_q_th', 'end_q_thd']}}}, {'name':
    'exact-decompression', 'title': 'Exact decompression half (bottom to liftoff, k_d; DOP853 integration)',
    'section': '2.2', 'equations': ['2', '3'], 'params': ['m', 'l0', 'k_d', 'g_s', 'q_r_lo', 'c'], 'options':
    [_repeated39, _repeated40, _repeated3], 'module': 'exact_decompression', 'summary':
    "the exact stance's decompression half, the same integration split at the bottom", 'roles': [],
    'specialized': [], 'choices': {}, 'extras': [], 'whole': 'exact', 'start': 'bottom', 'end': 'liftoff',
    'requires': [], 'kernels': {'half': {'module': 'exact_decompression', 'name': 'exact_decompression', 'x':
    ['q_r_b', 'q_rd_b', 'q_th_b', 'q_thd_b'], 'p': ['m', 'l0', 'k_d', 'g_s', 'q_r_lo', 'c', 'rtol', 'atol',
    'liftoff'], 'out': ['t_half', 'end_q_r', 'end_q_rd', 'end_q_th', 'end_q_thd']}, 'apex': {'module':
    'exact_decompression', 'name': 'exact_decompression_apex', 'x': ['q_r_b', 'q_rd_b', 'q_th_b', 'q_thd_b'],
    'p': ['m', 'l0', 'k_d', 'g_s', 'g_f', 'q_r_lo', 'c', 'rtol', 'atol', 'liftoff'], 'out': ['apex_height',
    'apex_speed', 't_half', 't_ascent', 'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd']}}}, {
    'name': 'iterative-compression', 'title':
    'Iterative compression half (touchdown to bottom, k_c; converging form)', 'section': '5.2.1', 'equations':
    ['29', '30', '31', '32', '114', '115', '116', '117', '118', '123'], 'params': ['m', 'l0', 'k_c', 'g_s',
    'c'], 'options': [_repeated34, _repeated35, _repeated36, _repeated15], 'module': 'iterative_compression',
    'summary':
    'the compression half of `iterative`: bottom leg length from the radial work, Picard passes on '
    'Gauss nodes in u', 'roles': [], 'specialized': ['zeroth'], 'choices': _repeated19, 'extras': [{'name':
    'passes', 'doc': 'Picard passes run', 'unit': '1', 'odd': False}], 'whole': 'iterative', 'start':
    'touchdown', 'end': 'bottom', 'requires': [], 'kernels': {'half': {'module': 'iterative_compression',
    'name': 'iterative_compression_zeroth_geyer', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': [
    'm', 'l0', 'k_c', 'g_s', 'c', 'nodes', 'iterations', 'tol'], 'out': ['t_half', 'end_q_r', 'end_q_rd',
    'end_q_th', 'end_q_thd', 'passes'], 'base': 'iterative_compression'}}}, {'name':
    'iterative-report-compression', 'title':
    'Iterative compression half as printed (touchdown to bottom, k_c)', 'section': '5.2.1', 'equations': [
    '114', '115', '116', '117', '118', '119', '120', '121', '122', '123', '124', '125', '126', '128', '129',
    '130', '131', '132', '133', '134', '135', '154'], 'params': ['m', 'l0', 'k_c', 'g_s'], 'options':
    _repeated18, 'module': 'iterative_report_compression', 'summary':
    'the compression half of `iterative-report`: the chain anchored at touchdown, the printed point '
    '(123), bottom leg length of the zeroth iterate', 'roles': [], 'specialized': ['zeroth'], 'choices':
    _repeated19, 'extras': [], 'whole': 'iterative-report', 'start': 'touchdown', 'end': 'bottom', 'requires':
    [], 'kernels': {'half': {'module': 'iterative_report_compression', 'name':
    'iterative_report_compression_zeroth_geyer', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m',
    'l0', 'k_c', 'g_s', 'variant', 'iterations', 'bottom_length'], 'out': ['t_half', 'end_q_r', 'end_q_rd',
    'end_q_th', 'end_q_thd'], 'base': 'iterative_report_compression'}}}, {'name': 'iterative-decompression',
    'title': 'Iterative decompression half (bottom to liftoff, k_d; converging form)', 'section': '5.2.2',
    'equations': ['29', '30', '31', '32', '37', '41', '137', '138', '139', '140', '141', '143'], 'params': [
    'm', 'l0', 'k_d', 'g_s', 'q_r_lo', 'c'], 'options': [_repeated34, _repeated35, _repeated36, _repeated3],
    'module': 'iterative_decompression', 'summary':
    "the decompression half of `iterative` from any bottom state: zeroth iterate the bottom's angle "
    'and angular momentum held, liftoff p_r from the radial work', 'roles': [], 'specialized': [], 'choices':
    {}, 'extras': [{'name': 'passes', 'doc': 'Picard passes run', 'unit': '1', 'odd': False}], 'whole':
    'iterative', 'start': 'bottom', 'end': 'liftoff', 'requires': [], 'kernels': {'half': {'module':
    'iterative_decompression', 'name': 'iterative_decompression', 'x': ['q_r_b', 'q_rd_b', 'q_th_b',
    'q_thd_b'], 'p': ['m', 'l0', 'k_d', 'g_s', 'q_r_lo', 'c', 'nodes', 'iterations', 'tol', 'liftoff'], 'out':
    ['t_half', 'end_q_r', 'end_q_rd', 'end_q_th', 'end_q_thd', 'passes']}, 'apex': {'module':
    'iterative_decompression', 'name': 'iterative_decompression_apex', 'x': ['q_r_b', 'q_rd_b', 'q_th_b',
    'q_thd_b'], 'p': ['m', 'l0', 'k_d', 'g_s', 'g_f', 'q_r_lo', 'c', 'nodes', 'iterations', 'tol', 'liftoff'],
    'out': ['apex_height', 'apex_speed', 't_half', 't_ascent', 'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th',
    'liftoff_q_thd']}}}, {'name': 'iterative-report-decompression', 'title':
    'Iterative decompression half as printed (bottom to liftoff, k_d)', 'section': '5.2.2', 'equations': [
    '137', '138', '139', '140', '141', '143', '144', '145', '146', '147', '148', '149', '150'], 'params': [
    'm', 'l0', 'k_d', 'g_s', 'q_r_lo'], 'options': [_repeated11, _repeated12], 'module':
    'iterative_report_decompression', 'summary':
    "the decompression half of `iterative-report` from any bottom state: E_ba the bottom state's "
    "energy with k_d, zeroth iterate the bottom's angle and angular momentum held", 'roles': [],
    'specialized': [], 'choices': {}, 'extras': [], 'whole': 'iterative-report', 'start': 'bottom', 'end':
    'liftoff', 'requires': [], 'kernels': {'half': {'module': 'iterative_report_decompression', 'name':
    'iterative_report_decompression', 'x': ['q_r_b', 'q_rd_b', 'q_th_b', 'q_thd_b'], 'p': ['m', 'l0', 'k_d',
    'g_s', 'q_r_lo', 'variant', 'iterations'], 'out': ['t_half', 'end_q_r', 'end_q_rd', 'end_q_th',
    'end_q_thd']}, 'apex': {'module': 'iterative_report_decompression', 'name':
    'iterative_report_decompression_apex', 'x': ['q_r_b', 'q_rd_b', 'q_th_b', 'q_thd_b'], 'p': ['m', 'l0',
    'k_d', 'g_s', 'g_f', 'q_r_lo', 'variant', 'iterations'], 'out': ['apex_height', 'apex_speed', 't_half',
    't_ascent', 'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd']}}}]

EXACT = {'name': 'exact', 'title': 'Exact stance by numerical integration (DOP853)', 'section': '2.2',
    'equations': ['1', '2', '3', '27'], 'params': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'c'], 'options': [{'name':
    'method', 'kind': 'choice', 'default': 'compiled', 'doc':
    'which DOP853 implementation integrates the stance (same algorithm, events and statuses)', 'choices': [{
    'value': 'compiled', 'doc': 'numba-compiled, batches in parallel'}, {'value': 'scipy', 'doc':
    "scipy's solve_ivp, the reference"}], 'low': None, 'high': None, 'at_rest_length': [], 'kernel': False,
    'specialize': False, 'backends': {'scipy': 'slipmaps.runtime.exact.reference'}, 'roles': []}, _repeated39,
    _repeated40, _repeated3], 'module': 'exact', 'summary':
    'the polar stance equations of motion (2)-(3) integrated with events for the bottom (k_c -> k_d), '
    'liftoff and failures: the ground truth', 'roles': [], 'specialized': [], 'choices': {}, 'extras': [],
    'requires': [], 'as_printed': False, 'approximation_statuses': [], 'kernels': {'stance': {'module':
    'exact', 'name': 'exact_stance', 'x': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0',
    'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'rtol', 'atol', 'liftoff'], 'out': _repeated0},
    'apex_return': {'module': 'exact', 'name': 'exact_apex_return', 'x': ['b_y_apex', 'b_xd_apex', 'q_th_td',
    'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c',
    'rtol', 'atol', 'liftoff'], 'out': _repeated1}, 'state_at': {'module': 'exact', 'name': 'exact_state_at',
    'x': ['t', 'q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f',
    'q_r_td', 'q_r_lo', 'c', 'rtol', 'atol', 'liftoff'], 'out': ['q_r', 'q_rd', 'q_th', 'q_thd']},
    'stance_jacobian': {'module': 'exact_jacobian', 'name': 'exact_stance_jacobian', 'x': ['q_r_td',
    'q_rd_td', 'q_th_td', 'q_thd_td'], 'p': ['m', 'l0', 'k_c', 'k_d', 'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c',
    'rtol', 'atol', 'liftoff'], 'out': _repeated0, 'wrt': ['q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k_c',
    'k_d', 'c']}, 'apex_return_jacobian': {'module': 'exact_jacobian', 'name': 'exact_apex_return_jacobian',
    'x': ['b_y_apex', 'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate'], 'p': ['m', 'l0', 'k_c', 'k_d',
    'g_s', 'g_f', 'q_r_td', 'q_r_lo', 'c', 'rtol', 'atol', 'liftoff'], 'out': _repeated1, 'wrt': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'ground', 'retraction_rate', 'k_c', 'k_d', 'c']}}, 'fixed': {}}

MODEL = {'apex_to_touchdown': {'module': 'model', 'name': 'apex_to_touchdown_entry', 'x': ['b_y_apex',
    'b_xd_apex', 'q_th_td', 'q_r_td', 'g_f', 'ground', 'retraction_rate'], 'p': [], 'out': ['touchdown_q_r',
    'touchdown_q_rd', 'touchdown_q_th', 'touchdown_q_thd', 't_flight', 'foot_x']}, 'liftoff_to_apex': {
    'module': 'model', 'name': 'liftoff_to_apex_entry', 'x': ['q_r', 'q_rd', 'q_th', 'q_thd', 'g_f',
    'direction'], 'p': [], 'out': ['apex_b_y', 'apex_b_xd', 't_flight', 'dx_flight', 'apex_b_x']},
    'stance_polar_rhs': {'module': 'model', 'name': 'stance_polar_rhs_entry', 'x': ['q_r', 'q_rd', 'q_th',
    'q_thd', 'm', 'l0', 'k', 'g_s'], 'p': [], 'out': ['d_q_r', 'd_q_rd', 'd_q_th', 'd_q_thd']},
    'stance_cartesian_rhs': {'module': 'model', 'name': 'stance_cartesian_rhs_entry', 'x': ['b_x', 'b_xd',
    'b_y', 'b_yd', 'm', 'l0', 'k', 'g_s'], 'p': [], 'out': ['d_b_x', 'd_b_xd', 'd_b_y', 'd_b_yd']},
    'stance_energy': {'module': 'model', 'name': 'stance_energy_entry', 'x': ['q_r', 'q_rd', 'q_th', 'q_thd',
    'm', 'l0', 'k', 'g_s'], 'p': [], 'out': ['energy']}, 'polar_to_cartesian': {'module': 'model', 'name':
    'polar_to_cartesian_entry', 'x': ['q_r', 'q_rd', 'q_th', 'q_thd'], 'p': [], 'out': ['out_b_x', 'out_b_xd',
    'out_b_y', 'out_b_yd']}, 'cartesian_to_polar': {'module': 'model', 'name': 'cartesian_to_polar_entry',
    'x': ['b_x', 'b_xd', 'b_y', 'b_yd'], 'p': [], 'out': ['out_q_r', 'out_q_rd', 'out_q_th', 'out_q_thd']},
    'max_step': {'module': 'model', 'name': 'max_step_entry', 'x': ['m', 'l0', 'k', 'g_s'], 'p': [], 'out': [
    'step']}, 'stance_time_limit': {'module': 'model', 'name': 'stance_time_limit_entry', 'x': ['m', 'l0',
    'k_c', 'k_d', 'g_s'], 'p': [], 'out': ['t_max']}, 'bottom_quartic': {'module': 'model', 'name':
    'bottom_quartic_entry', 'x': ['p_b', 'E_ab', 'm', 'l0', 'k_c', 'g_s'], 'p': [], 'out': ['q_r_b']}}

SIMULATION = {'DEFAULT_RTOL': 1e-11, 'DEFAULT_ATOL': 1e-12, 'COLLAPSE_FRACTION': 0.001, 'T_MAX_PERIODS': 20,
    'MAX_STEP_FRACTION': 0.0625}

REST_LENGTH_TOLERANCE = 1e-09
