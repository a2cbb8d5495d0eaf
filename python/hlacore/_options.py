"""The options of :class:`hlacore.Gateway` and :class:`hlacore.rti.RTIAmbassador`, declared once in the native
core's tables (``cpp/rti/server/options.cpp``, ``cpp/rti/client/options.cpp``) that ``rtig`` and the HLA 1.3
C++ API read too: keyword values become the text those tables check, and the tables' help the keywords' docs."""

from __future__ import annotations

import os
import textwrap
from collections.abc import Iterable, Mapping
from typing import Optional

#: A table's row: keyword, rtig flag or environment variable, placeholder (None: a switch), repeated,
#: default as text, help.
Row = tuple[str, Optional[str], Optional[str], bool, str, str]


def texts(value: object) -> list[str]:
    """A keyword's value as the texts the table takes: several for a list (each) or a mapping (``KEY=VALUE``)."""
    if isinstance(value, bool):
        return ["true" if value else "false"]  # not "1": a number option refuses a bool
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    if isinstance(value, Mapping):
        return [f"{key}={os.fspath(item)}" for key, item in value.items()]
    if isinstance(value, Iterable):
        return [text for item in value for text in texts(item)]
    return [str(value)]


def given(rows: list[Row], values: Mapping[str, object]) -> list[tuple[str, str]]:
    """(keyword, text) for each value given, None being none, in the table's order."""
    return [(row[0], text) for row in rows if values.get(row[0]) is not None for text in texts(values[row[0]])]


def document(rows: list[Row], where: str) -> str:
    """The keywords' docs, a paragraph each: ``where`` formats the row's flag or variable ("``rtig {}``")."""
    paragraphs = []
    for keyword, spelled, _metavar, repeated, default, help_text in rows:
        notes = [where.format(spelled)] if spelled else []
        if default:
            notes.append(f"default {default}")
        if repeated:
            notes.append("several allowed")
        paragraphs.append(textwrap.fill(f"``{keyword}`` ({'; '.join(notes)}): {help_text}.", width=110,
                                        initial_indent="    ", subsequent_indent="    ", break_on_hyphens=False,
                                        break_long_words=False))
    return "\n\n".join(paragraphs)
