"""The exact map, ``"exact"``: the stance equations of motion (2)-(3) integrated numerically.

Declared like every other map (a :class:`~..mapspec.MapSpec`), so the generated composition that
gives every map its apex return (the exact flights, the ground, the signed speed, the step
geometry) and its Jacobians gives the exact map the same ones. Only its stance is not a closed
form: it is the kernel ``stance`` of the generator's support module ``exact_stance`` (numba-compiled
DOP853 with events for the bottom, where k_c switches to k_d, liftoff and the failures), declared
here as an *external* kernel with its Jacobian (the variational equations with saltation at the
bottom, ``stance_jacobian``), which the generated derivatives go through.

It takes the leg damping ``c`` (derive/params.py; the field's damper term from
:func:`..model.mechanics.stance_polar_damping`), and option ``liftoff``: ``"force"`` (default) ends
the stance where the leg force k_d (l0 - q_r) - c q_rd falls to 0 (the ground cannot pull) or at
q_r = q_r_lo, whichever comes first; ``"length"`` at q_r = q_r_lo only. At c = 0 both are the
lossless stance, bit for bit. Its Jacobian has a column for c (:data:`JACOBIAN_INPUTS`).

Option ``method``: ``"compiled"`` (default) runs those kernels; ``"scipy"`` the ``solve_ivp``
reference (``slipmaps.runtime.exact.reference``, a backend of its own, 1-2 ms per stance). This map
is the ground truth: :data:`GROUND_TRUTH`, not in ``MAPS`` (the approximations).

Its halves (``HALVES``): ``exact-compression`` (touchdown -> bottom with k_c) and
``exact-decompression`` (bottom -> liftoff with k_d), the same integration split at the bottom
(the external kernels ``compression`` and ``decompression``): a plant for a controller that
chooses k_d at the bottom from the measured bottom state.
"""

from __future__ import annotations

from .. import catalog
from ..halfspec import HALF_OUTPUTS, HalfInputs, HalfSpec, start_args
from ..ir import Call, Group, Kernel
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..model.simulation import DEFAULT_ATOL, DEFAULT_RTOL
from ..tangent import derivative_fields

#: The support module of the exact stance's kernels (derive/templates/exact_stance.py.j2).
_MODULE = "exact_stance"
_PARAMS = ("m", "l0", "k_c", "k_d", "g_s", "c")

_OPTIONS = (
    Option(
        "method",
        "which DOP853 implementation integrates the stance (same algorithm, events and statuses)",
        "compiled",
        choices=(
            ("compiled", "numba-compiled, batches in parallel"),
            ("scipy", "scipy's solve_ivp, the reference"),
        ),
        backends=(("scipy", "slipmaps.runtime.exact.reference"),),
    ),
    Option("rtol", "relative tolerance of the DOP853 integration", DEFAULT_RTOL, low=1e-14, high=1e-3),
    Option("atol", "absolute tolerance of the DOP853 integration", DEFAULT_ATOL, low=1e-16, high=1e-3),
    Option(
        "liftoff",
        "where a damped leg lifts off (the same liftoff at c = 0)",
        "force",
        choices=(
            ("force", "where the leg force k_d (l0 - q_r) - c q_rd falls to 0, or at q_r = q_r_lo if first"),
            ("length", "at q_r = q_r_lo (the leg's pull on the ground ignored)"),
        ),
    ),
)
#: The option ``liftoff`` (the exact stance template's codes come from it).
LIFTOFF = _OPTIONS[-1]

#: The arguments of the external stance kernels, in their order: the stance kernel's.
_ARGS = (
    catalog.TOUCHDOWN
    + tuple(catalog.PARAMS[p] for p in _PARAMS)
    + (catalog.PARAMS["q_r_lo"],)
    + tuple(o.arg() for o in _OPTIONS if o.kernel)
)
#: The stance Jacobian's columns: the touchdown state, the stiffnesses and the damping.
JACOBIAN_INPUTS = tuple(a.name for a in catalog.TOUCHDOWN) + ("k_c", "k_d", "c")

STANCE_JACOBIAN = Kernel(
    name="stance_jacobian",
    summary="Exact stance and its Jacobian (variational equations, saltation at the bottom and liftoff).",
    equations=("2", "3"),
    args=_ARGS,
    steps=(),
    outputs=catalog.STANCE + Group("", derivative_fields(catalog.STANCE, JACOBIAN_INPUTS)),
    module=_MODULE,
    external=True,
)

STANCE = Kernel(
    name="stance",
    summary="Exact stance: DOP853 integration of (2)-(3) with events for the bottom and liftoff.",
    equations=("2", "3"),
    args=_ARGS,
    steps=(),
    outputs=catalog.STANCE,
    module=_MODULE,
    external=True,
    jacobian=STANCE_JACOBIAN,
    jacobian_wrt=JACOBIAN_INPUTS,
)


STATE_AT = Kernel(
    name="state_at",
    summary="Exact polar state a time t after touchdown (k_c until the bottom, then k_d).",
    equations=("2", "3"),
    args=(catalog.TIME,) + _ARGS,
    steps=(),
    outputs=catalog.TRAJECTORY,
    module=_MODULE,
    external=True,
)


def _build(inputs: MapInputs) -> MapBuild:
    args = {a.name: a.symbol for a in _ARGS}

    def state_at(t) -> tuple:
        bind = {name: name for name in STATE_AT.output_names}
        return (Call(STATE_AT, {"t": t, **args}, bind, comment="the exact state at t (exact_stance)"),)

    bind = {name: name for name in STANCE.output_names}
    return MapBuild(
        steps=(Call(STANCE, args, bind, comment="the exact stance (exact_stance)"),),
        state_at=state_at,
    )


_HALF_PARAMS = {
    "touchdown": ("m", "l0", "k_c", "g_s", "q_r_lo", "c"),
    "bottom": ("m", "l0", "k_d", "g_s", "q_r_lo", "c"),
}
_TOLERANCES = tuple(o for o in _OPTIONS if o.kernel and o is not LIFTOFF)
#: Each half's kernel options: the tolerances, and for the half that ends at liftoff its option.
_HALF_OPTIONS = {"touchdown": _TOLERANCES, "bottom": (*_TOLERANCES, LIFTOFF)}


def _half_kernel(name: str, start: str) -> Kernel:
    args = (
        start_args(start)
        + tuple(catalog.PARAMS[p] for p in _HALF_PARAMS[start])
        + tuple(o.arg() for o in _HALF_OPTIONS[start])
    )
    return Kernel(
        name=name,
        summary=f"Exact {name} half: DOP853 integration of (2)-(3) from the {start} state.",
        equations=("2", "3"),
        args=args,
        steps=(),
        outputs=HALF_OUTPUTS,
        module=_MODULE,
        external=True,
    )


def _half_build(kernel: Kernel):
    def build(inputs: HalfInputs) -> tuple:
        bind = {name: name for name in kernel.output_names}
        return (
            Call(
                kernel,
                {a.name: a.symbol for a in kernel.args},
                bind,
                comment="the exact half (exact_stance)",
            ),
        )

    return build


HALVES = tuple(
    HalfSpec(
        name=f"exact-{half}",
        title=f"Exact {half} half ({start} to {end}, {k}; DOP853 integration)",
        section="2.2",
        equations=("2", "3"),
        whole="exact",
        start=start,
        params=_HALF_PARAMS[start],
        build=_half_build(_half_kernel(half, start)),
        options=_HALF_OPTIONS[start],
        summary=f"the exact stance's {half} half, the same integration split at the bottom",
    )
    for half, start, end, k in (
        ("compression", "touchdown", "bottom", "k_c"),
        ("decompression", "bottom", "liftoff", "k_d"),
    )
)

GROUND_TRUTH = MapSpec(
    name="exact",
    title="Exact stance by numerical integration (DOP853)",
    section="2.2",
    equations=("1", "2", "3", "27"),
    params=_PARAMS,
    build=_build,
    options=_OPTIONS,
    summary="the polar stance equations of motion (2)-(3) integrated with events for the bottom "
    "(k_c -> k_d), liftoff and failures: the ground truth",
)
