"""Control and planning on the maps: deadbeat steps, multi-step runs on a plant, scenarios, evaluation.

Modules, one job each (imports run one way: ``control`` uses ``api``, ``exact`` and ``analysis``;
nothing below imports it):

- :mod:`.compiled`: the deadbeat solve compiled with numba (bounded, line-searched Gauss-Newton
  with the map's generated Jacobian), bound per map to its kernels;
- :mod:`.deadbeat`: :func:`slipmaps.deadbeat`, :func:`slipmaps.deadbeat_batch` and the prepared
  controller :class:`~.deadbeat.Deadbeat`; plan statuses :class:`~.deadbeat.PlanStatus`
  (``REACHED``, ``UNREACHABLE``, ``MAP_FAILED``).
"""
