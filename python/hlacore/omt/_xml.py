"""Reading an OMT file's elements: a property in either layout (1516-2000's attributes, 1516-2010's child
elements), numbers, array cardinalities and the enumerators that select a variant's alternative."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ElementTree
from typing import Any

_RANGE = re.compile(r"\[\s*([^\].]+?)\s*\.\.\s*([^\]]+?)\s*\]")


def _local(tag: Any) -> str:
    """An element's tag without its XML namespace."""
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def _texts(element: ElementTree.Element, key: str) -> list[str]:
    """The values of property ``key``: the attribute (1516-2000 layout) or
    the text of each child element of that name (1516-2010 layout)."""
    attribute = element.get(key)
    if attribute is not None:
        return [attribute.strip()]
    return [(child.text or "").strip() for child in element
            if _local(child.tag) == key]


def _text(element: ElementTree.Element, key: str) -> str | None:
    """The first non-empty value of property ``key``, or None."""
    for text in _texts(element, key):
        if text:
            return text
    return None


def _children(element: ElementTree.Element, kind: str
              ) -> list[ElementTree.Element]:
    """The child elements of ``element`` called ``kind``."""
    return [child for child in element if _local(child.tag) == kind]


def _integer(text: str) -> int:
    """Parse a decimal (or ``0x``-prefixed) integer."""
    try:
        return int(text)
    except ValueError:
        return int(text, 0)


def _cardinality(text: str) -> list[tuple[int, int | None]]:
    """The ``(lower, upper)`` bounds of each dimension of an arrayData
    cardinality (``Dynamic``, ``3``, ``[1..10]``, ``2,3``); ``upper`` is
    None when unbounded."""
    dimensions: list[tuple[int, int | None]] = []
    for part in text.split(","):
        part = part.strip()
        try:
            if part.lower() == "dynamic":
                dimensions.append((0, None))
                continue
            match = _RANGE.fullmatch(part)
            if match:
                low, high = match.groups()
                dimensions.append((
                    0 if low.lower() == "dynamic" else _integer(low),
                    None if high.lower() == "dynamic" else _integer(high)))
                continue
            dimensions.append((_integer(part), _integer(part)))
        except ValueError:
            raise ValueError(
                f"cardinality {text!r} is not Dynamic, a number or a range "
                f"[low..high]") from None
    return dimensions


def _enumerator_token(token: str) -> str | int:
    """An alternative's enumerator: an integer if it is one, else a name."""
    return int(token) if re.fullmatch(r"[+-]?\d+", token) else token


def _alternative_items(text: str) -> list[Any]:
    """Parse an alternative's enumerators: comma-separated names,
    ``HLAother`` (None) and ranges ``[A..C]`` (slices)."""
    items: list[Any] = []
    for token in text.split(","):
        token = token.strip()
        if not token:
            continue
        match = _RANGE.fullmatch(token)
        if token == "HLAother":
            items.append(None)
        elif match:
            items.append(slice(_enumerator_token(match.group(1)),
                               _enumerator_token(match.group(2))))
        else:
            items.append(_enumerator_token(token))
    return items
