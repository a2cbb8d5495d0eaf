"""The test FMUs, built from the project's own C sources (tests/data/fmu/<model>/) with the FMI headers that
fmpy's wheel carries: compiled with the system's C compiler into a shared library and zipped with the model
description as an .fmu. Each build is cached under the directory given, keyed by a hash of its sources, so a
session compiles each model once. Nothing built here is committed."""

from __future__ import annotations

import hashlib
import pathlib
import re
import shutil
import subprocess
import sys
import zipfile

from support import DATA

FMU_SOURCES = DATA / "fmu"


def fmi_headers() -> pathlib.Path:
    """The directory of fmi2Functions.h and fmi3Functions.h in the installed fmpy."""
    import fmpy

    return pathlib.Path(fmpy.__file__).parent / "c-code"


def build_fmu(model: str, into: pathlib.Path) -> pathlib.Path:
    """The .fmu of tests/data/fmu/<model>/ (its C files and modelDescription.xml), built into ``into``.

    The binary is named after the model identifier and goes where its FMI version puts it:
    binaries/linux64/ for FMI 2, binaries/x86_64-linux/ (FMPy's platform tuple) for FMI 3."""
    from fmpy import platform_tuple

    source_dir = FMU_SOURCES / model
    c_files = sorted(source_dir.glob("*.c"))
    description = source_dir / "modelDescription.xml"
    text = description.read_text()
    identifier = re.search(r'modelIdentifier="([^"]+)"', text).group(1)  # type: ignore[union-attr]
    platform = platform_tuple if 'fmiVersion="3.0"' in text else "linux64"
    digest = hashlib.sha256(b"".join(f.read_bytes() for f in c_files) + text.encode()).hexdigest()[:16]
    fmu = into / f"{model}-{digest}.fmu"
    if fmu.exists():
        return fmu
    work = into / f"{model}-{digest}.build"
    shutil.rmtree(work, ignore_errors=True)
    binary = work / "binaries" / platform / f"{identifier}.so"
    binary.parent.mkdir(parents=True)
    subprocess.run(["cc", "-shared", "-fPIC", "-O2", "-Wall", f"-I{fmi_headers()}", "-o", str(binary),
                    *map(str, c_files), "-lm"], check=True, timeout=120)
    partial = fmu.with_suffix(".part")
    with zipfile.ZipFile(partial, "w") as archive:
        archive.write(description, "modelDescription.xml")
        archive.write(binary, f"binaries/{platform}/{binary.name}")
    partial.rename(fmu)  # whole or absent, should two sessions share the cache
    shutil.rmtree(work)
    return fmu


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
