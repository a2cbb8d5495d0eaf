"""The three-RTI benchmark's moving parts: each RTI's server (hlacore's rtig, OpenRTI's rtinode, CERTI's rtig
with an rtia per federate), and one workload of bench/rtis/hla13_bench.cpp run as a federation of processes
against it. The RTIs are built by bench/rtis/build.sh (./scripts/bench.sh calls it with the archives'
folder) into $HLACORE_RTIS (default build/rtis), with the benchmark program compiled against each as
$HLACORE_RTIS/bench/hla13_bench-<rti>."""

from __future__ import annotations

import os
import pathlib
import socket
import tempfile
import time
from typing import Any, Optional

from hlacore.processes import Child, Rtig

from .federation import FOM
from .outputs import ROOT
from .procs import bench_rtig

RTIS = ("hlacore", "openrti", "certi")


def rtis_dir() -> pathlib.Path:
    return pathlib.Path(os.environ.get("HLACORE_RTIS") or ROOT / "build" / "rtis")


def bench_binary(rti: str) -> str:
    """hla13_bench compiled against `rti` (by bench/rtis/build.sh); AssertionError naming what to run if absent."""
    path = rtis_dir() / "bench" / f"hla13_bench-{rti}"
    assert path.exists(), f"{path} is missing: ./scripts/bench.sh builds it (bench/rtis/build.sh ARCHIVES)"
    return str(path)


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
        install = rtis_dir() / rti
        if rti == "openrti":
            self.federation = f"rti://127.0.0.1:{port}/Bench"  # OpenRTI names the server in the federation's URL
            self._child = Child([str(install / "bin" / "rtinode"), "-i", f"127.0.0.1:{port}"])
        else:
            self.federation = "Bench"
            for variable in ("http_proxy", "HTTP_PROXY", "CERTI_HTTP_PROXY"):
                self.env.pop(variable, None)  # the rtia would otherwise connect through a proxy
            self.env.update(CERTI_HOST="127.0.0.1", CERTI_TCP_PORT=str(port), CERTI_UDP_PORT=str(port + 1),
                            CERTI_HOME=str(install), CERTI_FOM_PATH=str(pathlib.Path(FOM).parent),
                            CERTI_NO_STATISTICS="1", PATH=f"{install / 'bin'}:{self.env.get('PATH', '')}",
                            LD_LIBRARY_PATH=str(install / "lib"))
            # rtig appends its audit log RTIG.log to its working directory: a temporary one.
            self._child = Child([str(install / "bin" / "rtig"), "-l", "127.0.0.1"], env=self.env, cwd=self._dir.name)
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

