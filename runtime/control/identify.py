"""Identification: the effective parameters with which a model map predicts a plant's next apex.

A plant that is not a SLIP (the MuJoCo robot: its foot's mass, its losses at touchdown and at the
leg stop, its skidding foot, its hip servo) steps differently from the map with its nominal
parameters. :func:`identify` fits the map's parameters to logged hops, so that the map, given a
hop's measured apex and controls, predicts its next apex:

    next apex = F(h, (1 - loss) v, q_th, ground, rate; m, l0, s k_c, s k_d)

``F`` the apex-return map (any map with generated Jacobians), ``h``, ``v`` the measured apex
(``measured_height``, ``measured_speed`` of a run), ``q_th`` the commanded angle at the apex
(``swing_angle``: what the controller sets, so the fit takes up the hip servo's lag), ``ground``
the touchdown ground relative to the ground under the apex, ``rate`` the scenario's retraction
rate, ``k_c``, ``k_d`` the commanded stiffnesses. The fitted names (``fit``):

* ``"k"``: the factor ``s`` on both commanded stiffnesses (the leg is stiffer or softer than
  commanded); reported as :attr:`Identified.k_factor`;
* ``"m"``: the mass ``m`` [kg];
* ``"l0"``: the rest length ``l0`` [m] (the touchdown and liftoff lengths keep their ratio to it);
* ``"loss"``: the fraction of the apex speed lost in a step (applied to the speed before the map:
  the horizontal velocity the foot's impact takes at touchdown; negative: a gain).

The maps depend on the stiffness and the mass only through k / m (gravity does not depend on the
mass), so ``"k"`` and ``"m"`` together are one parameter twice: refused. A stiffness factor ``s``
is the mass m / s, and :attr:`Identified.params` states it so (the nominal stiffness, the mass
m / s), so that a controller planning on the identified model commands the stiffness it plans.

The fit: SciPy's ``least_squares`` (trust region reflective, within bounds) on the residuals
(predicted minus logged next apex, height per l0 and speed per sqrt(g l0) of the nominal
parameters), its Jacobian from the map's generated apex-return Jacobian: the columns of the apex
speed (for ``loss``) and of the stiffnesses (``k``, and ``m`` by d/dm = -(k_c d/dk_c + k_d d/dk_d)
/ m), and for ``l0`` the map's dimensional homogeneity: scaling every length by c and every time
by sqrt(c) (g fixed; speeds by sqrt(c), stiffnesses per mass by 1/c, retraction rates by
1/sqrt(c)) scales the next apex height by c and its speed by sqrt(c), so

    l0 dF/dl0 = e F - h dF/dh - v/2 dF/dv - ground dF/dground + rate/2 dF/drate + k_c dF/dk_c + k_d dF/dk_d

(``e`` = 1 for the height, 1/2 for the speed; tests/test_identify.py checks it against central
differences on every map). Hops are split into a fitted and a held-out part (``holdout``, seeded);
:class:`Identified` reports the prediction errors of the nominal and the fitted model on both.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..api.calls import KERNELS, Call
from ..api.params import SlipParams

__all__ = ["FIT_NAMES", "Hops", "Identified", "hops_of", "identify"]

#: The names :func:`identify` can fit (module docstring).
FIT_NAMES = ("k", "m", "l0", "loss")
#: Bounds of each fitted quantity, relative to its nominal value (``loss``: absolute).
_BOUNDS = {"k": (0.2, 5.0), "m": (0.2, 5.0), "l0": (0.5, 1.5), "loss": (-0.5, 0.5)}


@dataclass(frozen=True)
class Hops:
    """Logged hops (arrays of n): the measured apex ``apex_height``, ``apex_speed``, the commanded
    ``touchdown_angle`` (at the apex), the touchdown ``ground`` relative to the apex's ground, the
    commanded ``k_c``, ``k_d``, the ``retraction_rate``, and the next apex ``next_apex_height``,
    ``next_apex_speed``."""

    apex_height: np.ndarray
    apex_speed: np.ndarray
    touchdown_angle: np.ndarray
    ground: np.ndarray
    k_c: np.ndarray
    k_d: np.ndarray
    retraction_rate: np.ndarray
    next_apex_height: np.ndarray
    next_apex_speed: np.ndarray

    def __len__(self) -> int:
        return self.apex_height.shape[0]

    def take(self, rows) -> Hops:
        return Hops(**{k: getattr(self, k)[rows] for k in self.__dataclass_fields__})


def hops_of(runs) -> Hops:
    """The hops of runs (a :class:`~.runs.RunBatch`, a :class:`~.runs.Run` or a sequence of either):
    every step whose plant status is OK, with finite values."""
    items = runs if isinstance(runs, Sequence) and not isinstance(runs, (str, bytes)) else [runs]
    parts = []
    for item in items:
        batch = getattr(item, "batch", item)
        if not hasattr(batch, "values") or not hasattr(batch, "codes"):
            raise TypeError(
                f"runs must be RunBatch or Run objects (slipmaps.run_batch), got {type(item).__name__}"
            )
        rows = slice(item.index, item.index + 1) if hasattr(item, "batch") else slice(None)
        v = {k: x[rows] for k, x in batch.values.items()}
        ground = v["ground"]
        before = np.concatenate([np.zeros((ground.shape[0], 1)), ground[:, :-1]], axis=1)
        cols = {
            "apex_height": v["measured_height"],
            "apex_speed": v["measured_speed"],
            "touchdown_angle": v["swing_angle"],
            "ground": ground - before,
            "k_c": v["k_c"],
            "k_d": v["k_d"],
            "retraction_rate": np.full(ground.shape, float(batch.scenario.retraction_rate)),
            "next_apex_height": v["next_apex_height"],
            "next_apex_speed": v["next_apex_speed"],
        }
        ok = batch.codes["plant_status"][rows] == 0
        for x in cols.values():
            ok &= np.isfinite(x)
        parts.append({k: x[ok] for k, x in cols.items()})
    return Hops(**{k: np.concatenate([p[k] for p in parts]) for k in parts[0]})


@dataclass(frozen=True)
class Identified:
    """The result of :func:`identify`: ``params`` (the identified :class:`SlipParams`: a stiffness
    factor stated as the mass m / s), ``loss`` (the fraction of the apex speed lost per step: the
    scenario's ``model_loss``), ``k_factor``, the ``fitted`` values by name, the nominal
    ``nominal`` parameters, and the one-step prediction errors of the nominal and the identified
    model on the fitted and the held-out hops (``errors_nominal`` and
    ``errors_fitted``: by part, ``height`` [m] and ``speed`` [m/s] mean absolute and largest, and
    relative ones)."""

    map: str
    params: SlipParams
    loss: float
    k_factor: float
    fitted: dict
    nominal: SlipParams
    errors_nominal: dict
    errors_fitted: dict
    hops: int
    held_out: int
    cost: float
    message: str

    def scenario(self) -> dict:
        """The scenario fields that plan with the identified model: ``params`` and ``model_loss``."""
        return {"params": self.params, "model_loss": self.loss}

    def summary(self) -> str:
        """The identified values and the errors before and after, as lines of text."""
        fit = ", ".join(f"{k} {v:.6g}" for k, v in self.fitted.items())
        lines = [f"identified on {self.map} from {self.hops} hops ({self.held_out} held out): {fit}"]
        for label, err in (("nominal", self.errors_nominal), ("identified", self.errors_fitted)):
            e = err["held_out"] if self.held_out else err["fitted"]
            lines.append(
                f"  {label:>10}: height {1e3 * e['height_mean']:.2f} mm mean, "
                f"{1e3 * e['height_max']:.2f} max; speed {100 * e['speed_rel_mean']:.3f} % mean, "
                f"{100 * e['speed_rel_max']:.3f} % max"
            )
        return "\n".join(lines)


class _Model:
    """The map with a set of fitted values: its predictions and their derivatives for :func:`identify`."""

    def __init__(self, name: str, nominal: SlipParams, fit: tuple[str, ...], options: dict):
        self.name, self.nominal, self.fit, self.options = name, nominal, fit, options
        self.constant = "k" in Call.of(name, nominal.with_(k=nominal.k_c), options).spec("apex_return").p

    def params(self, z: dict) -> SlipParams:
        p = self.nominal
        l0 = z.get("l0", p.l0)
        m = z.get("m", p.m) / z.get("k", 1.0)
        c = l0 / p.l0
        return p.with_(m=m, l0=l0, q_r_td=p.q_r_td * c, q_r_lo=p.q_r_lo * c)

    def evaluate(self, z: dict, hops: Hops, jacobian: bool):
        """The predicted next apex (n, 2), the status per hop and (``jacobian``) the derivatives
        (n, 2, len(fit)) with respect to the fitted values."""
        p = self.params(z)
        s, loss = z.get("k", 1.0), z.get("loss", 0.0)
        kc, kd = hops.k_c, hops.k_d  # the factor s is in the mass, m / s
        v_in = (1.0 - loss) * hops.apex_speed
        values = {
            "b_y_apex": hops.apex_height,
            "b_xd_apex": v_in,
            "q_th_td": hops.touchdown_angle,
            "ground": hops.ground,
            "retraction_rate": hops.retraction_rate,
        }
        if self.constant:
            values["k"] = kc
            call = Call.of(self.name, p.with_(k=p.k_c), self.options)
        else:
            values |= {"k_c": kc, "k_d": kd}
            call = Call.of(self.name, p, self.options)
        role = "apex_return_jacobian" if jacobian else "apex_return"
        spec = call.spec(role)
        out, status = KERNELS.rows(call, role, values, {}, len(hops), False)
        at = [spec.outputs.index("apex_height"), spec.outputs.index("apex_speed")]
        pred = out[:, at]
        if not jacobian:
            return pred, status
        n_out, wrt = len(spec.outputs), spec.wrt
        J = out[:, n_out : n_out + n_out * len(wrt)].reshape(-1, n_out, len(wrt))[:, at, :]
        col = {w: J[:, :, j] for j, w in enumerate(wrt)}
        stiff = (
            col["k"] * kc[:, None] if self.constant else col["k_c"] * kc[:, None] + col["k_d"] * kd[:, None]
        )
        D = np.empty((len(hops), 2, len(self.fit)))
        for j, name in enumerate(self.fit):
            if name == "k":
                D[:, :, j] = stiff / s
            elif name == "m":
                D[:, :, j] = -stiff / z["m"]
            elif name == "loss":
                D[:, :, j] = -hops.apex_speed[:, None] * col["b_xd_apex"]
            else:  # l0: the map's dimensional homogeneity (module docstring)
                e = np.array([1.0, 0.5])
                scaled = (
                    e * pred
                    - hops.apex_height[:, None] * col["b_y_apex"]
                    - 0.5 * v_in[:, None] * col["b_xd_apex"]
                    - hops.ground[:, None] * col["ground"]
                    + 0.5 * hops.retraction_rate[:, None] * col["retraction_rate"]
                    + stiff
                )
                D[:, :, j] = scaled / p.l0
        return pred, status, D


def _errors(pred: np.ndarray, status: np.ndarray, hops: Hops) -> dict:
    ok = (status == 0) & np.isfinite(pred).all(axis=1)
    if not ok.any():
        return {"count": 0, "failed": int(len(hops))}
    dh = np.abs(pred[ok, 0] - hops.next_apex_height[ok])
    dv = np.abs(pred[ok, 1] - hops.next_apex_speed[ok])
    rv = dv / np.maximum(np.abs(hops.next_apex_speed[ok]), 1e-9)
    return {
        "count": int(ok.sum()),
        "failed": int((~ok).sum()),
        "height_mean": float(dh.mean()),
        "height_max": float(dh.max()),
        "height_rel_mean": float((dh / hops.next_apex_height[ok]).mean()),
        "speed_mean": float(dv.mean()),
        "speed_max": float(dv.max()),
        "speed_rel_mean": float(rv.mean()),
        "speed_rel_max": float(rv.max()),
    }


def _check_fit(fit) -> tuple[str, ...]:
    if isinstance(fit, str):
        fit = (fit,)
    fit = tuple(fit)
    if not fit:
        raise ValueError(f"fit must name at least one of {', '.join(FIT_NAMES)}")
    for name in fit:
        if name not in FIT_NAMES:
            raise ValueError(f"fit: unknown name {name!r}; the names are {', '.join(FIT_NAMES)}")
    if len(set(fit)) != len(fit):
        raise ValueError(f"fit names a quantity twice: {fit!r}")
    if "k" in fit and "m" in fit:
        raise ValueError("fit: 'k' and 'm' enter the maps only as k / m: fit one of them")
    return tuple(n for n in FIT_NAMES if n in fit)


def identify(
    runs,
    map: str = "iterative",
    fit=("k", "l0", "loss"),
    *,
    params: SlipParams | None = None,
    holdout: float = 0.25,
    seed: int = 0,
    **options,
) -> Identified:
    """Fit the effective parameters ``fit`` of map ``map`` (with its ``options``) to the hops of
    ``runs`` (module docstring): a :class:`~.runs.RunBatch`, a :class:`~.runs.Run`, a sequence of
    them, or :class:`Hops`. ``params``: the nominal parameters the fit starts from (default: the
    runs' scenario's, the controller's model); ``holdout``: the fraction of the hops held out of
    the fit to measure the prediction on (a seeded random choice; 0: none)."""
    from scipy.optimize import least_squares

    fit = _check_fit(fit)
    hops = runs if isinstance(runs, Hops) else hops_of(runs)
    if params is None:
        first = runs[0] if isinstance(runs, Sequence) else runs
        sc = getattr(getattr(first, "batch", first), "scenario", None)
        if sc is None:
            raise ValueError("give params= (the nominal parameters): the hops carry no scenario")
        params = sc.params
    if not isinstance(params, SlipParams):
        raise TypeError(f"params must be SlipParams, got {type(params).__name__}")
    holdout = float(holdout)
    if not 0.0 <= holdout < 1.0:
        raise ValueError(f"holdout must be a fraction in [0, 1), got {holdout!r}")
    n = len(hops)
    if n < 2 * len(fit):
        raise ValueError(
            f"identify needs at least {2 * len(fit)} hops with an OK step for {len(fit)} values, got {n}"
        )
    order = np.random.default_rng(seed).permutation(n)
    k = int(round(holdout * n))
    test, train = hops.take(np.sort(order[:k])), hops.take(np.sort(order[k:]))
    model = _Model(map, params, fit, dict(options))
    start = {"k": 1.0, "m": params.m, "l0": params.l0, "loss": 0.0}
    ref = {"k": 1.0, "m": params.m, "l0": params.l0, "loss": 1.0}  # the unknowns' scales
    lo = [(_BOUNDS[f][0] * ref[f] if f != "loss" else _BOUNDS[f][0]) for f in fit]
    hi = [(_BOUNDS[f][1] * ref[f] if f != "loss" else _BOUNDS[f][1]) for f in fit]
    x0 = np.array([start[f] / ref[f] for f in fit])
    scale = np.array([ref[f] for f in fit])
    weight = np.array([1.0 / params.l0, 1.0 / math.sqrt(params.g_f * params.l0)])

    def values(x):
        return dict(zip(fit, x * scale, strict=True))

    def residuals(x):
        pred, status = model.evaluate(values(x), train, False)
        r = (pred - np.stack([train.next_apex_height, train.next_apex_speed], axis=1)) * weight
        return np.where(np.isfinite(r), r, 1.0).ravel()  # a failed hop: a large residual

    def jac(x):
        _, _, D = model.evaluate(values(x), train, True)
        D = D * weight[None, :, None] * scale[None, None, :]
        return np.where(np.isfinite(D), D, 0.0).reshape(-1, len(fit))

    sol = least_squares(
        residuals, x0, jac=jac, bounds=(np.array(lo) / scale, np.array(hi) / scale), x_scale="jac"
    )
    z = values(sol.x)
    errors = {}
    for label, zz in (("nominal", {}), ("fitted", z)):
        errors[label] = {
            part: _errors(*model.evaluate(zz, h, False), h)
            for part, h in (("fitted", train), ("held_out", test))
        }
    return Identified(
        map=map,
        params=model.params(z),
        loss=float(z.get("loss", 0.0)),
        k_factor=float(z.get("k", 1.0)),
        fitted={f: float(z[f]) for f in fit},
        nominal=params,
        errors_nominal=errors["nominal"],
        errors_fitted=errors["fitted"],
        hops=n,
        held_out=k,
        cost=float(sol.cost),
        message=str(sol.message),
    )
