"""FOM parse time of a generated 1000-class × 10-attribute .fed: the C++ parser as the gateway and
createFederationExecution use it (`_core.parse_fed`), and hlacore.fed's dataclasses on top."""

from __future__ import annotations

import pytest

import hlacore.fed
from hlacore import _core

from .fomgen import generate_fed

ROUNDS = 30

pytestmark = pytest.mark.benchmark(group="FOM parse")


@pytest.mark.parametrize("levels", [1, 3], ids=["flat", "tree"])
def test_parse_fed(measure, levels: int) -> None:
    text = generate_fed(1000, 10, levels)
    seconds = measure(f"fom.{'flat' if levels == 1 else 'tree'}", lambda: _core.parse_fed(text, "gen.fed"), ROUNDS)
    assert len(_core.parse_fed(text, "gen.fed")["object_classes"]) == 1002 and seconds


def test_parse_text_dataclasses(measure) -> None:
    text = generate_fed(1000, 10, 3)
    measure("fom.tree.python", lambda: hlacore.fed.parse_text(text, "gen.fed"), ROUNDS)
