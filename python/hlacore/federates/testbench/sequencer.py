"""The sequencer: reads the stimulus file (a scenario) and sends it to the models at the start time."""

from __future__ import annotations

import pathlib
from typing import Union

from hlacore.federates.de import Actor
from hlacore.federates.robot_driver.navigation import Scenario

__all__ = ["Sequencer"]


class Sequencer(Actor):
    """Sends the :class:`Scenario` read from ``stimulus`` (a path, or a Scenario) on ``output`` at the start.

    The stimulus file is the scenario text form (``grid``, ``walls``, ``start``, ``goal`` lines); the
    robot under test is given the same file.
    """

    def __init__(self, name: str, stimulus: Union[str, pathlib.Path, Scenario]) -> None:
        super().__init__(name)
        self.scenario = stimulus if isinstance(stimulus, Scenario) else Scenario.load(stimulus)
        self.output = self.add_output("output")

    def initialize(self) -> None:
        """Schedule the firing at the start time."""
        self.fire_at(self.director_or_raise().start_time)

    def fire(self) -> None:
        """Send the scenario on ``output``."""
        self.output.send(self.scenario)
