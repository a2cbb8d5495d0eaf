"""``HLAuse``: define the data types of an OMT/FOM XML file in ``hlacore.omt``, as PyHLA's does."""

from __future__ import annotations

import os
import xml.etree.ElementTree as ElementTree

from ._base import HLAdataType
from ._namespace import _define, _standard_type
from ._reader import _Definition, _FOMReader
from ._xml import _local, _text

_KINDS = frozenset(("basicData", "simpleData", "enumeratedData", "arrayData",
                    "fixedRecordData", "variantRecordData"))


def HLAuse(filename: str | os.PathLike[str]) -> dict[str, HLAdataType]:
    """Define the data types of an IEEE 1516 OMT/FOM XML file in ``hlacore.omt``.

    Returns ``{name: dataType}`` in declaration order and, as PyHLA's
    ``HLAuse`` does, sets each name as an attribute of ``hlacore.omt``::

        import hlacore.omt as fom
        fom.HLAuse("robot.xml")
        data = fom.Pose2D.pack({"x": 1.0, "y": 2.0, "theta": 0.5})

    Both layouts are read, with or without an XML namespace: 1516-2000's,
    whose properties are attributes
    (``<simpleData name="Meters" representation="HLAfloat64BE"/>``), and
    1516-2010's, whose properties are child elements
    (``<simpleData><name>Meters</name><representation>...``).  The data
    types become:

    * ``basicData``: an integer or a float of ``size`` bits (8, 16, 32 or
      64) in the ``endian`` byte order; a float when the name or the
      interpretation says "float", else an integer, signed unless the name
      or the interpretation says "unsigned";
    * ``simpleData``: its representation (the name is an alias of the same
      object);
    * ``enumeratedData``: an :class:`HLAenumerated`; an enumerator with
      several values takes the first, and the others decode to it; a value
      beyond a signed representation's range but within its width (the RPR
      FOM's ``EmitterTypeEnum16`` has 32805 in an ``HLAinteger16BE``) is read
      as its bit pattern (-32731), with one warning for the type;
    * ``arrayData``: an :class:`HLAfixedArray` or :class:`HLAvariableArray`
      of cardinality ``Dynamic``, a number or a range ``[1..10]`` (its upper
      bound is the maximum); a multi-dimensional cardinality ``2,3`` nests
      arrays, the first dimension outermost;
    * ``fixedRecordData``: an :class:`HLAfixedRecord` of its ``field``
      elements (1516-2010's record extension by ``include`` is ignored);
    * ``variantRecordData``: an :class:`HLAvariantRecord`; an alternative's
      enumerators are comma-separated names, ``HLAother`` and ranges
      ``[A..C]`` (in the enumeration's declaration order), and an
      alternative whose name or data type is ``NA`` carries no value.

    A type may be used before it is declared.  A name the file uses but
    does not define is looked up in ``hlacore.omt`` (among its own types and
    those of earlier ``HLAuse`` calls) when first used, so FOM modules may
    be loaded in any order; a name still undefined then raises
    ``KeyError`` naming it and the type that uses it.  A type whose
    encoding is not a standard one (``RPRnullTerminatedArray`` ...), a
    ``basicData`` of another size, or a type that contains itself loads,
    and raises ``NotImplementedError`` naming the type and the encoding
    when packed or unpacked.

    ``HLAuse`` never replaces ``hlacore.omt``'s own names: a FOM that declares
    a standard type (``HLAinteger32BE``, ``HLAASCIIstring``,
    ``HLAboolean`` ...) keeps the package's, and the returned dict maps the
    name to it.  Note that the 1516-2010 MIM declares ``HLAboolean`` as an
    enumeration of ``HLAfalse`` and ``HLAtrue``, whereas here it packs and
    unpacks ``bool`` (with the same bytes).  A type whose name is taken by
    another attribute of the module (``pack_string``, ``Buffer`` ...) is in
    the returned dict and serves the file's references but is not set as
    an attribute.  Names defined by an earlier ``HLAuse`` are replaced; a
    name defined twice in one file takes the later definition.  Type
    checkers do not know the attributes ``HLAuse`` sets: typed code should
    use the returned dict.

    Raises ``OSError`` (``FileNotFoundError`` ...) naming the file if it
    cannot be read, and ``ValueError`` naming the file if it is not
    well-formed XML, not an ``objectModel`` or has a malformed data type
    (no name, a fixed array without a fixed cardinality, an alternative
    naming an enumerator its discriminant lacks ...).
    """
    path = os.fspath(filename)
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as exc:
        raise ValueError(f"{path}: malformed XML: {exc}") from None
    if _local(root.tag) != "objectModel":
        raise ValueError(
            f"{path}: not an HLA object model (the root element is "
            f"<{_local(root.tag)}>, not <objectModel>)")
    definitions: dict[str, _Definition] = {}
    for element in root.iter():
        kind = _local(element.tag)
        if kind not in _KINDS:
            continue
        name = _text(element, "name")
        if not name:
            raise ValueError(f"{path}: a {kind} element has no name")
        definitions[name] = _Definition(kind, element)
    reader = _FOMReader(path, definitions)
    types = {name: reader.type_of(name) for name in definitions}
    for name, datatype in types.items():
        if _standard_type(name) is not None:
            continue
        _define(name, datatype)
    return types
