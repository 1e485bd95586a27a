"""Pictures of a logged run: MuJoCo's renderer (headless), a matplotlib drawing where there is no GL,
and a GIF writer.

A run logged by ``Hopper(..., log_rate=fps)`` (:class:`~.hopper.Trajectory`) becomes frames (RGB
arrays, height x width x 3):

- :func:`mujoco_frames`: MuJoCo's offscreen ``Renderer`` with a camera that follows the hip.
  Headless it needs ``MUJOCO_GL=egl`` set before mujoco is imported (:mod:`.mj` sets it when there
  is no ``DISPLAY``); software rendering runs at about 9-15 frames/s at 320x240-640x480;
- :func:`drawn_frames`: the robot drawn with matplotlib from the logged states (body, leg, foot,
  the ground's profile), no GL needed;
- :func:`frames`: MuJoCo's when a GL context can be made, else the drawing;
- :func:`write_gif`: the frames as an animated GIF (Pillow, which matplotlib brings).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .hopper import Hopper, Trajectory
from .mj import mujoco

__all__ = ["drawn_frames", "frames", "mujoco_frames", "write_gif"]

#: The camera: distance [m], elevation [deg], height of the point it looks at [m] above the hip's
#: ground.
CAMERA = {"distance": 4.0, "elevation": -5.0, "height": 0.7}


def mujoco_frames(hopper: Hopper, trajectory: Trajectory | None = None, width: int = 480, height: int = 360):
    """Frames of ``trajectory`` (default: the hopper's log) rendered by MuJoCo, the camera
    following the hip from the side."""
    mj = mujoco()
    tr = hopper.trajectory if trajectory is None else trajectory
    _, qpos, _ = tr.arrays()
    model, L = hopper.model, hopper.layout
    data = mj.MjData(model)
    cam = mj.MjvCamera()
    cam.type = mj.mjtCamera.mjCAMERA_FREE
    cam.azimuth, cam.elevation, cam.distance = 90.0, CAMERA["elevation"], CAMERA["distance"]
    out = []
    with mj.Renderer(model, height, width) as renderer:
        for q in qpos:
            data.qpos[:] = q
            mj.mj_forward(model, data)
            x = float(q[L.x])
            ground = hopper.terrain.height_at(x)
            cam.lookat[:] = (x, 0.0, (0.0 if math.isnan(ground) else ground) + CAMERA["height"])
            renderer.update_scene(data, cam)
            out.append(renderer.render().copy())
    return out


def drawn_frames(hopper: Hopper, trajectory: Trajectory | None = None, width: int = 480, height: int = 360):
    """Frames of ``trajectory`` (default: the hopper's log) drawn with matplotlib: the torso, the
    leg (hip to foot), the foot (red in stance) and the ground."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    tr = hopper.trajectory if trajectory is None else trajectory
    _, qpos, phase = tr.arrays()
    p, L = hopper.params, hopper.layout
    dpi = 80
    fig, ax = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    span = CAMERA["distance"] * width / height / 2
    out = []
    try:
        for q, stance in zip(qpos, phase, strict=True):
            ax.clear()
            x, z = float(q[L.x]), float(q[L.z])
            pitch = float(q[L.pitch]) if L.pitch is not None else 0.0
            th = pitch + float(q[L.hip])
            r = p.l0 + float(q[L.leg]) - p.foot_radius
            fx, fz = x + r * math.sin(th), z - r * math.cos(th)
            xs = np.linspace(x - span, x + span, 400)
            ground = hopper.terrain.height_at(xs)
            mid = (np.nanmean(ground) if np.isfinite(ground).any() else 0.0) + CAMERA["height"]
            ax.fill_between(xs, ground, mid - 2 * span, color="0.75")
            half = 0.25 * p.l0
            c, s = math.cos(pitch), math.sin(pitch)
            ax.plot([x - half * c, x + half * c], [z + half * s, z - half * s], lw=8, color="#4066a6")
            ax.plot([x, fx], [z, fz], lw=2.5, color="0.3")
            ax.add_patch(plt.Circle((fx, fz), p.foot_radius * 2, color="#c84c33" if stance else "0.4"))
            ax.set_xlim(x - span, x + span)
            ax.set_ylim(mid - span * height / width, mid + span * height / width)
            ax.set_aspect("equal")
            ax.set_axis_off()
            fig.canvas.draw()
            out.append(np.asarray(fig.canvas.buffer_rgba())[..., :3].copy())
    finally:
        plt.close(fig)
    return out


def frames(hopper: Hopper, trajectory: Trajectory | None = None, width: int = 480, height: int = 360):
    """``(frames, how)``: MuJoCo's rendering (``how = "mujoco"``) when a GL context can be made, else
    the matplotlib drawing (``how = "matplotlib"``)."""
    try:
        return mujoco_frames(hopper, trajectory, width, height), "mujoco"
    except Exception:  # no GL context (no EGL, no display): draw instead
        return drawn_frames(hopper, trajectory, width, height), "matplotlib"


def write_gif(images, path, fps: float) -> Path:
    """``images`` (RGB arrays) as an animated GIF at ``fps`` frames/s, looping; returns the path."""
    from PIL import Image

    if not images:
        raise ValueError("write_gif: no frames to write (log the run with Hopper(log_rate=...))")
    path = Path(path)
    pics = [Image.fromarray(np.asarray(f, dtype=np.uint8)) for f in images]
    pics[0].save(path, save_all=True, append_images=pics[1:], duration=int(round(1000 / fps)), loop=0)
    return path
