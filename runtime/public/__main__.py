"""``python -m slipmaps ...`` runs the ``slipmaps`` command line."""

import sys

from slipmaps.runtime.cli import main

if __name__ == "__main__":  # not again in a process a study spawns (multiprocessing re-imports it)
    sys.exit(main())
