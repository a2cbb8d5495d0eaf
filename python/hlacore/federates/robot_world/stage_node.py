"""Deprecated alias of :mod:`hlacore.federates.ros_bridge.stage_node`; removed in the next release."""

from hlacore._deprecated import moved

moved(__name__, "hlacore.federates.ros_bridge.stage_node")
