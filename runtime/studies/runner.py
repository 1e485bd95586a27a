"""``slipmaps accuracy``: every study of runtime/studies/, through the one writer of :mod:`.study`.

The studies, in the order they are written: accuracy (every map and its variants against the exact
simulator), convergence (the maps with a pass count, n = 0..8), stiffness (the maps that accept
k_c != k_d, over k_d/k_c), stability (periodic gaits and the self-stable region) and reproductions
(published claims checked by code; all maps only). A study with nothing to measure among the chosen
maps writes nothing (:meth:`.study.Study.applies`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from ..api import index
from .accuracy import baseline
from .accuracy_report import AccuracyStudy
from .convergence import ConvergenceStudy
from .reproductions_report import ReproductionsStudy
from .stability_report import StabilityStudy
from .stiffness_report import StiffnessStudy
from .study import Study, write

__all__ = ["STUDIES", "chosen_maps", "studies", "report_path", "run"]

#: The studies of ``slipmaps accuracy``, in the order they are written; the first one's report is
#: the path the command is given.
STUDIES: tuple[type[Study], ...] = (
    AccuracyStudy,
    ConvergenceStudy,
    StiffnessStudy,
    StabilityStudy,
    ReproductionsStudy,
)


def chosen_maps(map_names=None) -> list[str] | None:
    """The maps the studies measure: all (None), or ``map_names`` after the baseline map (role
    "baseline", the accuracy study's reference); ValueError for an unknown name."""
    if map_names is None:
        return None
    names = [baseline(), *[n for n in map_names if n != baseline()]]
    for n in names:
        index.get(n)
    return names


def studies(map_names=None) -> list[Study]:
    """The studies of ``slipmaps accuracy`` that apply to ``map_names`` (default: all maps; given, the
    baseline map is measured with them)."""
    names = chosen_maps(map_names)
    return [s for s in (cls(names) for cls in STUDIES) if s.applies()]


def report_path(out: str | Path, study: Study, plain_names: bool = True) -> Path:
    """Where ``study``'s report goes when the accuracy report is ``out``: ``out`` itself for the first
    study, else beside it ``<name>.md`` (``plain_names``: all maps, or the quick report's chosen
    ones) or ``<name>_<out's stem>.md`` (chosen maps)."""
    md = Path(out)
    if study.name == STUDIES[0].name:
        return md
    return md.with_name(f"{study.name}.md" if plain_names else f"{study.name}_{md.stem}.md")


def run(
    out: str | Path,
    map_names=None,
    show_progress: bool | None = None,
    plain_names: bool | None = None,
    on_study: Callable[[Study], None] | None = None,
) -> list[Path]:
    """Measure and write every study (:func:`studies`) of all maps, or of ``map_names`` with the
    baseline map for reference: the accuracy report ``out`` (+ .json, .png) and beside it the others
    (:func:`report_path`), named ``<name>.md`` when ``plain_names`` (default: for all maps only; the
    reduced report of ``slipmaps report --quick`` reads its chosen maps' records by those names), else
    ``<name>_<out's stem>.md``; ``on_study(study)`` is called as each study starts (``slipmaps
    report``'s progress). Returns the written paths: per study its report, record and figure."""
    chosen = studies(map_names)
    plain = map_names is None if plain_names is None else plain_names
    Path(out).parent.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    for study in chosen:
        if on_study is not None:
            on_study(study)
        written += write(study, report_path(out, study, plain), show_progress)
    return written
