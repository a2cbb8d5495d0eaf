"""Where the C++ APIs of this installation are: ``python -m hlacore.config --cflags --libs`` (HLA 1.3),
``python -m hlacore.config --api 1516e --cflags --libs`` (IEEE 1516-2010); and hlacore-rtia, which CERTI-built
federates start in place of CERTI's rtia: ``python -m hlacore.config --rtia``.

hlacore installs, inside the package, the headers of the HLA 1.3 C++ interface (``RTI.hh``,
``fedtime.hh``, ``NullFederateAmbassador.hh``) with the libraries ``libRTI-NG.so`` and ``libFedTime.so``, the
headers of the IEEE 1516-2010 one (``RTI/RTI1516.h`` and the rest of SISO's layout) with ``librti1516e.so`` and
``libfedtime1516e.so``, a CMake package config (``find_package(hlacore)``, targets ``hlacore::RTI-NG`` and
``hlacore::rti1516e``) and pkg-config files (``hlacore.pc``, ``hlacore-rti1516e.pc``). This module prints the
flags and folders a build needs (docs/cpp-api.md, docs/rti1516e.md)::

    g++ -std=c++17 federate.cpp $(python -m hlacore.config --cflags --libs) -o federate
    g++ -std=c++17 federate.cpp $(python -m hlacore.config --api 1516e --cflags --libs) -o federate
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


# Each C++ API: its headers' folder and a header in it, its libraries (the first found in lib_dir()), the
# CMake option that builds it.
APIS = {"hla13": ("hla13", "RTI.hh", ("RTI-NG", "FedTime"), "HLACORE_HLA13"),
        "1516e": ("rti1516e", "RTI/RTI1516.h", ("rti1516e", "fedtime1516e"), "HLACORE_RTI1516E")}


def include_dir(api: str = "hla13") -> pathlib.Path:
    """The folder of the API's headers: RTI.hh, fedtime.hh and NullFederateAmbassador.hh (``"hla13"``), or
    the ``RTI/`` folder of IEEE 1516-2010's (``"1516e"``)."""
    folder, header, _libraries, option = APIS[api]
    return _existing(PREFIX / "include" / folder, header, option)


def lib_dir(api: str = "hla13") -> pathlib.Path:
    """The folder holding the API's libraries (libRTI-NG.so and libFedTime.so; librti1516e.so and
    libfedtime1516e.so)."""
    _folder, _header, libraries, option = APIS[api]
    return _existing(PREFIX / "lib", f"lib{libraries[0]}.so", option)


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


def cflags(api: str = "hla13") -> list[str]:
    """The compiler flags of a federate using the C++ API ``api``."""
    return [f"-I{include_dir(api)}"]


def libs(api: str = "hla13") -> list[str]:
    """The linker flags: the API's two libraries, found at run time through an rpath to their folder."""
    lib = lib_dir(api)
    return [f"-L{lib}", f"-Wl,-rpath,{lib}", *(f"-l{name}" for name in APIS[api][2])]


def _existing(folder: pathlib.Path, member: str, option: str = "HLACORE_HLA13") -> pathlib.Path:
    if not (folder / member).is_file():
        raise FileNotFoundError(f"{folder / member} is missing: this hlacore was built without that C++ API "
                                f"(CMake option {option})")
    return folder


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Print what the options ask for, in the order given, on one line."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.config", description=__doc__.splitlines()[0])
    parser.add_argument("--api", choices=sorted(APIS), default="hla13",
                        help="the C++ API of --cflags, --libs, --include-dir and --lib-dir (default hla13)")
    for option, what in [("--cflags", "compiler flags"), ("--libs", "linker flags"),
                         ("--include-dir", "the headers' folder"), ("--lib-dir", "the libraries' folder"),
                         ("--cmake-dir", "the CMake package config's folder (hlacore_DIR)"),
                         ("--pkg-config-dir", "hlacore.pc's folder (PKG_CONFIG_PATH)"),
                         ("--rtia", "hlacore-rtia, for CERTI_RTIA (docs/certi.md)")]:
        parser.add_argument(option, dest="wanted", action="append_const", const=option, help=what)
    args = parser.parse_args(argv)
    wanted, api = args.wanted, args.api
    if not wanted:
        parser.error("say what to print: --cflags, --libs, --include-dir, --lib-dir, --cmake-dir, --pkg-config-dir "
                     "or --rtia")
    answers = {"--cflags": lambda: cflags(api), "--libs": lambda: libs(api),
               "--include-dir": lambda: [str(include_dir(api))], "--lib-dir": lambda: [str(lib_dir(api))], "--cmake-dir": lambda: [str(cmake_dir())],
               "--pkg-config-dir": lambda: [str(pkg_config_dir())], "--rtia": lambda: [str(rtia())]}
    try:
        print(" ".join(word for option in wanted for word in answers[option]()))
    except FileNotFoundError as e:
        print(f"hlacore.config: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
