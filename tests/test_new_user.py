"""What a new user hit (tracker issue 9, first part), each as the user met it: the command line's
plot path, read-only installs (numba's cache, `generate` outside a checkout), the comparison's one
rule for physical failures and its exit status, the touchdown leg length, flags named as typed, the
step defaults that scale with the leg, plain numbers in messages, strings refused as numbers,
`python -m slipmaps` / `--version` / help texts, the README's import paths and where `slipmaps
accuracy` writes.

Then tracker issue 16 (the command line at first contact): every path a command writes checked
first, a quantity given twice and a 10^11-point grid in a sweep, a closed pipe, a fixed-point
search whose every step fails, the eigenvalue and the Floquet multipliers told apart, messages and
the example sweep file, and maps without a trajectory (the README's examples: test_readme.py)."""

from __future__ import annotations

import importlib.util
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tracemalloc
from pathlib import Path

import documents
import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.api.params import HUMAN_RUNNER, ROBOT_HOPPER
from slipmaps.runtime.cli import compare as compare_module
from slipmaps.runtime.cli.app import build_parser, main
from slipmaps.runtime.cli.defaults import default_apex
from slipmaps.runtime.studies import checkout

P = HUMAN_RUNNER
ROOT = Path(__file__).resolve().parent.parent
#: The width of every line of the comparison table (header, rule and rows).
TABLE_WIDTH = 89


def _one_line_error(capsys, needle: str) -> str:
    err = capsys.readouterr().err
    assert err.startswith("slipmaps ") and ": error: " in err, err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert needle in err, err
    return err


def _table(out: str) -> list[str]:
    """The header, rule and rows of the comparison table in ``out``."""
    lines = out.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("quantity"))
    end = next((i for i in range(start, len(lines)) if not lines[i].strip()), len(lines))
    return lines[start:end]


def _refuse_work(monkeypatch):
    """Make any computation fail the test: the checks must come first."""

    def no_work(*args, **kwargs):
        raise AssertionError("computed before refusing the arguments")

    monkeypatch.setattr(compare_module, "compare", no_work)


# --- `compare --plot` into a directory that is not there -----------------------------------------


def test_plot_into_a_missing_directory_creates_it(tmp_path, capsys):
    png = tmp_path / "new" / "dir" / "x.png"
    assert main(["compare", "--against", "geyer", "--plot", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"plot: {png}" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("where", "needle"),
    [
        ("file/x.png", "cannot create the directory"),  # its parent is a file
        ("x.txt", "give an image file name"),
        (".", "is a directory"),
    ],
)
def test_plot_path_that_cannot_be_written_is_refused_before_computing(
    where, needle, tmp_path, monkeypatch, capsys
):
    (tmp_path / "file").write_text("not a directory")
    _refuse_work(monkeypatch)
    assert main(["compare", "--plot", str(tmp_path / where)]) == 2
    _one_line_error(capsys, needle)


# --- read-only installs ------------------------------------------------------------------------


def test_generate_outside_a_checkout_is_one_line(tmp_path, monkeypatch, capsys):
    """A non-editable install has no pyproject.toml above the package: the message alone, exit 2."""
    from slipmaps.derive import generate

    monkeypatch.setattr(generate, "ROOT", tmp_path)
    assert main(["generate", "--check"]) == 2
    _one_line_error(capsys, "works on a source checkout (pip install -e '.[derive]')")


def _installed_copy(dest: Path) -> Path:
    """The layout of a non-editable install (``pip install .``): site/slipmaps/{__init__, __main__,
    derive, generated, runtime}, copied without caches."""
    site = dest / "site"
    pkg = site / "slipmaps"
    pkg.mkdir(parents=True)
    public = Path(slipmaps.__file__).resolve().parent
    for name in ("__init__.py", "__main__.py"):
        shutil.copy2(public / name, pkg / name)
    for sub in ("derive", "generated", "runtime"):
        src = Path(importlib.util.find_spec(f"slipmaps.{sub}").submodule_search_locations[0]).resolve()
        shutil.copytree(src, pkg / sub, ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    return site


def _read_only_runner(ro: Path):
    """A function running argv with ``ro`` read-only: chmod for a normal user; for root (whom
    permissions do not stop) a read-only bind mount in a private mount namespace."""
    if os.geteuid() != 0:
        for path in [ro, *ro.rglob("*")]:
            path.chmod(0o555 if path.is_dir() else 0o444)
        return lambda argv, env: subprocess.run(argv, env=env, capture_output=True, text=True, timeout=300)
    if shutil.which("unshare") is None:
        pytest.skip("running as root without unshare: cannot make a directory read-only")
    mount = 'mount --bind "$1" "$1" && mount -o remount,bind,ro "$1" && shift && exec "$@"'
    probe = subprocess.run(["unshare", "-m", "sh", "-c", mount, "sh", str(ro), "true"], capture_output=True)
    if probe.returncode != 0:
        pytest.skip(f"running as root and cannot bind-mount read-only: {probe.stderr.decode()[-200:]}")
    return lambda argv, env: subprocess.run(
        ["unshare", "-m", "sh", "-c", mount, "sh", str(ro), *argv],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_read_only_install_without_a_writable_home(tmp_path):
    """`pip install .` into a read-only place, HOME read-only, NUMBA_CACHE_DIR unset: slipmaps caches
    its kernels in a private temp directory with one warning (also when numba was imported first),
    nothing inside the install, and `generate --check` is a one-line error. Measured: about 4 s, most
    of it compiling Geyer's stance once."""
    ro = tmp_path / "ro"
    site = _installed_copy(ro)
    home = ro / "home"
    home.mkdir()
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    run = _read_only_runner(ro)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "XDG_"))}
    env.update(PYTHONPATH=str(site), HOME=str(home), TMPDIR=str(scratch), PYTHONDONTWRITEBYTECODE="1")
    code = (
        "import {first}, os, slipmaps\n"
        "r = slipmaps.stance('geyer', slipmaps.HUMAN_RUNNER, (1.0, -1.5, 0.35, -4.5))\n"
        "from slipmaps.generated import geyer\n"
        "from slipmaps import kernel_cache\n"
        "print(r.status.name, slipmaps.__file__, kernel_cache.cache_root(),\n"
        "      geyer.geyer_stance._cache._cache_path)\n"
    )
    try:
        for first in ("sys", "numba"):  # numba imported before slipmaps: the locator still applies
            done = run([sys.executable, "-c", code.format(first=first)], env)
            assert done.returncode == 0, done.stderr[-3000:]
            status, init, cache, kernel_dir = done.stdout.split()
            assert status == "OK" and init == str(site / "slipmaps" / "__init__.py")
            assert Path(cache).parent == scratch, cache  # HOME is read-only: the private temp dir
            assert Path(kernel_dir).parent == Path(cache), kernel_dir
            assert done.stderr.count("RuntimeWarning") == 1 and "NUMBA_CACHE_DIR" in done.stderr
            assert list(Path(cache).rglob("geyer.geyer_stance-*.nbi")), "numba did not cache there"
            assert not list(site.rglob("*.nbi")), "numba cached inside the install"
        done = run([sys.executable, "-m", "slipmaps", "generate", "--check"], env)
        assert done.returncode == 2
        assert "Traceback" not in done.stderr and "works on a source checkout" in done.stderr
        assert done.stderr.strip().splitlines()[-1].startswith("slipmaps generate: error: ")
    finally:
        for path in [ro, *ro.rglob("*")]:
            if not path.is_symlink():
                path.chmod(0o755 if path.is_dir() else 0o644)


def test_kernels_are_cached_outside_the_package_reinstall_cannot_be_shadowed(tmp_path):
    """Issue 16's root cause: numba wrote its cache into the installed package, and the files left by
    `pip uninstall` shadowed the next (editable) install. Every compiled kernel of slipmaps, generated
    (the exact simulator's included) or hand-written, is cached under $XDG_CACHE_HOME/slipmaps/numba
    (or NUMBA_CACHE_DIR when set), in a folder per source directory; other numba code keeps numba's
    own default. Geyer's map compiles in seconds; the exact simulator's modules are generated modules
    too (.ci/run checks after the README's main job, which runs it, that nothing was cached inside the
    installed package)."""
    site = _installed_copy(tmp_path / "install")
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "other.py").write_text(
        "from numba import njit\n\n@njit(cache=True)\ndef f(x):\n    return x + 1.0\n"
    )
    code = (
        "import slipmaps, other\n"
        "from slipmaps.generated import geyer\n"
        "from slipmaps import kernel_cache\n"
        "assert slipmaps.apex_return('geyer', slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35).ok\n"
        "assert other.f(1.0) == 2.0\n"
        "print(kernel_cache.cache_root(), geyer.geyer_stance._cache._cache_path,\n"
        "      other.f._cache._cache_path)\n"
    )
    base = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "XDG_"))}
    base.update(PYTHONPATH=f"{site}{os.pathsep}{foreign}", PYTHONDONTWRITEBYTECODE="1")
    xdg = tmp_path / "xdg"
    done = subprocess.run(
        [sys.executable, "-c", code], env={**base, "XDG_CACHE_HOME": str(xdg)}, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr[-3000:]
    root, kernel_dir, other_dir = done.stdout.split()
    assert Path(root) == xdg / "slipmaps" / "numba" and Path(kernel_dir).parent == Path(root)
    assert Path(other_dir) == foreign / "__pycache__", other_dir  # numba's default for other code
    cached = {p.parent.name.split("_")[0] for p in Path(root).rglob("*.nbi")}
    assert cached == {"generated"}, cached
    assert not list(site.rglob("*.nbi")) and not list(site.rglob("*.nbc")), "numba cached inside the install"
    # NUMBA_CACHE_DIR, numba's own setting, still wins
    mine = tmp_path / "mine"
    done = subprocess.run(
        [sys.executable, "-c", code],
        env={**base, "NUMBA_CACHE_DIR": str(mine)},
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    root, kernel_dir, other_dir = done.stdout.split()
    assert root == "None" and Path(kernel_dir).parent == mine and Path(other_dir).parent == mine


def test_a_kernel_calling_other_files_is_cached_under_the_digest_of_the_kernel_sources(tmp_path):
    """numba checks only a cached kernel's own file, but the kernel holds the compiled code of what it
    calls: the deadbeat solver's cached solve (runtime/control/compiled.py) holds the generated
    kernels it calls. A kernel outside the generated modules (whose headers hash the generated
    modules they import) is cached in a folder named after the digest of every kernel source's
    content, which any edit of one changes."""
    from slipmaps import kernel_cache
    from slipmaps.runtime.control import compiled

    sources = kernel_cache.kernel_sources()
    names = {Path(p).name for p in sources}
    assert {"compiled.py", "exact_stance.py", "dop853.py", "flight.py", "geyer.py"} <= names, names
    files = [tmp_path / "a.py", tmp_path / "b.py"]
    for f, text in zip(files, ("x = 1\n", "y = 2\n"), strict=True):
        f.write_text(text)
    digest = kernel_cache.sources_digest.__wrapped__
    before = digest(tuple(map(str, files)))
    files[1].write_text("y = 3\n")
    assert digest(tuple(map(str, files))) != before
    if kernel_cache.cache_root() is not None:  # (NUMBA_CACHE_DIR set: numba's own folders)
        from slipmaps.generated import geyer

        assert compiled.solve_rows._cache._cache_path.endswith("-" + kernel_cache.sources_digest())
        assert kernel_cache.sources_digest() not in geyer.geyer_stance._cache._cache_path


# --- compare: one rule for physical failures, exit status ---------------------------------------


@pytest.mark.parametrize(
    ("argv", "failed"),
    [
        (["--angle", "0.2"], {"reference exact": "LIFTOFF_DOWNWARD", "map geyer": "LIFTOFF_DOWNWARD"}),
        (["--apex-speed", "100"], {"reference exact": "LIFTOFF_DOWNWARD", "map geyer": "LIFTOFF_DOWNWARD"}),
        (["--apex-height", "0.9"], {"reference exact": "APEX_TOO_LOW", "map geyer": "APEX_TOO_LOW"}),
        (["--angle", "1.4", "--map", "iterative-decompression"], {"reference exact": "FALL"}),
    ],
)
def test_compare_physical_failure_is_a_status_in_an_aligned_table(argv, failed, capsys):
    assert main(["compare", "--no-plot", *argv]) == 1
    out = capsys.readouterr().out
    table = _table(out)
    assert {len(line) for line in table} == {TABLE_WIDTH}, table  # n/a cells keep the columns
    assert any(line.rstrip().endswith("n/a") for line in table)
    assert "mn/a" not in out and "an/a" not in out
    below = out.split("\n\n")[-1].splitlines()  # under the table: each failed side
    for side, status in failed.items():
        line = next(line for line in below if line.startswith(f"{side}: "))
        assert line.startswith(f"{side}: {status}: ")


def test_apex_below_the_touchdown_height_says_so_once_with_rounded_numbers(capsys):
    assert main(["compare", "--no-plot", "--apex-height", "0.9"]) == 1
    out = capsys.readouterr().out
    line = next(line for line in out.splitlines() if line.startswith("reference exact: "))
    # touchdown height cos(0.35) = 0.9393727128473789 m, shown to 6 digits
    assert line.endswith("(apex height 0.9 m, touchdown height 0.939373 m)"), line
    assert line.count("no touchdown") == 1 and "0.9393727" not in line
    assert "touchdown: none" in out


def test_compare_json_exit_status_and_statuses(capsys):
    assert main(["compare", "--no-plot", "--json", "--apex-height", "0.9"]) == 1
    data = json.loads(capsys.readouterr().out)  # valid JSON: no NaN in it
    assert data["ok"] is False and data["map_status"] == data["against_status"] == "APEX_TOO_LOW"
    assert all(r["value"] is None and r["reference"] is None for r in data["rows"])
    assert data["touchdown"] == {"q_r": None, "q_rd": None, "q_th": None, "q_thd": None}


def test_exit_status_is_documented():
    from slipmaps.runtime.cli import app as cli

    compare_help = build_parser()._subparsers._group_actions[0].choices["compare"].format_help()
    for text in (compare_help, (ROOT / "docs" / "getting_started.md").read_text(), cli.__doc__):
        flat = " ".join(text.split())
        for code in (
            r"0 (when )?both sides ran",
            r"1 (when )?a side failed physically",
            r"2 (for )?a user error",
        ):
            assert re.search(code, flat), (code, flat[:200])


# --- the touchdown leg length of a touchdown state ------------------------------------------------


def test_touchdown_state_sets_the_touchdown_leg_length(capsys):
    argv = ["compare", "--no-plot", "--touchdown", "0.5", "-2", "0.3", "-4"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "q_r_td=0.5 m (the touchdown state's q_r)" in out.splitlines()[0]
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["params"]["q_r_td"] == 0.5 and data["touchdown_given"] is True
    c = compare_module.compare(P, touchdown=(0.5, -2.0, 0.3, -4.0), against="geyer")
    assert c.params.q_r_td == 0.5


def test_touchdown_state_contradicting_q_r_td_is_refused(capsys):
    argv = ["compare", "--no-plot", "--touchdown", "0.5", "-2", "0.3", "-4", "--q-r-td", "0.9"]
    assert main(argv) == 2
    _one_line_error(capsys, "--q-r-td 0.9 contradicts --touchdown, whose q_r 0.5 is the touchdown leg length")


# --- stiffness flags named as typed ---------------------------------------------------------------


def test_one_stiffness_flag_alone_says_k_c_differs_from_k_d(capsys):
    assert main(["compare", "--no-plot", "--against", "geyer-vs", "--k-c", "15000"]) == 0
    err = capsys.readouterr().err
    assert err.startswith("slipmaps compare: note: only --k-c given: k_d keeps its default 20000 N/m")
    assert main(["compare", "--no-plot", "--against", "geyer-vs", "--k-c", "15000", "--k-d", "20000"]) == 0
    assert capsys.readouterr().err == ""  # both given: nothing to say


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["--k", "-5"], "--k must be finite and positive, got -5.0"),
        (["--k-c", "-5"], "--k-c must be finite and positive, got -5.0"),
        (["--k-d", "0"], "--k-d must be finite and positive, got 0.0"),
        (["--k", "1", "--k-c", "2"], "give either --k or --k-c/--k-d"),
        (["--q-r-td", "1.2"], "--q-r-td must not exceed the rest length l0=1.0, got 1.2"),
        (["--apex-speed", "nan"], "--apex-speed must be finite, got nan"),
        (["--touchdown", "1.2", "-1", "0.3", "-4"], "--touchdown q_r must lie in (0, l0=1.0], got 1.2"),
    ],
)
def test_bad_values_name_the_flag_typed(argv, needle, monkeypatch, capsys):
    _refuse_work(monkeypatch)
    assert main(["compare", "--no-plot", *argv]) == 2
    err = _one_line_error(capsys, needle)
    assert "SlipParams" not in err


def test_slip_params_name_k_when_k_set_both():
    with pytest.raises(ValueError, match=r"^SlipParams\.k must be finite and positive, got -5\.0$"):
        slipmaps.SlipParams(k=-5)


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: slipmaps.SlipParams(mass=3), "SlipParams: got an unexpected keyword argument 'mass'"),
        (lambda: slipmaps.SlipParams(80, 1, 2e4, 4), "SlipParams: too many positional arguments"),
        (lambda: slipmaps.HUMAN_RUNNER.with_(mass=3), "SlipParams has no field(s) mass"),
    ],
)
def test_an_unknown_slip_params_argument_names_slip_params_and_its_arguments(call, needle):
    """`SlipParams(mass=3)` said only "got an unexpected keyword argument 'mass'"."""
    with pytest.raises(TypeError) as err:
        call()
    message = str(err.value)
    assert message.startswith(needle) and "\n" not in message, message
    assert message.endswith("; its arguments: m, l0, k, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c"), message


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["--speed", "nan"], "--speed must be finite, got nan"),
        (["--speed", "5", "inf"], "--speed must be finite, got inf"),
        (["--apex-height", "-1"], "--apex-height must not be negative, got -1.0"),
        (["--energy", "0", "--speed", "5"], "--energy must be positive, got 0.0"),
        (["--energy-speed", "nan", "--angle", "0.4"], "--energy-speed must be finite, got nan"),
        (["--energy", "900", "--angle", "2"], "--angle must lie in (-pi/2, pi/2) (the leg above the ground)"),
    ],
)
def test_gait_names_the_flag_of_a_bad_number(argv, needle, nothing_runs, capsys):
    """`slipmaps gait --speed nan` said "speed must be finite": the flag is --speed."""
    assert main(["gait", *argv]) == 2
    _one_line_error(capsys, f"slipmaps gait: error: {needle}")


def test_gait_has_no_figure_like_run(tmp_path, capsys):
    """`--no-figure`, as `run`'s: no figure, whatever --figure says (before: an unknown flag)."""
    figure = tmp_path / "region.png"
    argv = ["gait", "--no-exact", "--map", "geyer", "--speed", "5", "--no-progress", "--figure", str(figure)]
    assert main([*argv, "--no-figure"]) == 0
    out = capsys.readouterr().out
    assert "wrote" not in out and not figure.exists()
    assert "geyer" in out and "fixed point" not in out.split("\n")[2]  # the row found the gait


# --- defaults that scale with the leg -------------------------------------------------------------


def test_default_step_scales_with_the_leg():
    assert default_apex(HUMAN_RUNNER) == {"apex_height": 1.0, "apex_speed": 5.0, "touchdown_angle": 0.35}
    robot = default_apex(ROBOT_HOPPER)
    assert robot["apex_height"] == 0.25 and robot["apex_speed"] == pytest.approx(2.5, rel=1e-15)
    # kappa 12.74 against the human's 25.48: 0.35 sqrt(2) = 0.495 rad
    assert robot["touchdown_angle"] == pytest.approx(0.35 * math.sqrt(2.0), rel=1e-12)


def test_robot_parameters_run_with_the_default_step(capsys):
    """The issue's case: `--m 3 --l0 0.25 --k 1500` failed with the human's 1.0 m, 5 m/s. With the
    scaled step both sides run (measured: next apex 0.204 m, 2.67 m/s; Geyer within 3.3 %)."""
    assert main(["compare", "--no-plot", "--json", "--m", "3", "--l0", "0.25", "--k", "1500"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["ok"] and data["map_status"] == data["against_status"] == "OK"
    speed = next(r for r in data["rows"] if r["quantity"] == "next apex speed")
    assert abs(speed["rel_error"]) < 0.05


def test_relative_and_absolute_apex_flags_agree(capsys):
    rel = ["--apex-height-l0", "1.1", "--froude", "1.2"]
    absolute = ["--apex-height", str(1.1 * 0.25), "--apex-speed", str(1.2 * math.sqrt(9.81 * 0.25))]
    rows = []
    for flags in (rel, absolute):
        argv = [
            "compare",
            "--no-plot",
            "--json",
            "--against",
            "geyer",
            "--l0",
            "0.25",
            "--m",
            "3",
            "--k",
            "1500",
        ]
        assert main([*argv, *flags]) == 0
        rows.append(json.loads(capsys.readouterr().out)["touchdown"])
    assert rows[0] == pytest.approx(rows[1], rel=1e-14)
    with pytest.raises(SystemExit) as exc:
        build_parser().parse_args(["compare", "--apex-height", "1", "--apex-height-l0", "1"])
    assert exc.value.code == 2


def test_help_shows_the_scaled_defaults_and_which_flags_are_absolute():
    text = " ".join(build_parser()._subparsers._group_actions[0].choices["compare"].format_help().split())
    for needle in ("--apex-height-l0", "units of l0 (default 1.0", "--froude", "(default 1.596", "absolute"):
        assert needle in text
    assert "0.495 rad for the robot hopper" in text


# --- plain numbers and names in messages, strings are not numbers -----------------------------------


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (
            lambda: slipmaps.apex_return("geyer", P, np.float64("nan"), 5.0, 0.35),
            "apex_height must be finite, got nan",
        ),
        (
            lambda: slipmaps.apex_return("geyer", P, np.float64(-1), 5.0, 0.35),
            "apex_height must not be negative, got -1.0",
        ),
        (
            lambda: slipmaps.stance("geyer", P, np.array([1.0, np.nan, 0.3, -4])),
            "touchdown q_rd must be finite, got nan",
        ),
        (
            lambda: slipmaps.trajectory("geyer", P, (1, -1, 0.3, -4), t=[0.0, np.nan]),
            "t[1] must be finite, got nan",
        ),
        (lambda: slipmaps.SlipParams(m=np.float64(-1)), "SlipParams.m must be finite and positive, got -1.0"),
        (
            lambda: slipmaps.stance("gravity-type2", P, (1, -1, 0.3, -4), tol=np.float64("nan")),
            "'tol' must be finite, got nan",
        ),
    ],
)
def test_messages_show_plain_numbers_and_names(call, needle):
    with pytest.raises(ValueError) as exc:
        call()
    assert needle in str(exc.value) and "np." not in str(exc.value) and "float64" not in str(exc.value)


@pytest.mark.parametrize(
    "call",
    [
        lambda: slipmaps.apex_return("geyer", P, "1.0", 5.0, 0.35),
        lambda: slipmaps.apex_return("geyer", P, b"1.0", 5.0, 0.35),
        lambda: slipmaps.stance("geyer", P, ("1.0", -1.5, 0.35, -4.5)),
        lambda: slipmaps.stance_batch("geyer", P, np.array([["1.0", "-1.5", "0.35", "-4.5"]])),
        lambda: slipmaps.apex_return_batch("geyer", P, ["1.0"], 5.0, 0.35),
        lambda: slipmaps.trajectory("geyer", P, (1.0, -1.5, 0.35, -4.5), t=["0.01"]),
        lambda: slipmaps.SlipParams(g_s="9.81"),
        lambda: slipmaps.stance("gravity-type2", P, (1.0, -1.5, 0.35, -4.5), tol="1e-3"),
    ],
)
def test_strings_are_not_numbers(call):
    with pytest.raises(TypeError, match="must (be|hold) (a )?(real )?number"):
        call()


# --- python -m slipmaps, --version, help texts, README ------------------------------------------


def test_python_m_slipmaps_and_version():
    done = subprocess.run(
        [sys.executable, "-m", "slipmaps", "--version"], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    assert re.fullmatch(r"slipmaps \S+( \(not installed\))?\n", done.stdout)


def test_every_subcommand_has_a_description():
    subparsers = build_parser()._subparsers._group_actions[0].choices
    assert set(subparsers) >= {"maps", "compare", "generate", "equations", "accuracy"}
    for name, parser in subparsers.items():
        assert parser.description and len(parser.description) > 40, name


def test_readme_names_importable_modules_and_cites_the_report_by_title():
    """The README and the pages that took its sections (tests/documents.py) name importable modules
    only and no file of the report; the README cites the report by its title, the performance page
    (numba's cache, from the README) names NUMBA_CACHE_DIR."""
    text = "\n".join(documents.text(name) for name in documents.DOCUMENTS)
    assert "stance_maps" not in text
    for dotted in sorted(set(re.findall(r"(?<![\w/.])slipmaps(?:\.[A-Za-z_]\w*)+", text))):
        parts = dotted.split(".")
        module = next(
            ".".join(parts[:n])
            for n in range(len(parts), 0, -1)
            if importlib.util.find_spec(".".join(parts[:n]))
        )
        obj = importlib.import_module(module)
        for attr in parts[len(module.split(".")) :]:
            obj = getattr(obj, attr)  # AttributeError names what the README got wrong
    flat = " ".join(documents.text("README.md").split())
    assert "SLIP: Approximate Stance Map for Nonsymmetric Motions and Variable Stiffness" in flat
    assert not re.search(r"\S+\.(pdf|tex)\b", text), "the report is cited by its title, not a path"
    assert "NUMBA_CACHE_DIR" in documents.text("docs/performance.md")


# --- where `slipmaps accuracy` writes -------------------------------------------------------------


@pytest.fixture
def no_measuring(monkeypatch):
    """Record where `slipmaps accuracy` would write instead of measuring (about 40 s of CPU)."""
    from slipmaps.runtime.studies import runner

    calls = []
    monkeypatch.setattr(runner, "run", lambda out, names, show_progress=None: calls.append(out) or [])
    return calls


def test_accuracy_writes_into_the_checkouts_docs_from_any_directory(tmp_path, monkeypatch, no_measuring):
    assert checkout.docs_dir() == ROOT / "docs"
    monkeypatch.chdir(tmp_path)
    assert main(["accuracy"]) == 0
    assert no_measuring == [ROOT / "docs" / "accuracy.md"]
    assert not (tmp_path / "docs").exists()


def test_accuracy_outside_a_checkout_needs_out(tmp_path, monkeypatch, no_measuring, capsys):
    installed = tmp_path / "site-packages" / "slipmaps" / "runtime"
    installed.mkdir(parents=True)
    assert checkout.checkout_root(installed) is None
    monkeypatch.setattr(checkout, "docs_dir", lambda: None)
    monkeypatch.chdir(tmp_path)
    assert main(["accuracy"]) == 2
    _one_line_error(capsys, "give --out DIR")
    assert no_measuring == []
    assert main(["accuracy", "--out", "reports"]) == 0
    assert main(["accuracy", "--map", "geyer", "--out", "r/geyer.md"]) == 0
    assert no_measuring == [Path("reports") / "accuracy.md", Path("r/geyer.md")]


# --- tracker issue 16: first contact with the command line ------------------------------------------
#
# Each test is one item of the issue as the user met it. Paths are refused before any work (the
# work itself is replaced by a function that fails the test), so those tests cost nothing.


def _refuse(monkeypatch, module, name):
    def no_work(*args, **kwargs):
        raise AssertionError(f"{module.__name__}.{name} ran before refusing the arguments")

    monkeypatch.setattr(module, name, no_work)


@pytest.fixture
def nothing_runs(monkeypatch):
    """Every command's work fails the test: compare, sweep, the fixed points and the accuracy study."""
    from slipmaps.runtime.analysis import gait
    from slipmaps.runtime.studies import runner
    from slipmaps.runtime.sweep import run as sweep

    _refuse(monkeypatch, compare_module, "compare")
    _refuse(monkeypatch, sweep, "sweep")
    _refuse(monkeypatch, gait, "fixed_points")
    _refuse(monkeypatch, runner, "run")


SWEEP = ["sweep", "--map", "geyer", "--fixed", "apex_height=1", "--axis", "apex_speed=3:7:5"]
SWEEP += ["--axis", "touchdown_angle=0.3"]


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        ([*SWEEP, "--out", "{file}"], "--out {file} is a file, not a directory"),
        (
            [*SWEEP, "--out", "{file}/sub"],
            "--out {file}/sub: cannot create the directory {file}/sub: {file} is",
        ),
        (["accuracy", "--out", "{file}"], "--out {file} is a file, not a directory"),
        (["accuracy", "--map", "geyer", "--out", "{file}/g.md"], "--out {file}/g.md: cannot create the dir"),
        (["gait", "--figure", "{file}/x.png"], "--figure {file}/x.png: cannot create the directory {file}: "),
        (
            ["gait", "--figure", "{dir}"],
            "--figure {dir} is a directory; give a file, e.g. {dir}/stability.png",
        ),
        (["gait", "--figure", "{dir}/x.txt"], "--figure {dir}/x.txt: give an image file name ending in .png"),
        (["compare", "--plot", "{file}/x.png"], "{file} is a file, not a directory"),
    ],
)
def test_every_written_path_is_checked_before_any_work(argv, needle, tmp_path, nothing_runs, capsys):
    """`sweep --out`, `accuracy --out`, `gait --figure` and `compare --plot`: one helper
    (runtime/api/paths.py) checks each before anything runs; one line naming the flag, exit 2."""
    file = tmp_path / "c.pdf"
    file.write_text("a file, not a directory")
    fill = {"file": str(file), "dir": str(tmp_path)}
    assert main([a.format(**fill) for a in argv]) == 2
    _one_line_error(capsys, needle.format(**fill))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.pdf"]  # nothing created beside it


def test_the_python_sweep_refuses_a_file_as_its_directory(tmp_path):
    (tmp_path / "f").write_text("x")
    sw = slipmaps.Sweep("geyer", {"apex_speed": [5.0]}, {"apex_height": 1.0, "touchdown_angle": 0.3})
    with pytest.raises(ValueError, match=r"^out .*f is a file, not a directory; give a directory$"):
        slipmaps.sweep(sw, tmp_path / "f")


@pytest.mark.parametrize(
    ("extra", "needle"),
    [
        (
            ["--axis", "apex_speed=3:4:2"],
            "--axis apex_speed given twice (apex_speed=3:7:5 and apex_speed=3:4:2): give each quantity once",
        ),
        (["--fixed", "apex_speed=3"], "apex_speed: given both --axis and --fixed"),
        (["--fixed", "apex_height=2"], "--fixed apex_height given twice (apex_height=1 and apex_height=2)"),
    ],
)
def test_a_quantity_given_twice_is_refused(extra, needle, tmp_path, nothing_runs, capsys):
    assert main([*SWEEP, *extra, "--out", str(tmp_path / "o")]) == 2
    _one_line_error(capsys, needle)


def test_a_quantity_twice_in_a_toml_file_or_in_python_is_refused(tmp_path, nothing_runs, capsys):
    listed = tmp_path / "listed.toml"
    listed.write_text(
        'map = "geyer"\nout = "o"\n'
        'axes = [{ name = "apex_speed", values = [3.0] }, { name = "apex_speed", values = [4.0] }]\n'
        "[fixed]\napex_height = 1.0\ntouchdown_angle = 0.3\n"
    )
    assert main(["sweep", str(listed)]) == 2
    _one_line_error(capsys, "axis 'apex_speed' given twice in axes")
    both = tmp_path / "both.toml"
    both.write_text(
        'map = "geyer"\nout = "o"\n[fixed]\napex_height = 1.0\napex_speed = 3.0\n'
        "[axes]\napex_speed = [3.0, 4.0]\ntouchdown_angle = [0.3]\n"
    )
    assert main(["sweep", str(both)]) == 2
    _one_line_error(capsys, "apex_speed: both fixed and swept")
    with pytest.raises(ValueError, match="both fixed and swept"):
        slipmaps.Sweep("geyer", {"apex_speed": [3.0]}, {"apex_speed": 3.0, "apex_height": 1.0})
    with pytest.raises(ValueError, match="given twice"):
        slipmaps.Sweep.from_dict(
            {"map": "geyer", "axes": [{"name": "k", "values": [1e4]}, {"name": "k", "values": [2e4]}]}
        )


def test_a_grid_of_1e11_points_is_planned_without_allocating_the_axis():
    """`--axis apex_speed=1:2:100000000000`: 3e11 rows. The definition, the chunk plan and a
    chunk's points are computed from row indices (the axis is never allocated: 745 GiB)."""
    n = 100_000_000_000
    tracemalloc.start()
    sw = slipmaps.Sweep(
        "geyer", {"apex_speed": f"1:2:{n}", "touchdown_angle": [0.3, 0.35, 0.4]}, {"apex_height": 1.0}
    )
    first = sw.points(*sw.chunk_bounds(0))
    last = sw.points(*sw.chunk_bounds(sw.chunks - 1))
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert sw.rows == 3 * n and sw.chunks == -(-3 * n // sw.chunk_rows)
    i = np.arange(sw.chunk_rows)
    step = np.float64(1.0) / (n - 1)
    assert np.array_equal(first["apex_speed"], (i // 3) * step + 1.0)  # numpy.linspace's arithmetic
    assert np.array_equal(first["touchdown_angle"], np.array([0.3, 0.35, 0.4])[i % 3])
    assert last["apex_speed"][-1] == 2.0 and last["touchdown_angle"][-1] == 0.4
    assert peak < 50e6, peak  # measured 2.1e7 (one chunk of 262144 rows, a few columns)


def test_a_grid_of_1e11_points_runs_from_the_command_line(tmp_path, capsys):
    """The whole command without computing a row (--max-chunks 0): refused without --yes (its
    size stated), then with it the output directory, its manifest and the summary, no per-row or
    per-chunk list up front."""
    argv = ["sweep", "--map", "geyer", "--fixed", "apex_height=1", "--axis", "apex_speed=1:2:100000000000"]
    argv += ["--axis", "touchdown_angle=0.3:0.4:3", "--out", str(tmp_path / "huge"), "--max-chunks", "0"]
    assert main([*argv, "--json"]) == 2
    assert "300,000,000,000 rows" in capsys.readouterr().err
    assert main([*argv, "--json", "--yes"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["rows"] == 300_000_000_000 and summary["rows_done"] == 0 and not summary["complete"]
    manifest = json.loads((tmp_path / "huge" / "manifest.json").read_text())
    assert manifest["rows"] == 300_000_000_000


def test_grid_points_equal_numpys_spacing_bit_for_bit():
    """Points computed from their indices equal numpy.linspace / geomspace (a resumed sweep's chunks
    match the ones written before)."""
    from slipmaps.runtime.sweep.axes import Axis

    for low, high, num in (
        (3.0, 7.0, 41),
        (0.25, 0.45, 21),
        (1e-3, 10.0, 1001),
        (2.0, 2.0, 1),
        (5.0, 5.0, 3),
    ):
        for scale, space in (("linear", np.linspace), ("log", np.geomspace)):
            axis = Axis.of("x", {"low": low, "high": high, "num": num, "scale": scale})
            assert np.array_equal(axis.grid_values(), space(low, high, num)), (low, high, num, scale)
            idx = np.array([num - 1, 0, num // 2])
            assert np.array_equal(axis.grid_at(idx), space(low, high, num)[idx])


def _closed_pipe_run(argv: list[str]) -> subprocess.CompletedProcess:
    """``python -m slipmaps ARGV`` writing into a pipe whose reader has already gone (`| head -1`
    after head has exited): every write fails with EPIPE."""
    read, write = os.pipe()
    os.close(read)
    try:
        return subprocess.run(
            [sys.executable, "-m", "slipmaps", *argv],
            stdout=write,
            stderr=subprocess.PIPE,
            text=True,
            timeout=300,
        )
    finally:
        os.close(write)


@pytest.mark.parametrize("argv", [["maps"], ["maps", "--json"], ["compare", "--help"]])
def test_a_reader_that_closes_early_ends_the_command_quietly(argv):
    """`slipmaps maps | head -1` printed a BrokenPipeError traceback."""
    from slipmaps.runtime.cli.app import BROKEN_PIPE

    done = _closed_pipe_run(argv)
    assert done.stderr == "", done.stderr
    assert done.returncode in ((0, BROKEN_PIPE) if "--help" in argv else (BROKEN_PIPE,))


class _ClosedPipe:
    """A standard output whose reader has gone: every write (and flush) raises BrokenPipeError."""

    def __init__(self, fd: int) -> None:
        self.fd = fd

    def write(self, text: str) -> int:
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self) -> None:
        raise BrokenPipeError(32, "Broken pipe")

    def fileno(self) -> int:
        return self.fd


@pytest.mark.parametrize(
    "argv",
    [
        ["maps"],
        ["compare", "--no-plot", "--against", "geyer"],
        ["gait", "--no-exact", "--map", "geyer", "--speed", "5", "--no-progress"],
        ["sweep", *SWEEP[1:], "--no-progress", "--out", "{tmp}/s"],
    ],
)
def test_every_verb_handles_a_closed_pipe(argv, tmp_path, monkeypatch):
    """Every verb's output goes through main's one handler: exit BROKEN_PIPE, nothing raised."""
    from slipmaps.runtime.cli.app import BROKEN_PIPE

    fd = os.open(os.devnull, os.O_WRONLY)
    try:
        monkeypatch.setattr(sys, "stdout", _ClosedPipe(fd))
        assert main([a.format(tmp=tmp_path) for a in argv]) == BROKEN_PIPE
    finally:
        os.close(fd)


def test_a_search_whose_every_step_fails_says_so(capsys):
    """`slipmaps gait --map gravity-type2 --option iterations=1` printed "no fixed point" on every
    line: every step of the scan is NOT_CONVERGED at the default tol. Now the row says so, the JSON
    has the status, message and the scan's status counts, and the exit status is 1."""
    argv = ["gait", "--no-exact", "--map", "gravity-type2", "--option", "iterations=1", "--speed", "5"]
    assert main([*argv, "--no-progress"]) == 1
    (row,) = [line for line in capsys.readouterr().out.splitlines() if line.startswith("h 1 m")]
    assert "no fixed point: every step of the scan failed (96 steps: NOT_CONVERGED" in row
    assert row.endswith("NOT_CONVERGED: " + slipmaps.MESSAGES[int(slipmaps.Status.NOT_CONVERGED)])
    assert main([*argv, "--no-progress", "--json"]) == 1
    (line,) = json.loads(capsys.readouterr().out)["lines"]
    assert line["status"] == "NOT_CONVERGED" and line["fixed_points"] == []
    assert line["message"].startswith("every step of the scan failed")
    assert sum(line["scan"].values()) == 96 and "OK" not in line["scan"]
    assert line["scan"]["NOT_CONVERGED"] > 48
    # with the tolerance off (the README's example), the same iteration runs and finds the gait
    assert main([*argv, "--option", "tol=0", "--no-progress", "--json"]) == 0
    (line,) = json.loads(capsys.readouterr().out)["lines"]
    assert line["status"] == "OK" and len(line["fixed_points"]) == 1


def test_gait_labels_the_eigenvalue_and_the_multipliers(capsys):
    """`gait --map geyer`: eigenvalue 0.856 beside multipliers (1, 0.788). The table says which is
    which, and notes the maps whose step does not conserve the energy (the exact one does)."""
    from slipmaps.runtime.analysis.gait import DEFINITIONS

    assert main(["gait", "--map", "geyer", "--speed", "5", "--no-progress"]) == 0
    out = capsys.readouterr().out
    flat = " ".join(out.split())
    head = out.splitlines()[0]
    assert "lambda 1-D" in head and "multipliers 2x2" in head and "eigenvalue" not in head
    assert "lambda 1-D: " + " ".join(DEFINITIONS["eigenvalue"].split()) in flat
    assert "multipliers 2x2: " + " ".join(DEFINITIONS["multipliers"].split()) in flat
    assert "note: geyer's step does not conserve the flight energy" in flat
    assert "note: exact" not in flat
    assert main(["gait", "--map", "geyer", "--speed", "5", "--no-progress", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["definitions"] == DEFINITIONS
    geyer = next(line for line in data["lines"] if line["map"] == "geyer")
    (p,) = geyer["fixed_points"]
    assert abs(p["multipliers"][0][0] - 1.0) < 1e-12 and abs(p["multipliers"][1][0] - p["eigenvalue"]) > 0.05
    assert p["energy_gradient_error"] > 0.05


def test_equations_json_help_says_it_prints_one_array():
    eq = build_parser()._subparsers._group_actions[0].choices["equations"].format_help()
    assert "one JSON array" in " ".join(eq.split()) and "JSON object per equation" not in eq


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (
            ["compare", "--no-plot", "--map", "gravity-type2", "--option", "iterations=2.5"],
            "option 'iterations' must be a whole number, got '2.5'",
        ),
        (
            ["compare", "--no-plot", "--map", "gravity-type2", "--option", "tol=x"],
            "option 'tol' must be a number, got 'x'",
        ),
        (
            ["sweep", "--map", "geyer", "--axis", "apex_sped=3:4:2", "--out", "o"],
            "unknown sweep quantity 'apex_sped'; a sweep of kind 'apex_return' varies or fixes: apex_height",
        ),
        (
            ["sweep", "--map", "geyer", "--axis", "apex_speed=3:4:2", "--out", "o"],
            "a sweep of kind 'apex_return' needs apex_height, touchdown_angle",
        ),
    ],
)
def test_messages_read_as_english(argv, needle, nothing_runs, capsys):
    """ "must be a int" and "a apex_return sweep" are gone."""
    assert main(argv) == 2
    err = _one_line_error(capsys, needle)
    assert "a int" not in err and "a float" not in err and "a apex_return" not in err


def test_a_toml_files_unknown_key_lists_every_accepted_key(tmp_path, nothing_runs, capsys):
    """The message named only the definition's keys; out, format, scheduler and combine (in the
    README) were missing. It lists slipmaps.runtime.sweep.run.KEYS, the keys split_keys accepts."""
    from slipmaps.runtime.sweep import axes as sweep_axes
    from slipmaps.runtime.sweep.run import KEYS, load

    path = tmp_path / "s.toml"
    path.write_text('map = "geyer"\noutput = "o"\n')
    assert main(["sweep", str(path)]) == 2
    err = _one_line_error(capsys, f"{path}: unknown key(s) output; the keys are {', '.join(KEYS)}")
    assert all(key in err for key in ("out", "format", "scheduler", "combine", "axes", "fixed"))
    with pytest.raises(ValueError, match="the keys are " + ", ".join(KEYS)):
        load(path)
    path.write_text('map = "geyer"\n[fixed]\napex_height = 1.0\ntouchdown_angle = 0.3\n')
    path.write_text(path.read_text() + "[axes]\napex_speed = { low = 3, high = 7, count = 5 }\n")
    assert main(["sweep", str(path), "--out", str(tmp_path / "o")]) == 2
    _one_line_error(capsys, "unknown key(s) count; the keys are " + ", ".join(sweep_axes.AXIS_KEYS))
    assert "values" in sweep_axes.AXIS_KEYS


def test_the_region_figure_cites_the_paper_it_reproduces():
    """The figure cited Seyfarth et al. 2003, the README 2002 (the text is now docs/control_planning.md's):
    the self-stable region is the 2002 J Biomech paper's; the two marked reference points come from the
    2003 paper's captions, named so."""
    from slipmaps.runtime.studies import stability_report

    title = " ".join(stability_report.REGION_TITLE.split())
    assert "Seyfarth et al. 2002" in title and "A movement criterion for running" in title
    assert "2003" not in title
    marks = stability_report.REGION_MARKS
    assert "2003" in marks and "Swing-leg retraction" in marks and "J Exp Biol" in marks
    readme = " ".join((ROOT / "docs" / "control_planning.md").read_text().split())
    assert re.findall(r"Seyfarth et al\.,? (\d{4})", readme) and set(
        re.findall(r"Seyfarth et al\.,? (\d{4})", readme)
    ) == {"2002"}
    assert "A movement criterion for running" in readme


def test_the_example_sweep_file_writes_relative_to_the_current_directory(tmp_path, monkeypatch, capsys):
    """examples/sweep.toml wrote into the checkout and needed pyarrow without saying so: its
    comment says what Parquet needs, its out is relative to the directory it runs from."""
    example = ROOT / "examples" / "sweep.toml"
    text = example.read_text()
    header = text.split("\n\n")[0]
    assert "pip install 'slipmaps[parquet]'" in header and "--format csv" in header
    assert "relative to the directory you run" in " ".join(header.replace("#", " ").split())
    in_checkout = (ROOT / "sweep_type5").exists()
    monkeypatch.chdir(tmp_path)
    monkeypatch.setitem(sys.modules, "pyarrow", None)  # as without the parquet extra
    assert main(["sweep", str(example), "--no-progress"]) == 2
    _one_line_error(capsys, "need pyarrow: pip install 'slipmaps[parquet]'")
    assert main(["sweep", str(example), "--format", "csv", "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert "sweep of gravity-type5: 9963 of 9963 rows (complete)" in out
    assert (tmp_path / "sweep_type5" / "sweep.csv").is_file()
    assert (ROOT / "sweep_type5").exists() == in_checkout  # nothing written into the checkout


def test_a_map_without_a_trajectory_says_so_and_names_the_maps_with_one():
    """`slipmaps.trajectory("iterative")` raised "has no trajectory (only event states)"."""
    with pytest.raises(ValueError) as exc:
        slipmaps.trajectory("iterative", P, (1.0, -1.5, 0.35, -4.5))
    text = str(exc.value)
    assert "\n" not in text and text.startswith("map 'iterative' has no trajectory")
    having = [m.name for m in slipmaps.maps() if m.has_trajectory]
    assert "geyer" in having and "exact" in having and "iterative" not in having
    assert text.endswith("maps with a trajectory: " + ", ".join(having))


def _figure_of(monkeypatch, argv, capsys):
    """The matplotlib figure `slipmaps compare ... --plot` draws (captured instead of written)."""
    import matplotlib.figure

    drawn = []
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", lambda fig, *a, **k: drawn.append(fig))
    assert main(argv) == 0
    capsys.readouterr()
    (fig,) = drawn
    return fig


@pytest.mark.parametrize(
    ("argv", "label", "events"),
    [
        (["--map", "iterative"], "iterative: event states only (no trajectory)", 3),
        (
            ["--map", "iterative-decompression", "--k-c", "20000", "--k-d", "25000"],
            "iterative-decompression: bottom and liftoff states only (no trajectory)",
            2,
        ),
    ],
)
def test_a_map_without_a_trajectory_is_plotted_as_its_event_states(argv, label, events, monkeypatch, capsys):
    """`compare --map iterative --plot`: dotted lines joined the three event states like a real
    V-shaped trajectory. Now: markers only, no line, labelled; the exact stance drawn beside them
    (for the decompression half too, from the touchdown, not from the half's bottom state)."""
    fig = _figure_of(monkeypatch, ["compare", *argv, "--plot", "x.png"], capsys)
    for ax in fig.axes:
        marks = [line for line in ax.get_lines() if line.get_label() == label]
        (mark,) = marks
        assert mark.get_linestyle() == "None" and mark.get_marker() == "o" and len(mark.get_xdata()) == events
        exact = [line for line in ax.get_lines() if line.get_label().startswith("exact")]
        assert exact and len(exact[0].get_xdata()) > 50 and exact[0].get_xdata()[0] == 0.0
        assert label in [t.get_text() for t in ax.get_legend().get_texts()]
        names = {t.get_text() for t in ax.texts}
        assert names == ({"touchdown", "bottom", "liftoff"} if events == 3 else {"bottom", "liftoff"})
