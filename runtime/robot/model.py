"""The robot's MuJoCo model: a planar monoped built from :class:`~.params.RobotParams` and a
:class:`~.terrain.Terrain`.

Bodies and joints (x forward, z up; the robot moves in the x-z plane):

- ``torso``: slides ``x`` and ``z`` (its origin is the hip; qpos are the hip's world coordinates),
  with ``pitch = "hinge"`` a hinge ``pitch`` about -y (the body's pitch, counterclockwise positive
  like the leg angle); its centre of mass at the hip;
- ``thigh``: the ``hip`` hinge about -y, so that the hinge angle is the library's leg angle (from
  the vertical, counterclockwise positive, the foot ahead of the hip for a positive angle; with the
  pitch hinge, the leg's angle is pitch + hip); its centre of mass at the hip;
- ``foot``: the ``leg`` slide along the leg, s = l - l0 in [-stroke, 0] (its range is the leg's
  stops: full length at 0, bottomed out at -stroke), a sphere of ``foot_radius`` whose centre lies
  ``l - foot_radius`` from the hip.

Only the foot touches the ground (the torso's and the thigh's geoms are drawn, never collide).

Actuators (:data:`ACTUATORS`), all on MuJoCo's side of the physics step so that the controller sets
them once per control period and MuJoCo computes the force every physics step:

- ``spring``: the leg's series-elastic spring, an affine actuator whose force is ctrl (l0 - l): the
  controller sets ctrl = k [N/m] (k_c until the bottom, k_d after it), clipped at ``force_limit``;
  it only pushes (l <= l0), and no joint stiffness pulls the foot in flight;
- ``damper``: force -ctrl dl/dt, ctrl [N s/m]: ``leg_damping`` in stance, critical damping of the
  foot on the spring in flight (retraction);
- ``leg_motor``: a force ctrl [N] along the leg (shortens the leg after liftoff);
- ``hip``: a torque ctrl [N m] on the hip, within ``hip_torque_limit``.

Measured (``python benchmarks/bench_robot.py``, side by side in one run): the same force set from
Python before every physics step makes a hop 1.3-2.3x slower, for the same next apex.

Contacts and the leg stops: ``solref = (contact_time, contact_damping)``, ``solimp``; the foot's
friction ``friction`` (torsional and rolling 0); integrator ``implicitfast``.
"""

from __future__ import annotations

from dataclasses import dataclass

from .mj import mujoco, numbers
from .params import THIGH_GYRATION, RobotParams
from .terrain import Terrain

__all__ = ["ACTUATORS", "Layout", "build", "xml"]

#: The actuators, in order (module docstring).
ACTUATORS = ("spring", "damper", "leg_motor", "hip")


def xml(params: RobotParams, terrain: Terrain | None = None) -> str:
    """The MJCF text of the robot on ``terrain`` (flat ground when None)."""
    p = params.check()
    terrain = Terrain.flat() if terrain is None else terrain
    solref, solimp = numbers(p.contact_time, p.contact_damping), numbers(*p.solimp)
    contact = f'solref="{solref}" solimp="{solimp}" friction="{numbers(p.friction, 0, 0)}" condim="3"'
    it = p.thigh_mass * THIGH_GYRATION**2
    i_foot = 0.4 * p.foot_mass * p.foot_radius**2
    pitch = '<joint name="pitch" type="hinge" axis="0 -1 0"/>' if p.pitch == "hinge" else ""
    torso_l = 0.25 * p.l0
    return f"""<mujoco model="slipmaps monoped">
  <compiler angle="radian" autolimits="true" inertiafromgeom="false"/>
  <option timestep="{p.timestep!r}" integrator="implicitfast" gravity="0 0 {-p.gravity!r}"/>
  <visual><global offwidth="1280" offheight="960"/></visual>
  <asset>
    <texture type="skybox" builtin="gradient" rgb1=".93 .95 .97" rgb2=".62 .7 .8" width="64" height="64"/>
    <texture name="grid" type="2d" builtin="checker" rgb1=".82 .84 .86" rgb2=".72 .74 .77"
             width="256" height="256"/>
    <material name="grid" texture="grid" texrepeat="1 1" texuniform="true"/>
    {terrain.assets_xml()}
  </asset>
  <worldbody>
    <light pos="0 -3 4" dir="0 1 -1" directional="true"/>
    {terrain.geoms_xml(contact + ' material="grid" contype="1" conaffinity="1"')}
    <body name="torso">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      {pitch}
      <inertial pos="0 0 0" mass="{p.body_mass!r}" diaginertia="{numbers(*[p.body_inertia] * 3)}"/>
      <geom type="box" size="{numbers(torso_l, 0.08, 0.06)}" rgba=".25 .4 .65 1"
            contype="0" conaffinity="0" group="1"/>
      <body name="thigh">
        <joint name="hip" type="hinge" axis="0 -1 0"/>
        <inertial pos="0 0 0" mass="{p.thigh_mass!r}" diaginertia="{numbers(it, it, it)}"/>
        <geom type="capsule" fromto="{numbers(0, 0, 0, 0, 0, -0.45 * p.l0)}" size="0.025" rgba=".3 .3 .3 1"
              contype="0" conaffinity="0" group="1"/>
        <body name="foot" pos="{numbers(0, 0, -(p.l0 - p.foot_radius))}">
          <joint name="leg" type="slide" axis="0 0 -1" range="{numbers(-p.stroke, 0)}"
                 solreflimit="{solref}" solimplimit="{solimp}"/>
          <inertial pos="0 0 0" mass="{p.foot_mass!r}" diaginertia="{numbers(i_foot, i_foot, i_foot)}"/>
          <geom type="capsule" fromto="{numbers(0, 0, 0, 0, 0, 0.5 * p.l0)}" size="0.012" rgba=".6 .6 .6 1"
                contype="0" conaffinity="0" group="1"/>
          <geom name="foot" type="sphere" size="{p.foot_radius!r}" rgba=".8 .3 .2 1"
                contype="1" conaffinity="1" group="1" {contact}/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <general name="spring" joint="leg" gaintype="affine" gainprm="0 -1 0" biastype="none"
             ctrlrange="0 1e9" forcerange="{numbers(-p.force_limit, p.force_limit)}"/>
    <general name="damper" joint="leg" gaintype="affine" gainprm="0 0 -1" biastype="none"
             ctrlrange="0 1e9"/>
    <motor name="leg_motor" joint="leg" ctrlrange="-1e9 1e9"/>
    <motor name="hip" joint="hip" ctrlrange="{numbers(-p.hip_torque_limit, p.hip_torque_limit)}"/>
  </actuator>
</mujoco>
"""


@dataclass(frozen=True)
class Layout:
    """Where the model keeps each coordinate: qpos/qvel addresses of ``x``, ``z``, ``pitch`` (None
    when locked), ``hip``, ``leg``; the foot geom's id."""

    x: int
    z: int
    pitch: int | None
    hip: int
    leg: int
    foot_geom: int

    @classmethod
    def of(cls, model) -> Layout:
        mj = mujoco()

        def adr(name: str) -> int:
            return int(model.jnt_qposadr[mj.mj_name2id(model, mj.mjtObj.mjOBJ_JOINT, name)])

        has_pitch = mj.mj_name2id(model, mj.mjtObj.mjOBJ_JOINT, "pitch") >= 0
        return cls(
            x=adr("x"),
            z=adr("z"),
            pitch=adr("pitch") if has_pitch else None,
            hip=adr("hip"),
            leg=adr("leg"),
            foot_geom=int(mj.mj_name2id(model, mj.mjtObj.mjOBJ_GEOM, "foot")),
        )


def build(params: RobotParams, terrain: Terrain | None = None):
    """The compiled ``mujoco.MjModel`` of the robot on ``terrain`` (flat ground when None)."""
    mj = mujoco()
    terrain = Terrain.flat() if terrain is None else terrain
    model = mj.MjModel.from_xml_string(xml(params, terrain))
    terrain.load(model)
    return model
