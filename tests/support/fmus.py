"""The test FMUs, built from the project's own sources: C models (tests/data/fmu/<model>/) compiled by
hlacore.fmu.build, and a Python one by pythonfmu. Each build is cached under the directory given, keyed by a
hash of its sources, so a session builds each model once. Nothing built here is committed."""

from __future__ import annotations

import hashlib
import pathlib
import shutil
import subprocess
import sys

from hlacore.fmu import build

from support import DATA

FMU_SOURCES = DATA / "fmu"


def build_fmu(model: str, into: pathlib.Path) -> pathlib.Path:
    """The .fmu of tests/data/fmu/<model>/ (its C files and modelDescription.xml), built into ``into`` by
    hlacore.fmu.build (cached there by a hash of the sources)."""
    return build.build_fmu(FMU_SOURCES / model, into)


def build_python_fmu(model: str, into: pathlib.Path) -> pathlib.Path:
    """The .fmu of the pythonfmu script tests/data/fmu/<model>/<model>.py, built by ``pythonfmu build`` into
    ``into`` (cached by the script's hash, like :func:`build_fmu`)."""
    script = FMU_SOURCES / model / f"{model}.py"
    digest = hashlib.sha256(script.read_bytes()).hexdigest()[:16]
    out = into / f"{model}-{digest}"
    built = list(out.glob("*.fmu")) if out.is_dir() else []
    if built:
        return built[0]
    partial = into / f"{model}-{digest}.part"
    shutil.rmtree(partial, ignore_errors=True)
    subprocess.run([sys.executable, "-m", "pythonfmu", "build", "-f", str(script), "-d", str(partial)], check=True,
                   timeout=120, capture_output=True)
    partial.rename(out)
    return next(out.glob("*.fmu"))
