"""Test configuration: under CI (``CI`` set), Hypothesis runs derandomized so a red run is reproducible.

Locally it explores new examples each run (and keeps failures in .hypothesis/).
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
