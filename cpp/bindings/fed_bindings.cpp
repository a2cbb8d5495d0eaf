// hlacore._core.parse_fed(text, file_name) and parse_fom_modules(modules): the whole Fom as plain Python data, turned into dataclasses by
// hlacore.fed. FedError is deliberately not caught here: module.cpp translates it to ErrorReadingFED.
//
// Returned shape (handles are ints, a missing space is None, parent 0 becomes None):
//   {"source_name": str, "federation_name": str, "fed_version": str,
//    "spaces": [(handle, name, [(handle, name), ...]), ...],
//    "object_classes": [(handle, name, qualified_name, parent, (child, ...),
//                        [(handle, name, transport, order, space), ...]), ...],
//    "interaction_classes": [(handle, name, qualified_name, parent, (child, ...), transport, order, space,
//                             [(handle, name), ...]), ...],
//    "update_rates": [(name, rate), ...]}
// where transport is "reliable" | "best_effort" and order is "timestamp" | "receive".
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <string_view>
#include <vector>

#include "fed_parser/omt.hpp"

namespace py = pybind11;
using namespace hlacore::fom;

namespace {

py::str transport_name(Transport t) { return py::str(t == Transport::BestEffort ? "best_effort" : "reliable"); }
py::str order_name(Order o) { return py::str(o == Order::Timestamp ? "timestamp" : "receive"); }

py::object space_or_none(const std::string& s) { return s.empty() ? py::object(py::none()) : py::object(py::str(s)); }
py::object parent_or_none(Handle h) { return h == 0 ? py::object(py::none()) : py::object(py::int_(h)); }

py::tuple handles(const std::vector<Handle>& hs) {
    py::tuple out(hs.size());
    for (std::size_t i = 0; i < hs.size(); ++i) out[i] = py::int_(hs[i]);
    return out;
}

py::dict to_python(const Fom& fom) {
    py::list spaces;
    for (const RoutingSpace& s : fom.spaces) {
        py::list dims;
        for (const Dimension& d : s.dimensions) dims.append(py::make_tuple(d.handle, d.name));
        spaces.append(py::make_tuple(s.handle, s.name, dims));
    }

    py::list objects;
    for (const ObjectClass& c : fom.object_classes) {
        py::list attrs;
        for (const Attribute& a : c.attributes) {
            attrs.append(py::make_tuple(a.handle, a.name, transport_name(a.transport), order_name(a.order),
                                        space_or_none(a.space)));
        }
        objects.append(py::make_tuple(c.handle, c.name, c.qualified_name, parent_or_none(c.parent),
                                      handles(c.children), attrs));
    }

    py::list interactions;
    for (const InteractionClass& c : fom.interaction_classes) {
        py::list params;
        for (const Parameter& p : c.parameters) params.append(py::make_tuple(p.handle, p.name));
        interactions.append(py::make_tuple(c.handle, c.name, c.qualified_name, parent_or_none(c.parent),
                                           handles(c.children), transport_name(c.transport), order_name(c.order),
                                           space_or_none(c.space), params));
    }

    py::dict out;
    out["source_name"] = fom.source_name;
    out["federation_name"] = fom.federation_name;
    out["fed_version"] = fom.fed_version;
    out["spaces"] = spaces;
    out["object_classes"] = objects;
    out["interaction_classes"] = interactions;
    py::list rates;
    for (const UpdateRate& r : fom.update_rates) rates.append(py::make_tuple(r.name, r.rate));
    out["update_rates"] = rates;
    return out;
}

// (text, file name) pairs as Python gives them.
std::vector<FomModule> modules_of(const std::vector<std::pair<std::string, std::string>>& pairs) {
    std::vector<FomModule> modules;
    for (const auto& [text, file_name] : pairs) modules.push_back({text, file_name});
    return modules;
}

}  // namespace

void bind_fed(py::module_& m) {
    m.def(
        "parse_fed",
        [](std::string_view text, const std::string& file_name) {  // a view: a 10 MB text is not copied
            Fom fom;
            {
                py::gil_scoped_release release;
                fom = parse_fom(text, file_name);
            }
            return to_python(fom);
        },
        py::arg("text"), py::arg("file_name"),
        "Parse a FOM: the text of an HLA 1.3 .fed file or of an OMT XML FOM module (by what the text is); raises "
        "ErrorReadingFED (\"FILE:LINE:COL: message\") on the first error. Returns plain data (see hlacore.fed for "
        "the typed form).");
    m.def(
        "parse_fom_modules",
        [](const std::vector<std::pair<std::string, std::string>>& modules) {
            const auto list = modules_of(modules);
            Fom fom;
            {
                py::gil_scoped_release release;
                fom = parse_omt(list);
            }
            return to_python(fom);
        },
        py::arg("modules"),
        "Parse OMT XML FOM modules, (text, file name) pairs merged in order (a class may appear in several); "
        "raises ErrorReadingFED (\"FILE:LINE:COL: message\") on the first error or conflict. Returns plain data "
        "as parse_fed does.");
    m.def(
        "fom_bundle",
        [](const std::vector<std::pair<std::string, std::string>>& modules,
           const std::vector<std::pair<std::string, std::string>>& added) {
            std::vector<FomModule> all = modules_of(modules);
            for (FomModule& m : modules_of(added)) all.push_back({std::move(m.text), std::move(m.file_name), true});
            return py::bytes(bundle(all));
        },
        py::arg("modules"), py::arg("added") = std::vector<std::pair<std::string, std::string>>{},
        "Several FOM modules, (text, file name) pairs, as the one text a federation is created from (a bundle: "
        "cpp/fed_parser/omt.hpp), and those added at joins after them, in order (each numbered after the ones "
        "before it, keeping their handles); parse_fed reads it back.");
}
