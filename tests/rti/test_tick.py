"""tick(): evoking callbacks, waiting with the GIL released, Ctrl-C, exceptions raised by callbacks."""

import array
import fcntl
import os
import select
import signal
import socket
import termios
import threading
import time
import traceback

import pytest

import hlacore.rti as rti

from support import ROBOT_FED, barrier, python_subprocess, share_robot_location, tick_until


@pytest.fixture
def robot_pair(federation):
    pub, sub = federation("publisher"), federation("subscriber")
    robot, location = share_robot_location(pub, sub)
    barrier(sub.rtia)
    obj = pub.rtia.registerObjectInstance(robot)
    return pub, sub, obj, location


def test_tick_without_arguments_returns_at_once_when_idle(federation):
    """tick() does not wait: with nothing to deliver it returns False immediately."""
    fed = federation("a")
    assert fed.rtia.tick() is False


def test_tick_waits_up_to_minimum_for_the_first_callback(federation):
    """tick(min, max) with nothing to deliver waits about min seconds, then returns False."""
    fed = federation("a")
    start = time.monotonic()
    assert fed.rtia.tick(0.3, 1.0) is False
    assert time.monotonic() - start >= 0.25


def test_blocking_tick_releases_the_gil_and_wakes_on_arrival(robot_pair):
    """While one thread waits in tick(10, 10), another thread runs Python and its update ends the wait."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    progress = []

    def other_thread():
        for i in range(50):
            progress.append(i)
            time.sleep(0.002)
        pub.rtia.updateAttributeValues(obj, {location: b"wake"}, "")

    thread = threading.Thread(target=other_thread)
    thread.start()
    sub.rtia.tick(10.0, 10.0)
    thread.join()
    assert len(progress) == 50
    assert sub.amb.named("reflectAttributeValues")[0][1] == {location: b"wake"}


def test_exception_in_callback_propagates_and_keeps_the_rest_queued(robot_pair):
    """A callback's exception leaves tick() with its traceback; the undelivered callbacks come next tick."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    seen = []

    def reflectAttributeValues(obj, attributes, tag, order, transport, time=None, retraction=None):
        seen.append(attributes[location])
        if attributes[location] == b"0":
            raise ValueError("user bug in reflect")

    sub.amb.reflectAttributeValues = reflectAttributeValues
    for i in range(3):
        pub.rtia.updateAttributeValues(obj, {location: str(i).encode()}, "")
    deadline = time.monotonic() + 5
    with pytest.raises(ValueError, match="user bug") as error:
        while time.monotonic() < deadline:
            sub.rtia.tick(0.05, 0.5)
    frames = [frame.name for frame in traceback.extract_tb(error.value.__traceback__)]
    assert "reflectAttributeValues" in frames
    tick_until(lambda: len(seen) == 3, sub.rtia)
    assert seen == [b"0", b"1", b"2"]


def test_callbacks_may_call_the_rti(robot_pair):
    """A callback can call RTI services (re-entrantly, on the ticking thread)."""
    pub, sub, obj, location = robot_pair

    def discoverObjectInstance(o, cls, name):
        sub.rtia.requestObjectAttributeValueUpdate(o, [location])

    sub.amb.discoverObjectInstance = discoverObjectInstance
    tick_until(lambda: pub.amb.named("provideAttributeValueUpdate"), sub.rtia, pub.rtia)
    assert pub.amb.named("provideAttributeValueUpdate") == [(obj, (location,))]


def test_tick_stops_delivering_after_maximum(robot_pair):
    """tick(minimum, maximum) delivers for at most maximum seconds; what is left stays queued."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    seen: list[bytes] = []

    def slow_reflection(o, attributes, *rest):
        seen.append(attributes[location])
        time.sleep(0.02)

    sub.amb.reflectAttributeValues = slow_reflection
    for i in range(20):
        pub.rtia.updateAttributeValues(obj, {location: b"%d" % i}, "")
    barrier(pub.rtia)  # the gateway has forwarded them ...
    barrier(sub.rtia)  # ... and the subscriber has queued them, reading up to its answer
    assert sub.rtia.tick(0.05, 0.1) is True  # 20 callbacks of 20 ms do not fit in 0.1 s
    assert 1 <= len(seen) <= 8
    tick_until(lambda: len(seen) == 20, sub.rtia)
    assert seen == [b"%d" % i for i in range(20)]


def test_tick_returns_true_while_the_socket_holds_frames_not_yet_read(robot_pair):
    """A read takes small frames a batch at a time (client.hpp, kReadBatchBytes): tick() counts the frames the
    read left in the socket as pending, so `while tick()` delivers everything that had arrived."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    seen: list[bytes] = []
    sub.amb.reflectAttributeValues = lambda o, attributes, *rest: seen.append(attributes[location])
    with socket.socket(fileno=os.dup(sub.rtia.fileno())) as conn:
        conn.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)  # room for several batches
        count = 8000  # about 40 bytes each on the wire: 320 kB, more than two batches
        for i in range(count):
            pub.rtia.updateAttributeValues(obj, {location: b"%d" % i}, "")
        barrier(pub.rtia)  # the gateway has taken them
        waiting = array.array("i", [0])
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            fcntl.ioctl(conn.fileno(), termios.FIONREAD, waiting)
            if waiting[0] >= count * 38:
                break
            time.sleep(0.01)
        assert waiting[0] >= count * 38, f"only {waiting[0]} bytes reached the subscriber's socket"
    ticks = 0
    while sub.rtia.tick() and ticks < 1000:
        ticks += 1
    assert seen == [b"%d" % i for i in range(count)]
    assert ticks >= 2  # each tick() delivered a batch and said more was waiting


def test_a_method_replaced_between_ticks_is_the_one_called(robot_pair):
    """The ambassador's methods are looked up once per tick (cpp/bindings/callbacks.cpp), not kept beyond it."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    first: list[bytes] = []
    second: list[bytes] = []
    sub.amb.reflectAttributeValues = lambda o, attributes, *rest: first.append(attributes[location])
    pub.rtia.updateAttributeValues(obj, {location: b"1"}, "")
    tick_until(lambda: first, sub.rtia)
    sub.amb.reflectAttributeValues = lambda o, attributes, *rest: second.append(attributes[location])
    pub.rtia.updateAttributeValues(obj, {location: b"2"}, "")
    tick_until(lambda: second, sub.rtia)
    assert (first, second) == ([b"1"], [b"2"])


def test_missing_callbacks_are_ignored(federation):
    """A FederateAmbassador without a callback method simply does not get that callback."""
    registrar = federation("registrar")
    bare = rti.RTIAmbassador(registrar.rtia.address)
    bare.joinFederationExecution("bare", "TestFed", rti.FederateAmbassador())
    registrar.rtia.registerFederationSynchronizationPoint("x", "")
    barrier(registrar.rtia)
    bare.tick(0.5, 0.5)
    bare.synchronizationPointAchieved("x")  # accepted: the announcement was delivered (and ignored)
    bare.resignFederationExecution(rti.ResignAction.NoAction)


def test_fileno_becomes_readable_when_a_callback_arrives(robot_pair):
    """fileno() lets another event loop wait for callbacks with select()."""
    pub, sub, obj, location = robot_pair
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    readable, _, _ = select.select([sub.rtia.fileno()], [], [], 0)
    assert readable == []
    pub.rtia.updateAttributeValues(obj, {location: b"x"}, "")
    readable, _, _ = select.select([sub.rtia.fileno()], [], [], 5)
    assert readable == [sub.rtia.fileno()]


def test_ctrl_c_interrupts_a_blocking_tick(gateway_address):
    """SIGINT ends a tick(30, 30) wait in another process with KeyboardInterrupt, promptly."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    with python_subprocess("tick_forever.py", gateway_address) as proc:
        assert proc.read_line(30) == "ticking"
        time.sleep(0.2)  # let it enter the wait; the signal must interrupt a wait in progress
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=10) == 0, proc.stderr()
        assert proc.read_line(5).startswith("interrupted after")
    creator.destroyFederationExecution("TestFed")
