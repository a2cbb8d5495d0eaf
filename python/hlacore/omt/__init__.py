"""Encoding helpers for HLA attribute and parameter values.

This module is a pure-Python replacement for PyHLA's ``hla.omt``: a PyHLA
federate ports by changing ``import hla.omt as fom`` into
``import hlacore.omt as fom``.  It provides

* the IEEE 1516.2 basic data types (``HLAinteger32BE``, ``HLAfloat64LE``,
  ``HLAASCIIstring`` ...) as objects with ``pack(value) -> bytes``,
  ``unpack(buffer, offset=0) -> (value, size)`` and ``octetBoundary``;
* the standard names of the IEEE 1516.2 MIM that FOMs reference without
  defining them: ``HLAbyte`` and ``HLAASCIIchar`` (one octet),
  ``HLAunicodeChar``, ``HLAoctetPairBE`` and ``HLAoctetPairLE`` (16 bits)
  and ``HLAopaqueData`` (count-prefixed bytes);
* the composite type constructors ``HLAfixedArray``, ``HLAvariableArray``,
  ``HLAfixedRecord``, ``HLAvariantRecord`` and ``HLAenumerated`` that pad
  elements and fields to their octet boundary (relative to the start of
  the composite) as the IEEE 1516.2 encoding rules require;
* ``HLAencoding(name)``, PyHLA's forward reference to a data type defined
  later in this module's namespace;
* ``HLAuse(filename)``, which reads the data types of an IEEE 1516-2000 or
  1516-2010 OMT/FOM XML file and defines them in this module, as PyHLA's
  does (``fom.HLAuse("robot.xml"); fom.Pose.pack(...)``);
* ``HLAboolean`` and ``HLAunicodeString``, which PyHLA lacked;
* the helpers used by Ptolemy II through JCERTI's ``EncodingHelpers``
  (``pack_string``/``unpack_string``, ``pack_int``/``unpack_int`` ...):
  big-endian numbers, booleans as 4-byte integers and strings as UTF-8
  bytes followed by one NUL byte.

Error policy: every ``unpack`` raises ``ValueError`` naming the type and the
number of bytes needed versus available when the buffer is too short, and
never returns a truncated value.  Packing a value that does not fit the
type (an integer out of range, a float too large for ``float32``, a
non-ASCII ``HLAASCIIstring``) raises ``ValueError`` as well; a value of the
wrong kind (a ``str`` for an integer type) raises ``TypeError``; a missing
record field raises ``KeyError``.  A composite type prefixes the message
with where the error is (``Record.field``, ``Array[3]``).  A forward
reference that names no data type raises ``KeyError`` when used, and a
type whose encoding this module does not implement (a FOM's
``RPRnullTerminatedArray``, say) raises ``NotImplementedError`` when
packed or unpacked.
"""

from __future__ import annotations

# One job per module: _bytes (buffer checks, counts, padding), _base (HLAdataType, composites' layout),
# _basic (the basic types), _arrays, _record, _enumerated, _variant (the composites), _encoding (forward
# references), _namespace (this package's names), _xml, _reader, _unsupported and _use (HLAuse), _jcerti
# (JCERTI's helpers).
from ._arrays import HLAfixedArray, HLAvariableArray
from ._base import HLAdataType
from ._basic import (HLAASCIIchar, HLAASCIIstring, HLAboolean, HLAbyte, HLAfloat32BE, HLAfloat32LE,
                     HLAfloat64BE, HLAfloat64LE, HLAinteger16BE, HLAinteger16LE, HLAinteger32BE,
                     HLAinteger32LE, HLAinteger64BE, HLAinteger64LE, HLAoctet, HLAoctetPairBE,
                     HLAoctetPairLE, HLAopaqueData, HLAunicodeChar, HLAunicodeString, Unsignedinteger16BE,
                     Unsignedinteger32BE, Unsignedinteger64BE)
from ._bytes import Buffer
from ._encoding import HLAencoding
from ._enumerated import HLAenumerated, HLAenumerator
from ._jcerti import (pack_boolean, pack_double, pack_float, pack_int, pack_long, pack_short, pack_string,
                      unpack_boolean, unpack_double, unpack_float, unpack_int, unpack_long, unpack_short,
                      unpack_string)
from ._namespace import _bind, _fom_types  # _fom_types: what HLAuse defined (the tests restore it)
from ._record import HLAfixedRecord
from ._use import HLAuse
from ._variant import HLAvariantRecord

__all__ = [
    "HLAdataType",
    "HLAoctet",
    "HLAbyte",
    "HLAASCIIchar",
    "HLAunicodeChar",
    "HLAoctetPairBE",
    "HLAoctetPairLE",
    "HLAinteger16BE",
    "HLAinteger16LE",
    "HLAinteger32BE",
    "HLAinteger32LE",
    "HLAinteger64BE",
    "HLAinteger64LE",
    "HLAfloat32BE",
    "HLAfloat32LE",
    "HLAfloat64BE",
    "HLAfloat64LE",
    "Unsignedinteger16BE",
    "Unsignedinteger32BE",
    "Unsignedinteger64BE",
    "HLAASCIIstring",
    "HLAunicodeString",
    "HLAopaqueData",
    "HLAboolean",
    "HLAfixedArray",
    "HLAvariableArray",
    "HLAfixedRecord",
    "HLAvariantRecord",
    "HLAenumerated",
    "HLAenumerator",
    "HLAencoding",
    "HLAuse",
    "pack_string",
    "unpack_string",
    "pack_short",
    "unpack_short",
    "pack_int",
    "unpack_int",
    "pack_long",
    "unpack_long",
    "pack_float",
    "unpack_float",
    "pack_double",
    "unpack_double",
    "pack_boolean",
    "unpack_boolean",
]

# HLAencoding looks names up here and HLAuse defines a FOM's types here (PyHLA's scripts set their own types
# as attributes of the module too); bound last, so that every name above is one HLAuse never replaces.
_bind(globals())
