"""MuJoCo, the robot's optional dependency: imported on first use, with one line when it is missing;
and the text of numbers in MJCF attributes (:func:`numbers`).

:func:`mujoco` returns the module. Headless (no ``DISPLAY``), it sets ``MUJOCO_GL=egl`` before the
first import unless ``MUJOCO_GL`` is set already (MuJoCo reads it once, at import): offscreen
rendering then works without a display (osmesa is not needed).
"""

from __future__ import annotations

import importlib
import os

__all__ = ["MISSING", "headless_gl", "mujoco", "numbers"]

MISSING = "the robot (slipmaps.runtime.robot) needs MuJoCo: pip install 'slipmaps[robot]'"


def headless_gl() -> None:
    """Without a ``DISPLAY``, ``MUJOCO_GL=egl`` unless it is set (call before importing mujoco)."""
    if not os.environ.get("DISPLAY"):
        os.environ.setdefault("MUJOCO_GL", "egl")


def mujoco():
    """The ``mujoco`` module; ImportError (one line, :data:`MISSING`) when it is not installed."""
    headless_gl()
    try:
        return importlib.import_module("mujoco")
    except ImportError as e:
        raise ImportError(MISSING) from e


def numbers(*xs: float) -> str:
    """An MJCF attribute's numbers: each the shortest repr of its float, space-separated."""
    return " ".join(repr(float(x)) for x in xs)
