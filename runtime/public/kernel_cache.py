"""Where numba caches slipmaps' compiled kernels: in a user cache directory, never inside the install.

Every compiled kernel of slipmaps (the generated maps in ``slipmaps.generated`` and the exact
simulator in ``slipmaps.runtime``) is ``njit(cache=True)``. numba's default puts that cache beside
the source, in the installed package's ``__pycache__``. ``pip uninstall``, and the editable
reinstall of the README's second quick-start command, removes the package's own files but not
numba's ``.nbi``/``.nbc`` files: the folder left behind in site-packages then shadows the editable
install (``import slipmaps`` finds an empty namespace package). So slipmaps' kernels are cached in:

1. ``NUMBA_CACHE_DIR`` when it is set (numba's own setting; it applies to all numba code);
2. else ``$XDG_CACHE_HOME/slipmaps/numba`` (``~/.cache/slipmaps/numba``; on macOS
   ``~/Library/Caches/slipmaps/numba``, on Windows ``%LOCALAPPDATA%\\slipmaps\\numba``);
3. else, when that is not writable (a read-only home), a private directory under the temporary
   directory, with one warning naming it.

Inside it numba keeps one folder per source directory (its name and a hash of its path), and checks
each entry against its source file's stamp (modification time and size) and numba's version, so two
installs never share entries. A cached kernel holds the compiled code of every kernel it calls, in
other files too, and numba checks only the caller's file (numba's documented limitation): the
deadbeat solver's cached entry points (runtime/control/compiled.py) hold the generated kernels
they call. So the folder of a kernel outside ``slipmaps.generated`` carries a digest of the
contents of every slipmaps source that defines kernels (:func:`kernel_sources`; the generated
modules included), and any change to one of them recompiles those kernels. The generated modules
need none: each states the hashes of the generated modules it imports in its header (``slipmaps
generate``; generated code imports only generated code, the exact simulator's support modules
included), so a change in a callee changes the caller's file, and an edit of a hand-written runtime
module never touches a generated one. With
``NUMBA_CACHE_DIR`` set, numba's own rules apply (without the digest). Clearing the cache is
removing the directory (:func:`cache_root` names it).

Only slipmaps' own files are redirected, by a cache locator that numba consults before its own
(:class:`SlipmapsCacheLocator`); other numba code in the process keeps numba's defaults. numba
calls the locators when a kernel is decorated, so :func:`install` runs when the package
``slipmaps`` is imported (``runtime/public/__init__.py``), before any kernel module.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import os
import sys
import tempfile
import warnings

from numba.core import caching, config

__all__ = [
    "SlipmapsCacheLocator",
    "cache_root",
    "install",
    "kernel_sources",
    "slipmaps_dirs",
    "sources_digest",
]

# numba spelled these with a leading underscore before it made them public.
_Locator = getattr(caching, "UserProvidedCacheLocator", None) or caching._UserProvidedCacheLocator
_CacheImpl = getattr(caching, "CacheImpl", None) or caching._CacheImpl


def _user_cache_home() -> str:
    if sys.platform == "win32":
        return os.environ.get("LOCALAPPDATA") or os.path.join(os.path.expanduser("~"), "AppData", "Local")
    if sys.platform == "darwin":
        return os.path.join(os.path.expanduser("~"), "Library", "Caches")
    return os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")


def _writable(path: str, mode: int = 0o700) -> bool:
    """numba's own test of a cache directory: it can be created (with ``mode``, less the umask) and a
    file written in it."""
    try:
        os.makedirs(path, mode=mode, exist_ok=True)
        tempfile.TemporaryFile(dir=path).close()
    except OSError:
        return False
    return True


def _private_temp_dir() -> str | None:
    """<tempdir>/slipmaps-numba-<uid>, kept between runs when it is this user's alone (else a fresh
    one: a shared directory's cache index could be planted by another user); None if none is writable."""
    uid = os.getuid() if hasattr(os, "getuid") else None
    path = os.path.join(tempfile.gettempdir(), f"slipmaps-numba-{uid if uid is not None else 'user'}")
    try:
        os.makedirs(path, mode=0o700, exist_ok=True)
        st = os.stat(path)
        if (uid is None or st.st_uid == uid) and not st.st_mode & 0o022 and _writable(path):
            return path
        return tempfile.mkdtemp(prefix="slipmaps-numba-")
    except OSError:
        return None


@functools.cache
def cache_root() -> str | None:
    """The directory slipmaps' kernels are cached in (module docstring), chosen once per process;
    None when numba's own choice applies (``NUMBA_CACHE_DIR`` set, or nothing writable)."""
    if config.CACHE_DIR:
        return None
    user = os.path.join(_user_cache_home(), "slipmaps", "numba")
    if _writable(user):
        return user
    chosen = _private_temp_dir()
    if chosen is None:
        warnings.warn(
            f"slipmaps: numba cannot cache the compiled kernels ({user} and the temporary directory are "
            "not writable): set NUMBA_CACHE_DIR to a writable directory",
            RuntimeWarning,
            stacklevel=2,
        )
        return None
    warnings.warn(
        f"slipmaps: {user} is not writable; numba caches the compiled kernels in {chosen} "
        "(set NUMBA_CACHE_DIR to choose another directory)",
        RuntimeWarning,
        stacklevel=2,
    )
    return chosen


@functools.cache
def slipmaps_dirs() -> tuple[str, ...]:
    """The directories of slipmaps' own sources (the package, its runtime and generated kernels),
    wherever they are installed (site-packages, or a checkout for an editable install)."""
    dirs = set()
    for name in ("slipmaps", "slipmaps.runtime", "slipmaps.generated"):
        spec = importlib.util.find_spec(name)
        if spec is not None and spec.submodule_search_locations:
            dirs.update(os.path.realpath(p) for p in spec.submodule_search_locations)
    return tuple(sorted(dirs))


def kernel_sources() -> tuple[str, ...]:
    """slipmaps' source files that define numba kernels (they import numba), sorted."""
    found = set()
    for d in slipmaps_dirs():
        for root, dirs, files in os.walk(d):
            dirs[:] = sorted(x for x in dirs if x != "__pycache__")
            for f in files:
                path = os.path.join(root, f)
                if f.endswith(".py") and _defines_kernels(path):
                    found.add(os.path.realpath(path))
    return tuple(sorted(found))


def _defines_kernels(path: str) -> bool:
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    except OSError:
        return False
    return "from numba import" in text or "import numba" in text


@functools.cache
def sources_digest(files: tuple[str, ...] | None = None) -> str:
    """12 hex digits of the sha256 of ``files``' contents (default :func:`kernel_sources`), each
    with its path relative to its slipmaps directory, so the digest is the same wherever the
    package is installed."""
    files = kernel_sources() if files is None else files
    h = hashlib.sha256()
    for path in files:
        rel = next((os.path.relpath(path, d) for d in slipmaps_dirs() if path.startswith(d + os.sep)), path)
        with open(path, "rb") as fh:
            h.update(rel.encode() + b"\0" + fh.read() + b"\0")
    return h.hexdigest()[:12]


def _generated(py_file: str) -> bool:
    return os.path.basename(os.path.dirname(os.path.realpath(py_file))) == "generated"


def _ours(py_file: str) -> bool:
    here = os.path.dirname(os.path.realpath(py_file))
    return any(here == d or here.startswith(d + os.sep) for d in slipmaps_dirs())


class SlipmapsCacheLocator(_Locator):
    """numba's user-provided-directory locator, rooted at :func:`cache_root`, for slipmaps' own
    source files only (it declines every other file, and declines when ``NUMBA_CACHE_DIR`` is set);
    a kernel outside the generated modules in a folder of the sources' digest (:func:`sources_digest`)."""

    def __init__(self, py_func, py_file):
        self._py_file = py_file
        self._lineno = py_func.__code__.co_firstlineno
        subpath = self.get_suitable_cache_subpath(py_file)
        if not _generated(py_file):  # its callees in other files: the sources' digest (module docstring)
            subpath += "-" + sources_digest()
        self._cache_path = os.path.join(cache_root(), subpath)

    @classmethod
    def from_function(cls, py_func, py_file):
        if config.CACHE_DIR or not os.path.exists(py_file) or not _ours(py_file) or cache_root() is None:
            return None
        # the source-file locators' own constructor check (the directory can be made and written)
        return super(_Locator, cls).from_function(py_func, py_file)


def install() -> None:
    """Put :class:`SlipmapsCacheLocator` first among the locators numba tries (once)."""
    classes = _CacheImpl._locator_classes
    if SlipmapsCacheLocator not in classes:
        classes.insert(0, SlipmapsCacheLocator)
