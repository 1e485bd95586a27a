"""A copy of the project for the tests that follow a tutorial in it (tests/test_tutorial.py,
tests/test_adding_an_input.py).

The copy holds the files of ``git ls-files`` (the worktree's content, uncommitted edits included).
It is importable as ``slipmaps`` the way a non-editable install lays the package out
(site/slipmaps/{the files of runtime/public, derive, generated, runtime}), the directories linked to
the copy's, so that ``slipmaps generate`` finds the copy as its checkout (``derive/``'s parent). Every
command runs in a subprocess with that site first on PYTHONPATH (before the editable install of the
real checkout) and numba's cache in a directory of the test's (NUMBA_CACHE_DIR): nothing is written
into the real checkout or its cache.

That cache starts with a copy of this process's entries for the generated modules
(:meth:`Checkout.seed`): a copied file keeps its modification time, so numba's stamp check (the
source's time and size) accepts the entries of every generated module the page leaves unchanged
(the exact simulator's, say: about 35 s of CPU to compile) and recompiles the ones ``slipmaps
generate`` rewrote, as in any checkout. A generated module's header hashes the generated modules it
imports, so a module whose callees changed is rewritten too.
"""

from __future__ import annotations

import json
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from documents import ROOT

#: A command of a tutorial that runs longer than this fails the test.
TIMEOUT = 900


def tracked() -> list[str]:
    """The files of the checkout (``git ls-files``), those of the worktree."""
    done = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True)
    if done.returncode != 0 or shutil.which("git") is None:
        pytest.skip(f"not a git checkout: {done.stderr.decode()[-200:]}")
    out = done.stdout
    return [p for p in out.decode().split("\0") if p and (ROOT / p).is_file()]


def copy_tracked(dest: Path) -> Path:
    for rel in tracked():
        (dest / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / rel, dest / rel)
    return dest


def site_of(copy: Path, site: Path) -> Path:
    """The package ``slipmaps`` of a non-editable install, its files linked to ``copy``'s."""
    pkg = site / "slipmaps"
    pkg.mkdir(parents=True)
    for f in (copy / "runtime" / "public").glob("*.py"):
        (pkg / f.name).symlink_to(f)
    for sub in ("derive", "generated", "runtime"):
        (pkg / sub).symlink_to(copy / sub, target_is_directory=True)
    return site


class Checkout:
    """A copy of the project at ``root`` (importable from ``site``) and the commands of the page run
    in it, numba's cache in ``cache``."""

    def __init__(self, root: Path, site: Path, cache: Path):
        self.root = root
        self.cache = cache
        self.site = site_of(root, site)
        self.env = {
            **os.environ,
            "PYTHONPATH": str(self.site),
            "NUMBA_CACHE_DIR": str(cache),
            "PYTHONHASHSEED": "0",
            "MPLBACKEND": "Agg",
        }

    def seed(self) -> Path:
        """Copy this process's numba cache entries of ``slipmaps.generated`` into the folder numba
        uses for the copy's generated modules (numba's ``NUMBA_CACHE_DIR`` layout: the folder's name
        and a hash of its path, the path as the copy's site names it); returns that folder."""
        from numba.core.caching import UserProvidedCacheLocator
        from slipmaps.generated import flight

        source = Path(flight.apex_to_touchdown._cache._cache_path)
        module = self.site / "slipmaps" / "generated" / "flight.py"
        dest = self.cache / UserProvidedCacheLocator.get_suitable_cache_subpath(str(module))
        dest.mkdir(parents=True, exist_ok=True)
        for f in source.glob("*.nb[ic]"):
            shutil.copyfile(f, dest / f.name)
        return dest

    def _run(self, argv: list[str]) -> str:
        done = subprocess.run(
            argv, cwd=self.root, env=self.env, capture_output=True, text=True, timeout=TIMEOUT
        )
        assert done.returncode == 0, (argv[2:], done.stdout[-2000:], done.stderr[-3000:])
        return done.stdout

    def commands(self, code: str) -> str:
        """The lines of a bash block (``slipmaps ...`` through this interpreter); their output."""
        out = ""
        for line in code.splitlines():
            words = shlex.split(line, comments=True)
            if words:
                out += self._run([sys.executable, "-m", *words] if words[0] == "slipmaps" else words)
        return out

    def python(self, code: str, then: str = "") -> dict:
        """A python block, then ``then`` (which prints JSON on the last line of the output)."""
        return json.loads(self._run([sys.executable, "-c", code + "\n" + then]).splitlines()[-1])
