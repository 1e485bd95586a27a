"""Draw docs/model.png, the SLIP model with slipmaps' conventions (docs/conventions.md).

Run from anywhere: ``python docs/figures/model.py`` rewrites docs/model.png. The figure shows the
stance at touchdown of a step toward +x: the toe at the origin, the body at
``(b_x, b_y) = (-q_r sin q_th, q_r cos q_th)``, the leg angle ``q_th`` from the vertical,
counterclockwise positive (positive here: the toe ahead of the body), the flight before it and
the apex.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

OUT = Path(__file__).resolve().parent.parent / "model.png"
Q_TH = 0.35  # touchdown leg angle [rad], the README's default step
Q_R = 1.0  # leg length at touchdown [m] (l0)


def spring(start: np.ndarray, end: np.ndarray, coils: int = 7, width: float = 0.05) -> np.ndarray:
    """The points of a zigzag spring from ``start`` to ``end`` with straight ends."""
    axis = end - start
    length = np.hypot(*axis)
    along, normal = axis / length, np.array([-axis[1], axis[0]]) / length
    s = np.concatenate([[0.0, 0.2], np.linspace(0.2, 0.8, 2 * coils + 1), [0.8, 1.0]])
    offset = np.zeros_like(s)
    offset[2:-2] = width * np.array([0.0, *[(-1) ** i for i in range(2 * coils - 1)], 0.0])
    return start + np.outer(s * length, along) + np.outer(offset, normal)


def draw() -> plt.Figure:
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=150)
    toe = np.array([0.0, 0.0])
    body = np.array([-Q_R * np.sin(Q_TH), Q_R * np.cos(Q_TH)])
    # ground, the vertical through the toe, the leg
    ax.axhline(0.0, color="0.3", lw=1.2)
    ax.fill_between([-1.6, 0.9], -0.08, 0.0, color="0.85", zorder=0)
    ax.plot([0, 0], [0, 1.1], ls="--", color="0.5", lw=0.9)
    pts = spring(toe, body)
    ax.plot(pts[:, 0], pts[:, 1], color="tab:blue", lw=1.6)
    ax.add_patch(plt.Circle(body, 0.07, color="tab:red", zorder=3))
    ax.annotate("m", body + [0.09, 0.02], color="tab:red", fontsize=11)
    # the leg angle: from the vertical to the leg, counterclockwise
    arc = np.linspace(0.0, Q_TH, 30)
    ax.plot(-0.6 * np.sin(arc), 0.6 * np.cos(arc), color="k", lw=1.0)
    ax.annotate(
        "",
        xy=(-0.6 * np.sin(Q_TH), 0.6 * np.cos(Q_TH)),
        xytext=(-0.6 * np.sin(0.8 * Q_TH), 0.6 * np.cos(0.8 * Q_TH)),
        arrowprops={"arrowstyle": "->", "lw": 1.0},
    )
    ax.annotate(r"$q_\theta > 0$", (-0.02, 0.64), fontsize=11, ha="center")
    ax.annotate(
        r"$q_r$ (rest length $l_0$, stiffness $k$)",
        (body / 2) + [-0.06, 0.0],
        fontsize=10,
        ha="right",
        color="tab:blue",
    )
    # the flight before touchdown, from the apex, and the direction of the step
    apex_x, apex_h, v = body[0] - 0.9, 1.18, 5.0
    t = np.linspace(0.0, (body[0] - apex_x) / v, 50)
    ax.plot(
        apex_x + v * t,
        apex_h - 9.81 / 2 * t**2 * (apex_h - body[1]) / (9.81 / 2 * t[-1] ** 2),
        ls=":",
        color="tab:red",
        lw=1.2,
    )
    ax.plot(apex_x, apex_h, "o", color="tab:red", ms=4)
    ax.annotate("apex (height, signed speed)", (apex_x, apex_h + 0.05), fontsize=9, ha="center")
    ax.annotate("", xy=(apex_x + 0.45, 0.25), xytext=(apex_x, 0.25), arrowprops={"arrowstyle": "->"})
    ax.annotate("+x: positive speed", (apex_x, 0.3), fontsize=9)
    # the body relative to the toe
    ax.annotate("", xy=(0.55, 0.35), xytext=(0.35, 0.35), arrowprops={"arrowstyle": "->"})
    ax.annotate("", xy=(0.35, 0.55), xytext=(0.35, 0.35), arrowprops={"arrowstyle": "->"})
    ax.annotate("$b_x$", (0.57, 0.33), fontsize=10)
    ax.annotate("$b_y$", (0.33, 0.58), fontsize=10)
    ax.annotate(r"$(b_x, b_y) = (-q_r \sin q_\theta,\ q_r \cos q_\theta)$", (0.05, 1.02), fontsize=9)
    ax.annotate("", xy=(0.75, 0.7), xytext=(0.75, 0.95), arrowprops={"arrowstyle": "->", "color": "0.3"})
    ax.annotate("$g$", (0.78, 0.8), fontsize=10, color="0.3")
    ax.annotate("toe", (0.03, -0.06), fontsize=9)
    ax.set_xlim(-1.6, 0.9)
    ax.set_ylim(-0.08, 1.32)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(
        "SLIP at touchdown: SI units, leg angle from the vertical, counterclockwise positive", fontsize=9
    )
    fig.tight_layout()
    return fig


if __name__ == "__main__":
    draw().savefig(OUT)
    print(OUT)
