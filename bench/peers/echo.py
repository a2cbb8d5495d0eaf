"""The far end of the raw TCP floors, in plain Python sockets (no hlacore).

usage: echo.py echo SIZE | echo.py sink RECORD BURST

Listens on 127.0.0.1, port 0, prints {"port": p} and serves one connection, with TCP_NODELAY as the
hlacore sockets have. echo: sends back every SIZE bytes it receives. sink: counts RECORD-byte records and
prints {"received": n} at every multiple of BURST. Exits when the connection closes.
"""

from __future__ import annotations

import json
import socket
import sys


def serve() -> socket.socket:
    with socket.create_server(("127.0.0.1", 0)) as listener:
        print(json.dumps({"port": listener.getsockname()[1]}), flush=True)
        conn, _ = listener.accept()
    conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return conn


def echo(conn: socket.socket, size: int) -> None:
    buf = bytearray(size)
    view = memoryview(buf)
    while True:
        got = 0
        while got < size:
            n = conn.recv_into(view[got:])
            if n == 0:
                return
            got += n
        conn.sendall(view)


def sink(conn: socket.socket, record: int, burst: int) -> None:
    total = reported = 0
    while chunk := conn.recv(1 << 20):
        total += len(chunk)
        while (total // record) >= reported + burst:
            reported += burst
            print(json.dumps({"received": reported}), flush=True)


def main() -> None:
    conn = serve()
    with conn:
        if sys.argv[1] == "echo":
            echo(conn, int(sys.argv[2]))
        else:
            sink(conn, int(sys.argv[2]), int(sys.argv[3]))


if __name__ == "__main__":
    main()
