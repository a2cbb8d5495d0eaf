// libFuzzer target for the .fed parser: arbitrary text as a FED file.
//
// The only exception allowed out of parse_fed is FedError, whose position must lie inside the text (line
// and column from 1). A FOM that parses must be self-consistent: handle h is at index h - 1, parents come
// before their children and list them, every attribute/parameter handle is unique within its class, and
// the name indexes find each class by its qualified name, each attribute, parameter, space and dimension
// by its name (names are unique where the parser checks them), the same after Fom::reindex().
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <algorithm>
#include <set>
#include <string_view>

#include "fed_parser/fom.hpp"

using namespace hlacore::fom;

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}

template <class Class, class Members, class Lookup, class MemberLookup>
void check_classes(const std::vector<Class>& classes, Members members, Lookup find, MemberLookup find_member) {
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const Class& c = classes[i];
        check(c.handle == i + 1);
        check(!c.name.empty());
        check(c.parent < c.handle);  // 0 (none) or declared before
        if (c.parent != 0) {
            const auto& siblings = classes[c.parent - 1].children;
            check(std::find(siblings.begin(), siblings.end(), c.handle) != siblings.end());
        }
        for (Handle child : c.children) check(child > c.handle && child <= classes.size() && classes[child - 1].parent == c.handle);
        std::set<Handle> seen;
        for (const auto& m : members(c)) {
            check(m.handle != 0 && seen.insert(m.handle).second);
            check(find_member(c, m.name) == &m);
        }
        check(find(c.qualified_name) == &c);
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        Fom fom = parse_fed(text, "fuzz.fed");
        for (int pass = 0; pass < 2; ++pass) {
            check_classes(
                fom.object_classes, [](const ObjectClass& c) -> const auto& { return c.attributes; },
                [&](std::string_view n) { return fom.find_object_class(n); },
                [](const ObjectClass& c, std::string_view n) { return c.attribute(n); });
            check_classes(
                fom.interaction_classes, [](const InteractionClass& c) -> const auto& { return c.parameters; },
                [&](std::string_view n) { return fom.find_interaction_class(n); },
                [](const InteractionClass& c, std::string_view n) { return c.parameter(n); });
            for (std::size_t i = 0; i < fom.spaces.size(); ++i) {
                const RoutingSpace& s = fom.spaces[i];
                check(s.handle == i + 1 && fom.find_space(s.name) == &s);
                for (const Dimension& d : s.dimensions) check(s.dimension(d.name) == &d);
            }
            fom.reindex();  // what a hand-built Fom relies on must agree with what the parser built
        }
    } catch (const FedError& e) {
        check(e.line() >= 1 && e.column() >= 1);
        check(e.file() == "fuzz.fed");
    }
    return 0;
}
