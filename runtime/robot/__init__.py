"""The robot: a planar monoped in MuJoCo (the optional extra ``robot``: ``pip install 'slipmaps[robot]'``).

A robot is not a SLIP: its foot has mass (it hits the ground at touchdown, is caught by the leg's
stop at liftoff), it bounces and skids, its hip is a servo, its sensors are noisy and late. This
package builds one and steps it hop by hop, apex to apex, so that the controllers of
:mod:`slipmaps.runtime.control` can run it as a plant. Modules, one job each:

- :mod:`.params`: :class:`~.params.RobotParams`, the documented parameter record (checked: one line
  per bad value), and its nominal SLIP (:meth:`~.params.RobotParams.slip_params`);
- :mod:`.terrain`: :class:`~.terrain.Terrain`, absolute ground levels per segment of x as a
  heightfield with ramps, boxes or a plane, and its exact ``height_at``;
- :mod:`.model`: the MJCF and the compiled ``mujoco.MjModel`` (joints, the spring as an actuator);
- :mod:`.swing`: the descent's commands (the leg's angle and stiffness over time since the apex);
- :mod:`.hopper`: :class:`~.hopper.Hopper`, one robot with its low-level controller: ``place``,
  ``descend``, ``ascend``, ``hop``, the hop's record :class:`~.hopper.Hop`;
- :mod:`.render`: frames of a logged run (MuJoCo's renderer headless, matplotlib without GL), GIFs;
- :mod:`.mj`: the optional import (one line when MuJoCo is missing).

Only :mod:`.params`, :mod:`.terrain` and :mod:`.swing` import without MuJoCo; everything that
simulates raises ImportError "... needs MuJoCo: pip install 'slipmaps[robot]'" without it.

Conventions: SI units; the leg's angle from the vertical, counterclockwise positive (the foot ahead
of the hip for forward running: the hip hinge turns about -y in MuJoCo's x-z plane); polar states
``(q_r, q_rd, q_th, q_thd)`` of the hip about the foot's contact point; the apex on the centre of
mass (its horizontal speed is constant in flight, the torso's is not while the leg swings).

Measured with the defaults (``python benchmarks/bench_robot.py``; 2-core AMD EPYC, MuJoCo 4.0.1, one
core): one hop from a 1.1 m apex with the ideal SLIP's periodic touchdown angle held from
the apex (k_c = k_d = 20 kN/m), the robot against the exact SLIP (m = body + thigh = 30.3 kg):

=======  ======  ==================  ===========  =========  =======  =========  =======
v [m/s]  angle   next apex - SLIP    energy lost  touchdown  liftoff  foot skid  bounces
=======  ======  ==================  ===========  =========  =======  =========  =======
3        0.1827  +2.1 mm, -2.73 %    1.47 %       3.80 J     3.05 J   14.6 mm    1
4        0.2277  +9.6 mm, -3.00 %    2.03 %       6.57 J     5.10 J   22.7 mm    1
5        0.2667  +18.7 mm, -3.08 %   2.49 %       10.03 J    7.72 J   34.9 mm    3
=======  ======  ==================  ===========  =========  =======  =========  =======

The touchdown loss (apex -> bottom) is 1.12-1.21 times the foot's kinetic energy as it meets the
ground, the liftoff loss (bottom -> next apex) 0.95-0.99 times the foot's kinetic energy relative
to the body at liftoff (its leg-wise part caught by the leg's stop, its swing stopped by the hip
servo). The robot's own periodic gait at (1.1 m, 4 m/s) needs k_d = 23.3 kN/m and touches down at
0.2011 rad, not the SLIP's 0.2277: the foot's momentum, lost at touchdown and taken from the body
at liftoff, costs about 2 % of the speed a hop, which a smaller angle wins back; with a 20 g foot
the periodic angle is 0.2256 rad. Speed (four runs of the benchmark, the machine's load 2-5 on its
2 cores): a 30-hop run (15.7 s simulated) takes 0.14-0.29 s, 54-112x real time; the bare physics
alone runs at 62-132x, the run takes 1.0-1.4x its time. The spring as an affine actuator costs
8.7-23 ms per simulated second; the same force set from Python before every physics step 1.3-2.3x
that, with the same next apex.
"""
