"""The three-RTI benchmark's moving parts: each RTI's server (hlacore's rtig, OpenRTI's rtinode, CERTI's rtig
with an rtia per federate), and one workload of a benchmark program of bench/rtis run as a federation of
processes against it: hla13_bench.cpp on the HLA 1.3 C++ API, or its twin rti1516e_bench.cpp on the IEEE
1516-2010 one (the same workloads, workloads.hh).

hlacore is always there. OpenRTI and CERTI are not built here: point the bench at your installs, each by the
prefix it was installed into.

    HLACORE_BENCH_OPENRTI=PREFIX   OpenRTI: PREFIX/include/RTI13/ (RTI.hh, fedtime.hh, NullFederateAmbassador.hh),
                                   PREFIX/lib/ or lib64/ (libRTI-NG.so, libFedTime.so), PREFIX/bin/rtinode
                                   (started as `rtinode -i 127.0.0.1:PORT`, the federation named
                                   rti://127.0.0.1:PORT/Bench); for the 1516-2010 program also
                                   PREFIX/include/rti1516e/ (RTI/RTI1516.h) and librti1516e.so, libfedtime1516e.so
    HLACORE_BENCH_CERTI=PREFIX     CERTI 3.5.1: PREFIX/include/hla13/ (the same headers), PREFIX/lib/ or lib64/
                                   (libRTI-NG.so, libFedTime.so), PREFIX/bin/rtig and PREFIX/bin/rtia (started as
                                   `rtig -l 127.0.0.1` with CERTI_HOME=PREFIX, CERTI_HOST, CERTI_TCP_PORT and
                                   PREFIX/bin first on PATH, whence each federate starts its rtia); the HLA 1.3
                                   program only

Each program is compiled against each RTI that is there (hlacore's from the installed package, hlacore.config)
into build/hla13_bench/hla13_bench-<rti> and build/rti1516e_bench/rti1516e_bench-<rti>, again whenever the
program or the RTI's library is newer than the binary or the prefix changed."""

from __future__ import annotations

import os
import pathlib
import socket
import subprocess
import tempfile
import time
from dataclasses import dataclass
from typing import Any, Optional

from hlacore import config
from hlacore.processes import Child, Rtig

from .federation import FOM
from .outputs import ROOT
from .procs import bench_rtig

RTIS = ("hlacore", "openrti", "certi")
VARIABLES = {"openrti": "HLACORE_BENCH_OPENRTI", "certi": "HLACORE_BENCH_CERTI"}  # the other RTIs' prefixes
NOT_INSTALLED = ("no other RTI installed: set HLACORE_BENCH_OPENRTI / HLACORE_BENCH_CERTI to their install "
                 "prefixes (docs/performance.md, \"Three RTIs\")")
RTIS_DIR = pathlib.Path(__file__).parent / "rtis"
HEADER = RTIS_DIR / "workloads.hh"  # the programs' shared part


@dataclass(frozen=True)
class Api:
    """A C++ API the benchmark has a program for: the program, its FOM, the libraries it links, the folder of
    the headers under each other RTI's prefix (the RTIs it runs on besides hlacore), the headers there and
    the compiler's standard."""

    name: str
    source: pathlib.Path
    fom: str
    libraries: tuple[str, ...]
    include: dict[str, str]
    headers: tuple[str, ...]
    std: str


APIS = {
    # C++14 and no deprecation warnings: CERTI's headers keep dynamic exception specifications.
    "hla13": Api("hla13", RTIS_DIR / "hla13_bench.cpp", FOM, ("RTI-NG", "FedTime"),
                 {"openrti": "include/RTI13", "certi": "include/hla13"},
                 ("RTI.hh", "fedtime.hh", "NullFederateAmbassador.hh"), "gnu++14"),
    "1516e": Api("1516e", RTIS_DIR / "rti1516e_bench.cpp", str(RTIS_DIR / "robot.xml"), ("rti1516e", "fedtime1516e"),
                 {"openrti": "include/rti1516e"}, ("RTI/RTI1516.h",), "c++17"),
}
# The executables each RTI's server needs.
_EXECUTABLES = {"openrti": ("rtinode",), "certi": ("rtig", "rtia")}


@dataclass(frozen=True)
class Install:
    """An RTI's C++ API (`api`) and server: the headers' and libraries' folders, the prefix (hlacore's: none)."""

    rti: str
    include: pathlib.Path
    lib: pathlib.Path
    prefix: Optional[pathlib.Path] = None
    api: str = "hla13"


def installed() -> tuple[str, ...]:
    """The other RTIs whose prefix variable is set, in RTIS order."""
    return tuple(rti for rti in RTIS[1:] if os.environ.get(VARIABLES[rti]))


def programs() -> tuple[tuple[str, str], ...]:
    """The (RTI, API) pairs the C++ programs run on, each RTI's beside each other: hlacore's two APIs, then each
    other RTI installed with the APIs the benchmark has for it (OpenRTI both, CERTI HLA 1.3)."""
    return tuple((rti, api) for rti in ("hlacore", *installed()) for api in APIS
                 if rti == "hlacore" or rti in APIS[api].include)


def column(rti: str, api: str) -> str:
    """The report's name of `rti` through `api` (rtis.<column>.<figure>): the RTI's for HLA 1.3, with
    "-1516e" for the 1516-2010 program."""
    return rti if api == "hla13" else f"{rti}-{api}"


def install(rti: str, api: str = "hla13") -> Install:
    """Where `rti` is, with its `api`: hlacore's installed package, or the prefix in $HLACORE_BENCH_OPENRTI /
    $HLACORE_BENCH_CERTI. AssertionError naming the variable and the missing file when the prefix is not set or
    lacks part of it."""
    if rti == "hlacore":
        return Install(rti, config.include_dir(api), config.lib_dir(api), api=api)
    variable = VARIABLES[rti]
    value = os.environ.get(variable)
    assert value, f"${variable} is not set: {NOT_INSTALLED}"
    prefix = pathlib.Path(value).expanduser().resolve()
    spec = APIS[api]
    assert rti in spec.include, f"the benchmark has no {api} program for {rti}"
    include = prefix / spec.include[rti]
    libs = [prefix / "lib", prefix / "lib64"]
    lib = next((d for d in libs if (d / f"lib{spec.libraries[0]}.so").exists()), libs[0])
    wanted = [*(include / name for name in spec.headers), *(lib / f"lib{name}.so" for name in spec.libraries),
              *(prefix / "bin" / name for name in _EXECUTABLES[rti])]
    missing = [str(path) for path in wanted if not path.exists()]
    assert not missing, f"${variable}={value} is not an install prefix of {rti}: missing {', '.join(missing)}"
    return Install(rti, include, lib, prefix, api)


def bench_binary(rti: str, api: str = "hla13") -> str:
    """The `api` program compiled against `rti` (install(rti, api)) into build/<program>/, unless the binary
    there was compiled by the same command (the same install) and is newer than the program, workloads.hh and
    the RTI's library; AssertionError with the compiler's output if compiling fails."""
    where, spec = install(rti, api), APIS[api]
    target = ROOT / "build" / spec.source.stem / f"{spec.source.stem}-{rti}"
    stamp = target.with_name(target.name + ".command")  # the command that compiled it
    command = ["g++", f"-std={spec.std}", "-O2", "-Wno-deprecated", "-DRTI_USES_STD_FSTREAM", str(spec.source),
               f"-I{where.include}", f"-L{where.lib}", f"-Wl,-rpath,{where.lib}", f"-Wl,-rpath-link,{where.lib}",
               *(f"-l{name}" for name in spec.libraries), "-o", str(target)]
    library = where.lib / f"lib{spec.libraries[0]}.so"
    if (target.exists() and stamp.exists() and stamp.read_text() == " ".join(command)
            and all(target.stat().st_mtime > p.stat().st_mtime for p in (spec.source, HEADER, library))):
        return str(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    stamp.unlink(missing_ok=True)
    done = subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    assert done.returncode == 0, (f"compiling {spec.source.name} against {rti} failed:\n{' '.join(command)}\n"
                                  f"{done.stderr[-4000:]}")
    stamp.write_text(" ".join(command))
    return str(target)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _wait_listening(port: int, child: Child, timeout: float = 10.0) -> None:
    """Until something listens on 127.0.0.1:`port`, read from /proc/net/tcp: a probe connection would
    disturb CERTI's rtig."""
    needle = f"0100007F:{port:04X}"
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for line in pathlib.Path("/proc/net/tcp").read_text().splitlines()[1:]:
            fields = line.split()
            if fields[1] == needle and fields[3] == "0A":  # 0A: LISTEN
                return
        if child.proc.poll() is not None:
            raise RuntimeError(f"the server exited ({child.proc.returncode}): {child.stderr()}")
        time.sleep(0.02)
    raise RuntimeError(f"nothing listens on 127.0.0.1:{port} after {timeout} s: {child.stderr()}")


class Server:
    """One RTI's server on 127.0.0.1, with the federation name and environment its federates use;
    `rtig_args` are hlacore's rtig's (bench_rtig()'s, --busy-poll US for one)."""

    def __init__(self, rti: str, *rtig_args: str) -> None:
        assert rti in RTIS and (rti == "hlacore" or not rtig_args), (rti, rtig_args)
        where = None if rti == "hlacore" else install(rti)  # first: it raises when the install is not there
        self.rti = rti
        self.env = dict(os.environ)
        self.address = ""  # hlacore's gateway, for its Python federates
        self._rtig: Optional[Rtig] = None
        self._child: Optional[Child] = None
        self._dir = tempfile.TemporaryDirectory(prefix=f"rti-{rti}-")
        if rti == "hlacore":
            self._rtig = bench_rtig(*rtig_args)
            self.federation = "Bench"
            self.address = self._rtig.address
            self.env["HLACORE_RTIG"] = self.address
            return
        port = _free_port()
        assert where is not None and where.prefix is not None
        prefix = where.prefix
        if rti == "openrti":
            self.federation = f"rti://127.0.0.1:{port}/Bench"  # OpenRTI names the server in the federation's URL
            self._child = Child([str(prefix / "bin" / "rtinode"), "-i", f"127.0.0.1:{port}"])
        else:
            self.federation = "Bench"
            for variable in ("http_proxy", "HTTP_PROXY", "CERTI_HTTP_PROXY"):
                self.env.pop(variable, None)  # the rtia would otherwise connect through a proxy
            self.env.update(CERTI_HOST="127.0.0.1", CERTI_TCP_PORT=str(port), CERTI_UDP_PORT=str(port + 1),
                            CERTI_HOME=str(prefix), CERTI_FOM_PATH=str(pathlib.Path(FOM).parent),
                            CERTI_NO_STATISTICS="1", PATH=f"{prefix / 'bin'}:{self.env.get('PATH', '')}",
                            LD_LIBRARY_PATH=str(where.lib))
            # rtig appends its audit log RTIG.log to its working directory: a temporary one.
            self._child = Child([str(prefix / "bin" / "rtig"), "-l", "127.0.0.1"], env=self.env, cwd=self._dir.name)
        try:
            _wait_listening(port, self._child)
        except BaseException:
            self.close()
            raise

    @property
    def pid(self) -> int:
        """The server process's pid (hlacore's rtig, OpenRTI's rtinode, CERTI's rtig)."""
        if self._rtig is not None:
            return self._rtig.child.pid
        assert self._child is not None
        return self._child.pid

    def close(self) -> None:
        if self._rtig is not None:
            self._rtig.stop()
        if self._child is not None:
            self._child.close()
        self._dir.cleanup()


def run(server: Server, workload: str, federates: int, n: int, m: int, timeout: float = 300.0,
        binary: Optional[str] = None, api: str = "hla13") -> dict[str, Any]:
    """One run of `workload` with `federates` processes of the `api` program (`binary`, else the one compiled
    against the server's RTI) against `server`; the creator's JSON result. Every process must exit 0 (each
    checks what it received); AssertionError otherwise."""
    binary = binary or bench_binary(server.rti, api)
    args = [workload, server.federation, APIS[api].fom]
    creator = Child([binary, *args, "create", "f0", str(federates), str(n), str(m)], env=server.env)
    others = [Child([binary, *args, "join", f"f{i}", str(federates), str(n), str(m)], env=server.env)
              for i in range(1, federates)]
    everyone = [creator, *others]
    try:
        result = creator.read_json(timeout=timeout)
        for child in everyone:
            assert child.wait(timeout=60.0) == 0, f"{server.rti} {workload}: {child.stderr()}"
        return result
    except RuntimeError as e:
        raise AssertionError(f"{server.rti} {workload}: {e}; others: {[c.stderr() for c in others]}") from None
    finally:
        for child in everyone:
            child.close()

