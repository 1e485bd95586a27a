"""The apex-return functions' inputs, built from the inputs table (``derive/params.py``).

The public apex-return functions (:func:`slipmaps.apex_return`, its batch and its Jacobians) take
the table's inputs by name: the rows without a default positionally after ``name, params`` in the
table's order (``apex_height, apex_speed, touchdown_angle``), the rows with one as keywords with
that default (``ground=0.0``). :func:`apex_signature` gives a function written as
``f(name, params, given, ...)`` that signature, so a new row of the table is a new argument of
every apex-return function (its checks by its domain in :func:`.maps.apex_inputs`) without an
edit here or in the functions.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable

from slipmaps.derive import params as _table

__all__ = ["REQUIRED", "DEFAULTS", "apex_signature"]

#: The inputs without a default, in the table's order: positional after ``name, params``.
REQUIRED: tuple[str, ...] = tuple(r["name"] for r in _table.APEX_INPUTS if "default" not in r)
#: The inputs with a default: keyword-only.
DEFAULTS: dict[str, float] = {r["name"]: r["default"] for r in _table.APEX_INPUTS if "default" in r}


def apex_signature(func: Callable) -> Callable:
    """``func(name, params, given, *rest)`` -> ``f(name, params, <REQUIRED>, *, <DEFAULTS>, *rest)``
    (``given`` the inputs by name, in the table's order). Wrong arguments raise TypeError as a
    Python signature does; the binding costs about a microsecond (no :meth:`inspect.Signature.bind`)."""
    sig = inspect.signature(func)
    head, rest = list(sig.parameters.values())[:2], list(sig.parameters.values())[3:]
    P = inspect.Parameter
    public = sig.replace(
        parameters=[
            *head,
            *(P(n, P.POSITIONAL_OR_KEYWORD) for n in REQUIRED),
            *(P(n, P.KEYWORD_ONLY, default=d) for n, d in DEFAULTS.items()),
            *rest,
        ]
    )
    n_req = len(REQUIRED)
    fname = func.__name__

    @functools.wraps(func)
    def wrapper(name, params, *args, **kwargs):
        if len(args) == n_req and not kwargs:  # the common call: every required input by position
            return func(name, params, dict(zip(REQUIRED, args, strict=True), **DEFAULTS))
        if len(args) > n_req:
            raise TypeError(
                f"{fname}() takes {n_req + 2} positional arguments but {len(args) + 2} were given"
            )
        given = dict(zip(REQUIRED, args, strict=False))
        for key in REQUIRED[: len(args)]:
            if key in kwargs:
                raise TypeError(f"{fname}() got multiple values for argument {key!r}")
        for key in REQUIRED[len(args) :]:
            if key not in kwargs:
                raise TypeError(f"{fname}() missing required argument: {key!r}")
            given[key] = kwargs.pop(key)
        for key, default in DEFAULTS.items():
            given[key] = kwargs.pop(key, default)
        return func(name, params, given, **kwargs)

    wrapper.__signature__ = public
    return wrapper
