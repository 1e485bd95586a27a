# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/generate.py
# Template:  derive/templates/init.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""slipmaps.generated: numba kernels rendered from the SymPy derivations in slipmaps.derive.

Modules:
    slip_model: SLIP stance equations of motion, energy and polar <-> Cartesian maps (report eqs 1-3, 27, sec
        2.2).
    flight: Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2).
    geyer: Geyer et al.'s approximate stance map (report section 3.1): stance, state-at-time and apex-return
        kernels.
    geyer_damped: Geyer et al.'s map with leg damping (damped radial oscillator per half) (report section
        3.1): stance, state-at-time and apex-return kernels.
    gravity: Gravity corrections types 0-4 (report sections 4.1-4.5): the stance, state-at-time and
        apex-return kernels of the maps gravity-type0, gravity-type1, gravity-type2, gravity-type3,
        gravity-type4 (one body, derive/share.py).
    gravity_type5: Gravity correction type 5 (time-varying momentum) (report section 4.6): stance,
        state-at-time and apex-return kernels.
    geyer_vs: Simple variable-stiffness map (Geyer et al. per half) (report section 5.1): stance,
        state-at-time and apex-return kernels.
    iterative: Iterative stance map (Schwind and Koditschek, converging form) (report section 5.2): stance,
        state-at-time and apex-return kernels.
    iterative_report: Iterative stance map (Schwind and Koditschek, as printed) (report section 3.2): stance,
        state-at-time and apex-return kernels.
    exact: Exact stance by numerical integration (DOP853) (report section 2.2): stance, state-at-time and
        apex-return kernels.
    flight_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module flight: JVP
        kernels, and for a map its stance and apex-return Jacobians.
    geyer_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer: JVP kernels,
        and for a map its stance and apex-return Jacobians.
    geyer_damped_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module
        geyer_damped: JVP kernels, and for a map its stance and apex-return Jacobians.
    geyer_vs_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer_vs: JVP
        kernels, and for a map its stance and apex-return Jacobians.
    gravity_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity: JVP
        kernels, and for a map its stance and apex-return Jacobians.
    gravity_type5_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module
        gravity_type5: JVP kernels, and for a map its stance and apex-return Jacobians.
    iterative_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative: JVP
        kernels, and for a map its stance and apex-return Jacobians.
    iterative_report_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module
        iterative_report: JVP kernels, and for a map its stance and apex-return Jacobians.
    exact_jacobian: Derivatives (forward mode, derive/tangent.py) of the kernels of module exact: JVP kernels,
        and for a map its stance and apex-return Jacobians.
    exact_compression: Exact compression half (touchdown to bottom, k_c; DOP853 integration) (report section
        2.2): touchdown -> bottom.
    exact_decompression: Exact decompression half (bottom to liftoff, k_d; DOP853 integration) (report section
        2.2): bottom -> liftoff.
    iterative_compression: Iterative compression half (touchdown to bottom, k_c; converging form) (report
        section 5.2.1): touchdown -> bottom.
    iterative_report_compression: Iterative compression half as printed (touchdown to bottom, k_c) (report
        section 5.2.1): touchdown -> bottom.
    iterative_decompression: Iterative decompression half (bottom to liftoff, k_d; converging form) (report
        section 5.2.2): bottom -> liftoff.
    iterative_report_decompression: Iterative decompression half as printed (bottom to liftoff, k_d) (report
        section 5.2.2): bottom -> liftoff.
    model: The model's kernels the runtime calls by name (the index's MODEL), as role kernels.
    maps_index: the index of every declared map (plain data).
    support: what the kernels share (stack arrays, a row's store and checks).
    status: status codes shared by all kernels and the exact simulator.
"""
