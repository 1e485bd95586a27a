"""Footholds: the controls of the next hops over stepping stones, planned ``horizon`` hops ahead on a
map (model-predictive: apply the first hop, plan again at the next apex).

At an apex (its height above the ground under it, its signed speed, its x, the ground's height:
positions and heights absolute, as a :class:`~.stones.Course`'s), :meth:`Footholds.plan` makes one
compiled call (:mod:`.footholds_solver`):

1. the candidate stone sequences: of the ``lookahead`` stones ahead (:meth:`Course.ahead
   <slipmaps.runtime.control.stones.Course.ahead>`), every sequence of ``horizon`` stones in order
   (a long stone may take two feet) whose feet the hops can reach: the first within ``reach``
   nominal steps of the neutral foothold (the foot at the neutral angle,
   :func:`~slipmaps.runtime.control.deadbeat.default_angle`, from this apex), each next one a
   nominal step on, within ``reach`` nominal steps (the nominal step: the model's periodic step
   at the first hop's target apex, the deadbeat from that apex to itself);
2. for each, the least squares of :mod:`.footholds_solver` (every foot inside its stone's usable
   part as deep as the hop allows, the next apexes close to the nominal targets and above the
   floor, the least change of the controls; on the map's generated apex-return Jacobian);
3. the plan: the sequence of least cost among the *feasible* ones (every foot inside its stone's
   usable part, every hop's map OK, every next apex moving in the target's direction): status
   ``FOOTHOLD``; without one, the least-cost sequence that ran, ``NO_FOOTHOLD`` (a foot lands
   outside its stone on the model); ``MAP_FAILED`` where the map failed on every sequence (the
   neutral angle and the nominal stiffness then); ``NO_FOOTHOLD`` with no candidate when no stone
   lies within reach.

The previous apex's plan warm-starts the sequences that continue it (``warm``: its controls of the
hops after its first).

``horizon = 0`` is the baseline, the deadbeat step aimed at a stone's centre: the deadbeat step
toward the nominal target (:class:`~.deadbeat.Deadbeat`) picks the stone nearest its foot, and the
deadbeat's own solver (:mod:`.compiled`) puts the foot (``foot_x``) on that stone's centre and the
next apex at the target height (the foot alone with one control); ``FOOTHOLD`` when the foot lands
inside the stone's usable part.

The controls are the deadbeat's (``controls``: the angle and k_d by default, the angle alone for a
constant-stiffness map; the angle is always one: it places the foot), within its bounds. The
least-squares weights (:data:`WEIGHTS`) put the foot first: a foot at the end of a usable part
costs as much as a next apex 1 l0 off its target height or sqrt(g_f l0) off its speed.
"""

from __future__ import annotations

import enum
import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from ..api.calls import KERNELS, Call
from ..api.index import model_kernels
from ..api.numeric import num
from ..api.params import SlipParams
from ..api.validate import check_params, real
from . import compiled
from . import footholds_solver as fs
from .deadbeat import ANGLE_SCALE, Deadbeat, checked_controls, control_bounds, default_angle
from .stones import LOOKAHEAD, Course, CourseError

__all__ = ["FootholdPlan", "FootholdStatus", "Footholds", "LOOKAHEAD", "REACH", "WEIGHTS", "footholds"]

#: The least-squares weights (module docstring; :mod:`.footholds_solver`): the foot (per half-width
#: of the usable part), the next apex's height (per l0) and speed (per sqrt(g_f l0)), the floor (per
#: l0), the least change of the controls (in the deadbeat's scaled norm).
WEIGHTS = {"foot": 1.0, "height": 1.0, "speed": 1.0, "floor": 3.0, "change": 0.01}
#: The feet a hop reaches about its nominal foothold, in nominal steps (module docstring).
REACH = 0.3
#: Iterations of a sequence's least squares at most, and its tolerance on the cost's relative change.
MAX_ITER = 20
TOL = 1e-8
#: The least time [s] from liftoff to the next apex a planned hop keeps, in units of sqrt(l0/g_f)
#: (0.064 s for a 1 m leg): below it a residual pulls the hop back (the body must rise after
#: liftoff with some speed to spare: a hop at the edge of LIFTOFF_DOWNWARD on the model may fail on
#: the plant), and below half of it the hop is not feasible.
MIN_ASCENT = 0.2


class FootholdStatus(str, enum.Enum):
    """How a plan ended (module docstring): ``FOOTHOLD``, ``NO_FOOTHOLD``, ``MAP_FAILED``."""

    FOOTHOLD = "FOOTHOLD"
    NO_FOOTHOLD = "NO_FOOTHOLD"
    MAP_FAILED = "MAP_FAILED"

    def __str__(self) -> str:
        return self.value


@dataclass(frozen=True)
class FootholdPlan:
    """A plan (module docstring), SI units, positions absolute. ``status``; ``stones`` the stone
    indices of the planned hops (-1: none); per hop (tuples, hop 1 first): ``feet`` the foot's x,
    ``margins`` its distance inside the stone's usable part (negative: outside), the next apex
    ``apex_heights`` (above that hop's stone), ``apex_speeds`` and ``apex_x``, the controls
    ``touchdown_angles``, ``k_c``, ``k_d``; ``touchdown_angle`` and ``foot`` the first hop's;
    ``cost`` the least squares' sum of squares; ``candidates`` the sequences within reach,
    ``feasible`` those feasible; ``iterations`` of the chosen one's solve, ``evaluations`` of the
    map (with its Jacobian) over every sequence; ``solve_us`` the plan's time [us]; ``horizon`` the
    hops planned (0: the baseline)."""

    status: FootholdStatus
    stones: tuple[int, ...]
    feet: tuple[float, ...]
    margins: tuple[float, ...]
    apex_heights: tuple[float, ...]
    apex_speeds: tuple[float, ...]
    apex_x: tuple[float, ...]
    touchdown_angles: tuple[float, ...]
    k_c: tuple[float, ...]
    k_d: tuple[float, ...]
    cost: float
    candidates: int
    feasible: int
    iterations: int
    evaluations: int
    solve_us: float
    horizon: int
    #: The chosen sequence's controls, hop after hop (the next plan's warm start).
    controls: tuple[float, ...] = field(default=(), repr=False)

    @property
    def touchdown_angle(self) -> float:
        """The first hop's touchdown angle [rad] (the one to apply)."""
        return self.touchdown_angles[0]

    @property
    def foot(self) -> float:
        """The first hop's planned foot [m]."""
        return self.feet[0]

    @property
    def ok(self) -> bool:
        return self.status == FootholdStatus.FOOTHOLD

    def as_dict(self) -> dict:
        """JSON-ready (None for NaN), statuses by name."""

        def f(x):
            return float(x) if math.isfinite(x) else None

        out = {"status": self.status.value, "horizon": self.horizon, "stones": list(self.stones)}
        for name in (
            "feet",
            "margins",
            "apex_heights",
            "apex_speeds",
            "apex_x",
            "touchdown_angles",
            "k_c",
            "k_d",
        ):
            out[name] = [f(x) for x in getattr(self, name)]
        out |= {"cost": f(self.cost), "candidates": self.candidates, "feasible": self.feasible}
        out |= {"iterations": self.iterations, "evaluations": self.evaluations, "solve_us": f(self.solve_us)}
        return out


class Footholds:
    """The footholds planner on map ``name`` (module docstring), prepared once: its kernels, the
    compiled least squares bound to them, the controls and their bounds. ``horizon`` (0: the
    deadbeat baseline, else the hops planned), ``lookahead`` (the stones seen), ``reach``,
    ``min_height`` (the floor of every planned apex above the next stone; default l0),
    ``weights`` (over the module's ``WEIGHTS``), ``max_iter`` and ``tol`` (a sequence's least squares);
    ``options`` the map's. The first plan compiles the solver for the map (seconds; cached on disk
    after the first process)."""

    def __init__(
        self,
        name: str,
        params: SlipParams,
        *,
        horizon: int = 2,
        controls=None,
        bounds=None,
        lookahead: int = LOOKAHEAD,
        reach: float = REACH,
        min_height: float | None = None,
        weights: dict | None = None,
        max_iter: int = MAX_ITER,
        tol: float = TOL,
        **options,
    ):
        check_params(params)
        for key, value, low in (
            ("horizon", horizon, 0),
            ("lookahead", lookahead, 1),
            ("max_iter", max_iter, 6),
        ):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
                raise ValueError(f"{key} must be a whole number >= {low}, got {value!r}")
        reach = real("reach", reach)
        if not 0.0 < reach < 1.0:
            raise ValueError(f"reach must lie in (0, 1) nominal steps, got {num(reach)}")
        call = Call.of(name, params, options)
        if call.backend is not KERNELS:
            raise ValueError(f"map {call.info.name!r} with these options runs outside the compiled kernels")
        self.call, self.name, self.params = call, call.info.name, params
        self.options = dict(options)  # the map's options as given (the deadbeat takes them so)
        self.controls = checked_controls(call, controls)
        if "touchdown_angle" not in self.controls:
            raise ValueError(
                f"controls must include touchdown_angle (it places the foot), got {self.controls!r}"
            )
        self.bounds = control_bounds(params, self.controls, bounds)
        self.horizon, self.lookahead, self.reach = int(horizon), int(lookahead), reach
        self.floor = params.l0 if min_height is None else real("min_height", min_height)
        if not self.floor > 0.0:
            raise ValueError(f"min_height must be positive, got {num(self.floor)}")
        unknown = sorted(set(weights or {}) - set(WEIGHTS))
        if unknown:
            raise ValueError(f"weights has no {unknown[0]!r}; the weights: {', '.join(WEIGHTS)}")
        self.weights = WEIGHTS | {k: real(f"weights[{k!r}]", v) for k, v in dict(weights or {}).items()}
        self.max_iter, self.tol = int(max_iter), real("tol", tol)
        apex, jac = call.spec("apex_return"), call.spec("apex_return_jacobian")
        self._jac = jac
        self._record = call.record(apex)
        descent = model_kernels()["apex_to_touchdown"]  # the flight: the clearance over the stones
        self._rows = fs.bind(apex.functions()[0], jac.functions()[0], descent.functions()[0])
        self._constant = "k" in jac.wrt
        self._ci, self._ctl_i, self._nominal_u = self._layout(apex, jac)
        order = ("b_y_apex", "b_xd_apex", "q_th_td", "ground", "retraction_rate")
        self._order = [order.index(a) for a in apex.x]
        p = params
        self._cf = np.zeros(len(fs.CF))
        fixed = {
            "w_foot": self.weights["foot"],
            "w_height": self.weights["height"],
            "w_speed": self.weights["speed"],
            "w_floor": self.weights["floor"],
            "w_reg": self.weights["change"],
            "l0": p.l0,
            "v_scale": math.sqrt(p.g_f * p.l0),
            "floor": self.floor,
            "tol": self.tol,
            "g_f": p.g_f,
            "q_r_td": p.q_r_td,
            "t_min": MIN_ASCENT * math.sqrt(p.l0 / p.g_f),
        }
        for key, value in fixed.items():
            self._cf[fs.CF.index(key)] = value
        self._at_cf = [fs.CF.index(k) for k in ("x0", "g0", "reach", "step", "margin")]
        lo = [self.bounds[c][0] for c in self.controls]
        hi = [self.bounds[c][1] for c in self.controls]
        change = [ANGLE_SCALE if c == "touchdown_angle" else p.k_c for c in self.controls]
        step = [1.0 if c == "touchdown_angle" else p.k_c for c in self.controls]
        self._ctl_f = np.array([lo, hi, self._nominal_u, change, step], dtype=float)
        self._gait = Deadbeat(self.name, params, controls=self.controls, bounds=self.bounds, **self.options)
        self._baseline = None
        if self.horizon == 0:
            self._baseline = Deadbeat(
                self.name, params, controls=self.controls, bounds=self.bounds, budget=False, **self.options
            )
            one = len(self.controls) == 1
            db = self._baseline
            # the foot and the next apex height (the foot alone with one control)
            self._centre_settings = db.solver.settings(
                targeted=(1, 0) if one else (1, 1), targets=("foot_x", "apex_height"), **db.fields
            )
        self._steps: dict = {}

    # ------------------------------------------------------------------------------------------
    def _layout(self, apex, jac):
        """The solver's integer settings (:data:`.footholds_solver.CI`), the controls' places (in
        ``p`` or ``x``, position, Jacobian column) and their nominal values (NaN for the angle,
        whose nominal is the neutral angle of each hop's speed)."""
        x, outs, wrt = apex.x, apex.outputs, jac.wrt
        ci = {
            "nc": len(self.controls),
            "n_out": len(outs),
            "n_wrt": len(wrt),
            "o_h": outs.index("apex_height"),
            "o_v": outs.index("apex_speed"),
            "o_l": outs.index("step_length"),
            "o_f": outs.index("foot_x"),
            "x_h": x.index("b_y_apex"),
            "x_v": x.index("b_xd_apex"),
            "x_th": x.index("q_th_td"),
            "x_g": x.index("ground"),
            "w_h": wrt.index("b_y_apex"),
            "w_v": wrt.index("b_xd_apex"),
            "max_iter": self.max_iter,
            "ce": next((self.controls.index(c) for c in ("k_d", "k_c") if c in self.controls), -1),
            "o_ta": outs.index("t_ascent"),
        }
        descent = model_kernels()["apex_to_touchdown"]
        ci |= {"d_nx": len(descent.x), "d_foot": descent.outputs.index("foot_x"), "d_width": descent.width}
        for key, arg in (("d_h", "b_y_apex"), ("d_v", "b_xd_apex"), ("d_th", "q_th_td"), ("d_qr", "q_r_td")):
            ci[key] = descent.x.index(arg)
        for key, arg in (("d_gf", "g_f"), ("d_g", "ground"), ("d_rate", "retraction_rate")):
            ci[key] = descent.x.index(arg)
        places, nominal = [], []
        for c in self.controls:
            arg = "q_th_td" if c == "touchdown_angle" else c
            in_p = arg not in x
            places.append((int(in_p), apex.p.index(arg) if in_p else x.index(arg), wrt.index(arg)))
            nominal.append(math.nan if c == "touchdown_angle" else float(self._record[apex.p.index(arg)]))
        ctl_i = np.ascontiguousarray(np.array(places, dtype=np.int64).T)
        return np.array([ci[k] for k in fs.CI], dtype=np.int64), ctl_i, np.array(nominal)

    def nominal_step(self, height: float, speed: float) -> tuple[float, float]:
        """The model's periodic step at the apex (``height``, ``speed``): its length [m] and its
        foot's x from the apex [m] (the deadbeat from the apex to itself; NaN where it does not
        reach it), cached by the apex to the millimetre."""
        key = (round(float(height), 3), round(float(speed), 3))
        hit = self._steps.get(key)
        if hit is None:
            res = self._gait.plan(*key, *key)
            out = res.prediction
            hit = (abs(out["step_length"]), out["foot_x"]) if res.reached else (math.nan, math.nan)
            self._steps[key] = hit
        return hit

    # ------------------------------------------------------------------------------------------
    def plan(
        self,
        apex_height: float,
        apex_speed: float,
        course: Course,
        *,
        x: float = 0.0,
        ground: float = 0.0,
        target_height=None,
        target_speed=None,
        warm: FootholdPlan | None = None,
        hops: int | None = None,
    ) -> FootholdPlan:
        """The plan from the apex (``apex_height`` above ``ground``, the absolute height of the
        ground under it; ``apex_speed``; its ``x``) over ``course`` (module docstring); the
        nominal targets of the hops ``target_height``, ``target_speed`` (a number or one per hop;
        default the apex's own); ``warm``: the previous apex's plan; ``hops``: the hops left to
        hop (a run's last steps plan no further: the horizon shrinks to them). Where no sequence
        of the horizon's length is feasible (none within reach where the course ends; none whose
        hops the map completes or whose feet stay inside), the horizon shrinks by one hop at a time
        to the first that has one; without any, the plan of the full horizon where a sequence ran
        (NO_FOOTHOLD), else the longest that ran."""
        t0 = time.perf_counter()
        H = max(self.horizon, 1) if hops is None else max(min(self.horizon, int(hops)), 1)
        Ht = _per_hop(apex_height if target_height is None else target_height, H, "target_height")
        Vt = _per_hop(apex_speed if target_speed is None else target_speed, H, "target_speed")
        if self.horizon == 0:
            return self._centre(apex_height, apex_speed, course, x, ground, Ht, Vt, t0)
        fallback = None
        for hops_now in range(H, 0, -1):
            plan = self._solve(
                apex_height, apex_speed, course, x, ground, Ht[:hops_now], Vt[:hops_now], warm, t0
            )
            if plan.ok:
                return plan
            if fallback is None or (fallback.status != FootholdStatus.NO_FOOTHOLD and plan.stones[0] >= 0):
                fallback = plan
        return replace(fallback, solve_us=(time.perf_counter() - t0) * 1e6)

    def _solve(self, apex_height, apex_speed, course, x, ground, Ht, Vt, warm, t0) -> FootholdPlan:
        """The plan over ``len(Ht)`` hops (:meth:`plan`)."""
        H = Ht.size
        nc = len(self.controls)
        visible = course.ahead(x, self.lookahead)
        first = int(visible[0]) if visible.size else len(course)
        step = self.nominal_step(Ht[0], Vt[0])[0]
        if not math.isfinite(step):  # no periodic step there: the speed over a stance and two falls
            step = abs(Vt[0]) * 2.0 * math.sqrt(2.0 * self.params.l0 / self.params.g_f)
        span = np.full(3 + H - 1, -1, dtype=np.int64)
        span[:3] = first, first + visible.size, self._jac.width
        warm_u = np.zeros(max((H - 1) * nc, 1))
        if warm is not None and H > 1 and len(warm.stones) >= H and warm.stones[0] >= 0:
            span[3:] = warm.stones[1:H]  # its hops after the first start the sequences that continue it
            warm_u[:] = warm.controls[nc : nc * H]
        x0 = np.array([apex_height, apex_speed, 0.0, 0.0, 0.0])[self._order]
        cf = self._cf.copy()
        cf[self._at_cf] = x, ground, self.reach * step, step, course.margin
        nominal = np.ascontiguousarray(np.stack([Ht, Vt], axis=1))
        U_nom = np.tile(self._nominal_u, (H, 1))
        angle = self.controls.index("touchdown_angle")
        U_nom[:, angle] = default_angle(self.params, np.concatenate([[apex_speed], Vt[:-1]]))
        ctl_f = self._ctl_f.copy()
        ctl_f[2] = U_nom[0]
        SEQ = np.empty((fs.MAX_SEQUENCES, H), dtype=np.int64)
        OUT = np.empty((fs.MAX_SEQUENCES, fs.out_width(H, nc)))
        RES = np.empty(len(fs.RESULTS), dtype=np.int64)
        args = (
            course.table,
            span,
            U_nom,
            warm_u,
            x0,
            self._record,
            self._ci,
            self._ctl_i,
            ctl_f,
            cf,
            nominal,
        )
        self._rows(*args, SEQ, OUT, RES)
        return self._read(SEQ, OUT, RES, H, apex_speed, t0)

    def _read(self, SEQ, OUT, RES, H: int, speed: float, t0: float) -> FootholdPlan:
        """The plan from the solver's rows (:mod:`.footholds_solver`)."""
        count, best, outcome = (int(v) for v in RES)
        if outcome >= 2:
            status = FootholdStatus.MAP_FAILED if outcome == 2 else FootholdStatus.NO_FOOTHOLD
            return self._failed(status, speed, H, t0, count)
        nc = len(self.controls)
        head = {name: j for j, name in enumerate(fs.OUT_HEAD)}
        row = OUT[best]
        nh, nhop = len(fs.OUT_HEAD), len(fs.HOP)
        hops = {name: row[nh + j : nh + H * nhop : nhop] for j, name in enumerate(fs.HOP)}
        u = row[nh + H * nhop :].reshape(H, nc)
        k_c, k_d = self._stiffness(u)
        return FootholdPlan(
            status=FootholdStatus.FOOTHOLD if outcome == 0 else FootholdStatus.NO_FOOTHOLD,
            stones=tuple(int(k) for k in SEQ[best]),
            feet=tuple(hops["foot"].tolist()),
            margins=tuple(hops["margin"].tolist()),
            apex_heights=tuple(hops["apex_height"].tolist()),
            apex_speeds=tuple(hops["apex_speed"].tolist()),
            apex_x=tuple(hops["apex_x"].tolist()),
            touchdown_angles=tuple(u[:, self.controls.index("touchdown_angle")].tolist()),
            k_c=k_c,
            k_d=k_d,
            cost=float(row[head["cost"]]),
            candidates=count,
            feasible=int((OUT[:count, head["feasible"]] == 1.0).sum()),
            iterations=int(row[head["iterations"]]),
            evaluations=int(np.nansum(OUT[:count, head["evaluations"]])),
            solve_us=(time.perf_counter() - t0) * 1e6,
            horizon=H,
            controls=tuple(u.reshape(-1).tolist()),
        )

    def _stiffness(self, u: np.ndarray) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """k_c and k_d of each hop from its controls (the nominal where not a control)."""
        p = self.params
        H = u.shape[0]
        col = {c: u[:, j] for j, c in enumerate(self.controls)}
        if "k" in col:
            return tuple(col["k"].tolist()), tuple(col["k"].tolist())
        k_c = col.get("k_c", np.full(H, p.k_c))
        k_d = col.get("k_d", np.full(H, p.k_c if self._constant else p.k_d))
        return tuple(k_c.tolist()), tuple(k_d.tolist())

    def _failed(self, status, speed, H, t0, candidates) -> FootholdPlan:
        """A plan with no sequence: the neutral angle and the nominal stiffness."""
        p = self.params
        nan = (math.nan,) * H
        return FootholdPlan(
            status=status,
            stones=(-1,) * H,
            feet=nan,
            margins=nan,
            apex_heights=nan,
            apex_speeds=nan,
            apex_x=nan,
            touchdown_angles=(default_angle(p, speed),) * H,
            k_c=(p.k_c,) * H,
            k_d=(p.k_c if self._constant else p.k_d,) * H,
            cost=math.nan,
            candidates=candidates,
            feasible=0,
            iterations=0,
            evaluations=0,
            solve_us=(time.perf_counter() - t0) * 1e6,
            horizon=0 if self.horizon == 0 else H,
        )

    # ------------------------------------------------------------------------------------------
    def _centre(self, h, v, course: Course, x, ground, Ht, Vt, t0) -> FootholdPlan:
        """The baseline (module docstring): the deadbeat aimed at a stone's centre."""
        visible = course.ahead(x, self.lookahead)
        step = self._gait.plan(h, v, Ht[0], Vt[0])  # the deadbeat step toward the target
        if visible.size == 0 or not step.ok:
            return self._failed(FootholdStatus.NO_FOOTHOLD, v, 1, t0, 0)
        lo, hi, y = course.lo, course.hi, course.heights
        centre = 0.5 * (lo + hi)
        k = int(visible[np.argmin(np.abs(centre[visible] - (x + step.prediction["foot_x"])))])
        db = self._baseline
        given = {
            "apex_height": h,
            "apex_speed": v,
            "ground": y[k] - ground,
            "touchdown_angle": step.touchdown_angle,
        }
        X = db._inputs(given, 1)
        T = np.array([[centre[k] - x, Ht[0]]])
        row = db.solver.run(X, db._record_clipped()[None, :], T, self._centre_settings)[0]
        head = compiled.HEAD_AT
        if int(row[head["plan_status"]]) == compiled.MAP_FAILED:
            return self._failed(FootholdStatus.MAP_FAILED, v, 1, t0, 1)
        u = row[head["u0"] : head["u0"] + len(self.controls)][None, :]
        out = dict(zip(db.outputs, row[compiled.N_HEAD :].tolist(), strict=True))
        foot = x + out["foot_x"]
        margin = float(min(foot - lo[k], hi[k] - foot))
        k_c, k_d = self._stiffness(u)
        return FootholdPlan(
            status=FootholdStatus.FOOTHOLD if margin >= 0.0 else FootholdStatus.NO_FOOTHOLD,
            stones=(k,),
            feet=(foot,),
            margins=(margin,),
            apex_heights=(out["apex_height"],),
            apex_speeds=(out["apex_speed"],),
            apex_x=(x + out["step_length"],),
            touchdown_angles=(float(u[0, self.controls.index("touchdown_angle")]),),
            k_c=k_c,
            k_d=k_d,
            cost=float(row[head["residual"]]) ** 2,
            candidates=1,
            feasible=int(margin >= 0.0),
            iterations=int(row[head["iterations"]]),
            evaluations=int(row[head["evaluations"]]),
            solve_us=(time.perf_counter() - t0) * 1e6,
            horizon=0,
            controls=tuple(u.reshape(-1).tolist()),
        )

    def warm_up(self) -> Footholds:
        """Compile the solver now (numba compiles on the first call). Returns self."""
        p = self.params
        v = math.sqrt(p.g_f * p.l0)
        step, foot = self.nominal_step(p.l0, v)
        if not math.isfinite(step):
            step, foot = p.l0, 0.5 * p.l0
        course = Course.of([[-0.1, foot + 0.3, 0.0], [foot + step - 0.3, foot + 3.0 * step, 0.0]])
        self.plan(p.l0, v, course)
        return self


def _per_hop(value, H: int, name: str) -> np.ndarray:
    """A target per hop: a number for every hop, or a sequence (the last value held)."""
    values = np.atleast_1d(np.asarray(value, dtype=float))
    if values.ndim != 1 or values.size == 0 or not np.isfinite(values).all():
        raise ValueError(f"{name} must be a finite number or one per hop, got {value!r}")
    if values.size >= H:
        return values[:H]
    return np.concatenate([values, np.full(H - values.size, values[-1])])


def footholds(
    model: str,
    params: SlipParams,
    apex,
    stones,
    *,
    horizon: int = 2,
    controls=None,
    margin: float | None = None,
    lookahead: int = LOOKAHEAD,
    target_height=None,
    target_speed=None,
    bounds=None,
    **options,
) -> FootholdPlan:
    """The footholds plan of map ``model`` from ``apex`` over ``stones`` (module docstring;
    docs/footholds.md).

    ``apex``: a mapping with ``height`` [m] (above the ground under it), ``speed`` [m/s] and
    optionally ``x`` [m] (default 0) and ``ground`` [m] (the absolute height of the ground under it;
    default the stone under ``x``, else 0). ``stones``: a :class:`~slipmaps.Course`, or a list of
    ``[x_a, x_b, height]`` [m] with ``margin`` [m] (default 0; given with a Course, it replaces the
    course's). ``horizon``: the hops planned (0: the deadbeat baseline); ``controls`` the deadbeat's
    (default the angle and k_d, the angle alone for a constant-stiffness map); ``lookahead`` the
    stones seen; ``target_height``, ``target_speed``: the nominal next apex of each hop (a number,
    or one per hop; default the apex's own); ``options``: the map's, and the planner's ``reach``,
    ``min_height``, ``weights``, ``max_iter``, ``tol`` (:class:`Footholds`). ValueError (one line)
    for a bad course, apex or setting, and when no stone lies within the first hop's reach."""
    if isinstance(stones, Course):
        course = stones if margin is None else Course.of(stones, margin)
    else:
        course = Course.of(stones, 0.0 if margin is None else margin)
    if not hasattr(apex, "keys"):
        raise TypeError(f"apex must be a mapping with height, speed (and x, ground), got {apex!r}")
    if not {"height", "speed"} <= set(apex) <= {"height", "speed", "x", "ground"}:
        raise ValueError(
            f"apex must have the keys height, speed (and optionally x, ground), got {sorted(apex)}"
        )
    h, v = real("apex height", apex["height"]), real("apex speed", apex["speed"])
    x = real("apex x", apex.get("x", 0.0))
    if "ground" in apex:
        ground = real("apex ground", apex["ground"])
    else:
        under = int(np.searchsorted(np.asarray(course.x_a), x, side="right")) - 1
        ground = course.height[under] if under >= 0 and x <= course.x_b[under] else 0.0
    keys = {k: options.pop(k) for k in ("reach", "min_height", "weights", "max_iter", "tol") if k in options}
    planner = _planner(model, params, horizon, controls, bounds, lookahead, keys, options)
    plan = planner.plan(
        h, v, course, x=x, ground=ground, target_height=target_height, target_speed=target_speed
    )
    if plan.candidates == 0:
        ahead = course.ahead(x, 3)
        where = (
            ", ".join(f"[{course.lo[i]:.6g}, {course.hi[i]:.6g}] m" for i in ahead)
            if ahead.size
            else f"none (the course ends at {course.end:.6g} m)"
        )
        step = planner.nominal_step(*(plan_target(t, d) for t, d in ((target_height, h), (target_speed, v))))[
            0
        ]
        foot = planner.nominal_step(h, v)[1]
        reach = planner.reach * step
        window = (
            f"within about [{x + foot - reach:.3g}, {x + foot + reach:.3g}] m "
            if math.isfinite(foot) and math.isfinite(reach)
            else ""
        )
        raise CourseError(
            f"stones: no stone within reach of the apex at x = {x:.6g} m: the first foot lands {window}"
            f"(the neutral foothold +-{planner.reach:g} nominal steps); the usable parts ahead: {where}"
        )
    return plan


def plan_target(value, default: float) -> float:
    """A hop's first target: ``value`` (a number or one per hop), else ``default``."""
    return default if value is None else float(np.atleast_1d(np.asarray(value, dtype=float))[0])


_PLANNERS: dict = {}


def _planner(model, params, horizon, controls, bounds, lookahead, keys, options) -> Footholds:
    """A prepared planner of these settings, cached when they are hashable."""
    kw = dict(horizon=horizon, controls=controls, bounds=bounds, lookahead=lookahead, **keys, **options)
    try:
        key = (model, params, repr(sorted(kw.items(), key=lambda item: item[0])))
        hash(key)
    except TypeError:
        return Footholds(model, params, **kw)
    hit = _PLANNERS.get(key)
    if hit is None:
        hit = _PLANNERS[key] = Footholds(model, params, **kw)
    return hit
