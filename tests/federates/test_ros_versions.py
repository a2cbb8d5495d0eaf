"""Which ROS the bridge speaks, and what a ROS 2 process is given: ``versions.detect``, ``ros2_env.environment``,
and the pins of ros2-requirements.txt and what its installer finds missing. No ROS runs here."""

from __future__ import annotations

import importlib.metadata as metadata
import os
import pathlib
import re
import sysconfig

import pytest

from hlacore.federates.ros_bridge import install_ros2, ros2_env
from hlacore.federates.ros_bridge.versions import detect

@pytest.mark.parametrize("env, expected", [
    ({"ROS_VERSION": "2", "ROS_MASTER_URI": "http://127.0.0.1:11311"}, 2),  # a setup script said so
    ({"ROS_VERSION": "1"}, 1),
    ({"ROS_MASTER_URI": "http://127.0.0.1:11311"}, 1),  # a ROS 1 user's shell
    ({}, 1),  # nothing: ROS 2 is neither installed (the empty prefix) nor importable here
])
def test_detect_follows_the_environment_then_what_is_installed(monkeypatch: pytest.MonkeyPatch,
                                                               tmp_path: pathlib.Path, env: dict[str, str],
                                                               expected: int) -> None:
    """$ROS_VERSION first, then $ROS_MASTER_URI, then whether ROS 2 is there."""
    for name in ("ROS_VERSION", "ROS_MASTER_URI"):
        monkeypatch.delenv(name, raising=False)
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    monkeypatch.setenv("HLACORE_ROS2_PREFIX", str(tmp_path))
    assert detect() == expected

def test_detect_picks_ros2_when_its_wheels_are_installed(monkeypatch: pytest.MonkeyPatch,
                                                         tmp_path: pathlib.Path) -> None:
    """A prefix holding rclpy and the Fast DDS middleware's library is ROS 2, installed."""
    for name in ("ROS_VERSION", "ROS_MASTER_URI"):
        monkeypatch.delenv(name, raising=False)
    rclpy = pathlib.Path(ros2_env.site_packages(str(tmp_path))) / "rclpy"
    rclpy.mkdir(parents=True)
    (rclpy / "__init__.py").write_text("")
    (tmp_path / "lib" / "librmw_fastrtps_cpp.so").write_bytes(b"")
    monkeypatch.setenv("HLACORE_ROS2_PREFIX", str(tmp_path))
    assert ros2_env.installed() and detect() == 2

def test_a_ros2_process_gets_the_wheels_paths_in_front_and_keeps_its_own(monkeypatch: pytest.MonkeyPatch,
                                                                        tmp_path: pathlib.Path) -> None:
    """PYTHONPATH and LD_LIBRARY_PATH start with the prefix's (site-packages; lib and every ros_*.libs) and
    keep what was there; the ament prefix, the middleware, Fast DDS's profile; building it twice changes
    nothing."""
    monkeypatch.setenv("HLACORE_ROS2_PREFIX", str(tmp_path))
    packages = pathlib.Path(ros2_env.site_packages(str(tmp_path)))
    for libs in ("ros_rcl.libs", "ros_fastdds.libs"):
        (packages / libs).mkdir(parents=True)
    base = {"PYTHONPATH": "/mine", "LD_LIBRARY_PATH": "/usr/local/lib", "PATH": "/bin"}
    env = ros2_env.environment(base, domain_id=7, log_dir="/tmp/logs")
    assert env["PYTHONPATH"].split(os.pathsep) == [str(packages), "/mine"]
    assert env["LD_LIBRARY_PATH"].split(os.pathsep) == [str(tmp_path / "lib"), str(packages / "ros_fastdds.libs"),
                                                        str(packages / "ros_rcl.libs"), "/usr/local/lib"]
    assert env["AMENT_PREFIX_PATH"] == str(tmp_path) and env["RMW_IMPLEMENTATION"] == "rmw_fastrtps_cpp"
    assert env["ROS_DOMAIN_ID"] == "7" and env["ROS_LOG_DIR"] == "/tmp/logs" and env["PATH"] == "/bin"
    assert pathlib.Path(env["FASTDDS_DEFAULT_PROFILES_FILE"]).read_text().count("<leaseDuration>") == 1
    assert ros2_env.ready(env) and not ros2_env.ready(base)
    assert ros2_env.environment(env, domain_id=7, log_dir="/tmp/logs") == env

def test_every_ros2_wheel_is_pinned_to_a_version_and_a_hash() -> None:
    """ros2-requirements.txt, shipped in the package (this is the installed one): each requirement
    `name==version --hash=sha256:<64 hex>`, rclpy 9.1.2 and the Fast DDS middleware among them, no bootstrapper
    (its .pth re-executes every Python of the venv)."""
    lines = [line.split("#", 1)[0].strip() for line in install_ros2.REQUIREMENTS.read_text().splitlines()]
    pins = [line for line in lines if line]
    assert len(pins) > 50
    for pin in pins:
        assert re.fullmatch(r"[a-z0-9-]+==[0-9][0-9.]*( --hash=sha256:[0-9a-f]{64})+", pin), pin
    names = {pin.split("==")[0] for pin in pins}
    assert {"ros-rclpy", "ros-rmw-fastrtps-cpp", "ros-geometry-msgs", "ros-nav-msgs", "ros-sensor-msgs",
            "ros-std-msgs", "ros-rosgraph-msgs"} <= names
    assert "ros-wheels-bootstrapper" not in names and "ros-rclpy==9.1.2" in {p.split()[0] for p in pins}

def test_the_installer_lists_what_a_prefix_lacks(tmp_path: pathlib.Path) -> None:
    """install_ros2.missing: under an empty prefix every pin but the "# if missing" ones this Python has; under one
    holding a pinned wheel's metadata at its version, that one no more, at another version, still."""
    text = install_ros2.REQUIREMENTS.read_text()
    pins = [line.split("#", 1)[0].strip() for line in text.splitlines() if line.split("#", 1)[0].strip()]
    optional = [line.split("#", 1)[0].strip() for line in text.splitlines()
                if line.rstrip().endswith(install_ros2.IF_MISSING)]

    def here(pin: str) -> bool:
        try:
            return bool(metadata.version(pin.split("==")[0]))
        except metadata.PackageNotFoundError:
            return False

    assert optional
    assert set(install_ros2.missing(str(tmp_path))) == set(pins) - {pin for pin in optional if here(pin)}
    packages = pathlib.Path(sysconfig.get_path("purelib", vars={"base": str(tmp_path), "platbase": str(tmp_path)}))
    for version, listed in (("9.1.2", False), ("9.1.1", True)):
        info = packages / "ros_rclpy-9.1.2.dist-info"
        info.mkdir(parents=True, exist_ok=True)
        (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: ros-rclpy\nVersion: {version}\n")
        rclpy = [pin for pin in install_ros2.missing(str(tmp_path)) if pin.startswith("ros-rclpy==")]
        assert bool(rclpy) == listed
