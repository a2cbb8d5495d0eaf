// A map of containers (class -> regions, object -> attributes) that drops a key once its container is empty.
#pragma once

namespace hlacore {

// Erases `inner` from outer[key], and the key when nothing is left under it; false when either was absent.
template <class Outer, class Key, class Inner>
bool erase_nested(Outer& outer, const Key& key, const Inner& inner) {
    auto it = outer.find(key);
    if (it == outer.end() || !it->second.erase(inner)) return false;
    if (it->second.empty()) outer.erase(it);
    return true;
}

}  // namespace hlacore
