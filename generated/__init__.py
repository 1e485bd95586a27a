# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/modules.py
# Template:  derive/templates/init.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# ----------------------------------------------------------------------------------------------
"""slipmaps.generated: numba kernels rendered from the SymPy derivations in slipmaps.derive.

Modules:
    slip_model: SLIP stance equations of motion, energy and polar <-> Cartesian maps (report eqs 1-3, 27, sec 2.2).
    flight: Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2).
    geyer: Geyer et al.'s approximate stance map and apex-return map (report section 3.1, eqs 7-26).
    status: status codes shared by all kernels and the exact simulator.
"""
