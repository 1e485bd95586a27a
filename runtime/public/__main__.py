"""``python -m slipmaps ...`` runs the ``slipmaps`` command line."""

import sys

from slipmaps.runtime.cli import main

sys.exit(main())
