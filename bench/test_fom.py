"""FOM parse time of generated .fed files: a 1000-class × 10-attribute FOM through the C++ parser as the
gateway and createFederationExecution use it (`_core.parse_fed`) and through hlacore.fed's dataclasses on
top; and a 10 MB FOM (25 classes × 10 000 attributes), parsed, and created as a federation in an rtig."""

from __future__ import annotations

import pathlib

import pytest

import hlacore.fed
from hlacore import _core, rti
from hlacore.processes import Rtig

from .fomgen import generate_fed

ROUNDS = 30
LARGE_ROUNDS = 5

pytestmark = pytest.mark.benchmark(group="FOM parse")


@pytest.mark.parametrize("levels", [1, 3], ids=["flat", "tree"])
def test_parse_fed(measure, levels: int) -> None:
    text = generate_fed(1000, 10, levels)
    seconds = measure(f"fom.{'flat' if levels == 1 else 'tree'}", lambda: _core.parse_fed(text, "gen.fed"), ROUNDS)
    assert len(_core.parse_fed(text, "gen.fed")["object_classes"]) == 1002 and seconds


def test_parse_text_dataclasses(measure) -> None:
    text = generate_fed(1000, 10, 3)
    measure("fom.tree.python", lambda: hlacore.fed.parse_text(text, "gen.fed"), ROUNDS)


def test_parse_10mb_fed(measure) -> None:
    text = generate_fed(25, 10_000)
    assert len(text) > 10_000_000
    measure("fom.10mb", lambda: _core.parse_fed(text, "gen.fed"), LARGE_ROUNDS)
    classes = _core.parse_fed(text, "gen.fed")["object_classes"]
    assert len(classes) == 27 and len(classes[-1][5]) == 10_001  # privilegeToDelete inherited


def test_create_federation_from_10mb_fed(measure, rtig: Rtig, tmp_path: pathlib.Path) -> None:
    """createFederationExecution + destroyFederationExecution: the client's own check of the file, the 10 MB
    sent, the gateway's parse."""
    fed = tmp_path / "gen.fed"
    fed.write_text(generate_fed(25, 10_000))
    rtia = rti.RTIAmbassador(rtig.address, timeout=60.0)  # the gateway took seconds before its parser was linear

    def create_and_destroy() -> None:
        rtia.createFederationExecution("Big", str(fed))
        rtia.destroyFederationExecution("Big")

    measure("fom.10mb.rtig", create_and_destroy, LARGE_ROUNDS)
