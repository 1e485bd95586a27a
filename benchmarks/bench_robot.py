"""Benchmark and basics of the MuJoCo robot (slipmaps.runtime.robot), one core.

1. Basics: from a 1.1 m apex at 3, 4 and 5 m/s with the ideal SLIP's periodic touchdown angle
   (``slipmaps.fixed_points("exact", params.slip_params(), apex_height=1.1, speed=v)``, the leg held
   at it from the apex, k_c = k_d = 20 kN/m), one hop of the robot against the exact SLIP's
   ``apex_return``: the next apex's height and speed, the energy lost and where (touchdown: apex ->
   bottom; liftoff: bottom -> next apex), the foot's skid and bounces.
2. The robot's own periodic touchdown angle at (1.1 m, 4 m/s) (the angle and k_d whose hop returns
   to the apex, ``scipy.optimize.fsolve``) beside the SLIP's.
3. Speed: a run of ``--hops`` hops at 4 m/s under a simple hop-level loop (foot placement from the
   measured speed, k_d from the energy at the bottom), simulated seconds per wall second, beside the
   bare physics (``mj_step`` with the controls fixed, the same simulated time) on the same model;
   best of ``--repeat``.
4. The leg spring: MuJoCo's affine actuator (ctrl = k, the force k (l0 - l) computed each physics
   step) against the same force set from Python before each physics step (a motor), side by side:
   wall time per simulated second and the difference in the next apex.

    python benchmarks/bench_robot.py [--hops N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
import slipmaps
from scipy.optimize import fsolve
from slipmaps.runtime.robot.hopper import Hopper
from slipmaps.runtime.robot.mj import mujoco
from slipmaps.runtime.robot.model import ACTUATORS
from slipmaps.runtime.robot.params import RobotParams
from slipmaps.runtime.robot.swing import hold

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

SPEEDS = (3.0, 4.0, 5.0)
APEX = 1.1


def basics(p: RobotParams) -> list[dict]:
    """One hop from (1.1 m, v) at the SLIP's periodic angle, the robot against the exact SLIP."""
    sp = p.slip_params()
    rows = []
    for v in SPEEDS:
        angle = slipmaps.fixed_points("exact", sp, apex_height=APEX, speed=v)[0].touchdown_angle
        slip = slipmaps.apex_return("exact", sp, APEX, v, angle)
        robot = Hopper(p)
        robot.place(APEX, v, leg_angle=angle)
        hop = robot.hop(hold(angle, p.k_c, p.k_d))
        lost = hop.energy_start - hop.energy_end
        rows.append(
            {
                "speed": v,
                "angle": angle,
                "status": str(hop.status),
                "slip_height": slip.next_apex_height,
                "robot_height": hop.next_apex_height,
                "d_height_mm": 1e3 * (hop.next_apex_height - slip.next_apex_height),
                "slip_speed": slip.next_apex_speed,
                "robot_speed": hop.next_apex_speed,
                "d_speed_pct": 100 * (hop.next_apex_speed / slip.next_apex_speed - 1),
                "energy_lost_pct": 100 * lost / hop.energy_start,
                "loss_touchdown_J": hop.loss_touchdown,
                "loss_liftoff_J": hop.loss_liftoff,
                "skid_mm": 1e3 * hop.skid,
                "bounces": hop.bounces,
                "d_stance_ms": 1e3 * (hop.t_stance - slip.t_stance),
            }
        )
    return rows


def periodic_angle(p: RobotParams, v: float = 4.0) -> dict:
    """The robot's (touchdown angle, k_d) whose hop from (1.1 m, v) returns there."""
    robot = Hopper(p)

    def miss(x):
        angle, kd = x
        robot.place(APEX, v, leg_angle=angle)
        robot.descend(hold(angle, p.k_c, kd * 1e4))
        hop = robot.ascend()
        return [hop.next_apex_height - APEX, hop.next_apex_speed - v]

    slip = slipmaps.fixed_points("exact", p.slip_params(), apex_height=APEX, speed=v)[0].touchdown_angle
    (angle, kd), info, _, _ = fsolve(miss, [slip, p.k_d / 1e4], full_output=True, epsfcn=1e-6)
    return {"speed": v, "robot_angle": angle, "robot_k_d": kd * 1e4, "slip_angle": slip, "miss": info["fvec"]}


def run(robot: Hopper, hops: int, v_d: float = 4.0) -> int:
    """A simple hop-level loop: foot placement v T_s / 2 + 0.15 (v - v_d), k_d restoring the
    energy at the bottom (plus the last hop's liftoff loss). Returns the hops done."""
    p = robot.params
    m, g = p.total_mass, p.gravity
    target = m * g * APEX + 0.5 * m * v_d**2
    t_s, v, loss = 0.118, v_d, 5.0
    robot.place(APEX, v_d, leg_angle=math.asin(v_d * t_s / 2 / p.l0))
    for i in range(hops):
        angle = math.asin(min(0.9, (v * t_s / 2 + 0.15 * (v - v_d)) / p.l0))
        down = robot.descend(hold(angle, p.k_c, p.k_c))
        if not down.ok:
            return i
        c = -robot.data.qpos[robot.layout.leg]
        kd = min(max(p.k_c + 2 * (target - down.energy_bottom + loss) / c**2, 0.5 * p.k_c), 3 * p.k_c)
        hop = robot.ascend(kd)
        if not hop.ok:
            return i
        t_s, v, loss = hop.t_stance, hop.next_apex_speed, hop.loss_liftoff
    return hops


def speed(p: RobotParams, hops: int, repeat: int) -> dict:
    """Simulated seconds per wall second: the run, and the bare physics for as long."""
    mj = mujoco()
    best_run, best_bare, sim = math.inf, math.inf, 0.0
    for _ in range(repeat):
        robot = Hopper(p)
        t = time.perf_counter()
        done = run(robot, hops)
        best_run = min(best_run, time.perf_counter() - t)
        sim = robot.data.time
        robot.place(APEX, 4.0, leg_angle=0.2)
        n = int(round(sim / p.timestep))
        t = time.perf_counter()
        mj.mj_step(robot.model, robot.data, n)
        best_bare = min(best_bare, time.perf_counter() - t)
    return {
        "hops": done,
        "simulated_s": sim,
        "wall_s": best_run,
        "realtime_x": sim / best_run,
        "bare_physics_wall_s": best_bare,
        "bare_realtime_x": sim / best_bare,
        "run_over_bare": best_run / best_bare,
    }


def spring_variants(p: RobotParams, repeat: int) -> dict:
    """The affine-actuator spring against a Python spring set each physics step (one hop at 4 m/s,
    the leg held at 0.2278 rad)."""
    mj = mujoco()
    angle = 0.22774888061184945
    robot = Hopper(p)
    best_affine, hop_affine = math.inf, None
    for _ in range(repeat):
        robot.place(APEX, 4.0, leg_angle=angle)
        t = time.perf_counter()
        hop_affine = robot.hop(hold(angle, p.k_c, p.k_d))
        best_affine = min(best_affine, time.perf_counter() - t)
    sim_affine = hop_affine.t_descent + hop_affine.t_stance + hop_affine.t_ascent
    # the same hop with the spring in Python: the affine actuator off (k = 0), the leg motor set to
    # k (l0 - l) before every physics step
    leg, spring, motor = robot.layout.leg, ACTUATORS.index("spring"), ACTUATORS.index("leg_motor")
    real_step = mj.mj_step

    def python_spring(model, data, nstep=1):
        k, f = data.ctrl[spring], data.ctrl[motor]
        data.ctrl[spring] = 0.0
        for _ in range(nstep):
            data.ctrl[motor] = f + min(k * -data.qpos[leg], p.force_limit)
            real_step(model, data)
        data.ctrl[spring], data.ctrl[motor] = k, f

    best_python, hop_python = math.inf, None
    robot._mj = _Patched(mj, python_spring)
    for _ in range(repeat):
        robot.place(APEX, 4.0, leg_angle=angle)
        t = time.perf_counter()
        hop_python = robot.hop(hold(angle, p.k_c, p.k_d))
        best_python = min(best_python, time.perf_counter() - t)
    robot._mj = mj
    return {
        "affine_ms_per_sim_s": 1e3 * best_affine / sim_affine,
        "python_ms_per_sim_s": 1e3 * best_python / sim_affine,
        "python_over_affine": best_python / best_affine,
        "d_height_mm": 1e3 * (hop_python.next_apex_height - hop_affine.next_apex_height),
        "d_speed": hop_python.next_apex_speed - hop_affine.next_apex_speed,
        "python_status": str(hop_python.status),
    }


class _Patched:
    """The mujoco module with ``mj_step`` replaced (the Python spring of :func:`spring_variants`)."""

    def __init__(self, mj, step):
        self._mj, self.mj_step = mj, step

    def __getattr__(self, name):
        return getattr(self._mj, name)


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--hops", type=int, default=30)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    p = RobotParams()
    out = {
        "machine": machine(),
        "mujoco": mujoco().__version__,
        "basics": basics(p),
        "periodic": periodic_angle(p),
        "speed": speed(p, args.hops, args.repeat),
        "spring": spring_variants(p, args.repeat),
    }
    if args.json:
        print(json.dumps(out, indent=1, default=lambda x: np.asarray(x).tolist()))
        return out
    print(f"machine: {out['machine']}; MuJoCo {out['mujoco']}")
    print("v [m/s] angle   next apex: robot - SLIP  energy lost  touchdown  liftoff  skid   bounces")
    for r in out["basics"]:
        print(
            f"{r['speed']:5.1f}  {r['angle']:.4f}  {r['d_height_mm']:+6.1f} mm {r['d_speed_pct']:+6.2f} %   "
            f"{r['energy_lost_pct']:5.2f} %    {r['loss_touchdown_J']:5.2f} J  {r['loss_liftoff_J']:5.2f} J "
            f"{r['skid_mm']:5.1f} mm {r['bounces']:3d}   ({r['status']})"
        )
    q = out["periodic"]
    print(
        f"periodic at (1.1 m, {q['speed']} m/s): robot {q['robot_angle']:.4f} rad, k_d "
        f"{q['robot_k_d']:.0f} N/m; SLIP {q['slip_angle']:.4f} rad"
    )
    s = out["speed"]
    print(
        f"{s['hops']} hops: {s['simulated_s']:.2f} s simulated in {s['wall_s']:.3f} s: "
        f"{s['realtime_x']:.0f}x real time (bare physics {s['bare_realtime_x']:.0f}x; the run takes "
        f"{s['run_over_bare']:.2f}x the bare physics)"
    )
    sp = out["spring"]
    print(
        f"spring: affine actuator {sp['affine_ms_per_sim_s']:.1f} ms per simulated s, Python per physics "
        f"step {sp['python_ms_per_sim_s']:.1f} ms ({sp['python_over_affine']:.2f}x); next apex differs by "
        f"{sp['d_height_mm']:+.3f} mm, {sp['d_speed']:+.4f} m/s"
    )
    return out


if __name__ == "__main__":
    main()
