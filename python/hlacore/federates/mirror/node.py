"""Deprecated alias of :mod:`hlacore.experiments.mirror.node`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.experiments.mirror.node")
