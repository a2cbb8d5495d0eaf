"""Where a bench run leaves its figures: build/bench/ always (results.json, results.md, the plot); and,
when every figure of the full run was measured, docs/grant-latency.png and the generated part of
docs/performance.md (between its two marker lines), so a partial run (-k) never overwrites the docs."""

from __future__ import annotations

import json
import pathlib
import shutil

from .report import Report

ROOT = pathlib.Path(__file__).resolve().parent.parent
BUILD = ROOT / "build" / "bench"
DOC = ROOT / "docs" / "performance.md"
BEGIN, END = "<!-- bench results: begin (written by ./scripts/bench.sh) -->", "<!-- bench results: end -->"
# The three-RTI table, written whenever a run measured all of it (./scripts/bench.sh -k three_rtis does).
RTIS_BEGIN = "<!-- three RTIs: begin (written by ./scripts/bench.sh -k three_rtis) -->"
RTIS_END = "<!-- three RTIs: end -->"


def results_markdown(report: Report, machine: dict[str, str], command: str) -> str:
    lines = [f"Measured {machine['date']} by `{command}`.", "", "| machine | |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in machine.items() if k != "date"]
    return "\n".join(lines) + "\n\n" + report.markdown()


def write(report: Report, machine: dict[str, str], command: str) -> list[pathlib.Path]:
    """Write the outputs; returns the paths written."""
    from .plot import grant_latency_png  # matplotlib only when the bench extras are installed

    BUILD.mkdir(parents=True, exist_ok=True)
    text = results_markdown(report, machine, command)
    written = [BUILD / "results.json", BUILD / "results.md"]
    written[0].write_text(json.dumps({"machine": machine, "command": command, "figures": report.summary(),
                                      "samples": report.samples}, indent=1) + "\n")
    written[1].write_text(text)
    png = BUILD / "grant-latency.png"
    if grant_latency_png(report, png):
        written.append(png)
    if report.three_rtis_complete():
        load = machine["load average (1 min) at start / end"]
        lines = [f"Measured {machine['date']} by `{command}` on {machine['cores']} cores of {machine['cpu']} "
                 f"(load average at start / end {load}).", "", report.three_rtis_markdown()]
        if _replace_section(DOC, "\n".join(lines), RTIS_BEGIN, RTIS_END) and DOC not in written:
            written.append(DOC)
    if report.complete():
        shutil.copyfile(png, ROOT / "docs" / "grant-latency.png")
        written.append(ROOT / "docs" / "grant-latency.png")
        if _replace_section(DOC, text) and DOC not in written:
            written.append(DOC)
    return written


def _replace_section(path: pathlib.Path, text: str, begin: str = BEGIN, end: str = END) -> bool:
    doc = path.read_text() if path.exists() else ""
    if begin not in doc or end not in doc:
        return False
    head, rest = doc.split(begin, 1)
    _, tail = rest.split(end, 1)
    path.write_text(f"{head}{begin}\n{text}\n{end}{tail}")
    return True
