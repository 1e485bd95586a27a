"""Published claims about the SLIP and its approximate stance maps, checked by code: the record of
docs/reproductions.json and its verdicts (:mod:`.reproductions_stance` and
:mod:`.reproductions_gaits` measure the claims, :mod:`.reproductions_report` renders the record and
holds the study, ``reproductions`` of ``slipmaps accuracy``).

The claims: Geyer, Seyfarth and Blickhan 2005 (the approximate stance within 1 % of the leg
compression and 0.6 deg of the leg angle), Yu, Li and Cai 2012 (next-apex error mean < 5 %, max
< 15 %), Seyfarth et al. 2002 / 2003 (a stable fixed point at 68 deg and 5 m/s), Tedrake's
Underactuated Robotics SLIP notebook (no fixed point at k l0/(m g) = 10.8), Heim and Spröwitz 2019
(vibly's SLIP viable set, :mod:`.reproductions_viability`). SI units, angles as in
docs/conventions.md.

A verdict is one of :data:`VERDICTS`, computed by :func:`add_verdicts` from the record as its JSON
file holds it (6 significant digits; :func:`measure` rounds first), so the verdicts follow from the
recorded numbers by the rules of :func:`geyer_summary`, :func:`yu_verdict`, :func:`stable_verdict`,
:func:`drake_verdict` and :func:`heim_verdict`, and the tests recompute them from the file.
"""

from __future__ import annotations

from . import study as pipeline
from .report_format import rounded
from .reproductions_gaits import DRAKE, measure_drake, measure_seyfarth
from .reproductions_stance import GEYER_COLUMNS, GEYER_DOMAIN, GEYER_TOL, YU_TARGET, measure_geyer, measure_yu
from .reproductions_viability import measure_heim

__all__ = [
    "VERDICTS",
    "HOLDS",
    "NARROWER",
    "FAILS",
    "geyer_summary",
    "yu_verdict",
    "stable_verdict",
    "drake_verdict",
    "heim_verdict",
    "HEIM_KEYS",
    "add_verdicts",
    "CLAIMS",
    "measure",
    "from_json",
]

HOLDS, NARROWER, FAILS = VERDICTS = ("holds", "holds on a narrower domain", "does not hold")


def _bound(rows: list, ok) -> tuple[float | None, float | None]:
    """Over ``rows`` sorted by compression: the compression of the last row before the first that
    fails ``ok`` (None when the first fails, or there is none), and that failing row's (None: none)."""
    c = GEYER_COLUMNS.index("compression")
    bad = next((i for i, r in enumerate(rows) if not ok(r)), None)
    last = len(rows) if bad is None else bad
    return (rows[last - 1][c] if last > 0 else None), (None if bad is None else rows[bad][c])


def geyer_summary(setting: dict) -> dict:
    """The claim's domain (rows with compression <= 20 %, attack >= 60 deg, sweep <= 60 deg), its
    largest errors, and the largest compression X such that every domain row with compression <= X
    is within both tolerances (None when the least compressed one is not; also per tolerance):
    "holds" when all are, "holds on a narrower domain" (compressions up to X) when X exists, else
    "does not hold"."""
    c = {name: i for i, name in enumerate(GEYER_COLUMNS)}
    d = GEYER_DOMAIN
    rows = sorted(
        (
            r
            for r in setting["rows"]
            if r[c["compression"]] <= d["compression"]
            and r[c["attack_deg"]] >= d["attack_deg"] - 1e-9
            and r[c["sweep_deg"]] <= d["sweep_deg"]
        ),
        key=lambda r: r[c["compression"]],
    )

    def q_r(r) -> bool:
        return r[c["q_r_error"]] <= GEYER_TOL["q_r"]

    def q_th(r) -> bool:
        return r[c["q_th_error_deg"]] <= GEYER_TOL["q_th_deg"]

    upto, first = _bound(rows, lambda r: q_r(r) and q_th(r))
    verdict = HOLDS if rows and first is None else (NARROWER if upto is not None else FAILS)
    return {
        "domain_rows": len(rows),
        "max_q_r_error": max((r[c["q_r_error"]] for r in rows), default=None),
        "max_q_r_error_of_compression": max((r[c["q_r_error_of_compression"]] for r in rows), default=None),
        "max_q_th_error_deg": max((r[c["q_th_error_deg"]] for r in rows), default=None),
        "holds_up_to_compression": upto,
        "first_violation_compression": first,
        "q_r_holds_up_to_compression": _bound(rows, q_r)[0],
        "q_th_holds_up_to_compression": _bound(rows, q_th)[0],
        "verdict": verdict,
    }


def _meets(s: dict) -> bool:
    return s["mean"] < YU_TARGET["mean"] and s["max"] < YU_TARGET["max"]


def yu_verdict(m: dict) -> dict:
    """The verdict of a map: "holds" when the mean and the max over its compared states meet the
    claim, else "holds on a narrower domain" at the angles of attack whose states meet it (if any)."""
    angles = [a["attack_deg"] for a in m["by_angle"] if _meets(a)]
    verdict = HOLDS if _meets(m) else (NARROWER if angles else FAILS)
    return {"holds_at_attack_deg": angles, "verdict": verdict}


def stable_verdict(points: list[dict]) -> str:
    """The verdict of a map's fixed points: "holds" when a completed one has abs(eigenvalue) < 1."""
    ok = any(p["status"] == "OK" and abs(p["eigenvalue"]) < 1.0 for p in points)
    return HOLDS if ok else FAILS


def drake_verdict(at: dict) -> str:
    """The verdict of a map's fixed points at 10.7 and 10.8: "holds" when there are some at 10.7 and
    none at 10.8."""
    return HOLDS if at[str(DRAKE["kappa"])] and not at[str(DRAKE["kappa_figure"])] else FAILS


#: The numbers of vibly's published arrays a reproduction of Heim and Spröwitz's viable set must equal.
HEIM_KEYS = (
    "pairs",
    "failed_pairs",
    "viable_pairs",
    "kernel_states",
    "measure_max",
    "measure_max_s",
    "measure_top",
    "failed_fingerprint",
    "viable_fingerprint",
)


def heim_verdict(heim: dict) -> str:
    """ "holds" when every number of :data:`HEIM_KEYS` of ``heim["ours"]`` equals the paper's (the
    fingerprints: Q_F and Q_V pair for pair), else "does not hold"."""
    return HOLDS if all(heim["ours"][k] == heim["paper"][k] for k in HEIM_KEYS) else FAILS


def add_verdicts(record: dict) -> dict:
    """Each claim's verdicts (and the numbers they are read from), computed from ``record``'s numbers."""
    for s in record["geyer"]["settings"]:
        s["summary"] = geyer_summary(s)
    for m in record["yu"]["maps"]:
        m.update(yu_verdict(m))
    record["seyfarth"]["verdicts"] = {
        n: stable_verdict(p) for n, p in record["seyfarth"]["fixed_points"].items()
    }
    record["drake"]["verdicts"] = {n: drake_verdict(s["at"]) for n, s in record["drake"]["subjects"].items()}
    record["heim"]["verdict"] = heim_verdict(record["heim"])
    return record


#: Each claim's key in the record and the function that measures it, in claim order.
CLAIMS = {
    "geyer": measure_geyer,
    "yu": measure_yu,
    "seyfarth": measure_seyfarth,
    "drake": measure_drake,
    "heim": measure_heim,
}


def measure(show_progress: bool | None = None, claims=None, record: dict | None = None) -> dict:
    """The record: each claim measured, rounded as its JSON file holds it, with its verdicts. With
    ``claims`` (keys of :data:`CLAIMS`) only those are measured, the others taken from ``record`` (a
    record as its file holds it, e.g. the committed docs/reproductions.json)."""
    names = list(CLAIMS) if claims is None else list(claims)
    unknown = [n for n in names if n not in CLAIMS]
    if unknown:
        raise ValueError(f"unknown claims {unknown}: choose from {list(CLAIMS)}")
    if len(names) < len(CLAIMS) and record is None:
        raise ValueError("measuring some claims needs the record of the others")
    raw = {n: (CLAIMS[n](show_progress) if n in names else record[n]) for n in CLAIMS}
    return add_verdicts(rounded(raw))


def from_json(text: str) -> dict:
    """The record of docs/reproductions.json: ``geyer``, ``yu``, ``seyfarth``, ``drake``, ``heim``."""
    return pipeline.from_json(text)
