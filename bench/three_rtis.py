"""The three-RTI benchmark's moving parts: each RTI's server (hlacore's rtig, OpenRTI's rtinode, CERTI's rtig
with an rtia per federate), and one workload of bench/rtis/hla13_bench.cpp run as a federation of processes
against it.

hlacore is always there. OpenRTI and CERTI are not built here: point the bench at your installs, each by the
prefix it was installed into.

    HLACORE_BENCH_OPENRTI=PREFIX   OpenRTI: PREFIX/include/RTI13/ (RTI.hh, fedtime.hh, NullFederateAmbassador.hh),
                                   PREFIX/lib/ or lib64/ (libRTI-NG.so, libFedTime.so), PREFIX/bin/rtinode
                                   (started as `rtinode -i 127.0.0.1:PORT`, the federation named
                                   rti://127.0.0.1:PORT/Bench)
    HLACORE_BENCH_CERTI=PREFIX     CERTI 3.5.1: PREFIX/include/hla13/ (the same headers), PREFIX/lib/ or lib64/
                                   (libRTI-NG.so, libFedTime.so), PREFIX/bin/rtig and PREFIX/bin/rtia (started as
                                   `rtig -l 127.0.0.1` with CERTI_HOME=PREFIX, CERTI_HOST, CERTI_TCP_PORT and
                                   PREFIX/bin first on PATH, whence each federate starts its rtia)

hla13_bench.cpp is compiled against each RTI that is there (hlacore's from the installed package,
hlacore.config) into build/hla13_bench/hla13_bench-<rti>, again whenever the program or the RTI's library is
newer than the binary or the prefix changed."""

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
SOURCE = pathlib.Path(__file__).parent / "rtis" / "hla13_bench.cpp"
BINARIES = ROOT / "build" / "hla13_bench"
# Where each RTI keeps its HLA 1.3 headers under its prefix, and the executables its server needs.
_HEADERS = {"openrti": "include/RTI13", "certi": "include/hla13"}
_EXECUTABLES = {"openrti": ("rtinode",), "certi": ("rtig", "rtia")}


@dataclass(frozen=True)
class Install:
    """An RTI's HLA 1.3 API and server: the headers' and libraries' folders, the prefix (hlacore's: none)."""

    rti: str
    include: pathlib.Path
    lib: pathlib.Path
    prefix: Optional[pathlib.Path] = None


def installed() -> tuple[str, ...]:
    """The other RTIs whose prefix variable is set, in RTIS order."""
    return tuple(rti for rti in RTIS[1:] if os.environ.get(VARIABLES[rti]))


def install(rti: str) -> Install:
    """Where `rti` is: hlacore's installed package, or the prefix in $HLACORE_BENCH_OPENRTI / $HLACORE_BENCH_CERTI.
    AssertionError naming the variable and the missing file when the prefix is not set or lacks part of it."""
    if rti == "hlacore":
        return Install(rti, config.include_dir(), config.lib_dir())
    variable = VARIABLES[rti]
    value = os.environ.get(variable)
    assert value, f"${variable} is not set: {NOT_INSTALLED}"
    prefix = pathlib.Path(value).expanduser().resolve()
    include = prefix / _HEADERS[rti]
    libs = [prefix / "lib", prefix / "lib64"]
    lib = next((d for d in libs if (d / "libRTI-NG.so").exists()), libs[0])
    wanted = [*(include / name for name in ("RTI.hh", "fedtime.hh", "NullFederateAmbassador.hh")),
              lib / "libRTI-NG.so", lib / "libFedTime.so",
              *(prefix / "bin" / name for name in _EXECUTABLES[rti])]
    missing = [str(path) for path in wanted if not path.exists()]
    assert not missing, f"${variable}={value} is not an install prefix of {rti}: missing {', '.join(missing)}"
    return Install(rti, include, lib, prefix)


def bench_binary(rti: str) -> str:
    """hla13_bench compiled against `rti` (install(rti)) into build/hla13_bench/, unless the binary there was
    compiled by the same command (the same install) and is newer than the program and the RTI's library;
    AssertionError with the compiler's output if compiling fails."""
    where = install(rti)
    target = BINARIES / f"hla13_bench-{rti}"
    stamp = target.with_name(target.name + ".command")  # the command that compiled it
    # C++14 and no deprecation warnings: CERTI's headers keep dynamic exception specifications.
    command = ["g++", "-std=gnu++14", "-O2", "-Wno-deprecated", "-DRTI_USES_STD_FSTREAM", str(SOURCE),
               f"-I{where.include}", f"-L{where.lib}", f"-Wl,-rpath,{where.lib}", f"-Wl,-rpath-link,{where.lib}",
               "-lRTI-NG", "-lFedTime", "-o", str(target)]
    library = where.lib / "libRTI-NG.so"
    if (target.exists() and stamp.exists() and stamp.read_text() == " ".join(command)
            and all(target.stat().st_mtime > p.stat().st_mtime for p in (SOURCE, library))):
        return str(target)
    BINARIES.mkdir(parents=True, exist_ok=True)
    stamp.unlink(missing_ok=True)
    done = subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    assert done.returncode == 0, f"compiling {SOURCE.name} against {rti} failed:\n{' '.join(command)}\n{done.stderr[-4000:]}"
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
        binary: Optional[str] = None) -> dict[str, Any]:
    """One run of `workload` with `federates` processes of hla13_bench (`binary`, else the one compiled
    against the server's RTI) against `server`; the creator's JSON result. Every process must exit 0 (each
    checks what it received); AssertionError otherwise."""
    binary = binary or bench_binary(server.rti)
    args = [workload, server.federation, FOM]
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

