"""hlacore.processes: reports are read with a deadline, errors and exits are named, everything is ended by pid."""

from __future__ import annotations

import pathlib
import signal

import pytest

from hlacore.processes import Rtig, python_peer

from support import rtig_executable


def script(tmp_path: pathlib.Path, body: str) -> pathlib.Path:
    path = tmp_path / "peer.py"
    path.write_text("import json, sys, time\n" + body)
    return path


def test_reports_are_read_in_order_even_when_printed_together(tmp_path: pathlib.Path) -> None:
    peer = python_peer(script(tmp_path, 'print(json.dumps({"a": 1})); print(json.dumps({"b": 2}))\n'))
    with peer:
        assert peer.read_json(10) == {"a": 1}
        assert peer.read_json(10) == {"b": 2}
        assert peer.wait(10) == 0


def test_a_silent_peer_fails_the_read_at_its_deadline_and_is_killed_on_close(tmp_path: pathlib.Path) -> None:
    with python_peer(script(tmp_path, "time.sleep(60)\n")) as peer:
        with pytest.raises(RuntimeError, match="no line from pid"):
            peer.read_line(0.3)
    assert peer.poll() == -signal.SIGKILL


def test_an_error_report_or_an_exit_is_named_with_the_peer_stderr(tmp_path: pathlib.Path) -> None:
    with python_peer(script(tmp_path, 'print(json.dumps({"error": "timeout"}))\n')) as peer:
        with pytest.raises(RuntimeError, match="reported {'error': 'timeout'}"):
            peer.read_json(10)
    with python_peer(script(tmp_path, 'sys.stderr.write("it broke"); sys.exit(4)\n')) as peer:
        with pytest.raises(RuntimeError, match=r"exited \(4\); stderr: it broke"):
            peer.read_line(10)


def test_rtig_runs_on_a_free_port_and_stops_cleanly(tmp_path: pathlib.Path) -> None:
    with Rtig(executable=rtig_executable(), log_path=tmp_path / "rtig.log") as server:
        host, port = server.address.rsplit(":", 1)
        assert host == "127.0.0.1" and int(port) > 0
    assert server.proc.returncode == 0
    assert (tmp_path / "rtig.log").exists()
