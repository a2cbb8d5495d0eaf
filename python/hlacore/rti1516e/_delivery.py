"""How callbacks reach the federate ambassador: evoked (HLA_EVOKED: evokeCallback and evokeMultipleCallbacks
deliver them on the caller's thread) or immediate (HLA_IMMEDIATE: a thread of the ambassador's delivers them
as they arrive), in both while enabled; and connectionLost, once, when the connection to the gateway is gone."""

from __future__ import annotations

import sys
import threading
import traceback
from typing import Any, Callable, Optional

from .. import _core
from ._callbacks import Adapter


class Delivery:
    """The callbacks of one connection: `inner` the HLA 1.3 ambassador, `adapter` its federate ambassador;
    `gone` is called once the connection is lost (after connectionLost)."""

    def __init__(self, inner: Any, adapter: Adapter, immediate: bool, gone: Callable[[], None]) -> None:
        self.inner, self.adapter = inner, adapter
        self.enabled = True
        # Held while the immediate thread delivers one callback: once set_enabled(False) returns, none starts.
        self._lock = threading.RLock()
        self.immediate = immediate
        self._gone = gone
        self._lost = False
        self._stop = threading.Event()
        self._thread: Optional[threading.Thread] = None
        if immediate:
            self._thread = threading.Thread(target=self._run, name="hlacore.rti1516e callbacks", daemon=True)
            self._thread.start()

    def pending(self) -> bool:
        """Whether callbacks wait to be delivered."""
        return not self._lost and (bool(self.adapter.local) or bool(self.inner._has_callbacks()))

    def one(self, wait: float) -> bool:
        """evokeCallback: one callback, waiting up to `wait` seconds for it."""
        if self.enabled and not self.immediate and not self.adapter.deliver_local():
            if self._guard(lambda: self.inner._wait(wait)):
                self._guard(lambda: self.inner._dispatch(self.adapter, False, 0.0))
        return self.pending()

    def many(self, minimum: float, maximum: float) -> bool:
        """evokeMultipleCallbacks: up to `minimum` seconds for the first, then what comes for `maximum`."""
        if self.enabled and not self.immediate:
            while self.adapter.deliver_local():
                pass
            self.inner._federate_ambassador = self.adapter
            self._guard(lambda: self.inner.tick(minimum, maximum))
        return self.pending()

    def set_enabled(self, on: bool) -> None:
        """enableCallbacks, disableCallbacks."""
        with self._lock:
            self.enabled = on

    def stop(self) -> None:
        """Ends the immediate thread (from any thread but its own, which it lets finish)."""
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=10)

    def _guard(self, call: Callable[[], Any]) -> Any:
        try:
            return call()
        except _core.RTIinternalError:
            why = self.inner._lost()
            if why is None or self._lost:
                raise
            self._lost = True
            self._stop.set()
            self.adapter.call("connectionLost", why)
            self._gone()
            return None

    def _run(self) -> None:
        while not self._stop.is_set():
            if not self.enabled:
                self._stop.wait(0.05)
                continue
            try:
                ready = self._guard(lambda: self.inner._wait(0.05))
                with self._lock:
                    if self.enabled and not self._lost and not self.adapter.deliver_local() and ready:
                        self._guard(lambda: self.inner._dispatch(self.adapter, False, 0.0))
            except Exception:  # nobody evokes to catch it: reported, and the next callback is delivered
                print("hlacore.rti1516e: a callback raised:", file=sys.stderr)
                traceback.print_exc()
