"""The report's missing sections 6-8 (Performance Analysis, Discussion, Conclusion), written from the records.

The report *SLIP: Approximate Stance Map for Nonsymmetric Motions and Variable Stiffness* left its
sections 6 (Performance Analysis, Simulation Results), 7 (Discussion) and 8 (Conclusion) empty.
docs/sections.md is written here from the records the studies write (docs/accuracy.json,
convergence.json, stiffness.json, stability.json, reproductions.json; control.json of the control
evaluation; the package's runtime/api/pareto.json from benchmarks/bench_pareto.py) and the record
of the report's equations (docs/equations.json, written by ``slipmaps generate`` from
derive/equations), through the Jinja2 template ``templates/sections.md.j2``:

- the prose is the template's; every number in it is a placeholder filled from a record
  (:class:`~.facts.Numbers`: ``{{ n.NAME }}``), never typed (tests/test_sections.py fails on a digit in
  the template's prose);
- every statement that compares numbers (a map beats another, a target is met) is a *claim*:
  ``{% call claim("NAME") %}...{% endcall %}``, whose condition :func:`.facts.claims` computes
  from the records. :func:`render` with ``strict=True`` (the site's build, the committed page, the test)
  raises :class:`ClaimFailed` naming the claim when the data no longer supports it, so prose and
  data cannot disagree silently; ``strict=False`` (the reduced run of ``slipmaps report --quick``,
  which measures a few maps only) marks such a claim and a number that was not measured instead.
- the tables (accuracy, cost, fixed points, errata, reproductions) are rendered from the records
  (:data:`.facts.TABLES`).

Entry points: :func:`write` (docs/sections.md and its figure from a directory of records; the
site's build calls it, docs/conf.py), ``slipmaps report`` (measures, then writes;
runtime/cli/report.py). Needs Jinja2 (the ``derive``, ``docs`` or ``test`` extra).
"""

from __future__ import annotations

import json
from pathlib import Path

from ..api.paths import save_figure, writing
from ..studies.accuracy_report import error_heatmaps
from .facts import CLAIMS, TABLES, MissingData, Numbers, claims, need

__all__ = [
    "RECORDS",
    "ClaimFailed",
    "MissingData",
    "Numbers",
    "CLAIMS",
    "load",
    "context",
    "render",
    "figure",
    "write",
]

#: The records the document reads from a directory (docs/), by key; ``reproductions`` is optional.
RECORDS = ("accuracy", "convergence", "stiffness", "stability", "control", "reproductions", "equations")
#: The document's file and its figure's, in the directory of the records.
PAGE, FIGURE = "sections.md", "sections.png"
_TEMPLATE = Path(__file__).with_name("templates") / "sections.md.j2"


class ClaimFailed(AssertionError):
    """A claim of the document's prose is not supported by the records; the message names it."""


# ----------------------------------------------------------------------------------------------
# The records
# ----------------------------------------------------------------------------------------------
def load(docs: str | Path) -> dict:
    """The records of directory ``docs`` (each ``<key>.json`` of :data:`RECORDS` that exists) and
    the cost-accuracy front (the package's pareto.json) under ``pareto``."""
    docs = Path(docs)
    out = {}
    for key in RECORDS:
        path = docs / f"{key}.json"
        if path.is_file():
            data = json.loads(path.read_text(encoding="utf-8"))
            data.pop("version", None)
            out[key] = data
    from ..api.front import measurement

    out["pareto"] = measurement()
    return out


# ----------------------------------------------------------------------------------------------
# Rendering
# ----------------------------------------------------------------------------------------------
def context(records: dict, strict: bool = True) -> dict:
    """The template's variables: ``n`` (:class:`Numbers`), ``table(NAME)``, ``claim(NAME)`` (a call
    block), ``has(KEY)`` (whether record KEY was measured), ``control_summary()``, ``figure``."""
    checks = claims(records)

    def claim(name: str, caller):
        if name not in checks:
            raise KeyError(f"the document has no claim {name!r}")
        try:
            ok = bool(checks[name]())
        except (MissingData, KeyError, ValueError, TypeError, StopIteration) as exc:
            if strict:
                raise MissingData(f"claim {name}: {exc}") from exc
            return f"[not measured in this run: {name}]"
        if not ok:
            if strict:
                raise ClaimFailed(f"the records do not support the claim {name!r}")
            return f"[not supported by this run's records: {name}]"
        return caller()

    def table(name: str) -> str:
        try:
            return TABLES[name](records)
        except (MissingData, KeyError, IndexError) as exc:
            if strict:
                raise MissingData(f"table {name}: {exc}") from exc
            return f"(not measured in this run: {name})"

    def control_summary() -> str:
        try:
            from ..control.report import summary

            if "control" not in records:
                raise MissingData("no control record")
            return summary(records["control"])
        except (MissingData, KeyError, ValueError) as exc:
            if strict:
                raise MissingData(f"the control summary: {exc}") from exc
            return "(not measured in this run: control)"

    return {
        "n": Numbers(records, strict),
        "claim": claim,
        "table": table,
        "has": lambda key: key in records,
        "control_summary": control_summary,
        "figure": FIGURE,
    }


def template_text() -> str:
    """The template's source (tests read its prose)."""
    return _TEMPLATE.read_text(encoding="utf-8")


def render(records: dict, strict: bool = True) -> str:
    """docs/sections.md from ``records`` (:func:`load`); see the module docstring for ``strict``."""
    import jinja2

    env = jinja2.Environment(
        undefined=jinja2.StrictUndefined, keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True
    )
    return env.from_string(template_text()).render(**context(records, strict))


def figure(records: dict, path: str | Path) -> Path:
    """The error maps of the document: next-apex error over apex speed and touchdown angle, one
    panel per map of the accuracy record's ``figure`` (the maps with the role "accuracy-figure"),
    one logarithmic color scale."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    heat = need(records, "accuracy")["figure"]
    shown = len(heat["apex_error"])
    cols = min(shown, 3)
    rows = -(-shown // cols)
    size = (4.2 * cols, 3.6 * rows)
    fig, axes = plt.subplots(rows, cols, figsize=size, squeeze=False, layout="constrained")
    mesh = error_heatmaps(heat, axes)  # the color scale: the decades of the errors drawn
    fig.colorbar(mesh, ax=axes, label="next-apex error |(dh, dv)| / |(h, v)| (white: a side fails)")
    fig.suptitle(f"{heat['grid']}, apex height {heat['apex_height']:g} m", fontsize=11)
    save_figure(fig, path, dpi=90)
    return Path(path)


def write(
    docs: str | Path,
    out: str | Path | None = None,
    strict: bool = True,
    draw: bool = True,
    records: dict | None = None,
) -> list[Path]:
    """Render the document from the records of directory ``docs`` (or ``records``, as :func:`load`
    gives them) into ``out`` (default ``docs``): sections.md and (``draw``) its figure; returns
    both paths. The page is written only when its text changes, so the site's build (docs/conf.py:
    the page always, the figure when missing) leaves a current checkout clean."""
    records = load(docs) if records is None else records
    out = Path(docs if out is None else out)
    out.mkdir(parents=True, exist_ok=True)
    page, fig = out / PAGE, out / FIGURE
    text = render(records, strict)
    if not page.is_file() or page.read_text(encoding="utf-8") != text:
        with writing(page):
            page.write_text(text, encoding="utf-8")
    if draw and "accuracy" in records:
        figure(records, fig)
    return [page, fig]
