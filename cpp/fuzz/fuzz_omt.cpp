// libFuzzer target for the OMT XML reader (cpp/fed_parser/omt.hpp): arbitrary bytes as a FOM module, alone
// and as the second module after a valid one, and as a text that may be a bundle of modules.
//
// The only exception allowed out of parse_omt is FedError, with a position inside the text (line and column
// from 1) or the MIM's. A FOM that parses is consistent as fuzz_fed checks it: handle h at index h - 1, parents
// before children, lookups by name find each class and member.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fed_parser/omt.hpp"

using namespace hlacore::fom;

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}

const char* const kFirst =
    "<objectModel><objects><objectClass><name>HLAobjectRoot</name><objectClass><name>A</name>"
    "<attribute><name>x</name><transportation>HLAreliable</transportation><order>TimeStamp</order></attribute>"
    "</objectClass></objectClass></objects></objectModel>";

void check_fom(const Fom& fom) {
    for (std::size_t i = 0; i < fom.object_classes.size(); ++i) {
        const ObjectClass& c = fom.object_classes[i];
        check(c.handle == i + 1 && c.parent < c.handle && fom.find_object_class(c.qualified_name) == &c);
        for (const Attribute& a : c.attributes) check(c.attribute(a.name) == &a);
    }
    for (std::size_t i = 0; i < fom.interaction_classes.size(); ++i) {
        const InteractionClass& c = fom.interaction_classes[i];
        check(c.handle == i + 1 && c.parent < c.handle && fom.find_interaction_class(c.qualified_name) == &c);
        for (const Parameter& p : c.parameters) check(c.parameter(p.name) == &p);
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (int second = 0; second < 2; ++second) {
        std::vector<FomModule> modules;
        if (second) modules.push_back({kFirst, "first.xml"});
        modules.push_back({text, "fuzz.xml"});
        try {
            check_fom(parse_omt(modules));
        } catch (const FedError& e) {
            check((e.file() == "fuzz.xml" && e.line() >= 1 && e.column() >= 1) || e.file() == "first.xml");
        }
    }
    // The same bytes as one text read by what it is: a .fed, a module or a bundle of modules, whose errors
    // name the bundle's own module names.
    try {
        check_fom(parse_fom(text, "fuzz.xml"));
    } catch (const FedError& e) {
        check(e.line() >= 1 && e.column() >= 1);
    }
    return 0;
}
