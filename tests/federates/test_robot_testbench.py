"""The testbench actors on the standalone DE director: reference, checker, display, delays, trace, plot."""

from __future__ import annotations

import csv
import dataclasses
import math
import pathlib

import pytest

from hlacore.federates.de import Director, Received, Recorder, TimedSource
from hlacore.federates.robot_driver import PAPER_5X5, LocationReport
from hlacore.trace import Hop
from hlacore.federates.testbench import (
    Checker,
    Display,
    ReferenceModel,
    Sequencer,
    Stats,
    cycle_hops,
    delay_table,
    format_table,
    write_plot,
    write_trace,
)

from support import PAPER_PATH


def report(cycle: int, cell: tuple[int, int], t: float = 100.0) -> LocationReport:
    return LocationReport(cycle, cell, cell, (cell[0] * 0.33, cell[1] * 0.33, 90.0), 1.0, ("goFront",),
                          t_action=t, t_send=t + 0.001, t_cycle=0.1)


def bench(arrivals: list[tuple[float, Received]], cycles: int = 4, precision: float = 0.25):
    """Sequencer -> reference -> checker <- a timed source of received reports; checker -> display."""
    director = Director()
    sequencer = Sequencer("sequencer", PAPER_5X5)
    reference = ReferenceModel("reference", cycles, latency=0.5)
    robot = TimedSource("robot", arrivals)
    checker = Checker("checker", precision)
    lines: list[str] = []
    display = Display("display", precision, lines.append)
    verdicts = Recorder("verdicts")
    sequencer.output.connect(reference.input)
    reference.output.connect(checker.expected)
    robot.output.connect(checker.actual)
    checker.output.connect(display.input, verdicts.input)
    director.add(sequencer, reference, robot, checker, display, verdicts)
    director.run()
    return checker, lines, verdicts


def received(cycle: int, cell: tuple[int, int], time: float, timestamp=None) -> tuple[float, Received]:
    return time, Received("robot", {"location": report(cycle, cell)}, timestamp, time, f"cycle {cycle}")


def test_reference_model_emits_the_a_star_mission_at_cycle_times():
    director = Director()
    sequencer, reference, sink = Sequencer("s", PAPER_5X5), ReferenceModel("r", 15, latency=0.5), Recorder("k")
    sequencer.output.connect(reference.input)
    reference.output.connect(sink.input)
    director.add(sequencer, reference, sink)
    director.run()
    assert [e.cell for e in sink.values] == PAPER_PATH
    assert [e.time for e in sink.values] == [k + 0.5 for k in range(15)]
    assert sink.times == [k + 0.5 for k in range(15)]


def test_checker_passes_matching_reports_on_time():
    checker, lines, verdicts = bench([received(k, PAPER_PATH[k], k + 0.5, k + 0.5) for k in range(4)])
    assert [v.cycle for v in verdicts.values] == [0, 1, 2, 3]
    assert not checker.value_errors and not checker.time_errors
    assert all(line.endswith("ok") for line in lines)


def test_checker_classifies_value_and_time_errors():
    arrivals = [
        received(0, PAPER_PATH[0], 0.5),
        received(1, (1, 1), 1.5),          # wrong cell, on time
        received(2, PAPER_PATH[2], 3.0),   # right cell, late
    ]                                      # cycle 3: never comes
    checker, lines, _ = bench(arrivals)
    missing = checker.finish()
    assert [v.cycle for v in missing] == [3]
    assert [v.cycle for v in checker.value_errors] == [1]
    assert [v.cycle for v in checker.time_errors] == [2, 3]
    assert "VALUE ERROR" in lines[1] and "TIME ERROR" not in lines[1]
    assert "TIME ERROR" in lines[2] and "VALUE ERROR" not in lines[2]


def test_stats_and_table_form():
    stats = Stats.of([0.1, 0.2, 0.3])
    assert (stats.mean, stats.max, stats.min, stats.count) == pytest.approx((200.0, 300.0, 100.0, 3))
    assert stats.std == pytest.approx(math.sqrt(20000 / 3))
    assert Stats.of([]).count == 0
    checker, _, _ = bench([received(k, PAPER_PATH[k], k + 0.5) for k in range(4)])
    table = delay_table(checker.verdicts, {k: 100.003 for k in range(4)})
    assert table["C^emb->DE"].mean == pytest.approx(2.0)
    assert table["t_cycle^emb"].mean == pytest.approx(100.0)
    text = format_table(table)
    assert text.splitlines()[0] == "| delay (4 cycles, ms) | mean | max | min | std | ± clock |"
    assert [line.split("|")[1].strip() for line in text.splitlines()[2:]] == ["t_cycle^emb", "C^emb->DE",
                                                                              "t_cycle^DE", "d_RT"]


def test_the_gateways_marks_split_the_communication_delay():
    checker, _, _ = bench([received(k, PAPER_PATH[k], k + 0.5) for k in range(4)])
    # report k: sent at 100.001; the gateway read it 1 ms later and wrote it on 3 ms after that.
    marks = cycle_hops([Hop(k + 1, k + 0.5, 100.002, 100.005) for k in range(4)])
    table = delay_table(checker.verdicts, {k: 100.006 for k in range(4)}, marks)
    assert table["C_RTI^emb"].mean == pytest.approx(1.0)
    assert table["t_cycle^RTI"].mean == pytest.approx(3.0)
    assert table["C_PT^RTI"].mean == pytest.approx(1.0)
    assert table["C^emb->DE"].mean == pytest.approx(5.0)  # the three hops together
    assert [line.split("|")[1].strip() for line in format_table(table).splitlines()[2:]] == [
        "t_cycle^emb", "C_RTI^emb", "t_cycle^RTI", "C_PT^RTI", "C^emb->DE", "t_cycle^DE", "d_RT"]


def test_marks_read_on_other_clocks_are_put_on_the_gateways_clock():
    """The robot's clock 1000 s ahead of the gateway's, the testbench's 2 s behind: the offsets (the robot's in
    its reports) put every mark on the gateway's clock, and each row that crosses clocks carries the sum of
    their uncertainties."""
    def skewed(k: int) -> tuple[float, Received]:
        sent = dataclasses.replace(report(k, PAPER_PATH[k], t=1100.0), clock_offset=-1000.0,
                                   clock_uncertainty=0.0005)
        return k + 0.5, Received("robot", {"location": sent}, None, k + 0.5, f"cycle {k}")

    checker, _, _ = bench([skewed(k) for k in range(4)])
    # Sent at 1100.001 on the robot's clock (100.001 on the gateway's), read by the gateway at 100.003 and
    # written on at 100.004, reflected at 98.006 on the testbench's clock (100.006).
    marks = cycle_hops([Hop(k + 1, None, 100.003, 100.004) for k in range(4)])
    table = delay_table(checker.verdicts, {k: 98.006 for k in range(4)}, marks, bench_clock=(2.0, 0.0002))
    assert (table["C_RTI^emb"].mean, table["C_RTI^emb"].clock) == pytest.approx((2.0, 0.5))
    assert (table["t_cycle^RTI"].mean, table["t_cycle^RTI"].clock) == pytest.approx((1.0, 0.0))
    assert (table["C_PT^RTI"].mean, table["C_PT^RTI"].clock) == pytest.approx((2.0, 0.2))
    assert (table["C^emb->DE"].mean, table["C^emb->DE"].clock) == pytest.approx((5.0, 0.7))
    assert table["t_cycle^emb"].clock == 0.0
    assert "| C_RTI^emb | 2.000 | 2.000 | 2.000 | 0.000 | 0.500 |" in format_table(table)


def test_trace_has_a_row_per_cycle_and_plot_is_optional(tmp_path: pathlib.Path):
    checker, _, _ = bench([received(k, PAPER_PATH[k], k + 0.5, k + 0.5) for k in range(3)])
    checker.finish()
    write_trace(tmp_path / "trace.csv", checker.verdicts, {0: 100.002}, 0.25)
    with open(tmp_path / "trace.csv", newline="") as stream:
        rows = list(csv.DictReader(stream))
    assert [r["cycle"] for r in rows] == ["0", "1", "2", "3"]
    assert rows[0]["c_emb_de_ms"] == "1.000" and rows[1]["c_emb_de_ms"] == ""
    assert rows[3]["robot_a"] == "" and rows[3]["time_error"] == "1"
    message = write_plot(tmp_path / "trajectory.png", checker.verdicts, PAPER_5X5, "test")
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert message.startswith("no plot: matplotlib is not installed")
        assert not (tmp_path / "trajectory.png").exists()
    else:
        assert (tmp_path / "trajectory.png").stat().st_size > 0


def test_testbench_keeps_the_directors_delegate(inprocess_gateway):
    """The testbench's arrival clock wraps a delegate the director already had; callbacks reach both."""
    from importlib import resources

    from hlacore.federates.de import HlaDirector
    from hlacore.federates.testbench import ArrivalClock, Testbench

    class Discoveries:
        def __init__(self) -> None:
            self.names: list[str] = []

        def discoverObjectInstance(self, obj, cls, name) -> None:
            self.names.append(name)

    mine = Discoveries()
    fom = str(resources.files("hlacore") / "foms" / "robot.fed")
    director = HlaDirector.join("testbench", "TestFed", fom, address=str(inprocess_gateway.address),
                                mode="TAR", lookahead=0.5, delegate=mine)
    try:
        testbench = Testbench(director, PAPER_5X5, 3)
        clock = director.ambassador.delegate
        assert isinstance(clock, ArrivalClock) and clock.inner is mine and testbench.clock is clock
        director.ambassador.discoverObjectInstance(None, None, "robot")
        assert clock.discovered == ["robot"] and mine.names == ["robot"]
    finally:
        director.resign()
        director.rtia.destroyFederationExecution("TestFed")
