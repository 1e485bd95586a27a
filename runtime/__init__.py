"""slipmaps.runtime: everything that runs the generated kernels, in subpackages by job.

Imports run one way (a test checks it): ``api`` (the public names, parameters, validation, results,
the index) < ``exact`` (the ``solve_ivp`` reference of the exact stance; the compiled simulator
is generated: generated/exact_stance.py, generated/dop853.py), ``robot`` (the MuJoCo monoped, an
optional extra: it uses ``api`` only) < ``analysis`` (periodic gaits),
``sweep`` (parameter sweeps), ``control`` (deadbeat steps, runs, scenarios, plants and their
evaluation: it uses ``api``, ``analysis`` and ``robot``) < ``studies`` (the accuracy, convergence,
stiffness and stability studies and their reports; the robot study, which runs the controllers),
``export`` (the C library's bindings) < ``report`` (the report's sections 6-8, written from the
studies' and the control evaluation's records) < ``cli`` (one module per command). Where numba
caches the compiled kernels is set up by the top-level package (``slipmaps.kernel_cache``); a kernel
compiling on its first call is a line on standard error from the moment the runtime is imported
(any public name but ``Status`` and ``MESSAGES`` imports it; ``slipmaps.derive`` does not):
``api/notices.py``.
"""

from .api import notices as _notices

_notices.install()
