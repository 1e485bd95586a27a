"""The studies written into docs/ by ``slipmaps accuracy``: every map against the exact simulator
(accuracy), the iterations' convergence, variable stiffness and periodic gaits' stability.

One pipeline: a :class:`~.study.Study` measures a JSON-able record, renders it as Markdown and draws
it; one writer (:func:`.study.write`) writes ``<name>.json``, ``.md`` and ``.png``; :func:`.runner.run`
runs every study (``slipmaps accuracy``). Per study, its measurement and its report: ``accuracy`` +
``accuracy_report`` (on the grids of ``grids``), ``convergence``, ``stiffness`` +
``stiffness_report``, ``stability`` + ``stability_report``; a measurement never imports its report.
The maps each study runs, and the values of their options, come from the roles in the index
(``MapInfo.roles``, ``Option.roles``), never from a list of names.
"""
