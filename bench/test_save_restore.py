"""Federation save and restore round trips with 1000 and 10000 objects over the standalone rtig (saves
kept in memory): keys save.N and restore.N (seconds per whole save or restore)."""

from __future__ import annotations

import pytest

from .save_restore import SaveRestore

ROUNDS = {1000: 30, 10000: 5}

pytestmark = pytest.mark.benchmark(group="save/restore")


@pytest.mark.parametrize("objects", sorted(ROUNDS))
@pytest.mark.parametrize("what", ["save", "restore"])
def test_save_restore(measure, rtig, objects: int, what: str) -> None:
    bench = SaveRestore(rtig.address, objects)
    try:
        measure(f"{what}.{objects}", getattr(bench, what), ROUNDS[objects])
    finally:
        bench.close()
