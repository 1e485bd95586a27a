# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/lower.py
# Template:  derive/templates/rows.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""The batch row stores of the Jacobians' batch forms, one function per layout (``store_row_<first>_<n>``:
a scalar kernel's ``n`` outputs, its derivatives from output ``first``, then its status), shared by every
generated ``*_jacobian`` module (derive/lower.py, ``row_store``)."""

import math

from numba import njit

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_10_60(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (60 outputs, the
    derivatives from column 10, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59],
        status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(10, 60):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(60):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_10_70(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (70 outputs, the
    derivatives from column 10, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(10, 70):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(70):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_11_77(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (77 outputs, the
    derivatives from column 11, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
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
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(11, 77):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(77):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_12_72(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (72 outputs, the
    derivatives from column 12, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], out[i, 70], out[i, 71], status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(12, 72):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(72):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_12_84(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (84 outputs, the
    derivatives from column 12, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], out[i, 70], out[i, 71], out[i, 72], out[i, 73], out[i, 74], out[i, 75], out[i, 76], out[i,
        77], out[i, 78], out[i, 79], out[i, 80], out[i, 81], out[i, 82], out[i, 83], status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(12, 84):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(84):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_13_91(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (91 outputs, the
    derivatives from column 13, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
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
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(13, 91):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(91):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_14_84(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (84 outputs, the
    derivatives from column 14, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
    (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8], out[i,
        9], out[i, 10], out[i, 11], out[i, 12], out[i, 13], out[i, 14], out[i, 15], out[i, 16], out[i, 17],
        out[i, 18], out[i, 19], out[i, 20], out[i, 21], out[i, 22], out[i, 23], out[i, 24], out[i, 25], out[i,
        26], out[i, 27], out[i, 28], out[i, 29], out[i, 30], out[i, 31], out[i, 32], out[i, 33], out[i, 34],
        out[i, 35], out[i, 36], out[i, 37], out[i, 38], out[i, 39], out[i, 40], out[i, 41], out[i, 42], out[i,
        43], out[i, 44], out[i, 45], out[i, 46], out[i, 47], out[i, 48], out[i, 49], out[i, 50], out[i, 51],
        out[i, 52], out[i, 53], out[i, 54], out[i, 55], out[i, 56], out[i, 57], out[i, 58], out[i, 59], out[i,
        60], out[i, 61], out[i, 62], out[i, 63], out[i, 64], out[i, 65], out[i, 66], out[i, 67], out[i, 68],
        out[i, 69], out[i, 70], out[i, 71], out[i, 72], out[i, 73], out[i, 74], out[i, 75], out[i, 76], out[i,
        77], out[i, 78], out[i, 79], out[i, 80], out[i, 81], out[i, 82], out[i, 83], status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(14, 84):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(84):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE


@njit(cache=True, error_model="numpy")
def store_row_15_105(out, status, i, res):
    """Row i of a Jacobian's batch form: the result ``res`` of its scalar kernel (105 outputs, the
    derivatives from column 15, then the status) into ``out[i]`` and ``status[i]``; a row whose
    values exist but a derivative does not (not finite) is NUMERICAL_RANGE, all NaN, as the public
    API reports it (runtime/api/jacobian.py)."""
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
        out[i, 86], out[i, 87], out[i, 88], out[i, 89], out[i, 90], out[i, 91], out[i, 92], out[i, 93], out[i,
        94], out[i, 95], out[i, 96], out[i, 97], out[i, 98], out[i, 99], out[i, 100], out[i, 101], out[i,
        102], out[i, 103], out[i, 104], status[i]) = res
    if status[i] == STATUS_OK:
        # v - v == 0 exactly when v is finite; one branch-free pass over the stored derivatives
        finite = True
        for j in range(15, 105):
            v = out[i, j]
            finite &= v - v == 0.0
        if not finite:
            for j in range(105):
                out[i, j] = math.nan
            status[i] = STATUS_NUMERICAL_RANGE
