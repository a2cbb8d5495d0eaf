"""Deprecated alias of :mod:`hlacore.experiments.paper1.de_controller`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.experiments.paper1.de_controller")
