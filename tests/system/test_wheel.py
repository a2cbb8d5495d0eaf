"""scripts/wheel.sh: one command builds a binary wheel that installs into a fresh virtual environment
and runs the main job there on a machine without a compiler, which this test makes by leaving only the fresh
environment's bin directory on PATH (no cc, gcc, clang, cmake or ninja reachable; CC and CXX unset).

It builds the wheel in build/wheel, where scripts/test.sh has just installed these very sources: seconds, not a
rebuild. pip fetches the wheel's dependencies (pymunk and what it needs) from the package index or its cache."""

from __future__ import annotations

import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time
from typing import Optional

import pytest

from support import ROOT

pytestmark = pytest.mark.slow  # a wheel built and installed into a fresh venv: minutes

COMPILERS = ("cc", "c++", "gcc", "g++", "clang", "clang++", "cmake", "ninja")
# What must not reach the fresh environment: a compiler named by variable, the checkout or .venv on the
# import path, the virtual environment the tests run in.
DROPPED = ("CC", "CXX", "CPP", "LD", "CFLAGS", "CXXFLAGS", "CPPFLAGS", "LDFLAGS", "CMAKE_GENERATOR",
           "CMAKE_MAKE_PROGRAM", "PYTHONPATH", "PYTHONHOME", "PYTHONSTARTUP", "VIRTUAL_ENV")


def run(argv: list[str], *, cwd: pathlib.Path, timeout: float, env: Optional[dict[str, str]] = None) -> str:
    """argv's stdout; the test fails when it exits non-zero or outlives `timeout` seconds (then it is killed
    with its whole process group: the compilers of a build, the Robot Federate of the job)."""
    with subprocess.Popen(argv, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, start_new_session=True) as proc:
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, err = proc.communicate()
            pytest.fail(f"{argv} did not end within {timeout} s\nstdout:\n{out[-3000:]}\nstderr:\n{err[-3000:]}")
    assert proc.returncode == 0, f"{argv} exited with {proc.returncode}\nstdout:\n{out[-3000:]}\nstderr:\n{err[-3000:]}"
    return out


def compiler_free_env(bin_dir: pathlib.Path) -> dict[str, str]:
    """This environment with PATH = bin_dir alone and no compiler variables (HOME and pip's settings stay)."""
    env = {name: value for name, value in os.environ.items() if name not in DROPPED}
    env.update(PATH=str(bin_dir), PYTHONNOUSERSITE="1", PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_INPUT="1")
    return env


def assert_no_compiler(env: dict[str, str]) -> None:
    reachable = {name: shutil.which(name, path=env["PATH"]) for name in COMPILERS}
    assert not any(reachable.values()), f"a compiler is reachable on PATH={env['PATH']}: {reachable}"


@pytest.mark.timeout(1800)  # a wheel after an edit of the C++ core rebuilds it (minutes on 2 cores)
def test_wheel_installs_and_runs_the_main_job_without_a_compiler(tmp_path: pathlib.Path) -> None:
    assert not tmp_path.resolve().is_relative_to(ROOT)  # nothing found through the working directory
    started = time.monotonic()
    lap = {"start": started}

    # The one command; its last line is the wheel's path.
    wheel = pathlib.Path(run(["bash", str(ROOT / "scripts" / "wheel.sh"), str(tmp_path / "dist")], cwd=tmp_path,
                             timeout=1500).splitlines()[-1])
    assert wheel.parent == tmp_path / "dist" and wheel.name.startswith("hlacore-") and wheel.suffix == ".whl"
    lap["wheel"] = time.monotonic()

    # A fresh virtual environment (no system site packages) of this CPython, the wheel's. Without a pip of its
    # own: this pip installs into it (pip --python), which spares the 5 s of ensurepip.
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--without-pip", str(venv)], cwd=tmp_path, timeout=120)
    bin_dir = venv / "bin"
    python = str(bin_dir / "python")
    env = compiler_free_env(bin_dir)
    assert_no_compiler(env)
    lap["venv"] = time.monotonic()

    # Binary wheels only: an sdist would need the compiler this machine does not have.
    run([sys.executable, "-m", "pip", "--python", python, "install", "--quiet", "--only-binary", ":all:",
         str(wheel)], cwd=tmp_path, env=env, timeout=300)
    assert_no_compiler(env)  # nor did the install bring one (cmake and ninja come as wheels)
    lap["install"] = time.monotonic()

    files = json.loads(run([python, "-c", "import json, sys, hlacore, hlacore._core; print(json.dumps("
                                          "[hlacore.__file__, hlacore._core.__file__, sys.prefix]))"],
                           cwd=tmp_path, env=env, timeout=60))
    for file in files:
        assert pathlib.Path(file).resolve().is_relative_to(venv.resolve()), files
        assert not pathlib.Path(file).resolve().is_relative_to(ROOT), files  # neither python/ nor .venv
    rtig = shutil.which("rtig", path=env["PATH"])
    assert rtig == str(bin_dir / "rtig")
    assert "usage: rtig" in run([rtig, "--help"], cwd=tmp_path, env=env, timeout=30)
    rtia = run([python, "-m", "hlacore.config", "--rtia"], cwd=tmp_path, env=env, timeout=30).strip()
    assert rtia == str(bin_dir / "hlacore-rtia")  # beside rtig, for CERTI_RTIA (docs/certi.md)
    assert "usage: hlacore-rtia" in run([rtia, "--help"], cwd=tmp_path, env=env, timeout=30)

    # The main job, on 5 of the path's 15 control cycles: its verdict and its outputs.
    out = tmp_path / "job"
    job = run([python, "-m", "hlacore.experiments.robot_in_the_loop", "--cycles", "5", "--out", str(out)],
              cwd=tmp_path, env=env, timeout=120)
    lap["job"] = time.monotonic()
    print(job)
    assert "checker: 5 cycles, 0 value errors, 0 time errors" in job
    assert job.splitlines()[-1] == "experiment finished: checker passed"
    assert len((out / "trace.csv").read_text().splitlines()) == 1 + 5

    steps = list(lap)
    print(f"{wheel.name}: {wheel.stat().st_size / 1e6:.2f} MB; "
          + ", ".join(f"{step} {lap[step] - lap[before]:.1f} s" for before, step in zip(steps, steps[1:]))
          + f"; total {time.monotonic() - started:.1f} s")
