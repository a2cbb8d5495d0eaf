"""The testbench of testing-rtes-hla-2016 §4 (UVM style) as DE actors on an HLA-aware director.

- :mod:`.sequencer` — the stimulus (a scenario file) into the models;
- :mod:`.reference` — the reference model: the same A* mission, one expected cell per cycle;
- :mod:`.checker` — per cycle value and arrival time against the reference (value vs time errors);
- :mod:`.display` — a progress line per cycle;
- :mod:`.plotter` — CSV trace and trajectory PNG (matplotlib optional);
- :mod:`.delays` — the delay decomposition in Table 1's form;
- :mod:`.bench` — the model on an :class:`~hlacore.federates.de.HlaDirector`, run and result.

Federates layer: imports the core, :mod:`hlacore.federates.de` and :mod:`hlacore.federates.robot_driver`.
The whole experiment (testbench here, robot in its own process) is
:mod:`hlacore.experiments.robot_in_the_loop`.

``python -m hlacore.federates.testbench --help`` runs the testbench federate alone. See ``docs/robot.md``.
"""

from .bench import ArrivalClock, Testbench, TestbenchResult
from .checker import Checker, Verdict
from .delays import ROWS, Stats, cycle_hops, delay_table, format_table
from .display import Display, format_verdict
from .plotter import write_plot, write_trace
from .reference import Expected, ReferenceModel
from .sequencer import Sequencer

__all__ = [
    "ArrivalClock",
    "Checker",
    "Display",
    "Expected",
    "ROWS",
    "ReferenceModel",
    "Sequencer",
    "Stats",
    "Testbench",
    "TestbenchResult",
    "Verdict",
    "cycle_hops",
    "delay_table",
    "format_table",
    "format_verdict",
    "write_plot",
    "write_trace",
]
