"""Figures of runs: the body path over the terrain with the leg at every touchdown and liftoff and
the targets; the apex per step against its targets; the swing leg's angle over each descent; an
animation (GIF: matplotlib's Agg canvas, frames saved by Pillow); a swing policy's controls against
the time since the apex (:func:`policy_figure`).

Every path written is checked before any work by the callers (:mod:`slipmaps.runtime.cli.run`);
here the figure is drawn and saved.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["animate", "policy_figure", "run_figure"]

_BODY = "#1f4e79"
_LEG_TD = "#c0392b"
_LEG_LO = "#27ae60"
_TARGET = "#e67e22"
_GROUND = "#6d4c41"


def _draw_path(ax, path, label_targets: bool = True):
    ax.plot(path.terrain[:, 0], path.terrain[:, 1], color=_GROUND, lw=1.5, label="ground")
    bottom = min(float(path.terrain[:, 1].min()), 0.0) - 0.3
    xs = path.terrain[:, 0]
    if np.all(np.diff(xs) >= 0) or np.all(np.diff(xs) <= 0):
        ax.fill_between(xs, path.terrain[:, 1], bottom, color=_GROUND, alpha=0.15, step=None)
    flight = np.where(path.stance, np.nan, path.y)
    stance = np.where(path.stance, path.y, np.nan)
    ax.plot(path.x, flight, color=_BODY, lw=1.2, label="body, flight")
    ax.plot(
        path.x,
        stance,
        color=_BODY,
        lw=2.4,
        label="body, stance" + ("" if path.sampled else " (interpolated)"),
    )
    for k in range(path.foot_x.size):
        fx, fy = path.foot_x[k], path.foot_y[k]
        bx, by = path.touchdown_body[k]
        ax.plot([fx, bx], [fy, by], color=_LEG_TD, lw=1.0, label="leg at touchdown" if k == 0 else None)
        lx, ly = path.liftoff_body[k]
        ax.plot(
            [fx, lx], [fy, ly], color=_LEG_LO, lw=1.0, ls="--", label="leg at liftoff" if k == 0 else None
        )
    ax.plot(path.foot_x, path.foot_y, "v", color="k", ms=4, label="foot")
    if label_targets and path.target.size:
        ax.plot(path.target[:, 0], path.target[:, 1], "o", mfc="none", mec=_TARGET, ms=7, label="target apex")
    if path.apex.size:
        ax.plot(path.apex[:, 0], path.apex[:, 1], ".", color=_BODY, ms=5)
    ax.set_ylim(bottom, float(np.nanmax(path.y)) + 0.35)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")


def _draw_swing(ax, run):
    """The swing leg's angle against the time since the apex, a line per descent, the touchdown
    marked (its colour darkening with the step)."""
    b, i, n = run.batch, run.index, len(run)
    t_d = b.values["t_descent"][i, :n]
    colours = matplotlib_colours(n)
    for k in range(n):
        if b.swing is None or not np.isfinite(t_d[k]):
            continue
        tt = np.linspace(0.0, t_d[k], b.swing.shape[2])
        ax.plot(tt, b.swing[i, k], "-", color=colours[k], lw=1.0)
        ax.plot([t_d[k]], [b.values["touchdown_angle"][i, k]], "o", color=colours[k], ms=3)
    policy = run.scenario.policy + (
        f" {run.scenario.retraction_rate:+g} rad/s" if run.scenario.policy == "retraction" else ""
    )
    ax.set_title(f"swing leg ({policy}); dots: touchdown", fontsize=9)
    ax.set_xlabel("time since the apex [s]")
    ax.set_ylabel("leg angle [rad]")
    ax.grid(alpha=0.3)


def matplotlib_colours(n: int):
    """``n`` colours from light to dark blue."""
    import matplotlib

    cmap = matplotlib.colormaps["Blues"]
    return [cmap(0.35 + 0.6 * k / max(n - 1, 1)) for k in range(n)]


def policy_figure(policy, out_path):
    """A swing policy's controls against the time since the apex: the interpolated table and its
    knots by status (REACHED filled, UNREACHABLE open), one panel per control that varies, and the
    grounds against their touchdown times; written to ``out_path``, returned."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..api.paths import save_figure

    used = policy.used
    t = policy.t_touchdown
    names = ["touchdown_angle"] + [c for c in ("k_c", "k_d") if np.ptp(getattr(policy, c)[used]) > 0]
    fig, axes = plt.subplots(
        1, len(names) + 1, figsize=(4.2 * (len(names) + 1), 3.6), constrained_layout=True
    )
    if used.any():
        fine = np.linspace(0.0, 1.05 * np.nanmax(t[used]), 400)
        curves = policy.controls_at(fine)
    units = {"touchdown_angle": "rad", "k_c": "N/m", "k_d": "N/m"}
    for ax, name in zip(axes, names, strict=False):
        if used.any():
            ax.plot(fine, curves[name], "-", color=_BODY, lw=1.0, label="policy")
        y = getattr(policy, name)
        reached = used & policy.reached
        ax.plot(t[reached], y[reached], "o", color=_BODY, ms=3, label="REACHED")
        ax.plot(
            t[used & ~policy.reached],
            y[used & ~policy.reached],
            "o",
            mfc="none",
            color=_LEG_TD,
            ms=4,
            label="UNREACHABLE",
        )
        ax.set_xlabel("time since the apex [s]")
        ax.set_ylabel(f"{name} [{units[name]}]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, frameon=False)
    ax = axes[-1]
    ax.plot(t[used], policy.grounds[used], ".", color=_GROUND)
    ax.set_xlabel("touchdown time [s]")
    ax.set_ylabel("ground [m]")
    ax.grid(alpha=0.3)
    fig.suptitle(
        f"swing policy on {policy.model}: apex {policy.apex_height:g} m, {policy.apex_speed:g} m/s -> "
        f"target {policy.target_height} m, {policy.target_speed} m/s",
        fontsize=10,
    )
    save_figure(fig, out_path)
    return out_path


def run_figure(run, out_path, *, title: str | None = None):
    """The run's figure (module docstring) written to ``out_path``; returns the path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = run.path()
    sc = run.scenario
    fig = plt.figure(figsize=(15, 7.5), constrained_layout=True)
    grid = fig.add_gridspec(2, 3, height_ratios=(1.35, 1.0))
    ax = fig.add_subplot(grid[0, :])
    _draw_path(ax, path)
    if sc.stones is not None and "planned_foot" in run.batch.values:  # the footholds' plans
        planned, stone = run.column("planned_foot"), run.column("planned_stone").astype(int)
        y = sc.stones.heights[np.clip(stone, 0, None)]
        ax.plot(planned, y, "^", mfc="none", color=_TARGET, ms=7, label="planned foot")
    span = float(np.ptp(path.x)) if path.x.size else 1.0
    ax.set_aspect("equal" if span < 25 else "auto")
    ax.legend(loc="upper left", fontsize=8, ncol=4, frameon=False)
    ax.set_title(title or f"{sc.name}: model {sc.model}, plant {sc.plant} ({run.status})", fontsize=11)
    steps = np.arange(len(run))
    nxt = steps + 1
    for col, (key, label, unit) in enumerate(
        (("height", "apex height", "m"), ("speed", "apex speed", "m/s"))
    ):
        a = fig.add_subplot(grid[1, col])
        a.plot(nxt, run.column(f"nominal_{key}"), "s", mfc="none", color="0.6", label="nominal target")
        a.plot(nxt, run.column(f"target_{key}"), "o", mfc="none", color=_TARGET, ms=8, label="planned target")
        a.plot(nxt, run.column(f"predicted_{key}"), "x", color="0.3", label=f"model ({sc.model})")
        a.plot(nxt, run.column(f"next_apex_{key}"), ".-", color=_BODY, label=f"plant ({sc.plant})")
        a.plot([0], [run.column(f"apex_{key}")[0]] if len(run) else [], ".", color=_BODY)
        a.set_xlabel("apex (after step)")
        a.set_ylabel(f"{label} [{unit}]")
        a.grid(alpha=0.3)
        if col == 0:
            a.legend(fontsize=8, frameon=False)
    _draw_swing(fig.add_subplot(grid[1, 2]), run)
    from ..api.paths import save_figure

    save_figure(fig, out_path)
    return out_path


def animate(run, out_path, *, fps: int = 20, speed: float = 0.5, progress=None):
    """A GIF of the run: the body, the leg (from the foot in stance; at the swing leg's angle in
    flight), the terrain and the targets; ``speed`` the playback speed (0.5: half real time). The
    view follows the body; its position is printed in the frame's label (a moving axis's tick
    labels cost most of a frame's drawing). Each frame is drawn once on the Agg canvas and handed to
    Pillow; the layout is computed on the first frame only. ``progress``: a bar of the frames drawn
    (None: on a terminal, after a second). Returns the path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image

    from ..api.paths import plain_ticks, writing
    from ..api.progress import Bar

    path = run.path(samples=30)
    sc = run.scenario
    l0 = sc.params.l0
    frames = max(2, int(math.ceil(float(path.t[-1]) / speed * fps))) if path.t.size else 2
    times = np.linspace(0.0, float(path.t[-1]) if path.t.size else 0.0, frames)
    fig, ax = plt.subplots(figsize=(8, 3.6), dpi=72, constrained_layout=True)
    ax.plot(path.terrain[:, 0], path.terrain[:, 1], color=_GROUND, lw=1.5)
    ax.plot(path.x, path.y, color=_BODY, lw=0.8, alpha=0.3)
    if path.target.size:
        ax.plot(path.target[:, 0], path.target[:, 1], "o", mfc="none", mec=_TARGET, ms=7, label="target apex")
    ax.plot(path.foot_x, path.foot_y, "v", color="k", ms=4)
    (body,) = ax.plot([], [], "o", color=_BODY, ms=10)
    (leg,) = ax.plot([], [], "-", color="k", lw=2.0)
    label = ax.text(0.01, 0.97, "", transform=ax.transAxes, va="top", fontsize=9)
    ax.set_title(f"{sc.name}: model {sc.model}, plant {sc.plant}", fontsize=10)
    y_lo = min(float(path.terrain[:, 1].min()), 0.0) - 0.2
    y_hi = float(np.nanmax(path.y)) + 0.3 if path.y.size else 2.0
    half = 4.0 * l0
    ax.set_ylim(y_lo, y_hi)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_xlabel(f"x (the view follows the body; {2 * half:g} m wide)")
    ax.set_ylabel("y [m]")

    def frame(k):
        t = times[k]
        x = float(np.interp(t, path.t, path.x))
        y = float(np.interp(t, path.t, path.y))
        body.set_data([x], [y])
        step = int(np.searchsorted(path.t_liftoff, t))
        if step < path.foot_x.size and path.t_touchdown[step] <= t <= path.t_liftoff[step]:
            leg.set_data([path.foot_x[step], x], [path.foot_y[step], y])
        else:
            th = (
                float(np.interp(t, path.t, np.where(np.isfinite(path.leg), path.leg, 0.0)))
                if path.t.size
                else 0.0
            )
            leg.set_data([x, x + l0 * math.sin(th)], [y, y - l0 * math.cos(th)])
        label.set_text(f"t = {t:.2f} s, x = {x:.2f} m, step {min(step, max(len(run) - 1, 0))}")
        ax.set_xlim(x - half, x + half)

    # The frame around the axes (title, labels, the y axis) is drawn once: every frame restores it
    # and draws the axes' background, its lines and its label over it (blitting on the Agg canvas).
    canvas = fig.canvas
    moving = [*ax.lines, label]
    frame(0)
    plain_ticks(fig)
    canvas.draw()  # the constrained layout once, then frozen
    fig.set_layout_engine("none")
    for artist in moving:
        artist.set_visible(False)
    canvas.draw()
    around = canvas.copy_from_bbox(fig.bbox)
    for artist in moving:
        artist.set_visible(True)
    images, palette = [], None
    try:
        with Bar(frames, f"GIF {out_path}", progress, unit="frames") as bar:
            for k in range(frames):
                frame(k)
                canvas.restore_region(around)
                ax.draw_artist(ax.patch)
                for artist in (*moving, *ax.spines.values()):
                    ax.draw_artist(artist)
                image = Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3].copy())
                if palette is None:  # one palette for every frame (the colours do not change)
                    palette = image.quantize(colors=64)
                images.append(image.quantize(palette=palette, dither=Image.Dither.NONE))
                bar.update(1)
    finally:
        plt.close(fig)
    with writing(out_path):
        images[0].save(out_path, save_all=True, append_images=images[1:], duration=round(1000 / fps), loop=0)
    return out_path
