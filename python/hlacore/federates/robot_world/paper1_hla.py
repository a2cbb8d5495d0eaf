"""Deprecated alias of :mod:`hlacore.experiments.paper1.hla`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.experiments.paper1.hla")
