"""Two federates in two processes exchange an object, an interaction and a synchronization point."""

import hlacore.rti as rti

from support import ROBOT_FED, python_subprocess

LOCATION = bytes(range(256)) + b"\x00tail"
COMMAND = b"go\x00\xff\xfe"


def test_robot_update_interaction_and_sync_point_across_processes(gateway_address):
    """A robot's location bytes, a command and its reply, and sync point 'start' cross two processes exactly."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    receiver = python_subprocess("robot_pair.py", gateway_address, "receiver")
    sender = None
    try:
        assert receiver.read_json() == {"joined": True}
        sender = python_subprocess("robot_pair.py", gateway_address, "sender")
        sent = sender.read_json()
        got = receiver.read_json()
        assert sender.wait(timeout=20) == 0, sender.stderr()
        assert receiver.wait(timeout=20) == 0, receiver.stderr()
    finally:
        for proc in (receiver, sender):
            if proc:
                proc.close()
    assert got["discovered_class"] == "robot"
    assert got["discovered_name"] == "robot-1"
    assert got["reflected"] == {"location": LOCATION.hex()}
    assert got["reflect_tag"] == "first fix"
    assert got["interaction"] == {"name": b"move".hex(), "value": COMMAND.hex()}
    assert got["removed"] is True
    assert sent["reply"] == COMMAND.hex()
    assert sent["reply_tag"] == "reply"
    assert got["synchronized"] == sent["synchronized"] == ["start"]
    creator.destroyFederationExecution("TestFed")
