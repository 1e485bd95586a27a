"""One robot stepping hop by hop: :class:`Hopper` (its MjModel, MjData and low-level controller).

A hop, apex to apex::

    robot = Hopper(RobotParams(), terrain)
    robot.place(apex_height=1.1, apex_speed=4.0, leg_angle=0.2278)
    hop = robot.hop(hold(0.2278, 20e3, 20e3))       # = descend(swing) then ascend()
    hop.status, hop.next_apex_height, hop.next_apex_speed, hop.skid, hop.loss_touchdown

The low-level controller runs every ``control_period`` on its sensors (:meth:`Hopper.sensors`:
truth plus the parameters' noise, ``latency`` periods old, the foot switch included); MuJoCo
computes the leg's forces every physics step from the controls it sets (:mod:`.model`):

- descent (:meth:`Hopper.descend`, from the apex): the hip servo tracks ``swing(t).angle`` (t since
  the apex; the command's rate, differenced over a period, fed forward), the spring takes
  ``swing(t).k_c``. Touchdown: the foot's first contact before the stance, its time where the
  foot's sole, moving as it did a control period before, meets the ground, the state interpolated
  to it; the spring's k_c and k_d are read from the swing at that time and latched (by the foot
  switch, at once). The stance: the leg compressed by at least :data:`STANCE_COMPRESSION` (the
  foot's first contacts bounce); a contact after which the foot leaves the ground with the leg at
  full length is a graze, forgotten. In stance the hip is free (pitch locked) or balances the
  body's pitch (hinge). Bottom: the first control step in stance where the leg stops compressing
  with the foot on the ground (a bounce lets the leg extend in the air); the spring takes k_d.
- ascent (:meth:`Hopper.ascend`): liftoff at the first control step where the leg is within
  :data:`LIFTOFF_TOLERANCE` of full length, the foot out of contact and the body rising; then the
  leg shortens by ``retraction`` (a critically damped servo on the leg) for ``retraction_hold`` of
  the ascent and extends again, while the hip servo swings the leg to ``leg_angle``; the apex where
  the centre of mass's vertical speed crosses zero (interpolated within the control period).

A hop's record is a :class:`Hop`. Polar states ``(q_r, q_rd, q_th, q_thd)`` are the hip's about
the foot's contact point (the foot centre's x, its sole's height), the point taken at rest like
the SLIP's toe (the rates from the hip's velocity over the ground), in the library's convention
(the hip at ``(-q_r sin q_th, q_r cos q_th)`` from it). The sphere's contact point lies below its
centre, not on the leg's axis: at touchdown q_th is the leg's angle times about 1 - r / l0 (0.2232
for a leg at 0.2277 rad), q_r within 0.5 mm of the leg's length. Energies [J] are the total
mechanical energy of every body plus the leg spring's ``k (l0 - l)^2 / 2`` at the spring's current
stiffness; the books balance by definition::

    energy_end = energy_start - loss_touchdown + switch_work - loss_liftoff

with ``loss_touchdown`` = apex -> bottom (the foot's impact, its skid, the hip servo's work),
``switch_work`` = (k_d - k_c) c^2 / 2 at the bottom's compression c, and ``loss_liftoff`` = bottom
-> next apex (the foot caught by the leg's stop and stopped by the hip servo).

Statuses (:class:`~slipmaps.generated.status.Status`): ``FALL`` when the leg bottoms out (within
1 mm of ``stroke``), its angle leaves +-pi/2, the body pitches beyond +-pi/2 or the hip comes
within two foot radii of the lowest ground; ``NO_TOUCHDOWN`` without a touchdown within the time
limit, or when the hip sinks that low before any touchdown (no ground there); ``NO_LIFTOFF`` when
a stance lasts longer than :data:`STANCE_LIMIT`. A hop that fails leaves the robot where it failed:
:meth:`Hopper.place` it again. Values a failed hop did not reach are NaN; an OK hop has none.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field, fields

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from .mj import mujoco
from .model import ACTUATORS, Layout, build
from .params import RobotParams
from .terrain import Terrain

__all__ = [
    "Descent",
    "Hop",
    "Hopper",
    "LIFTOFF_TOLERANCE",
    "Sensors",
    "STANCE_COMPRESSION",
    "STANCE_LIMIT",
    "Trajectory",
]

#: The leg compression [m] that starts a stance (the foot's first contacts bounce).
STANCE_COMPRESSION = 0.01
#: Liftoff: the leg within this of full length [m], the foot out of contact, the body rising.
LIFTOFF_TOLERANCE = 0.001
#: The longest stance [s] (NO_LIFTOFF after it).
STANCE_LIMIT = 1.0
_SPRING, _DAMPER, _MOTOR, _HIP = (ACTUATORS.index(a) for a in ("spring", "damper", "leg_motor", "hip"))
_NAN4 = (math.nan,) * 4


@dataclass(frozen=True)
class Sensors:
    """What the controller reads (truth plus noise, ``latency`` control periods old): the hip's
    ``x``, ``z`` [m] and rates ``xd``, ``zd`` [m/s]; the body's ``pitch`` [rad] and ``pitch_rate``
    [rad/s] (0 when locked); the leg's length ``leg_length`` [m] (hip to sole) and ``leg_rate``
    [m/s]; the ``hip_angle`` [rad] (the leg against the body) and ``hip_rate`` [rad/s]; ``contact``
    (the foot switch: no noise, the same latency). Noise (standard deviations, RobotParams):
    ``noise_position`` on x and z, ``noise_velocity`` on xd, zd and the leg's rate (and divided by
    l0 on the pitch and hip rates), ``noise_leg_length``, ``noise_hip_angle`` on the hip angle and
    the pitch."""

    x: float
    z: float
    pitch: float
    xd: float
    zd: float
    pitch_rate: float
    leg_length: float
    leg_rate: float
    hip_angle: float
    hip_rate: float
    contact: bool

    @property
    def leg_angle(self) -> float:
        """The leg's angle from the vertical [rad]: pitch + hip angle."""
        return self.pitch + self.hip_angle


@dataclass
class Descent:
    """The first half of a hop, apex -> bottom (module docstring; NaN where not reached, only
    with a status that is not OK): ``touchdown``, ``bottom`` polar states; ``t_descent`` (apex ->
    touchdown), ``t_bottom`` (touchdown -> bottom) [s]; ``foot_x`` (the contact point at touchdown
    relative to the apex's hip x) [m]; ``ground`` (the absolute height there) [m]; ``k_c``, ``k_d``
    [N/m] read from the swing at the touchdown; ``touchdown_angle`` (the leg's angle from the
    vertical at touchdown) [rad]; ``bounces`` so far; ``energy_start`` (at the apex) and
    ``energy_bottom`` [J]; ``peak_leg_force`` [N] and ``peak_hip_torque`` [N m] so far."""

    status: Status
    touchdown: np.ndarray = field(default_factory=lambda: np.full(4, math.nan))
    bottom: np.ndarray = field(default_factory=lambda: np.full(4, math.nan))
    t_descent: float = math.nan
    t_bottom: float = math.nan
    foot_x: float = math.nan
    ground: float = math.nan
    k_c: float = math.nan
    k_d: float = math.nan
    touchdown_angle: float = math.nan
    bounces: int = 0
    energy_start: float = math.nan
    energy_bottom: float = math.nan
    peak_leg_force: float = 0.0
    peak_hip_torque: float = 0.0
    _foot_td: float = math.nan  # the foot centre's x at touchdown (the skid's start)
    _apex_x: float = math.nan

    @property
    def ok(self) -> bool:
        return self.status == Status.OK


@dataclass
class Hop:
    """One hop's record, apex to apex (module docstring; times [s], lengths [m], energies [J];
    NaN only with a status that is not OK):

    ``status``, ``message``; polar states ``touchdown``, ``bottom``, ``liftoff``; ``t_descent``
    (apex -> touchdown), ``t_bottom`` (touchdown -> bottom), ``t_stance`` (touchdown -> liftoff),
    ``t_ascent`` (liftoff -> apex); ``foot_x`` (the contact point at touchdown relative to the
    apex's hip x), ``step_length`` (the hip's x, apex to apex), the next apex: ``next_apex_height``
    (the hip above the touchdown ground), ``next_apex_speed`` (the centre of mass's horizontal speed: the
    torso's changes in flight as the leg swings), ``apex_x`` (the hip's absolute x); ``ground``
    (the absolute height at the touchdown contact point); ``touchdown_angle`` [rad]; the robot's
    own: ``skid`` (the foot's horizontal travel in stance), ``bounces`` (foot flights in stance),
    ``scuffs`` (foot contacts in the ascent), ``energy_start``, ``energy_end`` (at both apexes),
    ``loss_touchdown``, ``switch_work``, ``loss_liftoff``, ``peak_leg_force`` [N],
    ``peak_hip_torque`` [N m], and the applied ``k_c``, ``k_d`` [N/m]."""

    status: Status
    message: str
    touchdown: np.ndarray
    bottom: np.ndarray
    liftoff: np.ndarray
    t_descent: float
    t_bottom: float
    t_stance: float
    t_ascent: float
    foot_x: float
    step_length: float
    next_apex_height: float
    next_apex_speed: float
    apex_x: float
    ground: float
    touchdown_angle: float
    skid: float
    bounces: int
    scuffs: int
    energy_start: float
    energy_end: float
    loss_touchdown: float
    switch_work: float
    loss_liftoff: float
    peak_leg_force: float
    peak_hip_torque: float
    k_c: float
    k_d: float

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    def as_dict(self) -> dict:
        """The record as a dict (polar states as ``touchdown_q_r`` ...)."""
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if isinstance(v, np.ndarray):
                out.update({f"{f.name}_{q}": float(x) for q, x in zip(_POLAR, v, strict=True)})
            else:
                out[f.name] = v
        return out


_POLAR = ("q_r", "q_rd", "q_th", "q_thd")


@dataclass
class Trajectory:
    """A logged run: ``time`` [s] (n,) and ``qpos`` (n, nq) at the logging rate, ``phase`` (n,):
    0 flight, 1 stance (for drawing)."""

    time: list = field(default_factory=list)
    qpos: list = field(default_factory=list)
    phase: list = field(default_factory=list)

    def arrays(self):
        """``(time, qpos, phase)`` as arrays."""
        return np.asarray(self.time), np.asarray(self.qpos), np.asarray(self.phase)


class Hopper:
    """The robot on ``terrain`` (flat ground when None) with parameters ``params`` (module
    docstring). ``log_rate`` [frames/s]: log the trajectory (:attr:`trajectory`) at that rate."""

    def __init__(self, params: RobotParams | None = None, terrain: Terrain | None = None, log_rate=None):
        self._mj = mujoco()
        self.params = p = (RobotParams() if params is None else params).check()
        self.terrain = Terrain.flat() if terrain is None else terrain
        self.model = build(p, self.terrain)
        self.data = self._mj.MjData(self.model)
        self.layout = Layout.of(self.model)
        self._rng = np.random.default_rng(p.seed)
        # the reading's noise, in _truth's order: angular rates get noise_velocity / l0
        pos, vel, ang = p.noise_position, p.noise_velocity, p.noise_hip_angle
        turn = vel / p.l0
        self._sigma = np.array([pos, pos, ang, vel, vel, turn, p.noise_leg_length, vel, ang, turn])
        self._noisy = bool(np.any(self._sigma > 0))
        self._mu = p.foot_mass * p.stance_mass / p.total_mass
        self._flight_c = 2.0 * math.sqrt(p.k_c * self._mu)  # critical damping of the foot on the spring
        self._right, self._bottomed = 0.5 * math.pi, p.l0 - p.stroke + 0.001
        self._w_foot, self._r = p.foot_mass / p.total_mass, p.foot_radius
        lowest = min(0.0, float(self.terrain.levels.min())) if self.terrain.levels.size else 0.0
        self._z_low = lowest + 2 * p.foot_radius
        self.trajectory = Trajectory() if log_rate else None
        self._frame = 1.0 / log_rate if log_rate else math.inf
        self._next_frame = 0.0
        self._descent: Descent | None = None
        self._t_apex = math.nan
        self._apex_x = math.nan

    # ---------------------------------------------------------------------------------------------
    # state and sensors
    def _truth(self) -> list:
        """[x, z, pitch, xd, zd, pitch_rate, l, ld, hip, hip_rate, contact] now (also kept as
        ``_now``)."""
        L, d = self.layout, self.data
        q, v = d.qpos.tolist(), d.qvel.tolist()
        pa = L.pitch
        now = [
            q[L.x],
            q[L.z],
            q[pa] if pa is not None else 0.0,
            v[L.x],
            v[L.z],
            v[pa] if pa is not None else 0.0,
            self.params.l0 + q[L.leg],
            v[L.leg],
            q[L.hip],
            v[L.hip],
            d.ncon > 0,
        ]
        self._now = now
        return now

    def _read(self) -> list:
        """The controller's reading (noise, latency) as a list in :meth:`_truth`'s order; one new
        reading per simulated instant (reading twice at one time returns the same)."""
        buf = self._buffer
        if self.data.time != self._read_at:
            r = self._truth()
            if self._noisy:
                r = [*(np.asarray(r[:10]) + self._sigma * self._rng.standard_normal(10)).tolist(), r[10]]
            buf.append(r)
            self._read_at = self.data.time
        return buf[0]

    def sensors(self) -> Sensors:
        """The controller's reading now (:class:`Sensors`: noise, ``latency`` periods old; taking it
        draws the noise of a control period)."""
        return Sensors(*self._read())

    def _kinematics(self, q, v) -> dict:
        """Hip, foot centre, leg angle and the centre of mass from qpos ``q`` and qvel ``v``."""
        p, L = self.params, self.layout
        pa = L.pitch
        th = q[L.hip] + (q[pa] if pa is not None else 0.0)
        thd = v[L.hip] + (v[pa] if pa is not None else 0.0)
        s, c = math.sin(th), math.cos(th)
        r = p.l0 + q[L.leg] - p.foot_radius
        rd = v[L.leg]
        fx, fz = q[L.x] + r * s, q[L.z] - r * c
        fxd = v[L.x] + rd * s + r * c * thd
        fzd = v[L.z] - rd * c + r * s * thd
        w = p.foot_mass / p.total_mass
        return {
            "x": q[L.x],
            "z": q[L.z],
            "xd": v[L.x],
            "zd": v[L.z],
            "th": th,
            "thd": thd,
            "fx": fx,
            "fz": fz,
            "fxd": fxd,
            "fzd": fzd,
            "com_xd": v[L.x] + w * (fxd - v[L.x]),
            "com_zd": v[L.z] + w * (fzd - v[L.z]),
        }

    def _polar(self, k: dict) -> np.ndarray:
        """The hip's polar state about the foot's contact point (the foot centre's x, its sole's
        height), the point at rest (the SLIP's toe: the hip's velocity over the ground)."""
        dx, dz = k["x"] - k["fx"], k["z"] - (k["fz"] - self.params.foot_radius)
        vx, vz = k["xd"], k["zd"]
        r2 = dx * dx + dz * dz
        r = math.sqrt(r2)
        return np.array([r, (dx * vx + dz * vz) / r, math.atan2(-dx, dz), (dx * vz - dz * vx) / r2])

    def energy(self) -> float:
        """The total mechanical energy now [J]: every body's kinetic and gravitational energy (MuJoCo's
        ``mj_energyPos``, ``mj_energyVel``) plus the leg spring's ``k (l0 - l)^2 / 2``."""
        m, d = self.model, self.data
        self._mj.mj_forward(m, d)
        self._mj.mj_energyPos(m, d)
        self._mj.mj_energyVel(m, d)
        c = -d.qpos[self.layout.leg]
        return float(d.energy[0] + d.energy[1] + 0.5 * d.ctrl[_SPRING] * c * c)

    def _log(self, stance: int):
        d = self.data
        if d.time >= self._next_frame:
            tr = self.trajectory
            tr.time.append(d.time)
            tr.qpos.append(d.qpos.copy())
            tr.phase.append(stance)
            self._next_frame = d.time + self._frame

    # ---------------------------------------------------------------------------------------------
    def place(self, apex_height: float, apex_speed: float, x: float = 0.0, leg_angle: float = 0.0) -> None:
        """The robot at an apex: the hip ``apex_height`` [m] above the ground under it at ``x`` [m],
        horizontal speed ``apex_speed`` [m/s], vertical 0, the leg at full length at ``leg_angle``
        [rad], the foot moving with the body, the body level."""
        for name, value in (("apex_height", apex_height), ("apex_speed", apex_speed), ("x", x)):
            if not math.isfinite(value):
                raise ValueError(f"place: {name} must be finite, got {value!r}")
        if not abs(leg_angle) < 0.5 * math.pi:
            raise ValueError(f"place: leg_angle [rad] must lie in (-pi/2, pi/2), got {leg_angle!r}")
        g = self.terrain.height_at(x)
        if not math.isfinite(g):
            raise ValueError(f"place: x must lie on the terrain {self.terrain.extent}, got {x!r}")
        p = self.params
        if not apex_height > p.l0 * math.cos(leg_angle) + p.foot_radius:
            raise ValueError(
                f"place: apex_height [m] must put the foot above the ground (> l0 cos(leg_angle) = "
                f"{p.l0 * math.cos(leg_angle):.6g}), got {apex_height!r}"
            )
        mj, m, d, L = self._mj, self.model, self.data, self.layout
        mj.mj_resetData(m, d)
        d.qpos[L.x], d.qpos[L.z], d.qpos[L.hip], d.qpos[L.leg] = x, g + apex_height, leg_angle, 0.0
        d.qvel[L.x] = apex_speed
        d.ctrl[:] = 0.0
        d.ctrl[_SPRING], d.ctrl[_DAMPER] = p.k_c, p.leg_damping
        mj.mj_forward(m, d)
        self._buffer = deque(maxlen=p.latency + 1)
        self._read_at = math.nan
        self._read()
        while len(self._buffer) <= p.latency:  # no older readings yet: the first one repeated
            self._buffer.append(self._buffer[0])
        self._t_apex, self._apex_x = 0.0, x
        self._descent = None
        self._ready = True
        self._next_frame = 0.0
        if self.trajectory is not None:
            self._log(0)

    # ---------------------------------------------------------------------------------------------
    def _hip_torque(self, r: list, angle: float, rate: float) -> float:
        p = self.params
        tau = p.hip_kp * (angle - r[2] - r[8]) + p.hip_kd * (rate - r[5] - r[9])
        lim = p.hip_torque_limit
        return lim if tau > lim else -lim if tau < -lim else tau

    def _balance_torque(self, r: list) -> float:
        """The stance hip torque: 0 with the pitch locked, else the body's attitude servo."""
        p = self.params
        if self.layout.pitch is None:
            return 0.0
        tau = p.pitch_kp * r[2] + p.pitch_kd * r[5]
        lim = p.hip_torque_limit
        return lim if tau > lim else -lim if tau < -lim else tau

    def _fallen(self) -> bool:
        """The robot has fallen (module docstring), from its true state at the last reading."""
        n = self._now
        return (
            abs(n[2] + n[8]) >= self._right
            or abs(n[2]) >= self._right
            or n[6] <= self._bottomed
            or n[1] < self._z_low
        )

    def _com_zd(self) -> float:
        """The centre of mass's vertical speed at the last reading [m/s]."""
        n = self._now
        th, thd = n[2] + n[8], n[5] + n[9]
        # the foot's vertical speed relative to the hip: -ld cos th + (l - r) sin th thd
        return n[4] + self._w_foot * (-n[7] * math.cos(th) + (n[6] - self._r) * math.sin(th) * thd)

    def descend(self, swing, time_limit: float = 3.0) -> Descent:
        """From the apex to the bottom (module docstring): the hip servo tracks ``swing(t)`` (t [s]
        since the apex; a callable returning a :class:`~.swing.Command`), the stiffness read at the
        touchdown. ``time_limit`` [s]: NO_TOUCHDOWN without a touchdown within it. The robot stays at
        the bottom, ready for :meth:`ascend`."""
        if not getattr(self, "_ready", False):
            raise RuntimeError("Hopper.descend: the robot is not at an apex: place() it first")
        self._ready = False
        mj, m, d, p = self._mj, self.model, self.data, self.params
        step, nsub, ctrl, q, v = mj.mj_step, p.substeps, d.ctrl, d.qpos, d.qvel
        T, l0, leg_dof = p.control_period, p.l0, self.layout.leg
        t0 = self._t_apex
        out = Descent(Status.OK, energy_start=self.energy(), _apex_x=self._apex_x)
        logging = self.trajectory is not None
        prev_angle = swing(max(d.time - t0, 0.0)).angle
        contact_t = math.nan
        held = stance = was_contact = False
        peak_f = peak_tau = 0.0
        pre = None
        while True:
            r = self._read()
            contact = self._now[10]
            t = d.time - t0
            if contact and not held:  # the touchdown, during the last control period
                held = True
                q_td, v_td, contact_t = self._touchdown(pre)
                out.t_descent = float(contact_t - t0)
                cmd = swing(out.t_descent)
                out.k_c, out.k_d = cmd.k_c, cmd.k_d
                k = self._kinematics(q_td, v_td)
                out.touchdown = self._polar(k)
                out._foot_td = k["fx"]
                out.foot_x = k["fx"] - self._apex_x
                out.ground = float(self.terrain.height_at(k["fx"]))
                out.touchdown_angle = k["th"]
                out.bounces = 0
            elif held:
                if contact and not was_contact:
                    out.bounces += 1
                if not stance:
                    if r[10] and l0 - r[6] >= STANCE_COMPRESSION:
                        stance = True
                    elif not contact and not r[10] and r[6] >= l0 - LIFTOFF_TOLERANCE:
                        # a graze: the foot left the ground, the leg at full length; forgotten
                        held = False
                        out = Descent(Status.OK, energy_start=out.energy_start, _apex_x=self._apex_x)
            was_contact = contact
            if stance and r[10] and r[7] >= 0.0:  # the bottom (not a bounce's extension)
                out.t_bottom = float(d.time - contact_t)
                out.bottom = self._polar(self._kinematics(q, v))
                out.energy_bottom = self.energy()
                break
            if self._fallen():  # the hip below the ground before a touchdown: there is no ground
                out.status = Status.FALL if held or self._now[1] >= self._z_low else Status.NO_TOUCHDOWN
                break
            if not held and t > time_limit:
                out.status = Status.NO_TOUCHDOWN
                break
            if held and d.time - contact_t > STANCE_LIMIT:
                out.status = Status.NO_LIFTOFF
                break
            if held:
                ctrl[_SPRING] = out.k_c
                tau = self._balance_torque(r)
            else:
                cmd = swing(t)
                ctrl[_SPRING] = cmd.k_c
                tau = self._hip_torque(r, cmd.angle, (cmd.angle - prev_angle) / T)
                prev_angle = cmd.angle
                pre = (q.copy(), v.copy(), d.time)
            ctrl[_HIP] = tau
            step(m, d, nsub)
            if logging:
                self._log(int(held))
            f = d.qfrc_actuator[leg_dof]
            peak_f = f if f > peak_f else peak_f
            peak_tau = -tau if -tau > peak_tau else tau if tau > peak_tau else peak_tau
        out.peak_leg_force, out.peak_hip_torque = float(peak_f), float(peak_tau)
        self._descent = out
        self._t_touchdown = contact_t
        return out

    def ascend(self, k_d: float | None = None, leg_angle: float | None = None) -> Hop:
        """From the bottom to the next apex (module docstring): the leg's spring at ``k_d`` [N/m]
        (default: the swing's k_d read at the touchdown), liftoff, the flight with the leg retracted
        and extended again while the hip servo swings the leg to ``leg_angle`` [rad] (default: this
        hop's touchdown angle). Returns the hop's :class:`Hop`; when it is OK the robot is at the
        next apex, ready for :meth:`descend`."""
        dsc = self._descent
        if dsc is None:
            raise RuntimeError("Hopper.ascend: the robot is not at a bottom: descend() first")
        self._descent = None
        if not dsc.ok:
            return self._record(dsc, dsc.status)
        kd = dsc.k_d if k_d is None else float(k_d)
        if not (math.isfinite(kd) and kd > 0):
            raise ValueError(f"Hopper.ascend: k_d [N/m] must be finite and > 0, got {k_d!r}")
        target = dsc.touchdown_angle if leg_angle is None else float(leg_angle)
        mj, m, d, p = self._mj, self.model, self.data, self.params
        step, nsub, ctrl, q, v = mj.mj_step, p.substeps, d.ctrl, d.qpos, d.qvel
        l0, leg_dof, g = p.l0, self.layout.leg, p.gravity
        logging = self.trajectory is not None
        c_b = -q[leg_dof]
        switch_work = 0.5 * (kd - dsc.k_c) * c_b * c_b
        ctrl[_SPRING] = kd
        peak_f, peak_tau = dsc.peak_leg_force, dsc.peak_hip_torque
        bounces, was_contact = dsc.bounces, True
        t_td = self._t_touchdown
        status = Status.OK
        liftoff = None
        # stance: bottom -> liftoff
        while True:
            r = self._read()
            contact = self._now[10]
            if contact and not was_contact:
                bounces += 1
            was_contact = contact
            if not r[10] and r[6] >= l0 - LIFTOFF_TOLERANCE and r[4] > 0.0:
                k = self._kinematics(q, v)
                liftoff = self._polar(k)
                t_lo, skid = d.time, k["fx"] - dsc._foot_td
                break
            if self._fallen():
                status = Status.FALL
                break
            if d.time - t_td > STANCE_LIMIT:
                status = Status.NO_LIFTOFF
                break
            tau = self._balance_torque(r)
            ctrl[_HIP] = tau
            step(m, d, nsub)
            if logging:
                self._log(1)
            f = d.qfrc_actuator[leg_dof]
            peak_f = f if f > peak_f else peak_f
            peak_tau = -tau if -tau > peak_tau else tau if tau > peak_tau else peak_tau
        if status != Status.OK:
            return self._record(dsc, status, peak_f=peak_f, peak_tau=peak_tau, bounces=bounces)
        # flight: liftoff -> apex, the leg retracted for retraction_hold of the predicted ascent
        t_release = t_lo + p.retraction_hold * max(r[4], 0.0) / g
        ctrl[_SPRING], ctrl[_DAMPER], ctrl[_MOTOR] = p.k_c, self._flight_c, -p.k_c * p.retraction
        scuffs, was_contact = 0, False
        prev = None
        while True:
            r = self._read()
            vz = self._com_zd()
            if vz <= 0.0:
                break
            contact = self._now[10]
            if contact and not was_contact:
                scuffs += 1
            was_contact = contact
            if self._fallen():
                status = Status.FALL
                break
            if d.time >= t_release:
                ctrl[_MOTOR] = 0.0
            tau = self._hip_torque(r, target, 0.0)
            ctrl[_HIP] = tau
            prev = (q.copy(), d.time, vz)
            step(m, d, nsub)
            if logging:
                self._log(0)
            peak_tau = -tau if -tau > peak_tau else tau if tau > peak_tau else peak_tau
        ctrl[_MOTOR], ctrl[_DAMPER] = 0.0, p.leg_damping
        if status != Status.OK:
            return self._record(dsc, status, peak_f=peak_f, peak_tau=peak_tau, bounces=bounces)
        # the apex: where the centre of mass's vertical speed crosses zero
        v_x = self._kinematics(q, v)["com_xd"]  # constant in flight
        if prev is None:
            q_a, t_a = q.copy(), d.time
        else:
            q0, t0, vz0 = prev
            a = vz0 / (vz0 - vz)
            q_a, t_a = q0 + a * (q - q0), float(t0 + a * (d.time - t0))
        L = self.layout
        self._t_apex, self._apex_x = t_a, q_a[L.x]
        self._ready = True
        e_end = self.energy()
        hop = self._record(
            dsc,
            Status.OK,
            peak_f=peak_f,
            peak_tau=peak_tau,
            bounces=bounces,
            liftoff=liftoff,
            t_stance=t_lo - t_td,
            t_ascent=t_a - t_lo,
            step_length=q_a[L.x] - dsc._apex_x,
            next_apex_height=q_a[L.z] - dsc.ground,
            next_apex_speed=v_x,
            apex_x=q_a[L.x],
            skid=skid,
            scuffs=scuffs,
            energy_end=e_end,
            switch_work=switch_work,
            k_d=kd,
        )
        return hop

    def hop(self, swing, time_limit: float = 3.0, leg_angle: float | None = None) -> Hop:
        """One hop: :meth:`descend` with ``swing``, then :meth:`ascend` with the k_d read at the
        touchdown."""
        self.descend(swing, time_limit)
        return self.ascend(leg_angle=leg_angle)

    def _record(self, dsc: Descent, status: Status, **got) -> Hop:
        """The hop's record from the descent ``dsc`` and what the ascent reached (``got``)."""
        nan = math.nan
        values = {
            "liftoff": np.full(4, nan),
            "t_stance": nan,
            "t_ascent": nan,
            "step_length": nan,
            "next_apex_height": nan,
            "next_apex_speed": nan,
            "apex_x": nan,
            "skid": nan,
            "scuffs": 0,
            "energy_end": nan,
            "switch_work": nan,
            "k_d": dsc.k_d,
            "peak_f": dsc.peak_leg_force,
            "peak_tau": dsc.peak_hip_torque,
            "bounces": dsc.bounces,
        }
        values.update(got)
        e0, eb, e1, sw = dsc.energy_start, dsc.energy_bottom, values["energy_end"], values["switch_work"]
        hop = Hop(
            status=Status(status),
            message=MESSAGES[int(status)],
            touchdown=dsc.touchdown,
            bottom=dsc.bottom,
            liftoff=values["liftoff"],
            t_descent=float(dsc.t_descent),
            t_bottom=float(dsc.t_bottom),
            t_stance=float(values["t_stance"]),
            t_ascent=float(values["t_ascent"]),
            foot_x=float(dsc.foot_x),
            step_length=float(values["step_length"]),
            next_apex_height=float(values["next_apex_height"]),
            next_apex_speed=float(values["next_apex_speed"]),
            apex_x=float(values["apex_x"]),
            ground=float(dsc.ground),
            touchdown_angle=float(dsc.touchdown_angle),
            skid=float(values["skid"]),
            bounces=int(values["bounces"]),
            scuffs=int(values["scuffs"]),
            energy_start=e0,
            energy_end=e1,
            loss_touchdown=e0 - eb,
            switch_work=sw,
            loss_liftoff=eb + sw - e1,
            peak_leg_force=float(values["peak_f"]),
            peak_hip_torque=float(values["peak_tau"]),
            k_c=float(dsc.k_c),
            k_d=float(values["k_d"]),
        )
        return hop

    def _touchdown(self, pre):
        """The touchdown's time and state: the time the foot's sole, moving as it did at the control
        step before the contact (``pre``), meets the ground; the state interpolated to that time
        between ``pre`` and now."""
        d = self.data
        q1, v1, t1 = d.qpos.copy(), d.qvel.copy(), d.time
        if pre is None:
            return q1, v1, t1
        q0, v0, t0 = pre
        k = self._kinematics(q0, v0)
        gap = k["fz"] - self.params.foot_radius - float(self.terrain.height_at(k["fx"]))
        a = gap / (-k["fzd"] * (t1 - t0)) if k["fzd"] < 0.0 else 1.0
        a = min(max(a, 0.0), 1.0)
        return q0 + a * (q1 - q0), v0 + a * (v1 - v0), float(t0 + a * (t1 - t0))
