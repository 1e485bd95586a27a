"""The exported C library from Python: compile it and call its role kernels through ctypes.

``slipmaps generate --target c DIR`` writes ``DIR/slipmaps.h`` and ``DIR/slipmaps.c``
(derive/ctarget.py). :func:`compile_library` builds them into a shared library with the flags the
export promises to compile under (warnings as errors); :class:`CLibrary` calls its kernels on rows,
through the library's own batch driver ``slipmaps_rows`` (one ctypes call per batch). The tests and
the benchmark use it to hold the C kernels to the numba ones; a robot's controller links the C
files directly (docs/c_export.md).
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np

#: What the exported sources must compile under without a warning.
STRICT = ("-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-pedantic")


def compiler() -> str | None:
    """The C compiler: ``$CC``, else ``cc``, ``gcc`` or ``clang`` on PATH; None without one."""
    for name in (os.environ.get("CC"), "cc", "gcc", "clang"):
        if name and shutil.which(name):
            return name
    return None


def compile_library(sources: list[Path], out: Path, *, cc: str | None = None, flags=STRICT, extra=()) -> Path:
    """Compile C ``sources`` into the shared library ``out`` with ``flags`` (``-fPIC -shared -lm``
    added). RuntimeError with the compiler's messages when it fails (a warning fails: -Werror)."""
    cc = cc or compiler()
    if cc is None:
        raise RuntimeError("no C compiler found: set CC or install gcc or clang")
    cmd = [cc, *flags, *extra, "-fPIC", "-shared", *map(str, sources), "-o", str(out), "-lm"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{run.stderr[-4000:]}")
    return Path(out)


_ROLE = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)
_PTR = ctypes.c_void_p


class CLibrary:
    """A compiled slipmaps C library: :meth:`address` of a role kernel's vector form,
    :meth:`rows` of a role kernel over many states."""

    def __init__(self, path: Path):
        self.path = Path(path)
        self.lib = ctypes.CDLL(str(self.path))
        f = self.lib.slipmaps_rows
        f.restype = None
        f.argtypes = [_PTR, ctypes.c_long, _PTR, ctypes.c_long, _PTR, ctypes.c_long, ctypes.c_long, _PTR]
        f.argtypes += [ctypes.c_long, _PTR]
        self._rows = f

    def address(self, kernel: str) -> int:
        """The C function pointer of kernel ``kernel``'s vector form, ``slipmaps_<kernel>_v``."""
        return ctypes.cast(getattr(self.lib, f"slipmaps_{kernel}_v"), ctypes.c_void_p).value

    def rows(self, kernel: str, X: np.ndarray, P: np.ndarray, n_out: int) -> tuple[np.ndarray, np.ndarray]:
        """``(OUT, STATUS)`` of ``kernel`` on the rows of ``X`` with the parameter records ``P``
        (one row for all, or one per row)."""
        X = np.ascontiguousarray(X, dtype=np.float64)
        P = np.ascontiguousarray(np.atleast_2d(P), dtype=np.float64)
        n = X.shape[0]
        OUT = np.empty((n, n_out))
        STATUS = np.empty(n, dtype=np.intc)
        self._rows(
            self.address(kernel),
            n,
            X.ctypes.data,
            X.shape[1],
            P.ctypes.data,
            P.shape[1],
            P.shape[0],
            OUT.ctypes.data,
            n_out,
            STATUS.ctypes.data,
        )
        return OUT, STATUS.astype(np.int64)
