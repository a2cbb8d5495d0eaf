"""Test hosts: network namespaces on this machine, each joined to the root namespace by a veth pair, so a test
runs a gateway and federates "on different machines". The `nethosts` fixture (tests/conftest.py) makes them.

Host k gets 10.213.k.1 inside its namespace; the root namespace holds 10.213.k.254 on the other end. There
is no route between the hosts: whatever crosses from one to another goes through a relay that the test runs
in the root namespace (hlacore.link.Link, listening on a host's .254 address and connecting to another
host's .1), which is where the emulated link sits. ``lan(a, b)`` wires two hosts directly instead (a veth
pair between their namespaces, 10.214.n.1 and .2), for traffic a relay cannot carry (ROS 1 nodes connect
to each other on ports they choose). Everything is removed at the end, also after a failure;
names carry this process's pid so that parallel runs do not collide, and the test processes of one run
(pytest-xdist's workers) number their hosts apart, 16 each, since the root namespace holds every host's .254
address. ``LoopbackNamespace`` is a namespace
with loopback only and no link out, for ROS 2's DDS.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
from dataclasses import dataclass

SUBNET = "10.213"
LAN_SUBNET = "10.214"
HOSTS_PER_WORKER = 16


def _first_host() -> int:
    worker = os.environ.get("PYTEST_XDIST_WORKER", "gw0")  # gw0, gw1, ... under pytest-xdist
    return 1 + HOSTS_PER_WORKER * int(worker[2:] or 0)


@dataclass(frozen=True)
class Host:
    name: str
    namespace: str
    address: str  # inside the namespace
    router: str  # its peer address in the root namespace, where relays towards it listen

    def exec_prefix(self) -> list[str]:
        """What runs a command inside this host: prefix it to the argv."""
        return ["ip", "netns", "exec", self.namespace]


class NetHosts:
    def __init__(self) -> None:
        self.hosts: list[Host] = []
        self._links: list[str] = []
        self._lans: list[tuple[str, str]] = []  # (namespace, one end of the pair)
        self._tag = f"hlc{os.getpid() % 100000}"

    def add(self, name: str) -> Host:
        if len(self.hosts) == HOSTS_PER_WORKER:
            raise ValueError(f"at most {HOSTS_PER_WORKER} test hosts")
        k = _first_host() + len(self.hosts)
        namespace, outside, inside = f"{self._tag}-{name}", f"{self._tag}o{k}", f"{self._tag}i{k}"
        host = Host(name, namespace, f"{SUBNET}.{k}.1", f"{SUBNET}.{k}.254")
        _ip("netns", "add", namespace)
        self.hosts.append(host)
        _ip("link", "add", outside, "type", "veth", "peer", "name", inside)
        self._links.append(outside)
        _ip("link", "set", inside, "netns", namespace)
        _ip("addr", "add", f"{host.router}/24", "dev", outside)
        _ip("link", "set", outside, "up")
        for args in (("addr", "add", f"{host.address}/24", "dev", inside), ("link", "set", inside, "up"),
                     ("link", "set", "lo", "up")):
            _ip("-n", namespace, *args)
        return host

    def lan(self, a: Host, b: Host) -> tuple[str, str]:
        """A direct link between hosts `a` and `b`; returns their addresses on it."""
        n = len(self._lans) + 1
        end_a, end_b = f"{self._tag}a{n}", f"{self._tag}b{n}"
        ips = (f"{LAN_SUBNET}.{n}.1", f"{LAN_SUBNET}.{n}.2")
        _ip("link", "add", end_a, "netns", a.namespace, "type", "veth", "peer", "name", end_b, "netns", b.namespace)
        self._lans.append((a.namespace, end_a))
        for host, end, ip in ((a, end_a, ips[0]), (b, end_b, ips[1])):
            _ip("-n", host.namespace, "addr", "add", f"{ip}/24", "dev", end)
            _ip("-n", host.namespace, "link", "set", end, "up")
        return ips

    def close(self) -> None:
        for namespace, end in self._lans:
            subprocess.run(["ip", "-n", namespace, "link", "del", end], capture_output=True)
        self._lans.clear()
        for link in self._links:  # deleting one end removes the pair
            subprocess.run(["ip", "link", "del", link], capture_output=True)
        for host in self.hosts:
            subprocess.run(["ip", "netns", "del", host.namespace], capture_output=True)
        self._links.clear()
        self.hosts.clear()


def _ip(*args: str) -> None:
    result = subprocess.run(["ip", *args], capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"ip {' '.join(args)}: {result.stderr.strip()}")


def namespaces_unavailable() -> str:
    """Why network namespaces cannot be made here, or "" when they can."""
    if not shutil.which("ip"):
        return "the ip command (Debian's iproute2) is not installed"
    probe = f"hlc{os.getpid() % 100000}-probe"
    made = subprocess.run(["ip", "netns", "add", probe], capture_output=True, text=True)
    if made.returncode != 0:
        return f"ip netns add failed: {made.stderr.strip()}"
    subprocess.run(["ip", "netns", "del", probe], capture_output=True)
    return ""



class LoopbackNamespace:
    """A network namespace with nothing but its loopback interface, for processes whose sockets must not
    leave it (ROS 2's DDS binds every interface it sees: here there is only ``lo``). Made on ``__enter__``;
    on ``__exit__`` every process still inside is killed by pid (they are this test's: the namespace is
    new) and the namespace is removed; :attr:`leftovers` then names the pids that had to be killed."""

    def __init__(self, name: str) -> None:
        self.name = f"hlc{os.getpid() % 100000}-{name}"
        self.leftovers: list[int] = []

    def exec_prefix(self) -> list[str]:
        """What runs a command inside the namespace: prefix it to the argv (``ip netns exec`` execs the
        command in place, so the started pid is the command's)."""
        return ["ip", "netns", "exec", self.name]

    def inode(self) -> int:
        """The namespace's identity: a process is inside iff ``/proc/PID/ns/net`` has this inode."""
        return os.stat(f"/run/netns/{self.name}").st_ino

    def pids(self) -> list[int]:
        """The processes inside the namespace now."""
        done = subprocess.run(["ip", "netns", "pids", self.name], capture_output=True, text=True)
        return [int(p) for p in done.stdout.split()]

    def links(self) -> list[str]:
        """The namespace's network interfaces."""
        done = subprocess.run(["ip", "-n", self.name, "-o", "link", "show"], capture_output=True, text=True,
                              check=True)
        return [line.split(":")[1].strip().split("@")[0] for line in done.stdout.splitlines()]

    def __enter__(self) -> "LoopbackNamespace":
        _ip("netns", "add", self.name)
        try:
            _ip("-n", self.name, "link", "set", "lo", "up")
        except BaseException:
            subprocess.run(["ip", "netns", "del", self.name], capture_output=True)
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        self.leftovers = self.pids()
        for pid in self.leftovers:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        subprocess.run(["ip", "netns", "del", self.name], capture_output=True)
