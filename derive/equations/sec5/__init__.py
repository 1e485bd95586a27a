"""Report section 5 (variable stiffness): rows 78-113 (section 5.1), 114-151 (section 5.2) and
152-154 (the bottom leg length closing section 5.2).

Section 5.1 (eqs 78-113) is Geyer's map of section 3.1 split at the bottom: apex to bottom (78)-(89)
with k_c (subscript ab), bottom to apex (90)-(105) with k_d (subscript ba), the energy jump (97)-(98)
and the continuity constraint (106)-(111), then the piecewise stance map (112)-(113). Its checks
compare the printed displays with :mod:`slipmaps.derive.maps.geyer` (the half's parameters put into
(7), (11)-(14), (17)-(19)) and :mod:`slipmaps.derive.maps.geyer_vs` (the half solutions, the jump,
the constraint, the map's second half). Rows 88, 112, 113 and 152 carry no tag in the scan; their
notes say how the number was assigned; (95) is a definition row for a number with no display.

Section 5.2 splits the stance at the bottom: the compression half (apex to bottom, 5.2.1, eqs
114-136: stiffness k_c, energy E_ab, p_r = -H_ab^{-1} < 0, integrated from touchdown) and the
decompression half (bottom to apex, 5.2.2, eqs 137-151: k_d, E_ba, from the bottom, the map of
section 3.2). Each half comes twice: with the mean-value rule of (38)-(40) (f the whole integrand,
g = 1) and with the variant of (128)/(144) (f = 1/H^{-1}, the weight g = 1, 1/sigma^2, sigma
integrated exactly). Each check compares a transcription of a printed display, typed as printed
(errors included), with :mod:`slipmaps.derive.model.mechanics` (114, 115, 137) or
:mod:`slipmaps.derive.maps.iterative_helpers` (the rest). The iterates are checked with the mean-value point
xi_hat_r left as a symbol; the point itself is checked where it is printed, (123), (132) and (143).
The bottom leg length (152)-(154) is checked against the energy (27) at a vertical bottom
(:func:`~slipmaps.derive.maps.geyer_vs.bottom_quartic`) and Geyer's bottom (13).

One module per subsection, imported here in report order (the order their entries are registered
in): :mod:`.sec5_1` (5.1), :mod:`.sec5_2_1` (5.2.1), :mod:`.sec5_2_2` (5.2.2) and
:mod:`.sec5_2_bottom` (the end of 5.2, rows 152-154); :mod:`.helpers` holds what the checks of 5.2
share and registers nothing.
"""

from . import sec5_1, sec5_2_1, sec5_2_2, sec5_2_bottom  # noqa: F401 (each registers its rows)

#: The report's subsections of section 5, each with its first equation number (152-154 close 5.2).
SUBSECTIONS = (("5.1", 78), ("5.2.1", 114), ("5.2.2", 137), ("5.2", 152))
