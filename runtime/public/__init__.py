"""slipmaps: approximate stance maps of the Spring-Loaded Inverted Pendulum (SLIP).

Derived in SymPy (``slipmaps.derive``), generated as numba kernels (``slipmaps.generated``),
checked against numerical integration (``slipmaps.runtime``). The public API, generic over maps::

    import slipmaps

    params = slipmaps.SlipParams(m=80.0, l0=1.0, k=20_000.0)
    [m.name for m in slipmaps.maps()]                      # "geyer", ..., "exact"
    res = slipmaps.apex_return("geyer", params, 1.0, 5.0, 0.35)
    res.apex_height, res.apex_speed, res.status
    batch = slipmaps.apex_return_batch("geyer", params, 1.0, speeds, angles)   # arrays broadcast
    batch["apex_height"], batch["status"]
    gaits = slipmaps.fixed_points("exact", params, apex_height=1.0, speed=5.0)  # periodic gaits
    gaits[0].touchdown_angle, gaits[0].eigenvalue, gaits[0].stable

Conventions: SI units; leg angle from the vertical, counterclockwise positive; polar state
``(q_r, q_rd, q_th, q_thd)``; times in a stance from touchdown. This file is installed as the
top-level package ``slipmaps`` (``pyproject.toml``, ``package-dir``).

numba caches the compiled kernels beside the generated modules (``generated/__pycache__``). In a
read-only install without ``NUMBA_CACHE_DIR``, importing ``slipmaps`` sets ``NUMBA_CACHE_DIR`` to a
writable directory, with one warning naming it (:func:`_numba_cache_fallback`).
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import sys
import tempfile
import warnings

#: Public name -> the module that defines it. Loaded on first use (PEP 562), so that importing
#: ``slipmaps.derive`` (``slipmaps generate``) never needs the generated kernels.
_EXPORTS = {
    "SlipParams": "slipmaps.runtime.params",
    "HUMAN_RUNNER": "slipmaps.runtime.params",
    "ROBOT_HOPPER": "slipmaps.runtime.params",
    "maps": "slipmaps.runtime.index",
    "MapInfo": "slipmaps.runtime.index",
    "stance": "slipmaps.runtime.maps",
    "stance_batch": "slipmaps.runtime.maps",
    "apex_return": "slipmaps.runtime.maps",
    "apex_return_batch": "slipmaps.runtime.maps",
    "trajectory": "slipmaps.runtime.maps",
    "half_stance": "slipmaps.runtime.maps",
    "half_stance_batch": "slipmaps.runtime.maps",
    "stance_jacobian": "slipmaps.runtime.jacobian",
    "stance_jacobian_batch": "slipmaps.runtime.jacobian",
    "apex_return_jacobian": "slipmaps.runtime.jacobian",
    "apex_return_jacobian_batch": "slipmaps.runtime.jacobian",
    "Jacobian": "slipmaps.runtime.jacobian",
    "JacobianBatch": "slipmaps.runtime.jacobian",
    "fixed_points": "slipmaps.runtime.gait",
    "FixedPoint": "slipmaps.runtime.gait",
    "Result": "slipmaps.runtime.results",
    "BatchResult": "slipmaps.runtime.results",
    "Status": "slipmaps.generated.status",
    "Sweep": "slipmaps.runtime.sweep",
    "sweep": "slipmaps.runtime.sweep",
    "read_sweep": "slipmaps.runtime.sweep",
    "MESSAGES": "slipmaps.generated.status",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    if name in _EXPORTS:
        value = getattr(importlib.import_module(_EXPORTS[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'slipmaps' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))


def _writable(path: str, mode: int = 0o777) -> bool:
    """numba's own test of a cache directory: it can be created (with ``mode``, less the umask) and a
    file written in it."""
    try:
        os.makedirs(path, mode=mode, exist_ok=True)
        tempfile.TemporaryFile(dir=path).close()
    except OSError:
        return False
    return True


def _private_temp_dir() -> str | None:
    """<tempdir>/slipmaps-numba-<uid>, kept between runs when it is this user's alone (else a fresh
    one: a shared directory's cache index could be planted by another user); None if none is writable."""
    uid = os.getuid() if hasattr(os, "getuid") else None
    path = os.path.join(tempfile.gettempdir(), f"slipmaps-numba-{uid if uid is not None else 'user'}")
    try:
        os.makedirs(path, mode=0o700, exist_ok=True)
        st = os.stat(path)
        if (uid is None or st.st_uid == uid) and not st.st_mode & 0o022 and _writable(path, 0o700):
            return path
        return tempfile.mkdtemp(prefix="slipmaps-numba-")
    except OSError:
        return None


def _numba_cache_fallback() -> None:
    """Give numba a writable cache directory when the install's is not.

    The generated kernels are ``@njit(cache=True)``: numba caches them in ``generated/__pycache__``,
    else in its user-wide cache (``~/.cache/numba``), and refuses to import them when neither is
    writable ("cannot cache function ...: no locator available"). When ``NUMBA_CACHE_DIR`` is unset
    and ``generated/__pycache__`` is not writable, this sets ``NUMBA_CACHE_DIR`` to the first
    writable of ``$XDG_CACHE_HOME/slipmaps/numba`` (``~/.cache/slipmaps/numba``) and a private
    directory under the temporary directory, with one warning naming it. It runs before any
    generated module is imported (they all import through this package); when numba's configuration
    was already read (numba imported first), it is reloaded so the setting still applies.
    """
    if os.environ.get("NUMBA_CACHE_DIR"):
        return
    spec = importlib.util.find_spec(__name__ + ".generated")
    if spec is None or not spec.submodule_search_locations:
        return
    pycache = os.path.join(list(spec.submodule_search_locations)[0], "__pycache__")
    if _writable(pycache):
        return
    user = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    user = os.path.join(user, "slipmaps", "numba")
    chosen = user if _writable(user, 0o700) else _private_temp_dir()
    if chosen is None:
        warnings.warn(
            f"slipmaps: numba cannot cache the compiled kernels ({pycache}, {user} and the temporary "
            "directory are not writable): set NUMBA_CACHE_DIR to a writable directory",
            RuntimeWarning,
            stacklevel=2,
        )
        return
    os.environ["NUMBA_CACHE_DIR"] = chosen
    if "numba.core.config" in sys.modules:
        sys.modules["numba.core.config"].reload_config()
    warnings.warn(
        f"slipmaps: {pycache} is not writable; numba caches the compiled kernels in {chosen} "
        "(set NUMBA_CACHE_DIR to choose another directory)",
        RuntimeWarning,
        stacklevel=2,
    )


_numba_cache_fallback()
