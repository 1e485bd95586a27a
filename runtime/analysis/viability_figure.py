"""The figure of a viability study (:meth:`~.viability.ViableSet.plot`).

One state dimension (apex height at a fixed energy): the state-action plane as an image (failing
steps dark, steps that do not fail but leave the kernel grey, the viable set Q_V in colour), with
the kernel S_V and the measure beside it against the same state axis (and vibly's s = m g y / E).
Two (apex height and speed): the share of actions that do not fail and the measure as images over
the state plane, the kernel's outline on both. Action axes beyond the touchdown angle are projected
(a pair of state and angle is viable when some value of the other actions is).
"""

from __future__ import annotations

import numpy as np

__all__ = ["figure", "state_image"]

_UNITS = {
    "apex_height": "m",
    "apex_speed": "m/s",
    "touchdown_angle": "deg",
    "k_d": "N/m",
    "retraction_rate": "rad/s",
}


def _label(name: str) -> str:
    return f"{name.replace('_', ' ')} [{_UNITS[name]}]"


def _state_action(vs):
    """(state x angle) images of 'fails for every other action' and 'viable for some'."""
    extra = tuple(range(vs.kernel.ndim + 1, vs.viable.ndim))
    failed = vs.failed.all(axis=extra) if extra else vs.failed
    viable = vs.viable.any(axis=extra) if extra else vs.viable
    return failed, viable


def figure(vs, path):
    """Draw ``vs`` (module docstring) into ``path`` (its suffix chooses the format); returns ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    from ..api.paths import save_figure

    title = f"viability of {vs.map}: {vs.kernel.sum()} of {vs.kernel.size} states in the kernel"
    if vs.energy is not None:
        title += f", energy {vs.energy:g} J"
    if vs.kernel.ndim == 1:
        fig, (ax, side) = plt.subplots(
            1, 2, figsize=(10, 4.2), gridspec_kw={"width_ratios": [3, 1.3]}, constrained_layout=True
        )
        h = vs.states["apex_height"]
        deg = np.degrees(vs.actions["touchdown_angle"])
        failed, viable = _state_action(vs)
        image = np.where(failed, 0, np.where(viable, 2, 1))
        cmap = ListedColormap(["#3b3b3b", "#c8c8c8", "#2a9d8f"])
        ax.pcolormesh(deg, h, image, cmap=cmap, vmin=0, vmax=2, shading="nearest", rasterized=True)
        ax.set_xlabel("touchdown angle from the vertical [deg]")
        ax.set_ylabel(_label("apex_height"))
        handles = [
            matplotlib.patches.Patch(color=c, label=t)
            for c, t in zip(cmap.colors, ("fails", "leaves the kernel", "viable (Q_V)"), strict=True)
        ]
        ax.legend(handles=handles, fontsize=8, loc="upper right", framealpha=0.9)
        side.fill_betweenx(
            h, 0, vs.kernel.astype(float), step="mid", color="#2a9d8f", alpha=0.25, label="kernel S_V"
        )
        side.plot(vs.measure, h, "-", color="#264653", lw=1.2, label="measure")
        side.set_xlabel("measure (share of viable actions)")
        side.set_xlim(0, max(0.05, float(vs.measure.max()) * 1.15))
        side.set_ylim(ax.get_ylim())
        side.legend(fontsize=8, frameon=False)
        if vs.energy is not None:
            s = vs.normalized_height
            twin = side.twinx()
            twin.set_ylim(*(np.array(ax.get_ylim()) * s[-1] / h[-1]))
            twin.set_ylabel("s = m g y / E")
    else:
        fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
        h, v = vs.states["apex_height"], vs.states["apex_speed"]
        axes_a = tuple(range(2, vs.failed.ndim))
        safe = (~vs.failed).mean(axis=axes_a)
        for ax, data, label in (
            (axes[0], safe, "share of actions that do not fail"),
            (axes[1], vs.measure, "measure (share of viable actions)"),
        ):
            mesh = state_image(ax, v, h, data, vs.kernel)
            fig.colorbar(mesh, ax=ax, label=label)
            ax.set_xlabel(_label("apex_speed"))
            ax.set_ylabel(_label("apex_height"))
    fig.suptitle(title, fontsize=10)
    save_figure(fig, path)
    return path


def state_image(ax, v, h, data, kernel, vmax=None):
    """``data`` over apex speed ``v`` and height ``h`` as an image on ``ax``, the outline of
    ``kernel`` (bool over the same states) on it in white; returns the image for a colour bar."""
    mesh = ax.pcolormesh(v, h, data, shading="nearest", cmap="viridis", vmin=0, vmax=vmax, rasterized=True)
    if kernel.any() and not kernel.all():
        ax.contour(v, h, kernel.astype(float), levels=[0.5], colors="w", linewidths=1.0)
    return mesh
