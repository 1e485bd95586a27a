"""Every file the package writes goes through one guard (issue: "What a new user tripped on"):
paths probed before the work, an OSError while writing one line naming the path, Ctrl-C on a run
one line and exit 130 with the steps already run, a run beyond the machine's memory refused."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from slipmaps.runtime.api.paths import writable_dir, writable_file, writing
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.control import runs

ROOT = Path(__file__).resolve().parent.parent
STOP = str(ROOT / "examples" / "stop.toml")
PROC = Path("/proc")
needs_proc = pytest.mark.skipif(not (PROC / "self").is_dir(), reason="no /proc on this system")


@needs_proc
def test_a_path_under_proc_is_refused_before_the_work():
    # /proc passes a permission check as root and refuses every new file: the probe finds it
    with pytest.raises(ValueError, match="/proc/x.png"):
        writable_file("--figure", "/proc/x.png", ("png",))
    with pytest.raises(ValueError, match="cannot create a file in /proc"):
        writable_dir("--out", "/proc")


def test_a_file_used_as_a_directory_is_refused(tmp_path):
    (tmp_path / "f").write_text("x")
    with pytest.raises(ValueError, match="is a file, not a directory"):
        writable_file("--figure", tmp_path / "f" / "x.png", ("png",))


def test_the_probe_leaves_nothing_behind(tmp_path):
    writable_file("--figure", tmp_path / "x.png", ("png",))
    assert list(tmp_path.iterdir()) == []


def test_an_oserror_while_writing_is_one_line_naming_the_path(tmp_path):
    target = tmp_path / "x.json"
    with pytest.raises(ValueError, match=r"cannot write .*x.json: No space left on device"):
        with writing(target):
            raise OSError(28, os.strerror(28))


@needs_proc
@pytest.mark.parametrize(
    "argv",
    [
        ["run", STOP, "--figure", "/proc/x.png"],
        ["run", STOP, "--no-figure", "--gif", "/proc/x.gif"],
        ["gait", "--figure", "/proc/g.png"],
        ["compare", "--plot", "/proc/c.png"],
        ["sweep", str(ROOT / "examples" / "sweep.toml"), "--out", "/proc/sweep"],
        ["accuracy", "--map", "geyer", "--out", "/proc/acc"],
        ["report", "--quick", "--out", "/proc/report"],
        ["run", "--evaluate", "--quick", "--out", "/proc/evaluation"],
    ],
)
def test_every_command_refuses_a_path_under_proc_before_the_work(argv, capsys, monkeypatch):
    if argv[0] == "sweep" and not Path(argv[1]).exists():
        pytest.skip("no example sweep definition")

    def no_work(*a, **k):
        raise AssertionError("the work started before the path was checked")

    monkeypatch.setattr(runs, "run_batch", no_work)
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "/proc/" in err[0]


def test_an_unguarded_oserror_is_one_line_and_exit_2(capsys, monkeypatch):
    from slipmaps.runtime.cli import run as run_cli

    def fails(args):
        raise PermissionError(13, "Permission denied", "/somewhere/x.csv")

    monkeypatch.setattr(run_cli, "run", fails)
    assert main(["run", STOP]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["slipmaps run: error: cannot write /somewhere/x.csv: Permission denied"]


def test_ctrl_c_on_run_prints_the_steps_already_run_and_exits_130(capsys, monkeypatch):
    step = runs._step

    def interrupted(ctl, n, *rest):
        if n == 2:
            raise KeyboardInterrupt
        return step(ctl, n, *rest)

    monkeypatch.setattr(runs, "_step", interrupted)
    assert main(["run", STOP, "--no-figure", "--steps", "5"]) == 130
    out, err = capsys.readouterr()
    rows = [line.split()[0] for line in out.splitlines() if line.strip()[:1].isdigit()]
    assert rows == ["0", "1"]
    assert err.strip().splitlines() == ["slipmaps run: interrupted after 2 step(s); nothing written"]


def test_ctrl_c_during_any_command_is_one_line_and_130(capsys, monkeypatch):
    from slipmaps.runtime.cli import run as run_cli

    def stop(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(run_cli, "run", stop)
    assert main(["run", STOP]) == 130
    assert capsys.readouterr().err.strip().splitlines() == ["slipmaps run: interrupted"]


def test_a_run_beyond_the_machines_memory_is_refused_with_the_estimate(capsys):
    assert main(["run", STOP, "--no-figure", "--steps", str(10**12)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--steps 1000000000000" in err[0] and "GB of memory" in err[0]


def test_the_memory_estimate_grows_with_the_steps_and_refuses_beyond_the_available():
    assert runs.memory_estimate(1, 2000) > 2 * runs.memory_estimate(1, 999)
    assert runs.check_memory(1, 10, available=10**9) == runs.memory_estimate(1, 10)
    with pytest.raises(ValueError, match="GB of memory"):
        runs.check_memory(1, 10**6, available=10**6)


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full on this system")
def test_a_full_device_while_writing_is_one_line_naming_the_path(tmp_path, capsys):
    """/dev/full accepts the open and fails every write with ENOSPC: the figure's path is named."""
    link = tmp_path / "c.png"
    link.symlink_to("/dev/full")
    assert main(["compare", "--map", "geyer", "--plot", str(link)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(link) in err[0] and "No space left on device" in err[0], err
