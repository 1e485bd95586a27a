"""Progress where work is long (issue 32, item 4; issue 52, item 3): numba compiling a kernel on
its first call is a line on standard error, from the Python API (silenced by ``slipmaps.notices``
or ``SLIPMAPS_NOTICES=0``) and, on a terminal only, from the command line; ``slipmaps report``
says which stage it runs, of how many."""

from __future__ import annotations

import importlib.util
import io
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import slipmaps
from slipmaps.runtime.api import notices
from slipmaps.runtime.api.notices import compile_notices, compiling_what
from slipmaps.runtime.cli import app
from slipmaps.runtime.cli.app import main

ROOT = Path(__file__).resolve().parent.parent


class Terminal(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True


def _fresh_kernel(tmp_path: Path, name: str, cache: bool):
    """A numba function never compiled before: a new module file under ``tmp_path`` (numba's own
    cache folder beside it when ``cache``), imported under a new name inside the package
    ``slipmaps`` (the notices announce slipmaps' own code only)."""
    path = tmp_path / f"{name}.py"
    if not path.exists():
        deco = "njit(cache=True)" if cache else "njit"
        path.write_text(f"from numba import njit\n\n\n@{deco}\ndef {name}(x):\n    return 2.0 * x + 1.0\n")
    spec = importlib.util.spec_from_file_location(f"slipmaps.{name}_{len(list(tmp_path.iterdir()))}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return getattr(module, name)


def test_a_compile_is_one_line_on_a_terminal_with_its_seconds(tmp_path):
    kernel = _fresh_kernel(tmp_path, "kernel_tty", cache=False)
    stream = Terminal()
    with compile_notices(stream, delay=0):
        assert kernel(1.0) == 3.0
    text = stream.getvalue()
    # one line, redrawn in place (\r) while it compiles, ended with the time it took
    assert text.count("\n") == 1 and text.endswith(" s\n"), repr(text)
    last = text.rstrip("\n").split("\r")[-1]
    line = r"compiling slipmaps' \S*kernel_tty \(first call in this process\) \.\.\. \d+\.\d s"
    assert re.fullmatch(line, last), last


def test_a_compile_says_nothing_when_standard_error_is_piped(tmp_path):
    kernel = _fresh_kernel(tmp_path, "kernel_piped", cache=False)
    stream = io.StringIO()  # isatty() is False: a pipe or a file
    with compile_notices(stream, delay=0):
        assert kernel(1.0) == 3.0
    assert stream.getvalue() == ""


def test_a_kernel_loaded_from_the_cache_says_nothing(tmp_path, monkeypatch):
    """numba fires its compile event on a cache miss only: the second process (here a second
    dispatcher of the same file) loads the kernel and prints no line."""
    from numba.core import config

    monkeypatch.setattr(config, "CACHE_DIR", str(tmp_path / "numba"))  # not the suite's cache
    stream = Terminal()
    with compile_notices(stream, delay=0):
        assert _fresh_kernel(tmp_path, "kernel_cached", cache=True)(1.0) == 3.0
    assert "kernel_cached (first call; cached afterwards)" in stream.getvalue()
    again = Terminal()
    with compile_notices(again, delay=0):
        assert _fresh_kernel(tmp_path, "kernel_cached", cache=True)(2.0) == 5.0
    assert again.getvalue() == ""


def test_a_short_compile_says_nothing(tmp_path):
    kernel = _fresh_kernel(tmp_path, "kernel_short", cache=False)
    stream = Terminal()
    with compile_notices(stream, delay=60.0):
        assert kernel(1.0) == 3.0
    assert stream.getvalue() == ""


@pytest.fixture
def api_notices(monkeypatch, capsys):
    """The process's notices as the Python API has them by default (always, on standard error),
    shown however short the compile; standard error a plain stream (capsys's: as a file or a
    notebook's), whose text ``api_notices()`` gives."""
    monkeypatch.setattr(notices.NOTICES, "enabled", True)
    monkeypatch.setattr(notices, "NOTICE_DELAY", 0.0)
    notices.install()
    return lambda: capsys.readouterr().err


def test_a_first_call_from_python_is_one_line_on_standard_error(api_notices, tmp_path):
    """Not only on a terminal: a script's log or a notebook gets the line too, once, as it is."""
    assert _fresh_kernel(tmp_path, "kernel_api", cache=False)(1.0) == 3.0
    line = r"compiling slipmaps' \S*kernel_api \(first call in this process\) \.\.\.\n"
    assert re.fullmatch(line, api_notices())


def test_notices_false_silences_them_and_returns_the_setting_before(api_notices, tmp_path):
    assert slipmaps.notices(False) is True
    try:
        assert _fresh_kernel(tmp_path, "kernel_quiet", cache=False)(1.0) == 3.0
    finally:
        assert slipmaps.notices(True) is False
    assert api_notices() == ""
    with pytest.raises(ValueError, match="notices takes True, False or None"):
        slipmaps.notices("no")


def test_numba_code_outside_slipmaps_is_not_announced(api_notices):
    from numba import njit

    @njit
    def theirs(x):
        return x + 1.0

    assert theirs(1.0) == 2.0
    assert api_notices() == ""


@pytest.mark.parametrize(("value", "enabled"), [("0", False), ("terminal", None), ("", True), ("1", True)])
def test_the_environment_variable_sets_the_default(value, enabled, monkeypatch):
    monkeypatch.setenv(notices.NOTICES_ENV, value)
    assert notices._from_environment() is enabled


#: A first public call in a fresh process, every compile announced however short.
FIRST_CALL = (
    "from slipmaps.runtime.api import notices\n"
    "notices.NOTICE_DELAY = 0.0\n"
    "import slipmaps\n"
    "assert slipmaps.apex_return('geyer', slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35).ok\n"
)


@pytest.mark.slow  # geyer's kernels compiled on an empty cache: 3-8 s
def test_a_first_call_says_what_compiles_and_a_kernel_in_the_cache_says_nothing(tmp_path):
    """Issue 52: a first call on an empty cache (piped standard error: the API's notices do not
    need a terminal) names the map and the role; the next process loads the kernel from numba's
    disk cache, which numba's compile event never fires for: nothing."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "SLIPMAPS_NOTICES"))}
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "cache")
    runs = [
        subprocess.run(
            [sys.executable, "-c", FIRST_CALL], env=env, capture_output=True, text=True, timeout=600
        )
        for _ in range(2)
    ]
    assert all(r.returncode == 0 for r in runs), runs[-1].stderr[-2000:]
    assert runs[0].stderr == "compiling slipmaps' geyer apex_return (first call; cached afterwards) ...\n"
    assert runs[1].stderr == ""


def test_a_role_kernel_is_named_by_its_map_and_role_another_by_its_file():
    from slipmaps.generated import exact_jacobian, geyer, iterative
    from slipmaps.runtime.control import footholds_solver

    assert compiling_what(exact_jacobian.exact_apex_return_jacobian) == "slipmaps' exact apex_return_jacobian"
    assert compiling_what(geyer.geyer_stance_rows) == "slipmaps' geyer stance, batch"
    assert compiling_what(iterative.iterative_stance_zeroth_geyer) == "slipmaps' iterative stance"  # default
    assert compiling_what(iterative.iterative_stance_zeroth_held) == "slipmaps' iterative stance (held)"
    assert compiling_what(geyer.geyer_solution) == "slipmaps' geyer_solution of generated/geyer.py"
    assert compiling_what(footholds_solver.plan_rows) == "slipmaps' footholds planner (plan_rows)"


@pytest.mark.parametrize("no_progress", [False, True])
def test_every_command_runs_with_the_notices(no_progress, tmp_path, monkeypatch):
    """The command line installs the notices once for every command (runtime/cli/app.py): a command
    that compiles shows the line on a terminal, none with --no-progress."""
    kernel = _fresh_kernel(tmp_path, f"kernel_cli_{int(no_progress)}", cache=False)

    def compiles(args):
        return 0 if kernel(1.0) == 3.0 else 1

    monkeypatch.setattr(app.report_cli, "run", compiles)
    monkeypatch.setattr(notices, "NOTICE_DELAY", 0.0)
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    argv = ["report", "--render-only"] + (["--no-progress"] if no_progress else [])
    assert main(argv) == 0
    shown = "compiling slipmaps'" in terminal.getvalue()
    assert shown is not no_progress, terminal.getvalue()


#: ``python -m slipmaps`` with a line for every compile, however short (a quiet machine compiles
#: geyer's kernels in less than the default second).
EVERY_COMPILE = (
    "import sys\n"
    "from slipmaps.runtime.api import notices\n"
    "from slipmaps.runtime.cli import main\n"
    "notices.NOTICE_DELAY = 0.0\n"
    "sys.exit(main(sys.argv[1:]))\n"
)


def _slipmaps(argv, cache: Path, stderr) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith("NUMBA_")}
    env["NUMBA_CACHE_DIR"] = str(cache)
    command = [sys.executable, "-c", EVERY_COMPILE, *argv]
    return subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=stderr, timeout=600)


@pytest.mark.skipif(sys.platform == "win32", reason="a pseudo-terminal needs a POSIX system")
def test_a_first_command_on_an_empty_cache_shows_what_compiles_on_a_terminal_only(tmp_path):
    """The new user's silent first minute: a command on an empty cache, its standard error a
    terminal (a pseudo-terminal), then piped; standard output stays clean in both."""
    import pty

    argv = ["compare", "--map", "geyer", "--against", "geyer", "--no-plot", "--json"]
    primary, secondary = pty.openpty()
    try:
        done = _slipmaps(argv, tmp_path / "cold-tty", secondary)
        os.close(secondary)
        secondary = None
        chunks = []
        while True:
            try:
                chunk = os.read(primary, 65536)
            except OSError:  # the terminal's other end is closed: all read
                break
            if not chunk:
                break
            chunks.append(chunk)
    finally:
        os.close(primary)
        if secondary is not None:
            os.close(secondary)
    assert done.returncode == 0
    terminal = b"".join(chunks).decode()
    line = r"compiling slipmaps' geyer \w+(, batch)? \(first call; cached afterwards\)"
    assert re.search(line, terminal), terminal
    assert b"compiling" not in done.stdout
    piped = _slipmaps(argv, tmp_path / "cold-pipe", subprocess.PIPE)
    assert piped.returncode == 0 and piped.stderr == b"", piped.stderr[-2000:]
    assert piped.stdout.startswith(b"{")


# --- slipmaps report: which stage, of how many -----------------------------------------------------


@pytest.fixture
def report_stages(tmp_path, monkeypatch):
    """``slipmaps report --quick`` with every stage's work replaced by a record of its name."""
    from slipmaps.runtime.control import report as control_report
    from slipmaps.runtime.report import sections
    from slipmaps.runtime.studies import runner

    ran = []

    def study(study, md, show_progress=None):
        ran.append(f"the {study.name} study")
        return []

    def control(out, examples, quick=False, progress=None):
        ran.append("the control evaluation")
        (Path(out) / "control_quick.json").write_text("{}")
        return []

    def page(out, records=None, strict=True, draw=True):
        ran.append("sections 6-8")
        return []

    monkeypatch.setattr(runner, "write", study)
    monkeypatch.setattr(control_report, "write", control)
    monkeypatch.setattr(sections, "load", lambda out: {})
    monkeypatch.setattr(sections, "write", page)
    return ["report", "--quick", "--out", str(tmp_path)], ran


def _stage_lines(err: str):
    return [line for line in err.splitlines() if line.startswith("slipmaps report: [")]


def test_report_on_a_terminal_says_which_stage_of_how_many(report_stages, monkeypatch):
    argv, ran = report_stages
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    assert main(argv) == 0
    lines = _stage_lines(terminal.getvalue())
    n = len(ran)
    assert n >= 4 and ran[-2:] == ["the control evaluation", "sections 6-8"]
    assert [re.sub(r" \(\d+ s so far\)$", "", line) for line in lines] == [
        f"slipmaps report: [{i}/{n}] {what}" for i, what in enumerate(ran, 1)
    ]
    assert all(line.endswith("s so far)") for line in lines), lines
    assert f"slipmaps report: {n} stages in " in terminal.getvalue()


def test_report_piped_is_one_plain_line_per_stage(report_stages, capsys):
    argv, ran = report_stages
    assert main(argv) == 0
    err = capsys.readouterr().err
    n = len(ran)
    assert err.splitlines() == [f"slipmaps report: [{i}/{n}] {what}" for i, what in enumerate(ran, 1)]
    assert "\r" not in err


def test_a_bar_counts_the_items_of_a_loop_and_closes_after_the_last():
    from slipmaps.runtime.api.progress import Bar

    stream = Terminal()
    sys_stderr, sys.stderr = sys.stderr, stream
    try:
        assert list(Bar(3, "kernels", True, unit="kernels").count("abc")) == ["a", "b", "c"]
    finally:
        sys.stderr = sys_stderr
    text = stream.getvalue()
    assert text.rstrip("\n").split("\r")[-1].startswith("kernels: [########################] 3/3 kernels")
    assert text.endswith("\n") and text.count("\n") == 1
