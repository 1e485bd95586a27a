"""Real numbers in the runtime's checks and messages: what counts as one, and how one is shown.

:func:`is_real` accepts int, float and numpy integer and float scalars (``numbers.Real``), not bool,
str or bytes. :func:`num` echoes a value as given, plainly (``nan``, ``-5.0``, ``1.0000001``: the
shortest repr of the float, never ``np.float64(...)``), so that a value just outside its domain is
shown as it was given; a computed quantity in a message is rounded where it is written (``:.6g``).
"""

from __future__ import annotations

import numbers

__all__ = ["NotANumber", "is_real", "num"]


class NotANumber(TypeError, ValueError):
    """A value that is not a real number where one is due (a string such as ``"1.0"``, bytes, None, a
    bool): a TypeError, and also a ValueError, which is what callers caught before strings were
    refused (as numpy's AxisError is both a ValueError and an IndexError)."""


def is_real(value: object) -> bool:
    """True for a real number (int, float, a numpy integer or float scalar), False for a bool."""
    kind = type(value)
    if kind is float or kind is int:  # the common case, without the ABC check
        return True
    return isinstance(value, numbers.Real) and kind is not bool


def num(value: object) -> str:
    """``value`` for a message: a real number as the shortest repr of its float (``-5.0``, ``nan``),
    anything else by its repr (``'1.0'``, ``b'1.0'``, ``None``)."""
    return repr(float(value)) if is_real(value) else repr(value)
