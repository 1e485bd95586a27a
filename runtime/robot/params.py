"""The robot's parameter record: :class:`RobotParams`, frozen, checked on construction.

Every field is declared once, with its default, unit, check and meaning (the dataclass field's
metadata; :data:`FIELDS` lists them as rows: name, unit, default, valid range, meaning). SI units
throughout: kg, m, s, N/m, N s/m, N m/rad, N m s/rad, N m.

The leg length ``l`` is what the leg sensor reports: the distance from the hip to the foot's sole,
the hip-to-foot-centre distance plus ``foot_radius``, ``l0`` at full length, so a vertical leg at
full length stands the hip ``l0`` above the ground (the SLIP's leg length). The spring carries
the body and the thigh in stance: the SLIP the maps should use is :meth:`RobotParams.slip_params`
(m = body_mass + thigh_mass, l0, k_c, k_d, the gravity).

Construction refuses bad values with a :class:`RobotParamsError` (a ValueError) whose message has
one line per bad value, every bad value reported, each naming the field, the value and the valid
range.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field, fields, replace

from ..api.numeric import is_real, num
from ..api.params import SlipParams

__all__ = ["FIELDS", "PITCH_MODES", "RobotParams", "RobotParamsError", "THIGH_GYRATION"]

#: The body's pitch: locked (a planar point on two slides), or a hinge balanced in stance by the hip.
PITCH_MODES = ("locked", "hinge")


#: The thigh's radius of gyration about the hip [m] (its inertia thigh_mass * 0.1^2).
THIGH_GYRATION = 0.1


class RobotParamsError(ValueError):
    """Bad robot parameters: ``problems`` holds one line per bad value (the message joins them)."""

    def __init__(self, problems: list[str]):
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


_RANGE = {
    "positive": "finite and > 0",
    "non_negative": "finite and >= 0",
    "count": "an integer >= 0",
    "int": "an integer",
    "fraction": "finite, in [0, 1)",
    "solimp": "three numbers d0, d_width in (0, 1), d0 <= d_width, width > 0",
    "pitch": "one of " + ", ".join(repr(p) for p in PITCH_MODES),
}


def _f(default, unit: str, check: str, doc: str):
    """A field declared once: its default, unit, check (a key of ``_RANGE``) and meaning."""
    return field(default=default, metadata={"unit": unit, "check": check, "doc": doc})


def _ok(check: str, v: object) -> bool:
    if check in ("count", "int"):
        whole = isinstance(v, numbers.Integral) and not isinstance(v, bool)
        return whole and (check == "int" or v >= 0)
    if check == "pitch":
        return v in PITCH_MODES
    if check == "solimp":
        try:
            d0, d1, w = (float(x) for x in v) if len(v) == 3 and all(is_real(x) for x in v) else (0, 0, 0)
        except TypeError:
            return False
        return 0.0 < d0 <= d1 < 1.0 and math.isfinite(w) and w > 0.0
    if not is_real(v) or not math.isfinite(v):
        return False
    return {"positive": v > 0, "non_negative": v >= 0, "fraction": 0 <= v < 1}[check]


def _show(v: object) -> str:
    return repr(int(v)) if isinstance(v, numbers.Integral) and not isinstance(v, bool) else num(v)


@dataclass(frozen=True)
class RobotParams:
    """The planar monoped's parameters (module docstring; every field's unit and range:
    :data:`FIELDS`). Defaults: a 30 kg body on a 1 m, 20 kN/m leg that hops at 3-5 m/s.

    The leg: a series-elastic spring whose force the low-level controller sets, k (l0 - l) with
    k = k_c until the bottom and k_d after it, clipped at ``force_limit``, plus ``leg_damping``;
    ``stroke`` below full length the leg bottoms out (a fall). After liftoff the leg shortens by
    ``retraction`` for ``retraction_hold`` of the ascent and extends again, at full length at the
    apex. The hip: a PD servo (``hip_kp``, ``hip_kd``, ``hip_torque_limit``) on the leg's angle from
    the vertical in flight; in stance the hip is free (pitch locked) or balances the body's pitch
    (``pitch = "hinge"``: torque ``pitch_kp`` pitch + ``pitch_kd`` pitch rate). Contacts and the
    leg's stops: MuJoCo solref (``contact_time``, ``contact_damping``), ``solimp``, ``friction``.
    Sensors: Gaussian noise of the given standard deviations (0: exact), ``latency`` control
    periods old, seeded by ``seed``."""

    body_mass: float = _f(30.0, "kg", "positive", "the torso's mass (its centre of mass at the hip)")
    thigh_mass: float = _f(0.3, "kg", "positive", "the thigh's mass (at the hip, swings with the leg)")
    foot_mass: float = _f(0.6, "kg", "positive", "the foot's mass (the sphere at the leg's end)")
    foot_radius: float = _f(0.02, "m", "positive", "the foot sphere's radius")
    l0: float = _f(1.0, "m", "positive", "full leg length, hip to the foot's sole (the leg stop)")
    k_c: float = _f(20_000.0, "N/m", "positive", "nominal leg stiffness while compressing (until the bottom)")
    k_d: float = _f(20_000.0, "N/m", "positive", "nominal leg stiffness after the bottom")
    force_limit: float = _f(6_000.0, "N", "positive", "the leg spring's largest force")
    leg_damping: float = _f(
        0.0, "N s/m", "non_negative", "viscous damping along the leg in stance and descent"
    )
    stroke: float = _f(0.3, "m", "positive", "how far the leg can compress from l0 (the lower stop)")
    hip_kp: float = _f(2_000.0, "N m/rad", "positive", "hip servo's angle gain")
    hip_kd: float = _f(60.0, "N m s/rad", "non_negative", "hip servo's rate gain")
    hip_torque_limit: float = _f(300.0, "N m", "positive", "hip servo's largest torque")
    retraction: float = _f(0.15, "m", "non_negative", "how far the leg shortens after liftoff")
    retraction_hold: float = _f(0.6, "1", "fraction", "fraction of the ascent the leg stays retracted")
    control_period: float = _f(0.001, "s", "positive", "the low-level controller's period")
    timestep: float = _f(0.0005, "s", "positive", "MuJoCo's physics step")
    contact_time: float = _f(0.002, "s", "positive", "contact and leg-stop solref time constant")
    contact_damping: float = _f(1.0, "1", "positive", "contact and leg-stop solref damping ratio")
    solimp: tuple = _f((0.95, 0.99, 0.001), "1", "solimp", "contact and leg-stop solimp (d0, d_width, width)")
    friction: float = _f(1.0, "1", "positive", "the foot's sliding friction coefficient")
    pitch: str = _f("locked", "", "pitch", "the body's pitch: 'locked' or 'hinge'")
    body_inertia: float = _f(10.0, "kg m^2", "positive", "the torso's pitch inertia about the hip (hinge)")
    pitch_kp: float = _f(1_000.0, "N m/rad", "non_negative", "stance attitude gain (hip torque per pitch)")
    pitch_kd: float = _f(200.0, "N m s/rad", "non_negative", "stance attitude rate gain")
    gravity: float = _f(9.81, "m/s^2", "positive", "gravitational acceleration (pointing down)")
    noise_position: float = _f(0.0, "m", "non_negative", "sensor noise std: body x and z")
    noise_velocity: float = _f(0.0, "m/s", "non_negative", "sensor noise std: rates (angular: / l0)")
    noise_leg_length: float = _f(0.0, "m", "non_negative", "sensor noise std: leg length")
    noise_hip_angle: float = _f(0.0, "rad", "non_negative", "sensor noise std: hip angle and body pitch")
    latency: int = _f(0, "periods", "count", "sensor latency in control periods (1: one period old)")
    seed: int = _f(0, "", "int", "the sensor noise's seed")

    def __post_init__(self):
        if isinstance(self.solimp, list):
            object.__setattr__(self, "solimp", tuple(self.solimp))
        self.check()

    def problems(self) -> list[str]:
        """One line per bad value (empty when every value is valid)."""
        out = []
        bad = set()
        for f in fields(self):
            unit, check = f.metadata["unit"], f.metadata["check"]
            v = getattr(self, f.name)
            if not _ok(check, v):
                bad.add(f.name)
                u = f" [{unit}]" if unit and unit != "1" else ""
                out.append(f"RobotParams.{f.name}{u} must be {_RANGE[check]}, got {_show(v)}")

        def rel(name: str, cond, text: str, *needs: str):
            if name not in bad and not (set(needs) & bad) and not cond():
                unit = self.__dataclass_fields__[name].metadata["unit"]
                out.append(f"RobotParams.{name} [{unit}] must be {text}, got {_show(getattr(self, name))}")

        p = self
        rel("foot_radius", lambda: p.foot_radius < 0.25 * p.l0, f"< l0/4 = {0.25 * p.l0:.6g} m", "l0")
        rel(
            "stroke",
            lambda: 0.02 <= p.stroke <= p.l0 - 2 * p.foot_radius,
            f"in [0.02, l0 - 2 foot_radius = {p.l0 - 2 * p.foot_radius:.6g}] m",
            "l0",
            "foot_radius",
        )
        rel("retraction", lambda: p.retraction < p.stroke, f"< stroke = {p.stroke:.6g} m", "stroke")
        rel("timestep", lambda: p.timestep <= 0.005, "<= 0.005 s")
        rel(
            "control_period",
            lambda: (
                p.control_period >= p.timestep
                and abs(p.control_period / p.timestep - round(p.control_period / p.timestep)) < 1e-9
            ),
            f"a whole multiple of timestep = {p.timestep:.6g} s",
            "timestep",
        )
        inertia, period = p.leg_inertia, p.control_period
        servo = ("control_period", "foot_mass", "thigh_mass", "foot_radius", "l0")  # what the bounds use
        rel(
            "hip_kd",
            lambda: p.hip_kd * period <= inertia,
            f"<= leg inertia / control_period = {inertia / period:.6g} (the discrete servo is unstable "
            "from about twice that)",
            *servo,
        )
        rel(
            "hip_kp",
            lambda: p.hip_kp * period**2 <= 0.5 * inertia,
            f"<= leg inertia / (2 control_period^2) = {0.5 * inertia / period**2:.6g}",
            *servo,
        )
        rel(
            "contact_time",
            lambda: p.contact_time >= 2 * p.timestep,
            f">= 2 timestep = {2 * p.timestep:.6g} s (MuJoCo raises a smaller one silently)",
            "timestep",
        )
        return out

    def check(self) -> RobotParams:
        """Self when every value is valid, else :class:`RobotParamsError` (one line per bad value)."""
        problems = self.problems()
        if problems:
            raise RobotParamsError(problems)
        return self

    def with_(self, **changes) -> RobotParams:
        """A checked copy with ``changes``."""
        return replace(self, **changes)

    # ------------------------------------------------------------------------------------------
    @property
    def stance_mass(self) -> float:
        """The mass the spring carries in stance [kg]: body + thigh."""
        return self.body_mass + self.thigh_mass

    @property
    def total_mass(self) -> float:
        """Every body's mass [kg]."""
        return self.body_mass + self.thigh_mass + self.foot_mass

    @property
    def leg_inertia(self) -> float:
        """The swinging leg's inertia about the hip [kg m^2]: the thigh's, the foot on its arm
        (l0 - foot_radius) and the foot sphere's own."""
        arm = self.l0 - self.foot_radius
        return (
            self.thigh_mass * THIGH_GYRATION**2
            + self.foot_mass * arm**2
            + 0.4 * self.foot_mass * self.foot_radius**2
        )

    @property
    def substeps(self) -> int:
        """Physics steps per control period."""
        return int(round(self.control_period / self.timestep))

    def slip_params(self, k_c: float | None = None, k_d: float | None = None) -> SlipParams:
        """The nominal SLIP of this robot for the maps: m = body + thigh, l0, k_c and k_d (these or
        the given ones), g_s = g_f = gravity."""
        return SlipParams(
            m=self.stance_mass,
            l0=self.l0,
            k_c=self.k_c if k_c is None else k_c,
            k_d=self.k_d if k_d is None else k_d,
            g_s=self.gravity,
            g_f=self.gravity,
        )


#: Every field as a row: (name, unit, default, valid range, meaning).
FIELDS: tuple[tuple[str, str, object, str, str], ...] = tuple(
    (f.name, f.metadata["unit"], f.default, _RANGE[f.metadata["check"]], f.metadata["doc"])
    for f in fields(RobotParams)
)
