#include "fed_parser/fom.hpp"

#include <algorithm>
#include <utility>

namespace hlacore::fom {
namespace {

template <typename Vec>
auto* by_handle(const Vec& items, Handle h) {
    using T = typename Vec::value_type;
    if (h == 0) return static_cast<const T*>(nullptr);
    if (h <= items.size() && items[h - 1].handle == h) return &items[h - 1];
    // Not laid out by handle. A class's members after one was added at join skip handles but stay sorted by
    // them (fed_parser/omt.hpp); a Fom built by hand may be in any order: then a scan.
    const auto sorted = std::lower_bound(items.begin(), items.end(), h, [](const T& item, Handle x) { return item.handle < x; });
    if (sorted != items.end() && sorted->handle == h) return &*sorted;
    if (h > items.size()) return static_cast<const T*>(nullptr);  // a Fom built by hand numbers from 1, no gaps
    for (const T& candidate : items) {
        if (candidate.handle == h) return &candidate;
    }
    return static_cast<const T*>(nullptr);
}

// The item of `items` recorded under `name` in `index`.
template <typename Vec, typename NameOf>
auto* by_name(const Vec& items, const NameIndex& index, std::string_view name, NameOf name_of) {
    return by_handle(items, index.find(name, name_of));
}

template <typename Vec>
auto* by_name(const Vec& items, const NameIndex& index, std::string_view name) {
    return by_name(items, index, name, [&](Handle h) -> std::string_view {
        const auto* item = by_handle(items, h);
        return item ? std::string_view(item->name) : std::string_view();
    });
}

// CERTI's rules: qualified name, then "<root>.<qualified name>", then the first class with that leaf name.
template <typename Vec>
auto* find_class(const Vec& classes, const NameIndex& qualified, const NameIndex& leaf, std::string_view name,
                 std::string_view root1, std::string_view root2) {
    auto qualified_name_of = [&](Handle h) -> std::string_view {
        const auto* c = by_handle(classes, h);
        return c ? std::string_view(c->qualified_name) : std::string_view();
    };
    if (const auto* c = by_name(classes, qualified, name, qualified_name_of)) return c;
    for (std::string_view root : {root1, root2}) {
        if (name.size() > root.size() + 1 && name.substr(0, root.size()) == root && name[root.size()] == '.') {
            if (const auto* c = by_name(classes, qualified, name.substr(root.size() + 1), qualified_name_of)) return c;
        }
    }
    return by_name(classes, leaf, name);
}

template <typename Vec>
void index_names(const Vec& items, NameIndex& index) {
    index.clear();
    for (const auto& item : items) {
        index.add(item.name, item.handle, [&](Handle h) { return std::string_view(by_handle(items, h)->name); });
    }
}

template <typename Vec>
void index_classes(const Vec& classes, NameIndex& qualified, NameIndex& leaf) {
    index_names(classes, leaf);
    qualified.clear();
    for (const auto& c : classes) {
        qualified.add(c.qualified_name, c.handle,
                      [&](Handle h) { return std::string_view(by_handle(classes, h)->qualified_name); });
    }
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
    return by_name(attributes, attribute_names, attribute_name);
}

const Attribute* ObjectClass::privilege_to_delete() const {
    const auto* a = attribute("privilegeToDelete");
    return a ? a : attribute("HLAprivilegeToDeleteObject");
}

const Parameter* InteractionClass::parameter(Handle h) const { return by_handle(parameters, h); }
const Parameter* InteractionClass::parameter(std::string_view parameter_name) const {
    return by_name(parameters, parameter_names, parameter_name);
}

const Dimension* RoutingSpace::dimension(Handle h) const { return by_handle(dimensions, h); }
const Dimension* RoutingSpace::dimension(std::string_view dimension_name) const {
    return by_name(dimensions, dimension_names, dimension_name);
}

const ObjectClass* Fom::object_class(Handle h) const { return by_handle(object_classes, h); }
const InteractionClass* Fom::interaction_class(Handle h) const { return by_handle(interaction_classes, h); }
const RoutingSpace* Fom::space(Handle h) const { return by_handle(spaces, h); }

const ObjectClass* Fom::find_object_class(std::string_view class_name) const {
    return find_class(object_classes, object_names, object_leaf_names, class_name, "ObjectRoot", "HLAobjectRoot");
}

const InteractionClass* Fom::find_interaction_class(std::string_view class_name) const {
    return find_class(interaction_classes, interaction_names, interaction_leaf_names, class_name, "InteractionRoot",
                      "HLAinteractionRoot");
}

const RoutingSpace* Fom::find_space(std::string_view space_name) const {
    return by_name(spaces, space_names, space_name);
}

const UpdateRate* Fom::find_update_rate(std::string_view rate_name) const {
    for (const auto& r : update_rates)
        if (r.name == rate_name) return &r;
    return nullptr;
}

void Fom::reindex() {
    index_names(spaces, space_names);
    for (auto& s : spaces) index_names(s.dimensions, s.dimension_names);
    index_classes(object_classes, object_names, object_leaf_names);
    for (auto& c : object_classes) index_names(c.attributes, c.attribute_names);
    index_classes(interaction_classes, interaction_names, interaction_leaf_names);
    for (auto& c : interaction_classes) index_names(c.parameters, c.parameter_names);
}

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
