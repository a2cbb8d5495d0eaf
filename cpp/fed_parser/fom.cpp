#include "fed_parser/fom.hpp"

#include <utility>

namespace hlacore::fom {
namespace {

// Linear scans: a Fom may also be built by hand or from the wire, so there is no index to keep in
// sync, and even 1000 classes scan in a few microseconds (lookups happen once per name at startup).

template <typename Vec>
auto* by_handle(const Vec& items, Handle h) {
    using T = typename Vec::value_type;
    if (h == 0 || h > items.size()) return static_cast<const T*>(nullptr);
    const T* item = &items[h - 1];
    if (item->handle == h) return item;
    for (const T& candidate : items) {  // not laid out by handle: fall back to a scan
        if (candidate.handle == h) return &candidate;
    }
    return static_cast<const T*>(nullptr);
}

template <typename Vec>
auto* by_name(const Vec& items, std::string_view name) {
    using T = typename Vec::value_type;
    for (const T& item : items) {
        if (item.name == name) return &item;
    }
    return static_cast<const T*>(nullptr);
}

// CERTI's rules: qualified name, then "<root>.<qualified name>", then the first class with that leaf name.
template <typename Vec>
auto* find_class(const Vec& classes, std::string_view name, std::string_view root1, std::string_view root2) {
    using T = typename Vec::value_type;
    for (const T& c : classes) {
        if (c.qualified_name == name) return &c;
    }
    for (std::string_view root : {root1, root2}) {
        if (name.size() > root.size() + 1 && name.substr(0, root.size()) == root && name[root.size()] == '.') {
            const std::string_view rest = name.substr(root.size() + 1);
            for (const T& c : classes) {
                if (c.qualified_name == rest) return &c;
            }
        }
    }
    return by_name(classes, name);
}

template <typename Vec>
bool is_subclass(const Vec& classes, Handle cls, Handle ancestor) {
    // The hop limit guards against a malformed hand-built Fom whose parent links form a cycle.
    for (std::size_t hops = 0; cls != 0 && hops <= classes.size(); ++hops) {
        if (cls == ancestor) return true;
        const auto* c = by_handle(classes, cls);
        if (c == nullptr) return false;
        cls = c->parent;
    }
    return false;
}

}  // namespace

const Attribute* ObjectClass::attribute(Handle h) const { return by_handle(attributes, h); }
const Attribute* ObjectClass::attribute(std::string_view attribute_name) const {
    return by_name(attributes, attribute_name);
}

const Attribute* ObjectClass::privilege_to_delete() const {
    const auto* a = attribute("privilegeToDelete");
    return a ? a : attribute("HLAprivilegeToDeleteObject");
}

const Parameter* InteractionClass::parameter(Handle h) const { return by_handle(parameters, h); }
const Parameter* InteractionClass::parameter(std::string_view parameter_name) const {
    return by_name(parameters, parameter_name);
}

const ObjectClass* Fom::object_class(Handle h) const { return by_handle(object_classes, h); }
const InteractionClass* Fom::interaction_class(Handle h) const { return by_handle(interaction_classes, h); }
const RoutingSpace* Fom::space(Handle h) const { return by_handle(spaces, h); }

const ObjectClass* Fom::find_object_class(std::string_view class_name) const {
    return find_class(object_classes, class_name, "ObjectRoot", "HLAobjectRoot");
}

const InteractionClass* Fom::find_interaction_class(std::string_view class_name) const {
    return find_class(interaction_classes, class_name, "InteractionRoot", "HLAinteractionRoot");
}

const RoutingSpace* Fom::find_space(std::string_view space_name) const { return by_name(spaces, space_name); }

bool Fom::is_object_subclass(Handle cls, Handle ancestor) const {
    return ancestor != 0 && is_subclass(object_classes, cls, ancestor);
}

bool Fom::is_interaction_subclass(Handle cls, Handle ancestor) const {
    return ancestor != 0 && is_subclass(interaction_classes, cls, ancestor);
}

FedError::FedError(std::string file, int line, int column, std::string message)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(std::move(message)) {}

}  // namespace hlacore::fom
