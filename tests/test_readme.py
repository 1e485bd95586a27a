"""Every example in README.md and in the site pages that hold what the README handed over to the site
(tests/documents.py: getting started, control and planning, sweeps, performance, ...) runs as
written (tracker issue 16): the shell commands of their bash blocks, their inline `slipmaps ...`
commands and their python blocks, in a scratch directory.

Each command is run in this process (``slipmaps.runtime.cli.app.main``; ``python3 -m slipmaps`` and the
console script are the same function, test_new_user.py checks both) from a temporary directory
holding a link to the checkout's examples/, so relative paths (``--out sweep_geyer``,
``examples/sweep.toml``) resolve as they do for a reader in the checkout and nothing is written
into it. The python blocks run in order in one namespace, the README's first, then the pages' in
the order of :data:`documents.DOCUMENTS` (later blocks use ``params``, ``td``...).

Not run, each for the reason in :data:`SKIPPED`: installing, the whole test suite (minutes; this
test is part of it), the commands that rewrite the checkout (``slipmaps generate``, ``slipmaps
accuracy``, which also takes minutes) and the Dask cluster's lines (a scheduler at the placeholder
address ``tcp://HOST:8786``), and the tutorial's marked steps of docs/adding_a_map.md, which add
a map: tests/test_tutorial.py runs them in a copy of the project. An inline span that is only
``slipmaps NAME`` names a subcommand in prose; it is checked to be one. Measured: about 35 s of CPU
once the kernels are cached, most of it ``slipmaps generate --check`` (21 s) and ``slipmaps
equations`` (9 s), both SymPy.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from documents import DOCUMENTS, blocks, text
from slipmaps.runtime.cli import build_parser, main

ROOT = Path(__file__).resolve().parent.parent

#: The documents' shell lines that are not run, and why (every other line must be a slipmaps command).
SKIPPED = {
    "python3 -m pip install .": "installs slipmaps (Quick start)",
    "python3 -m pip install -e '.[test]'": "installs slipmaps with the test extra (Quick start)",
    "python3 -m pytest -n auto --dist loadfile": "the whole suite: minutes, and this test is part of it",
    "dask scheduler": "starts a Dask scheduler that runs until stopped",
    "dask worker tcp://HOST:8786 --nthreads 1": "a worker for a scheduler at a placeholder address",
    "slipmaps sweep examples/sweep.toml --scheduler tcp://HOST:8786": "needs that scheduler (HOST)",
    "python3 -m pip install -e '.[derive]'": "installs slipmaps with the derive extra",
    "slipmaps generate": "rewrites the checkout's generated/ and docs",
    "slipmaps accuracy": "rewrites the checkout's docs/ and takes minutes",
    "slipmaps run --evaluate": "rewrites the checkout's docs/control.* and takes minutes",
}
PREFIXES = (("python3", "-m", "slipmaps"), ("python", "-m", "slipmaps"), ("slipmaps",))


def shell_commands() -> list[str]:
    """Every command of the bash blocks: continuation lines joined, comments dropped, ``&&``
    split."""
    out = []
    for _, block in blocks("bash"):
        for line in block.replace("\\\n", " ").splitlines():
            words = shlex.split(line, comments=True)
            if not words:
                continue
            text = " ".join(shlex.quote(w) if w != "&&" else w for w in words)
            out += [" ".join(c.split()) for c in text.split(" && ")]
    return out


def inline_commands() -> list[str]:
    """The inline code spans of the prose that are slipmaps commands (line breaks inside a span
    read as spaces)."""
    prose = "\n".join(re.sub(r"^```.*?^```", "", text(name), flags=re.S | re.M) for name in DOCUMENTS)
    spans = (" ".join(s.split()) for s in re.findall(r"`([^`]+)`", prose))
    return [s for s in spans if _argv(s) is not None]


def _argv(command: str) -> list[str] | None:
    """The arguments after ``slipmaps`` / ``python3 -m slipmaps``, or None for another program."""
    try:
        words = shlex.split(command)
    except ValueError:  # an unbalanced quote: a Python fragment, not a command
        return None
    for prefix in PREFIXES:
        if tuple(words[: len(prefix)]) == prefix:
            return words[len(prefix) :]
    return None


def _displayed(command: str) -> str:
    """A command as the skip list spells it (quoted as in the documents)."""
    return " ".join(shlex.quote(w) for w in shlex.split(command))


SUBCOMMANDS = set(build_parser()._subparsers._group_actions[0].choices)


def _is_a_name(argv: list[str]) -> bool:
    """``slipmaps NAME`` (or bare ``python -m slipmaps``) in prose: a command named, not run."""
    return len(argv) == 0 or (len(argv) == 1 and argv[0] in SUBCOMMANDS)


def _plan() -> tuple[list[list[str]], list[str], list[list[str]]]:
    """(commands to run, skipped lines, names of subcommands) of every document."""
    skip = {_displayed(k) for k in SKIPPED}
    run, skipped, named = [], [], []
    for command in shell_commands():
        if command in skip:
            skipped.append(command)
            continue
        argv = _argv(command)
        assert argv is not None, f"shell line {command!r} is neither run nor in SKIPPED"
        run.append(argv)
    for command in inline_commands():
        if command in skip:  # named in prose (``slipmaps run --evaluate`` rewrites docs/control.*)
            continue
        argv = _argv(command)
        (named if _is_a_name(argv) else run).append(argv)
    return run, skipped, named


@pytest.fixture
def scratch(tmp_path, monkeypatch) -> Path:
    """A working directory like the checkout's for the examples: examples/ linked, nothing else."""
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_the_plan_runs_almost_everything():
    run, skipped, named = _plan()
    assert len(run) >= 10, run
    assert len(skipped) <= len(SKIPPED) <= 10 and set(skipped) == {_displayed(k) for k in SKIPPED}
    assert any(a[:3] == ["compare", "--map", "gravity-type2"] for a in run), run  # the options example
    assert ["run", "--evaluate"] not in run  # also where the prose names it: it rewrites the checkout
    assert not any(a[:2] == ["run", "--evaluate"] for a in run), run  # --blind, --quick alike
    assert named
    for argv in named:
        assert not argv or argv[0] in SUBCOMMANDS, argv


def _run(argv: list[str]) -> int:
    try:
        return main(argv)
    except SystemExit as exc:  # --help, --version: argparse exits after printing
        return exc.code


def test_every_readme_command_runs_as_written(scratch, capsys):
    run, _, _ = _plan()
    for argv in run:
        code = _run(argv)
        captured = capsys.readouterr()
        assert code == 0, (argv, captured.err[-2000:])
        assert "Traceback" not in captured.err, argv
    written = {p.name for p in scratch.iterdir()}
    assert {"slipmaps_compare.png", "sweep_geyer", "sweep_exact", "sweep_type5"} <= written
    assert not any((ROOT / name).exists() for name in ("sweep_geyer", "sweep_exact")), "wrote the checkout"


def test_the_readme_table_is_what_compare_prints(scratch, capsys):
    """The output shown for the quick start's first command (docs/getting_started.md) is its table."""
    ((_, table),) = blocks("text")
    assert main(["compare", "--no-plot"]) == 0
    out = capsys.readouterr().out
    assert table.strip() in out, out


def test_the_readme_python_blocks_run_as_written(scratch):
    python = blocks("python")
    assert len(python) >= 4 and python[0][0] == "README.md"
    namespace: dict = {}
    for name, block in python:
        exec(compile(block, name, "exec"), namespace)  # the documents' own code, as written
    assert namespace["g"].ok and (scratch / "sweep_type5").is_dir()
    assert namespace["gaits"].status.name == "OK"
