"""The figure of a viability study on an unknown ground (:meth:`~.viability_robust.RobustSet.plot`):
per policy (constant k_d = k_c, k_d at the apex, k_d at the bottom) the share of touchdown angles
that are viable with some choice of k_d, as an image over apex speed and height on one colour
scale, the kernel's outline on it."""

from __future__ import annotations

__all__ = ["figure"]

_TITLES = {
    "constant": "k_d = k_c",
    "one-stage": "k_d chosen at the apex",
    "two-stage": "k_d chosen at the bottom",
}


def figure(rs, path):
    """Draw ``rs`` (module docstring) into ``path`` (its suffix chooses the format); returns ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..api.paths import save_figure
    from .viability_figure import state_image

    h, v = rs.states["apex_height"], rs.states["apex_speed"]
    top = max(float(p.angles.max()) for p in rs.policies.values()) or 1.0
    fig, axes = plt.subplots(1, len(rs.policies), figsize=(13, 4.2), constrained_layout=True, sharey=True)
    for ax, (name, p) in zip(axes, rs.policies.items(), strict=True):
        mesh = state_image(ax, v, h, p.angles, p.kernel, vmax=top)
        ax.set_title(f"{_TITLES[name]}: {int(p.kernel.sum())} states", fontsize=9)
        ax.set_xlabel("apex speed [m/s]")
    axes[0].set_ylabel("apex height above the ground [m]")
    fig.colorbar(mesh, ax=axes, label="share of viable touchdown angles")
    cm = ", ".join(f"{100 * g:+.3g}" for g in rs.ground)
    fig.suptitle(f"viability of {rs.map} on an unknown ground (touchdown ground {cm} cm)", fontsize=10)
    save_figure(fig, path)
    return path
