"""The gateway (`rtig`) run in-process, on a background thread."""

from __future__ import annotations

import math
import os
from types import TracebackType
from typing import TYPE_CHECKING, Any, Iterable, Mapping, Optional

from . import _core
from .rti import _busy_poll_error

if TYPE_CHECKING:
    from .monitor import Monitor


class Gateway:
    """An in-process gateway: the same C++ reactor as the ``rtig`` executable, on its own thread.

    ::

        with hlacore.Gateway(port=0) as gw:          # port 0 picks a free port
            rtia = hlacore.rti.RTIAmbassador(gw.address)

    The gateway listens from construction until :meth:`stop` (or the end of the ``with`` block).
    It logs dropped connections to stderr; ``verbose=True`` logs joins and federations too.
    ``save_dir`` is ``rtig --save-dir``: federation saves are written there as files and can be restored
    by a later gateway; without it saves are kept in memory only (docs/save-restore.md).
    ``trace`` names a CSV file for the message trace (``rtig --trace``): when each update and interaction
    arrived and each reflection of it left, on the host's monotonic clock (read by ``hlacore.trace``).
    ``record`` names an MCAP file to record every federation of the gateway into (``rtig --record``), read by
    :mod:`hlacore.recording`, replayed by ``python -m hlacore.replay`` (docs/record-replay.md); it is complete
    once the gateway stops.
    ``client_budget`` and ``stall_timeout`` are ``rtig --client-budget`` and ``--stall-timeout``, the flow
    control of docs/robustness.md: the bytes the gateway holds for one client (its output queue and the
    messages time management keeps for it) above which the clients sending to it are no longer read until
    it has taken half of them, and how long such a client may take nothing before it is dropped (0: never).
    ``max_frame`` is ``rtig --max-frame``: the largest message in bytes; clients learn it when they connect
    and raise ``ValueLengthExceeded`` at a call whose values would not fit. ``secret_file`` is ``rtig
    --secret-file``: clients prove they know the secret in it before anything else (docs/networking.md).
    ``max_datagram`` is ``rtig --max-datagram``: best effort over UDP on the same port, the largest datagram
    either side sends (larger best-effort messages go over TCP); 0 turns datagrams off.
    ``federation_secrets`` maps federation names to secret files (``rtig --federation-secret NAME=FILE``):
    creating, joining or destroying such a federation needs a proof of its secret
    (``RTIAmbassador(federation_secret_file=...)``).
    ``tls_cert`` and ``tls_key`` are ``rtig --tls-cert`` and ``--tls-key`` (both or neither): PEM files of the
    certificate (chain) and its private key (readable by its owner only); every connection is then TLS and
    clients connect with ``RTIAmbassador(tls=...)``; no datagrams are offered (best effort goes over the
    encrypted stream). :meth:`status` then trusts ``tls_cert`` itself.
    ``busy_poll_us`` is ``rtig --busy-poll``: each wait for the clients polls without sleeping for up to that
    many µs before it sleeps (0, the default: off; at most :attr:`MAX_BUSY_POLL_US`; docs/performance.md).
    ``unix`` is ``rtig --unix``: also listen on a Unix socket at that path, for federates on this host, which
    connect to :attr:`unix_address` (``"unix:PATH"``) with less CPU per message than over TCP; no datagrams
    and no TLS on it; the file is its owner's only and is removed when the gateway stops (docs/networking.md).
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
        fom_path: Iterable[str] = (),
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
    ) -> None:
        if client_budget < self.MIN_CLIENT_BUDGET:
            raise ValueError(f"client_budget must be at least {self.MIN_CLIENT_BUDGET} bytes, not {client_budget}")
        if not (math.isfinite(stall_timeout) and stall_timeout >= 0):
            raise ValueError(f"stall_timeout must be a finite number of seconds >= 0, not {stall_timeout}")
        self._secret_file = secret_file
        if (tls_cert is None) != (tls_key is None):
            raise ValueError("tls_cert and tls_key go together")
        self._tls_cert = os.fspath(tls_cert) if tls_cert is not None else None
        low, high = self.MAX_FRAME_RANGE
        if not low <= max_frame <= high:
            raise ValueError(f"max_frame must be between {low} and {high} bytes, not {max_frame}")
        low, high = self.MAX_DATAGRAM_RANGE
        if max_datagram != 0 and not low <= max_datagram <= high:
            raise ValueError(f"max_datagram must be 0 or between {low} and {high} bytes, not {max_datagram}")
        if error := _busy_poll_error(busy_poll_us):
            raise ValueError(error)
        self._gateway = _core.BackgroundGateway(host, port, list(fom_path), verbose,
                                                os.fspath(save_dir) if save_dir is not None else "",
                                                os.fspath(trace) if trace is not None else "",
                                                client_budget, stall_timeout, max_frame,
                                                os.fspath(secret_file) if secret_file is not None else "",
                                                max_datagram,
                                                {name: os.fspath(path) for name, path in (federation_secrets or {}).items()},
                                                self._tls_cert or "",
                                                os.fspath(tls_key) if tls_key is not None else "",
                                                os.fspath(record) if record is not None else "", busy_poll_us,
                                                os.fspath(unix) if unix is not None else "")
        self._unix = os.fspath(unix) if unix is not None else None

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
