"""Progress where work is long (issue 32, item 4): numba compiling a kernel on its first use is a
line on a terminal's standard error, and ``slipmaps report`` says which stage it runs, of how many;
nothing of either when standard error is piped."""

from __future__ import annotations

import importlib.util
import io
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from slipmaps.runtime.api import progress
from slipmaps.runtime.api.progress import compile_notices, compiling_what
from slipmaps.runtime.cli import app
from slipmaps.runtime.cli.app import main

ROOT = Path(__file__).resolve().parent.parent


class Terminal(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True


def _fresh_kernel(tmp_path: Path, name: str, cache: bool):
    """A numba function never compiled before: a new module file under ``tmp_path`` (numba's own
    cache folder beside it when ``cache``), imported under a new name."""
    path = tmp_path / f"{name}.py"
    if not path.exists():
        deco = "njit(cache=True)" if cache else "njit"
        path.write_text(f"from numba import njit\n\n\n@{deco}\ndef {name}(x):\n    return 2.0 * x + 1.0\n")
    spec = importlib.util.spec_from_file_location(f"{name}_{len(list(tmp_path.iterdir()))}", path)
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
    line = r"slipmaps: compiling \S*kernel_tty \(once per process\) \.\.\. \d+\.\d s"
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
    assert "kernel_cached (first use; cached for the next runs)" in stream.getvalue()
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


def test_a_generated_kernel_is_named_by_its_file():
    from slipmaps.generated import geyer

    assert compiling_what(geyer.geyer_stance) == "geyer_stance of generated/geyer.py"


@pytest.mark.parametrize("no_progress", [False, True])
def test_every_command_runs_with_the_notices(no_progress, tmp_path, monkeypatch):
    """The command line installs the notices once for every command (runtime/cli/app.py): a command
    that compiles shows the line on a terminal, none with --no-progress."""
    kernel = _fresh_kernel(tmp_path, f"kernel_cli_{int(no_progress)}", cache=False)

    def compiles(args):
        return 0 if kernel(1.0) == 3.0 else 1

    monkeypatch.setattr(app.report_cli, "run", compiles)
    monkeypatch.setattr(progress, "NOTICE_DELAY", 0.0)
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    argv = ["report", "--render-only"] + (["--no-progress"] if no_progress else [])
    assert main(argv) == 0
    shown = "slipmaps: compiling" in terminal.getvalue()
    assert shown is not no_progress, terminal.getvalue()


#: ``python -m slipmaps`` with a line for every compile, however short (a quiet machine compiles
#: geyer's kernels in less than the default second).
EVERY_COMPILE = (
    "import sys\n"
    "from slipmaps.runtime.api import progress\n"
    "from slipmaps.runtime.cli import main\n"
    "progress.NOTICE_DELAY = 0.0\n"
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
    line = r"slipmaps: compiling geyer_\w+ of generated/geyer\.py \(first use; cached for the next runs\)"
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
