"""The gateway's service-group state types on their own (tests/cpp/state_types_test.cpp, built with the
sanitizers by ./scripts/test.sh): regions and their overlap, a federate's DDM state, attribute ownership,
save/restore runs and files, held messages parked beyond a federate's share and the spill files; a
connection's read buffer, the values a federate decodes as views into it, and
the pieces of a stream with splices (wire/). The services built on them are tested through federates in the
group's own test file (test_ddm.py, test_ownership.py, test_save_restore.py), the buffers by
test_large_values.py."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

from support import ROOT

CASES = ["regions_from_bounds", "regions_overlap", "federate_regions", "attribute_ownership",
         "save_restore_runs", "save_restore_files", "read_buffer", "viewed_values", "splices_gather",
         "time_parking", "spill_files"]


def test_every_case_passes() -> None:
    default = ROOT / "build/asan/state_types_test"
    binary = Path(os.environ.get("HLACORE_TEST_STATE_TYPES", default))
    assert binary.exists(), f"{binary} is missing: ./scripts/test.sh builds it"
    run = subprocess.run([str(binary)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.split("\n")[:-1] == [f"ok {case}" for case in CASES]
