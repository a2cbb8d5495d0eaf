"""Short runs of the libFuzzer targets of cpp/fuzz (the wire decoder, the .fed parser, the OMT XML reader, the
JSON reader of the status report, a gateway session, the gateway's datagram port, hlacore-rtia's decoder of CERTI's protocol), and replays of their seed corpus and of the inputs that once failed
(cpp/fuzz/regressions/).

scripts/test.sh builds the targets (`scripts/fuzz.sh --build-only`, which installs clang when missing) and
points $HLACORE_TEST_FUZZERS at them. Without them these tests skip, except under CI=true where they fail.
Longer runs: `scripts/fuzz.sh SECONDS`."""

from __future__ import annotations

import os
import pathlib
import re
import subprocess

import pytest

from support import DATA, ROOT

FUZZ = ROOT / "cpp" / "fuzz"
FED_DATA = DATA / "fed"
SECONDS = int(os.environ.get("HLACORE_TEST_FUZZ_SECONDS", "10"))
SEEDS = {
    "wire": [FUZZ / "corpus" / "wire"],
    "fed": [FED_DATA / "good", FED_DATA / "bad"],
    "omt": [FUZZ / "corpus" / "omt"],
    "json": [FUZZ / "corpus" / "json"],
    "gateway": [FUZZ / "corpus" / "wire"],
    "datagram": [FUZZ / "corpus" / "wire"],
    "certi": [FUZZ / "corpus" / "certi"],
    "fedpro": [FUZZ / "corpus" / "fedpro"],
    "websocket": [FUZZ / "corpus" / "websocket"],
    "zip": [FUZZ / "corpus" / "zip"],
}
OPTIONS = {"wire": [], "fed": [f"-dict={FUZZ / 'fed.dict'}"], "omt": [], "json": [], "gateway": [], "datagram": [],
           "certi": [], "fedpro": [], "websocket": [], "zip": []}
TARGETS = list(SEEDS)
FAILURE = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|deadly signal|SUMMARY:")


def fuzzer(target: str) -> pathlib.Path:
    directory = os.environ.get("HLACORE_TEST_FUZZERS")
    path = pathlib.Path(directory) / f"fuzz_{target}" if directory else None
    if path is None or not path.is_file():
        why = f"fuzz_{target} is not built ($HLACORE_TEST_FUZZERS={directory!r}): run ./scripts/test.sh"
        if os.environ.get("CI") == "true":
            pytest.fail(why)
        pytest.skip(why)
    return path


def seed_dirs(target: str) -> list[pathlib.Path]:
    """The committed seeds, plus for the wire targets a sample frame of every message, which
    scripts/fuzz.sh has wire_seeds write next to the fuzzers."""
    if target in ("fed", "omt", "json", "certi", "fedpro", "websocket", "zip"):
        return SEEDS[target]
    return [*SEEDS[target], fuzzer(target).parent / "seeds-wire"]


def files_of(*directories: pathlib.Path) -> list[str]:
    return sorted(str(p) for d in directories for p in d.rglob("*") if p.is_file() and not p.name.startswith(".") and p.name != "README.md")


@pytest.mark.slow
@pytest.mark.parametrize("target", TARGETS)
def test_short_fuzz_run(target: str, tmp_path: pathlib.Path) -> None:
    """Each target runs SECONDS (10) from the committed seeds without a crash, a sanitizer report, a leak, a
    timeout or a failed consistency check (round trip of every decoded frame, handles of every parsed FOM, the
    gateway closing every session)."""
    binary = fuzzer(target)
    scratch = tmp_path / "corpus"
    scratch.mkdir()
    proc = subprocess.run(
        [str(binary), f"-max_total_time={SECONDS}", "-timeout=10", "-rss_limit_mb=2048", "-print_final_stats=1",
         f"-artifact_prefix={tmp_path}/", *OPTIONS[target], str(scratch), *map(str, seed_dirs(target))],
        stdin=subprocess.DEVNULL, capture_output=True, text=True, errors="replace", timeout=SECONDS + 90,
    )  # fmt: skip
    log = proc.stderr
    assert proc.returncode == 0 and not FAILURE.search(log), log[-5000:]
    assert not list(tmp_path.glob("crash-*")) and not list(tmp_path.glob("leak-*"))
    executions = int(re.search(r"stat::number_of_executed_units: *(\d+)", log).group(1))  # type: ignore[union-attr]
    coverage = re.findall(r"cov: (\d+)", log)
    assert executions > 0
    print(f"fuzz_{target}: {executions} executions in {SECONDS} s, cov {coverage[-1] if coverage else '?'}")


@pytest.mark.parametrize("target", TARGETS)
def test_seeds_and_regressions_replay(target: str) -> None:
    """Every committed seed and regression input runs once through its target cleanly; the wire seeds are all
    valid frames (HLACORE_FUZZ_EXPECT_VALID: a complete frame that does not decode aborts)."""
    binary = fuzzer(target)
    regressions = files_of(FUZZ / "regressions" / target)
    seeds = files_of(*seed_dirs(target))
    assert seeds
    runs = [(seeds, {"HLACORE_FUZZ_EXPECT_VALID": "1"} if target == "wire" else {})]
    if regressions:
        runs.append((regressions, {}))
    for inputs, env in runs:
        proc = subprocess.run(
            [str(binary), *inputs], stdin=subprocess.DEVNULL, capture_output=True, text=True, errors="replace", timeout=120,
            env=dict(os.environ, **env),
        )  # fmt: skip
        assert proc.returncode == 0 and not FAILURE.search(proc.stderr), proc.stderr[-5000:]
        assert proc.stderr.count("Executed ") == len(inputs), proc.stderr[-5000:]


def test_every_message_has_a_generated_seed() -> None:
    """wire_seeds wrote one frame per message of the list (the replay above shows each decodes and
    re-encodes to the same bytes), so a new message is fuzzed from a valid frame at once."""
    from hlacore import _core

    generated = fuzzer("wire").parent / "seeds-wire"
    assert {p.stem for p in generated.glob("*.bin")} == set(_core._message_names())
