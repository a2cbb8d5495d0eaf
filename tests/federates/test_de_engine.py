"""The DE engine without an RTI: event order (time, microstep, depth, sequence), peek/step/run, causality
checks and the library actors."""

from __future__ import annotations

import math
from typing import Any, Optional

import pytest

from hlacore.federates.de import (
    Actor,
    CausalityError,
    Clock,
    Delay,
    Director,
    EmptySchedule,
    Function,
    NoTokenError,
    Recorder,
    TimedSource,
)

Log = list[tuple[str, float, int]]


def into_sink(source: Any) -> tuple[Director, Recorder]:
    """A Director holding `source` (an actor with an `output` port) and a Recorder 'sink' that port feeds."""
    director = Director()
    sink = Recorder("sink")
    source.output.connect(sink.input)
    director.add(source, sink)
    return director, sink


class Logger(Actor):
    """Logs (name, time, microstep) at every firing; fires at ``times`` and passes tokens on."""

    def __init__(self, name: str, log: Log, times: tuple[float, ...] = ()) -> None:
        super().__init__(name)
        self.log = log
        self.times = times
        self.input = self.add_input("input")
        self.output = self.add_output("output")
        self.seen: list[list[Any]] = []

    def initialize(self) -> None:
        for t in self.times:
            self.fire_at(t)

    def fire(self) -> None:
        director = self.director_or_raise()
        self.log.append((self.name, director.now, director.microstep))
        self.seen.append(list(self.input.tokens))
        for token in self.input.tokens:
            self.output.send(token)


def test_simultaneous_events_fire_in_scheduling_order() -> None:
    """Equal time, microstep and depth: first scheduled, first fired (the sequence number)."""
    log: Log = []
    director = Director()
    c, a, b = Logger("c", log, (1.0,)), Logger("a", log, (1.0,)), Logger("b", log, (1.0,))
    director.add(c, a, b)
    director.run()
    assert log == [("c", 1.0, 0), ("a", 1.0, 0), ("b", 1.0, 0)]


def test_depth_orders_before_sequence() -> None:
    """A deeper actor scheduled first still fires after a shallower one at the same tag."""
    log: Log = []
    director = Director()
    deep = Logger("deep", log)
    source = Logger("source", log)
    source.output.connect(deep.input)
    director.add(deep, source)
    director.initialize()
    deep.fire_at(2.0)  # sequence 0, depth 1
    source.fire_at(2.0)  # sequence 1, depth 0
    assert (deep.depth, source.depth) == (1, 0)
    director.run()
    assert log == [("source", 2.0, 0), ("deep", 2.0, 0)]


def test_a_join_fires_once_per_tag_with_every_token() -> None:
    """Diamond: source → f → join and source → join; the join sees both tokens in one firing."""
    director = Director()
    source = TimedSource("source", [(1.0, 1), (2.0, 2)])
    double = Function("double", lambda x: 2 * x)
    join = Recorder("join")
    source.output.connect(join.input, double.input)
    double.output.connect(join.input)
    director.add(join, double, source)
    fired_before = director.firings
    director.run()
    assert [(r.time, r.microstep, r.value) for r in join.records] == [(1.0, 0, 1), (1.0, 0, 2), (2.0, 0, 2), (2.0, 0, 4)]
    assert director.firings - fired_before == 6  # 2 tags x (source, double, join): one firing each


def test_microsteps_order_events_at_the_same_time() -> None:
    """fire_at(now) and a zero delay go to the next microstep, which comes after every depth of the current one."""
    log: Log = []

    class Repeater(Logger):
        def fire(self) -> None:
            super().fire()
            if self.director_or_raise().microstep < 2:
                self.fire_at(self.now)
                self.fire_at(self.now)  # the same firing: one event per actor and tag

    director = Director()
    repeater = Repeater("repeater", log, (1.0,))
    deep = Logger("deep", log)
    hop = Logger("hop", log)
    deep.output.connect(hop.input)
    director.add(repeater, deep, hop)
    director.initialize()
    hop.fire_at(1.0)
    deep.fire_at(1.0)
    director.run()
    assert log == [
        ("repeater", 1.0, 0),
        ("deep", 1.0, 0),
        ("hop", 1.0, 0),  # depth 1 at microstep 0 before depth 0 at microstep 1
        ("repeater", 1.0, 1),
        ("repeater", 1.0, 2),
    ]
    assert (hop.depth, deep.depth, repeater.depth) == (1, 0, 0)


def test_send_delays_give_the_documented_tags() -> None:
    """send(v): same tag; send(v, delay=0): next microstep; send(v, delay=d): (now + d, 0)."""

    class Emitter(Actor):
        def __init__(self) -> None:
            super().__init__("emitter")
            self.output = self.add_output("output")

        def initialize(self) -> None:
            self.fire_at(1.0)

        def fire(self) -> None:
            self.output.send("now")
            self.output.send("zero", delay=0.0)
            self.output.send("later", delay=0.5)

    emitter = Emitter()
    director, sink = into_sink(emitter)
    director.run()
    assert [(r.time, r.microstep, r.value) for r in sink.records] == [(1.0, 0, "now"), (1.0, 1, "zero"), (1.5, 0, "later")]
    with pytest.raises(CausalityError, match="delay"):
        emitter.output.send("x", delay=-1.0)


def test_peek_step_and_empty_schedule() -> None:
    director = Director(start_time=10.0)
    source = TimedSource("source", [(12.0, "a"), (11.0, "b"), (12.0, "c")])
    sink = Recorder("sink")
    source.output.connect(sink.input)
    director.add(source, sink)
    assert director.now == 10.0
    assert director.peek() == 11.0
    director.step()  # the source at 11
    assert (director.now, sink.values) == (11.0, [])
    director.step()  # the sink at 11
    assert (director.now, sink.values) == (11.0, ["b"])
    assert director.peek() == 12.0
    director.step()
    director.step()
    assert sink.values == ["b", "a", "c"]  # equal times keep the order given
    assert director.peek() == math.inf
    with pytest.raises(EmptySchedule):
        director.step()


def test_run_until_is_inclusive_and_moves_time_to_until() -> None:
    director, sink = into_sink(Clock("clock", period=1.0, offset=0.5))
    director.run(until=2.5)
    assert sink.records and [(r.time, r.value) for r in sink.records] == [(0.5, 0), (1.5, 1), (2.5, 2)]
    assert director.now == 2.5
    director.run(until=4.0)
    assert sink.times == [0.5, 1.5, 2.5, 3.5]
    assert (director.now, director.peek()) == (4.0, 4.5)
    assert director.run(max_steps=3) == 3  # a clock runs for ever: max_steps bounds the loop
    assert sink.times == [0.5, 1.5, 2.5, 3.5, 4.5]


def test_clock_cycles_and_run_until_queue_empty() -> None:
    director, sink = into_sink(Clock("clock", period=0.25, cycles=4))
    assert director.run() == 8
    assert [(r.time, r.value) for r in sink.records] == [(0.0, 0), (0.25, 1), (0.5, 2), (0.75, 3)]
    assert director.now == 0.75


def test_a_zero_delay_loop_is_a_causality_error_and_a_delay_breaks_it() -> None:
    director = Director()
    f, g = Function("f", lambda x: x), Function("g", lambda x: x)
    f.output.connect(g.input)
    g.output.connect(f.input)
    director.add(f, g)
    with pytest.raises(CausalityError, match="zero-delay loop through f, g"):
        director.initialize()

    # A counter: add 1 and feed back through a delay of 1.
    director = Director()
    seed = TimedSource("seed", [(0.0, 0)])
    increment = Function("increment", lambda x: x + 1)
    delay = Delay("delay", 1.0)
    sink = Recorder("sink")
    seed.output.connect(increment.input)
    increment.output.connect(delay.input, sink.input)
    delay.output.connect(increment.input)
    director.add(seed, increment, delay, sink)
    director.run(until=3.0)
    assert [(r.time, r.value) for r in sink.records] == [(0.0, 1), (1.0, 2), (2.0, 3), (3.0, 4)]
    with pytest.raises(CausalityError, match="delayed port"):
        delay.output.send(1)


def test_events_in_the_past_are_refused() -> None:
    director = Director()
    source = TimedSource("source", [(2.0, "x")])
    director.add(source)
    director.run()
    with pytest.raises(CausalityError, match="asked to fire at 1.0"):
        source.fire_at(1.0)
    with pytest.raises(CausalityError):
        source.fire_at(math.inf)


def test_injected_tokens_are_clamped_to_now_and_go_to_the_next_microstep() -> None:
    """The way in for messages from outside: a late token fires at the current time, after the current tag."""
    director, sink = into_sink(TimedSource("source", [(5.0, "local")]))
    director.run()
    assert (director.now, director.microstep) == (5.0, 0)
    assert director.inject(sink.input, "late", 3.0) == (5.0, 1)
    assert director.inject(sink.input, "at now", 5.0) == (5.0, 1)
    assert director.inject(sink.input, "future", 7.0) == (7.0, 0)
    director.run()
    assert [(r.time, r.microstep, r.value) for r in sink.records] == [
        (5.0, 0, "local"),
        (5.0, 1, "late"),
        (5.0, 1, "at now"),
        (7.0, 0, "future"),
    ]


def test_tokens_last_one_firing_and_get_raises_without_one() -> None:
    seen: list[tuple[Optional[Any], Optional[Any]]] = []

    class Reader(Actor):
        def __init__(self) -> None:
            super().__init__("reader")
            self.input = self.add_input("input")

        def initialize(self) -> None:
            self.fire_at(3.0)  # a pure firing: no token

        def fire(self) -> None:
            if self.input.has_token():
                seen.append((self.input.get(), self.input.last()))
            else:
                with pytest.raises(NoTokenError, match="reader.input"):
                    self.input.get()
                seen.append((None, None))

    director = Director()
    source = TimedSource("source", [(1.0, "a"), (1.0, "b"), (2.0, "c")])
    reader = Reader()
    source.output.connect(reader.input)
    director.add(source, reader)
    director.run()
    assert seen == [("a", "b"), ("c", "c"), (None, None)]


def test_building_errors() -> None:
    director = Director()
    f = Function("f", lambda x: x)
    sink = Recorder("sink")
    f.output.connect(sink.input)
    director.add(f)
    with pytest.raises(RuntimeError, match="whose actor was not added"):
        director.initialize()
    with pytest.raises(ValueError, match="already has a port"):
        f.add_input("input")
    with pytest.raises(RuntimeError, match="has not been added"):
        Recorder("alone").fire_at(1.0)
    other = Director()
    with pytest.raises(RuntimeError, match="another director"):
        other.add(f)

