"""The MuJoCo robot as a run's plant: one :class:`~slipmaps.runtime.robot.hopper.Hopper` per run,
behind the plant interface the map plant implements (:mod:`.plant`).

``plant = "mujoco"`` in a scenario (``[plant] kind = "mujoco"``, ``slipmaps run --plant mujoco``):
:meth:`RobotPlant.start` builds each run's terrain from its touchdown grounds (one level per
segment: :mod:`slipmaps.runtime.robot.settings`; a stones course: its stones, :func:`stones_terrain`)
and its robot, to be placed at the scenario's
start apex with its leg at the first step's commanded angle; a step then hands each run's robot
the controller's command and records what the robot did:

- the swing leg: the angle set at the apex, held or retracting at the retraction rate, or a
  time-based policy's tables (the angle and the stiffness as functions of the time since the apex)
  for the hip servo to follow; the stiffness k_c until the bottom, k_d after it (a two-stage step:
  the k_d chosen at the bottom the robot measured, :meth:`RobotPlant.compress` and
  :meth:`RobotPlant.decompress`); during the ascent the servo brings the leg to the step's
  touchdown angle, the controller's next command arrives at the apex;
- the record: the same columns as a map plant's (the robot's polar states about its foot, its
  times, the next apex: the hip's height above the touchdown ground and the centre of mass's
  speed), the ``ground`` the foot met (relative to the ground under the apex: the terrain is the
  robot's, the controller is told it only when the scenario's terrain is ``known``), and the
  robot's own columns (:data:`COLUMNS`).

The plant's robots stay with the batch (:attr:`RobotPlant.hoppers`; the run's ``plant``): with a
``log_rate`` their trajectories are there to render (``slipmaps run --plant mujoco --gif``).
"""

from __future__ import annotations

import math

import numpy as np

from ..robot.settings import robot_settings
from .plant import Compressed, PlantSteps, blank_failed

__all__ = ["COLUMNS", "RobotPlant", "stones_terrain"]

#: The robot's own per-step records (``slipmaps.runtime.robot.hopper.Hop``'s fields): the foot's
#: skid [m], its bounces and scuffs, the energy at the apex and the step's losses [J], the peaks of
#: the leg force [N] and the hip torque [N m].
COLUMNS = (
    "skid",
    "bounces",
    "scuffs",
    "energy_start",
    "energy_end",
    "loss_touchdown",
    "switch_work",
    "loss_liftoff",
    "peak_leg_force",
    "peak_hip_torque",
)
_DESCENT = ("bounces", "energy_start", "peak_leg_force", "peak_hip_torque")


class RobotPlant:
    """The robot plant of scenario ``sc`` (module docstring)."""

    columns = COLUMNS
    has_halves = True
    name = "mujoco"

    def __init__(self, sc):
        from ..robot import hopper  # MuJoCo: one line naming the extra when it is not installed

        self._hopper = hopper
        self.settings = robot_settings(sc.plant_options)
        self.params = self.settings.params
        self.hoppers: list = []
        self._ground = np.zeros(0)  # each run's ground under its current apex (absolute)
        self._placed = np.zeros(0, dtype=bool)
        self._start = (sc.start_height, sc.start_speed)

    def _half(self, start: str):
        """Two-stage steps: the robot is measured at its bottom (nothing to refuse)."""

    def start(self, scenario, grounds, seeds) -> None:
        """One robot per run on its terrain (the rows of ``grounds``, one level per segment), its
        sensor noise seeded by the run's seed."""
        from ..robot.settings import step_estimate
        from ..robot.terrain import Terrain

        s = self.settings
        spacing = s.spacing or step_estimate(self.params, scenario.start_height, scenario.start_speed)
        ramp = min(s.ramp, spacing)
        # ground well beyond the last level: a run that outpaces its levels stays on the last one
        margin = 2.0 * grounds.shape[1] * spacing + 20.0
        self.spacing = spacing
        self.hoppers = []
        stones = None if scenario.stones is None else stones_terrain(scenario.stones)
        for r in range(grounds.shape[0]):
            terrain = stones or Terrain(grounds[r], spacing, kind=s.terrain, ramp=ramp, margin=margin)
            params = self.params.with_(seed=int(self.params.seed) * 1_000_003 + int(seeds[r]))
            self.hoppers.append(self._hopper.Hopper(params, terrain, log_rate=s.log_rate or None))
        self._ground = np.zeros(len(self.hoppers))
        self._placed = np.zeros(len(self.hoppers), dtype=bool)

    # ------------------------------------------------------------------------------------------
    def _swing(self, i, th, rate, kc, kd, swing):
        """Row ``i``'s swing command: a time-based table's row, or the angle held or retracting."""
        from ..robot.swing import Command, ramp

        if swing is None:
            return ramp(float(th[i]), float(rate[i]), float(kc[i]), float(kd[i]))
        table = _row(swing, i)
        fallback = (float(th[i]), float(kc[i]), float(kd[i]))

        def command(t: float):
            c = table.controls_at(t)
            values = (c["touchdown_angle"][0], c["k_c"][0], c["k_d"][0])
            return Command(*(v if math.isfinite(v) else f for v, f in zip(values, fallback, strict=True)))

        return command

    def _descend(self, rows, th, rate, kc, kd, swing):
        descents = []
        for i, r in enumerate(rows):
            robot = self.hoppers[r]
            command = self._swing(i, th, rate, kc, kd, swing)
            if not self._placed[r]:
                h, v = self._start
                robot.place(h, v, leg_angle=command(0.0).angle)
                self._placed[r] = True
            descents.append((robot, robot.descend(command)))
        return descents

    def _compressed(self, rows, descents) -> Compressed:
        n = len(descents)
        col = lambda name: np.array([getattr(d, name) for _, d in descents], dtype=float)  # noqa: E731
        status = np.array([int(d.status) for _, d in descents], dtype=np.int64)
        ground = col("ground") - self._ground[rows]
        out = Compressed(
            status=status,
            touchdown=np.stack([d.touchdown for _, d in descents]) if n else np.zeros((0, 4)),
            t_descent=col("t_descent"),
            foot_x=col("foot_x"),
            t_bottom=col("t_bottom"),
            bottom=np.stack([d.bottom for _, d in descents]) if n else np.zeros((0, 4)),
            ground=np.where(status == 0, ground, math.nan),
            k_c=col("k_c"),
            extras={"descents": descents, "k_d": col("k_d")},
        )
        return out

    @staticmethod
    def _columns(rows, th, rate, kc, kd):
        n = len(rows)
        return (np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in (th, rate, kc, kd))

    def compress(
        self,
        apex_height,
        apex_speed,
        touchdown_angle,
        ground,
        k_c,
        retraction_rate=0.0,
        *,
        swing=None,
        scale=1.0,
        rows=None,
    ) -> Compressed:
        """Each row's robot from its apex to its bottom (module docstring); the apex and the ground
        given are the robot's own (it keeps its state) and are not used."""
        rows = np.asarray(rows)
        th, rate, kc, kd = self._columns(rows, touchdown_angle, retraction_rate, k_c, k_c)
        return self._compressed(rows, self._descend(rows, th, rate, kc, kd, swing))

    def decompress(self, first: Compressed, k_d, *, rows=None) -> PlantSteps:
        """Each row's robot from its bottom on with ``k_d`` to its next apex."""
        rows = np.asarray(rows)
        kd = np.broadcast_to(np.asarray(k_d, dtype=float), (len(rows),))
        hops = []
        for i, (robot, d) in enumerate(first.extras["descents"]):
            if not d.ok:
                hops.append(None)
                continue
            hops.append(robot.ascend(float(kd[i]), leg_angle=float(d.touchdown_angle)))
        return self._steps(rows, first, hops)

    def step(
        self,
        apex_height,
        apex_speed,
        touchdown_angle,
        ground,
        k_c,
        k_d,
        retraction_rate=0.0,
        *,
        swing=None,
        scale=1.0,
        rows=None,
    ) -> PlantSteps:
        """Each row's robot from its apex to its next apex (module docstring), k_d from the bottom
        on as commanded (or read from the time-based tables at the touchdown)."""
        rows = np.asarray(rows)
        th, rate, kc, kd = self._columns(rows, touchdown_angle, retraction_rate, k_c, k_d)
        first = self._compressed(rows, self._descend(rows, th, rate, kc, kd, swing))
        k_applied = np.where(np.isfinite(first.extras["k_d"]), first.extras["k_d"], kd)
        return self.decompress(first, k_applied, rows=rows)

    def _steps(self, rows, first: Compressed, hops) -> PlantSteps:
        """The plant's record of the rows' hops (NaN where a hop failed, with its status)."""
        n = len(rows)
        status = first.status.copy()
        for i, hop in enumerate(hops):
            if hop is not None:
                status[i] = int(hop.status)

        def col(name, default=math.nan):
            return np.array([default if h is None else getattr(h, name) for h in hops], dtype=float)

        def states(name):
            return (
                np.stack([np.full(4, math.nan) if h is None else h.__dict__[name] for h in hops])
                if n
                else np.zeros((0, 4))
            )

        steps = PlantSteps(
            status=status,
            touchdown=first.touchdown,
            t_descent=first.t_descent,
            foot_x=first.foot_x,
            t_bottom=first.t_bottom,
            bottom=first.bottom,
            t_stance=col("t_stance"),
            liftoff=states("liftoff"),
            t_ascent=col("t_ascent"),
            next_apex_height=col("next_apex_height"),
            next_apex_speed=col("next_apex_speed"),
            step_length=col("step_length"),
            k_c=first.k_c,
            k_d=col("k_d"),
            ground=first.ground,
            extras={c: col(c) for c in COLUMNS},
        )
        for c in _DESCENT:  # what the descent measured, also where the ascent did not run
            descended = np.array([getattr(d, c) for _, d in first.extras["descents"]], dtype=float)
            steps.extras[c] = np.where(np.isfinite(steps.extras[c]), steps.extras[c], descended)
        ok = status == 0
        self._ground[rows[ok]] = np.array([h.ground for h in hops if h is not None and h.ok])
        return blank_failed(steps)


#: The stones' terrain: levels per segment of this length [m] (the stones' ends to the millimetre),
#: and the pits between stones this deep [m] below the lowest stone.
STONE_SPACING = 0.001
STONE_PIT = 0.5


def stones_terrain(course):
    """A stones course (:class:`~.stones.Course`) as the robot's terrain: boxes, one per stone at
    its height, pits :data:`STONE_PIT` below the lowest stone between them (a foot there misses:
    the run ends at it, MISSED); the ground at 0 before the first stone (the start apex's), and
    beyond the last stone the pit."""
    from ..robot.terrain import Terrain

    n = int(math.ceil(course.end / STONE_SPACING)) + 1
    mid = (np.arange(n) + 0.5) * STONE_SPACING
    under = np.searchsorted(np.asarray(course.x_a), mid, side="right") - 1
    j = np.clip(under, 0, len(course) - 1)
    on = (under >= 0) & (mid <= np.asarray(course.x_b)[j])
    levels = np.where(on, course.heights[j], min(course.height) - STONE_PIT)
    levels[mid < course.x_a[0]] = 0.0  # the start: the ground under the start apex, to the first stone
    return Terrain(levels, STONE_SPACING, kind="boxes", margin=20.0)


def _row(tables, i: int):
    """Row ``i`` of time-based policies' tables, as tables of one row."""
    from dataclasses import fields, replace

    cut = {}
    for f in fields(tables):
        x = getattr(tables, f.name)
        if isinstance(x, np.ndarray) and x.ndim >= 1 and x.shape[0] == tables.rows:
            cut[f.name] = x[i : i + 1]
        elif isinstance(x, dict):
            cut[f.name] = {k: v[i : i + 1] for k, v in x.items()}
    return replace(tables, **cut)
