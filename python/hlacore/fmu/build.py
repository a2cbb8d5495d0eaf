"""An FMU built from C sources: a directory with a ``modelDescription.xml`` and the model's ``*.c`` files,
compiled with the system's C compiler against the FMI headers FMPy's wheel carries (and hlacore's FMI 2
skeleton, ``c/hlacore_fmi2.h``: docs/fmu.md, "Writing an FMU in C"), zipped as an ``.fmu``."""

from __future__ import annotations

import hashlib
import pathlib
import re
import shutil
import subprocess
import zipfile
from typing import Union

from .errors import FmuError

#: hlacore's FMI 2 skeleton.
SKELETON = pathlib.Path(__file__).resolve().parent / "c"


def fmi_headers() -> pathlib.Path:
    """The directory of fmi2Functions.h and fmi3Functions.h in the installed FMPy."""
    import fmpy

    return pathlib.Path(fmpy.__file__).parent / "c-code"


def build_fmu(source_dir: Union[str, pathlib.Path], into: Union[str, pathlib.Path]) -> pathlib.Path:
    """The .fmu of ``source_dir``, built into ``into`` and kept there, named after the directory and a hash of
    the sources and the headers they may include (a second call with the same ones returns it without compiling).

    The binary is named after the model identifier and goes where the FMI version puts it: binaries/linux64/
    for FMI 2, FMPy's platform tuple (binaries/x86_64-linux/) for FMI 3. Raises :class:`FmuError` when the
    directory lacks a model description or C files, or the compiler is missing or fails (its messages)."""
    from fmpy import platform_tuple

    source_dir, into = pathlib.Path(source_dir), pathlib.Path(into)
    c_files = sorted(source_dir.glob("*.c"))
    description = source_dir / "modelDescription.xml"
    if not c_files or not description.is_file():
        raise FmuError(f"{source_dir}: an FMU's sources are a modelDescription.xml and *.c files")
    text = description.read_text()
    identifier = re.search(r'modelIdentifier="([^"]+)"', text)
    if identifier is None:
        raise FmuError(f"{description}: no modelIdentifier")
    platform = platform_tuple if 'fmiVersion="3.0"' in text else "linux64"
    # with the headers it may include: its own, those of the directory above (shared by sibling models), hlacore's
    sources = [*c_files, *sorted(source_dir.glob("*.h")), *sorted(source_dir.parent.glob("*.h")),
               *sorted(SKELETON.glob("*.h"))]
    digest = hashlib.sha256(b"".join(f.read_bytes() for f in sources) + text.encode()).hexdigest()[:16]
    fmu = into / f"{source_dir.name}-{digest}.fmu"
    if fmu.exists():
        return fmu
    work = into / f"{source_dir.name}-{digest}.build"
    shutil.rmtree(work, ignore_errors=True)
    binary = work / "binaries" / platform / f"{identifier.group(1)}.so"
    binary.parent.mkdir(parents=True)
    command = ["cc", "-shared", "-fPIC", "-O2", "-Wall", f"-I{fmi_headers()}", f"-I{SKELETON}", "-o", str(binary),
               *map(str, c_files), "-lm"]
    try:
        subprocess.run(command, check=True, timeout=120, capture_output=True, text=True)
    except FileNotFoundError:
        raise FmuError(f"{source_dir}: building an FMU needs a C compiler (cc)") from None
    except subprocess.CalledProcessError as error:
        raise FmuError(f"{source_dir}: the C compiler failed:\n{error.stderr}") from None
    partial = fmu.with_suffix(".part")
    with zipfile.ZipFile(partial, "w") as archive:
        archive.write(description, "modelDescription.xml")
        archive.write(binary, f"binaries/{platform}/{binary.name}")
    partial.rename(fmu)  # whole or absent, should two runs share the directory
    shutil.rmtree(work)
    return fmu
