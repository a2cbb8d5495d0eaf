"""Deprecated alias of :mod:`hlacore.experiments.robot_in_the_loop.experiment`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.experiments.robot_in_the_loop.experiment")
