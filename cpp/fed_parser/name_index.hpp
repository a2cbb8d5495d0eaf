// Name -> handle for the named items of one list (a class's attributes, the FOM's classes, its spaces), so
// that lookups by name and the parser's duplicate checks cost O(1) instead of a scan of the list.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

namespace hlacore::fom {

using Handle = std::uint32_t;  // 0 never names anything

// An open-addressing table of handles with their names' hashes: no names or pointers are kept, so the
// list that owns it can be copied or moved freely, and a copy (every subclass copies its parent's
// attribute index) is one flat copy of 8 bytes a slot. A lookup confirms a candidate through
// `name_of(handle)`, which returns the recorded item's name.
class NameIndex {
public:
    // Records `h` under `name` unless an item of that name is recorded already: the first declared wins.
    template <class NameOf>
    void add(std::string_view name, Handle h, NameOf&& name_of) {
        if ((size_ + 1) * 2 > slots_.size()) grow();  // at most half full: probes stay short
        const std::uint32_t hash = hash_of(name);
        std::size_t i = probe(name, hash, name_of);
        if (slots_[i].handle != 0) return;
        slots_[i] = Slot{h, hash};
        ++size_;
    }

    // The handle recorded under `name`, 0 if none.
    template <class NameOf>
    Handle find(std::string_view name, NameOf&& name_of) const {
        if (slots_.empty()) return 0;
        return slots_[probe(name, hash_of(name), name_of)].handle;
    }

    void clear() {
        slots_.clear();
        size_ = 0;
    }
    std::size_t size() const { return size_; }

private:
    struct Slot {
        Handle handle = 0;  // 0: empty
        std::uint32_t hash = 0;
    };

    static std::uint32_t hash_of(std::string_view name) {
        return static_cast<std::uint32_t>(std::hash<std::string_view>{}(name));
    }

    // The slot holding `name`, or the empty slot where it would go (linear probing).
    template <class NameOf>
    std::size_t probe(std::string_view name, std::uint32_t hash, NameOf& name_of) const {
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
            const Slot& s = slots_[i];
            if (s.handle == 0 || (s.hash == hash && name_of(s.handle) == name)) return i;
        }
    }

    void grow() {
        std::vector<Slot> old(slots_.size() < 8 ? 8 : slots_.size() * 2);
        old.swap(slots_);
        const std::size_t mask = slots_.size() - 1;
        for (const Slot& s : old) {  // names are distinct here: no need to compare them
            if (s.handle == 0) continue;
            std::size_t i = s.hash & mask;
            while (slots_[i].handle != 0) i = (i + 1) & mask;
            slots_[i] = s;
        }
    }

    std::vector<Slot> slots_;  // a power of two long, or empty
    std::size_t size_ = 0;
};

}  // namespace hlacore::fom
