"""Deprecated alias of :mod:`hlacore.experiments.robot_in_the_loop`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.experiments.robot_in_the_loop.__main__")
