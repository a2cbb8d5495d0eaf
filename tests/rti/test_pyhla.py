"""PyHLA scripts run unchanged: `python -m hlacore.pyhla SCRIPT` serves `import hla.rti` / `hla.omt`, and the
gateway is found through CERTI's CERTI_HOST / CERTI_TCP_PORT as PyHLA users set them."""

from __future__ import annotations

import os
import pathlib
import subprocess
import sys

import pytest

import hlacore.omt
import hlacore.pyhla
import hlacore.rti
from hlacore.processes import Child

from support import DATA

SCRIPTS = DATA / "pyhla"
COUNT = 10


def pyhla_script(name: str, *args: str, env: dict[str, str]) -> Child:
    return Child([sys.executable, "-m", "hlacore.pyhla", str(SCRIPTS / name), *args],
                 env=dict(os.environ, PYTHONUNBUFFERED="1", **env))


def test_pyhla_sender_and_receiver_run_unchanged_through_certi_variables(gateway_address: str) -> None:
    host, port = gateway_address.rsplit(":", 1)
    env = {"CERTI_HOST": host, "CERTI_TCP_PORT": port}
    fed = str(SCRIPTS / "uav.fed")
    with pyhla_script("uav-receive.py", str(COUNT), fed, env=env) as receiver:
        lines = [receiver.read_line(30)]
        while lines[-1] != "ready":
            lines.append(receiver.read_line(30))
        with pyhla_script("uav-send.py", str(COUNT), fed, env=env) as sender:
            assert sender.wait(60) == 0, sender.stderr()
        shown = [receiver.read_line(30)]
        while shown[-1] != "Done.":
            shown.append(receiver.read_line(30))
        assert receiver.wait(60) == 0, receiver.stderr()
    assert lines[:2] == ["Create ambassador", "Federation created."]
    assert shown[0] == "DISCOVER HAF SampleClass"
    reflections = [line.split() for line in shown if line.startswith("REFLECT")]
    assert [round(float(a), 2) for _, a, _, _ in reflections] == [round(3.14 + step, 2) for step in range(COUNT)]
    assert all(float(b) == pytest.approx(2.72, abs=1e-6) and tag == "update" for _, _, b, tag in reflections)


def test_install_serves_hlacores_modules_under_pyhlas_names() -> None:
    code = ("import hlacore.pyhla; hlacore.pyhla.install(); import hla.rti, hla.omt; from hla.rti import "
            "RTIAmbassador; import hlacore.rti, hlacore.omt; "
            "assert hla.rti is hlacore.rti and hla.omt is hlacore.omt and RTIAmbassador is hlacore.rti.RTIAmbassador; "
            "assert hlacore.pyhla.install() is __import__('sys').modules['hla']; print('ok')")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.stdout == "ok\n", done.stderr


def test_install_refuses_when_a_real_pyhla_is_imported(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "hla", type(sys)("hla"))
    with pytest.raises(ImportError, match="another 'hla' package is imported already"):
        hlacore.pyhla.install()


def test_a_missing_script_or_no_script_is_one_line_and_exit_2(tmp_path: pathlib.Path) -> None:
    missing = subprocess.run([sys.executable, "-m", "hlacore.pyhla", str(tmp_path / "nope.py")],
                             capture_output=True, text=True, timeout=60)
    assert (missing.returncode, missing.stderr) == (2, f"hlacore.pyhla: no such script: {tmp_path / 'nope.py'}\n")
    bare = subprocess.run([sys.executable, "-m", "hlacore.pyhla"], capture_output=True, text=True, timeout=60)
    assert bare.returncode == 2 and "usage: python -m hlacore.pyhla SCRIPT [ARGS...]" in bare.stderr


def test_the_scripts_exit_status_and_arguments_pass_through(tmp_path: pathlib.Path) -> None:
    script = tmp_path / "exits.py"
    script.write_text("import sys, hla.omt\nprint(sys.argv[1:], __name__)\nsys.exit(int(sys.argv[1]))\n")
    done = subprocess.run([sys.executable, "-m", "hlacore.pyhla", str(script), "3", "x"],
                          capture_output=True, text=True, timeout=60)
    assert (done.returncode, done.stdout) == (3, "['3', 'x'] __main__\n"), done.stderr
