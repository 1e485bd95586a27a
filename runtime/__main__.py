"""``python -m slipmaps.runtime ...`` runs the ``slipmaps`` command line (same as the console script)."""

import sys

from .cli import main

sys.exit(main())
