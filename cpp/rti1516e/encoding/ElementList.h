// The members of an array or a fixed record (internal to librti1516e): each a copy the composite owns or the
// caller's element, encoded in order, each padded to its octet boundary counted from the composite's start.
#ifndef HLACORE_RTI1516E_ENCODING_ELEMENTLIST_H
#define HLACORE_RTI1516E_ENCODING_ELEMENTLIST_H

#include <memory>
#include <vector>

#include "Octets.h"

namespace hlacore_rti1516e {

class ElementList {
public:
    ElementList() = default;
    // Copies every member, the caller's too: a copy owns all of its members.
    ElementList(ElementList const& other);
    ElementList& operator=(ElementList const&) = delete;

    size_t size() const { return _slots.size(); }
    void append(DataElement const& element);
    // Null throws EncoderException.
    void appendPointer(DataElement* element);
    // An index out of range throws EncoderException.
    void set(size_t index, DataElement const& element);
    void setPointer(size_t index, DataElement* element);
    DataElement const& get(size_t index) const;
    // Drops members past count, or appends copies of prototype up to it.
    void resize(size_t count, DataElement const& prototype);

    // start: where the composite began in buffer (encode), or the index it begins at (decode).
    void encodeInto(Octets& buffer, size_t start) const;
    size_t decodeFrom(Octets const& buffer, size_t index, size_t start);
    // Where the members end when the first follows position.
    size_t end(size_t position) const;
    // The largest of the members' octet boundaries and least.
    unsigned boundary(unsigned least) const;

private:
    struct Slot {
        std::unique_ptr<DataElement> own;
        DataElement* element;  // own, or the caller's
    };
    Slot& slot(size_t index);

    std::vector<Slot> _slots;
};

// The members of an array: all of the prototype's type, which set and setPointer check.
class Array {
public:
    Array(DataElement const& prototype, size_t count);
    Array(Array const& other);
    Array& operator=(Array const&) = delete;

    // EncoderException unless element is of the prototype's type.
    void check(DataElement const& element) const;
    void set(size_t index, DataElement const& element);
    void setPointer(size_t index, DataElement* element);
    bool isSameTypeAs(Array const& other) const;

    std::unique_ptr<DataElement> prototype;
    ElementList elements;
};

}  // namespace hlacore_rti1516e

#endif
