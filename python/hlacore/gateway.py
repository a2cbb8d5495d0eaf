"""The gateway (`rtig`) run in-process, on a background thread."""

from __future__ import annotations

import os
from types import TracebackType
from typing import TYPE_CHECKING, Any, Iterable, Mapping, Optional

from . import _core, _options

if TYPE_CHECKING:
    from .monitor import Monitor


class Gateway:
    """An in-process gateway: the same C++ reactor as the ``rtig`` executable, on its own thread.

    ::

        with hlacore.Gateway(port=0) as gw:          # port 0 picks a free port
            rtia = hlacore.rti.RTIAmbassador(gw.address)

    The gateway listens from construction until :meth:`stop` (or the end of the ``with`` block). It logs
    dropped connections to stderr. Each keyword is an ``rtig`` option, named in its entry below and checked
    by the same table: a value out of range raises :class:`ValueError` naming it, a secret, certificate or
    key file that cannot be used :class:`RuntimeError` saying why. With ``tls_cert``, :meth:`status` trusts
    that certificate itself. The keywords:

"""

    #: The smallest ``client_budget`` in bytes (a smaller one raises :class:`ValueError`).
    MIN_CLIENT_BUDGET: int = _core.MIN_CLIENT_BUDGET
    #: The bounds of ``max_frame`` in bytes, both included.
    MAX_FRAME_RANGE: tuple[int, int] = _core.MAX_FRAME_RANGE
    #: The bounds of ``max_datagram`` in bytes, both included, when it is not 0 (65507: the largest UDP payload
    #: over IPv4).
    MAX_DATAGRAM_RANGE: tuple[int, int] = _core.MAX_DATAGRAM_RANGE
    #: The longest ``busy_poll_us``.
    MAX_BUSY_POLL_US: int = _core.MAX_BUSY_POLL_US

    def __init__(
        self,
        host: str = "127.0.0.1",
        port: int = 60400,
        fom_path: Iterable[str | os.PathLike[str]] = (),
        verbose: bool = False,
        save_dir: Optional[str | os.PathLike[str]] = None,
        trace: Optional[str | os.PathLike[str]] = None,
        client_budget: int = 64 << 20,
        stall_timeout: float = 30.0,
        max_frame: int = 64 << 20,
        secret_file: Optional[str | os.PathLike[str]] = None,
        max_datagram: int = 1400,
        federation_secrets: Optional[Mapping[str, str | os.PathLike[str]]] = None,
        tls_cert: Optional[str | os.PathLike[str]] = None,
        tls_key: Optional[str | os.PathLike[str]] = None,
        record: Optional[str | os.PathLike[str]] = None,
        busy_poll_us: int = 0,
        unix: Optional[str | os.PathLike[str]] = None,
        frame_timeout: float = 10.0,
        spill_dir: Optional[str | os.PathLike[str]] = None,
        disk_budget: int = 1 << 30,
        time_semantics: str = "exact",
        fedpro: Optional[str] = None,
        fedpro_resume_timeout: float = 60.0,
    ) -> None:
        given = _options.given(_core.gateway_options(), locals())
        self._secret_file = secret_file
        self._tls_cert = os.fspath(tls_cert) if tls_cert is not None else None
        self._unix = os.fspath(unix) if unix is not None else None
        self._fedpro = fedpro
        self._gateway = _core.BackgroundGateway(given)

    @property
    def host(self) -> str:
        """The address the gateway listens on."""
        return str(self._gateway.host)

    @property
    def port(self) -> int:
        """The TCP port the gateway listens on (the one picked when constructed with port 0)."""
        return int(self._gateway.port)

    @property
    def address(self) -> str:
        """``"host:port"``, as :class:`hlacore.rti.RTIAmbassador` takes it."""
        return f"{self.host}:{self.port}"

    @property
    def unix_address(self) -> Optional[str]:
        """``"unix:PATH"`` when constructed with ``unix=PATH``, as :class:`hlacore.rti.RTIAmbassador` takes it;
        else None."""
        return f"unix:{self._unix}" if self._unix is not None else None

    @property
    def fedpro_address(self) -> Optional[str]:
        """``"host:port"`` of the HLA 4 Federate Protocol's door when constructed with
        ``fedpro="[PROTOCOL://]HOST:PORT"`` (the port picked, for port 0), as :class:`hlacore.fedpro.RTIambassador`
        takes it; else None."""
        port = int(self._gateway.fedpro_port)
        if not port:
            return None
        spec = (self._fedpro or "").split("://")[-1]
        host = spec.rpartition(":")[0] if ":" in spec else spec
        return f"{host or '127.0.0.1'}:{port}"

    @property
    def running(self) -> bool:
        """True until :meth:`stop` has returned."""
        return bool(self._gateway.running)

    def status(self) -> dict[str, Any]:
        """Per federation, each federate's time, lookahead, regulating/constrained, pending request and
        queued messages: see ``hlacore.status.status``."""
        from .status import status

        return status(self.address, self._secret_file, tls=self._tls_cert if self._tls_cert else False)

    def monitor(self, port: int = 0, host: str = "127.0.0.1", interval: float = 0.5) -> "Monitor":
        """The live web view of this gateway (:class:`hlacore.monitor.Monitor`), started: open its ``url`` in a
        browser; ``close()`` it, or use it in a ``with`` block. ``port`` 0 picks a free port."""
        from .monitor import Monitor

        return Monitor(self.address, host=host, port=port, interval=interval, secret_file=self._secret_file,
                       tls=self._tls_cert if self._tls_cert else False).start()

    def stop(self) -> None:
        """Stop serving and close every connection; idempotent."""
        self._gateway.stop()

    def __enter__(self) -> "Gateway":
        return self

    def __exit__(
        self,
        exc_type: Optional[type[BaseException]],
        exc: Optional[BaseException],
        tb: Optional[TracebackType],
    ) -> None:
        self.stop()

    def __repr__(self) -> str:
        state = "running" if self.running else "stopped"
        return f"<hlacore.Gateway {self.address} {state}>"


Gateway.__doc__ = f"{Gateway.__doc__}{_options.document(_core.gateway_options(), 'rtig ``{}``')}\n"
