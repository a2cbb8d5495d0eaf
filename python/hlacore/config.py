"""Where the HLA 1.3 C++ API of this installation is: ``python -m hlacore.config --cflags --libs``; and
hlacore-rtia, which CERTI-built federates start in place of CERTI's rtia: ``python -m hlacore.config --rtia``.

hlacore installs, inside the package, the headers of the HLA 1.3 C++ interface (``RTI.hh``,
``fedtime.hh``, ``NullFederateAmbassador.hh``), the libraries ``libRTI-NG.so`` and ``libFedTime.so``, a
CMake package config (``find_package(hlacore)``, target ``hlacore::RTI-NG``) and a pkg-config file
(``hlacore.pc``). This module prints the flags and folders a build needs (docs/cpp-api.md)::

    g++ -std=c++17 federate.cpp $(python -m hlacore.config --cflags --libs) -o federate
    cmake -Dhlacore_DIR=$(python -m hlacore.config --cmake-dir) ...
    PKG_CONFIG_PATH=$(python -m hlacore.config --pkg-config-dir) pkg-config --cflags --libs hlacore
    export CERTI_RTIA=$(python -m hlacore.config --rtia)      # docs/certi.md
"""

from __future__ import annotations

import argparse
import pathlib
import shutil
import sys
from typing import Optional, Sequence

PREFIX = pathlib.Path(__file__).resolve().parent


def include_dir() -> pathlib.Path:
    """The folder holding RTI.hh, fedtime.hh and NullFederateAmbassador.hh."""
    return _existing(PREFIX / "include" / "hla13", "RTI.hh")


def lib_dir() -> pathlib.Path:
    """The folder holding libRTI-NG.so and libFedTime.so."""
    return _existing(PREFIX / "lib", "libRTI-NG.so")


def cmake_dir() -> pathlib.Path:
    """The folder holding hlacoreConfig.cmake (give it as ``-Dhlacore_DIR``)."""
    return _existing(PREFIX / "lib" / "cmake" / "hlacore", "hlacoreConfig.cmake")


def pkg_config_dir() -> pathlib.Path:
    """The folder holding hlacore.pc (add it to ``PKG_CONFIG_PATH``)."""
    return _existing(PREFIX / "lib" / "pkgconfig", "hlacore.pc")


def rtia() -> pathlib.Path:
    """hlacore-rtia: installed beside this Python's rtig, else found on PATH."""
    beside = pathlib.Path(sys.executable).parent / "hlacore-rtia"
    found = beside if beside.is_file() else shutil.which("hlacore-rtia")
    if not found:
        raise FileNotFoundError(f"{beside} is missing: this hlacore was installed without its scripts")
    return pathlib.Path(found)


def cflags() -> list[str]:
    """The compiler flags of a federate using the HLA 1.3 C++ API."""
    return [f"-I{include_dir()}"]


def libs() -> list[str]:
    """The linker flags: the two libraries, found at run time through an rpath to their folder."""
    lib = lib_dir()
    return [f"-L{lib}", f"-Wl,-rpath,{lib}", "-lRTI-NG", "-lFedTime"]


def _existing(folder: pathlib.Path, member: str) -> pathlib.Path:
    if not (folder / member).is_file():
        raise FileNotFoundError(f"{folder / member} is missing: this hlacore was built without its HLA 1.3 C++ API "
                                "(CMake option HLACORE_HLA13)")
    return folder


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Print what the options ask for, in the order given, on one line."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.config", description=__doc__.splitlines()[0])
    for option, what in [("--cflags", "compiler flags"), ("--libs", "linker flags"),
                         ("--include-dir", "the headers' folder"), ("--lib-dir", "the libraries' folder"),
                         ("--cmake-dir", "the CMake package config's folder (hlacore_DIR)"),
                         ("--pkg-config-dir", "hlacore.pc's folder (PKG_CONFIG_PATH)"),
                         ("--rtia", "hlacore-rtia, for CERTI_RTIA (docs/certi.md)")]:
        parser.add_argument(option, dest="wanted", action="append_const", const=option, help=what)
    wanted = parser.parse_args(argv).wanted
    if not wanted:
        parser.error("say what to print: --cflags, --libs, --include-dir, --lib-dir, --cmake-dir, --pkg-config-dir "
                     "or --rtia")
    answers = {"--cflags": cflags, "--libs": libs, "--include-dir": lambda: [str(include_dir())],
               "--lib-dir": lambda: [str(lib_dir())], "--cmake-dir": lambda: [str(cmake_dir())],
               "--pkg-config-dir": lambda: [str(pkg_config_dir())], "--rtia": lambda: [str(rtia())]}
    try:
        print(" ".join(word for option in wanted for word in answers[option]()))
    except FileNotFoundError as e:
        print(f"hlacore.config: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
