// OMT XML FOM modules: expat reads each module into a small element tree (with each element's line and
// column), the modules' class trees merge, then the merged tree is numbered into a Fom as parse_fed numbers
// a .fed (classes in preorder, a class's inherited members first). Modules added at join merge into the same
// trees afterwards, one at a time, each numbering only what it adds (omt.hpp says how).
#include "fed_parser/omt.hpp"

#include <expat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace hlacore::fom {

namespace {

// Elements nested deeper are refused: the .fed parser's class depth and a few around the classes (it also
// bounds the recursion that merges and numbers the classes).
constexpr int kMaxDepth = 256 + 8;

struct Element {
    std::string name;  // without a namespace prefix
    std::vector<std::pair<std::string, std::string>> attributes;
    std::string text;
    std::vector<Element> children;
    int line = 1, column = 1;

    const Element* child(std::string_view n) const {
        for (const Element& c : children)
            if (c.name == n) return &c;
        return nullptr;
    }
    // An XML attribute (1516.2-2000) or a child element's text (1516.2-2010), trimmed; "" when absent.
    std::string value(std::string_view key) const {
        for (const auto& [k, v] : attributes)
            if (k == key) return trim(v);
        const Element* c = child(key);
        return c ? trim(c->text) : std::string();
    }
    static std::string trim(const std::string& s) {
        const auto b = s.find_first_not_of(" \t\r\n");
        if (b == std::string::npos) return {};
        return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
    }
};

std::string local(const char* name) {
    std::string n(name);
    const auto colon = n.rfind(':');
    return colon == std::string::npos ? n : n.substr(colon + 1);
}

// expat's callbacks build the tree; `path` holds the open elements.
struct TreeBuilder {
    XML_Parser parser;
    Element root;  // a document node: the module's element is its only child
    std::vector<Element*> path{&root};
    bool too_deep = false;

    static void start(void* data, const XML_Char* name, const XML_Char** attributes) {
        auto* b = static_cast<TreeBuilder*>(data);
        if (b->path.size() > kMaxDepth) {
            b->too_deep = true;
            XML_StopParser(b->parser, XML_FALSE);
            return;
        }
        Element e;
        e.name = local(name);
        for (int i = 0; attributes[i]; i += 2) e.attributes.emplace_back(local(attributes[i]), attributes[i + 1]);
        e.line = static_cast<int>(XML_GetCurrentLineNumber(b->parser));
        e.column = static_cast<int>(XML_GetCurrentColumnNumber(b->parser)) + 1;
        b->path.back()->children.push_back(std::move(e));
        b->path.push_back(&b->path.back()->children.back());
    }
    static void end(void* data, const XML_Char*) { static_cast<TreeBuilder*>(data)->path.pop_back(); }
    static void text(void* data, const XML_Char* s, int length) {
        auto* b = static_cast<TreeBuilder*>(data);
        if (b->path.size() > 1) b->path.back()->text.append(s, static_cast<std::size_t>(length));
    }
};

Element read_xml(const FomModule& m) {
    if (m.text.size() > kMaxFedBytes)
        throw FedError(m.file_name, 1, 1, "the FOM module is " + std::to_string(m.text.size()) +
                                              " bytes, more than the limit of " + std::to_string(kMaxFedBytes));
    std::unique_ptr<std::remove_pointer_t<XML_Parser>, decltype(&XML_ParserFree)> parser(XML_ParserCreate(nullptr),
                                                                                       &XML_ParserFree);
    if (!parser) throw std::bad_alloc();
    TreeBuilder b{parser.get(), {}, {}, false};
    b.path = {&b.root};
    XML_SetUserData(parser.get(), &b);
    XML_SetElementHandler(parser.get(), &TreeBuilder::start, &TreeBuilder::end);
    XML_SetCharacterDataHandler(parser.get(), &TreeBuilder::text);
    if (XML_Parse(parser.get(), m.text.data(), static_cast<int>(m.text.size()), XML_TRUE) != XML_STATUS_OK) {
        const int line = static_cast<int>(XML_GetCurrentLineNumber(parser.get()));
        const int column = static_cast<int>(XML_GetCurrentColumnNumber(parser.get())) + 1;
        throw FedError(m.file_name, line, column,
                       b.too_deep ? "elements nested more than " + std::to_string(kMaxDepth) + " deep"
                                  : std::string("not well-formed XML: ") + XML_ErrorString(XML_GetErrorCode(parser.get())));
    }
    return std::move(b.root);
}

// ---- the merged class trees ----

struct Delivery {
    Transport transport = Transport::Reliable;
    Order order = Order::Receive;
};

struct Place {
    std::string file;
    int line = 0, column = 0;
    std::string text() const { return file + ":" + std::to_string(line) + ":" + std::to_string(column); }
};

struct Member {
    std::string name;
    Delivery delivery;
    Place where;
    bool dimensions = false;  // it names dimensions: its space is kOmtSpace
    Handle handle = 0;        // 0 until numbered
};

// Whether a class or an attribute names dimensions: 1516.2-2010's <dimensions><dimension>, 2000's
// dimensions="A B".
bool names_dimensions(const Element& e) {
    const std::string listed = e.value("dimensions");
    if (!listed.empty() && listed != "NA") return true;
    const Element* d = e.child("dimensions");
    return d && std::any_of(d->children.begin(), d->children.end(), [](const Element& c) { return c.name == "dimension"; });
}

struct ClassTree {
    std::string name;
    Place where;
    std::optional<Delivery> delivery;  // an interaction class's own, once a module gives it
    Place delivery_where;
    bool dimensions = false;           // an interaction class that names dimensions
    Place dimensions_where;            // where it first did
    std::vector<Member> members;
    std::vector<ClassTree> children;
    Handle handle = 0;                 // 0 until numbered
    bool dirty = false;                // a module touched it or a class below it since it was numbered
};

// What differs between the two class trees of a module.
struct Family {
    const char* root;         // "HLAobjectRoot"
    const char* root_13;      // "ObjectRoot", HLA 1.3's name, accepted too
    const char* kind;         // "object class"
    const char* member;       // "attribute": the member element
    bool member_delivery;     // an attribute has a delivery of its own; an interaction class has one
};
constexpr Family kObjects{"HLAobjectRoot", "ObjectRoot", "object class", "attribute", true};
constexpr Family kInteractions{"HLAinteractionRoot", "InteractionRoot", "interaction class", "parameter", false};

class Merger {
public:
    explicit Merger(const FomModule& m) : module_(m) {}

    // The classes of a module's <objects> or <interactions> into the merged tree `root`. A top class that is
    // not the root (CERTI's XML for HLA 1.3 leaves the root out) is a subclass of it.
    void classes(const Element& list, const char* element, const Family& family, ClassTree& root) {
        for (const Element& e : list.children) {
            if (e.name != element) continue;
            const std::string name = e.value("name");
            if (name.empty()) fail(e, std::string("an ") + family.kind + " without a name");
            root.dirty = true;
            if (name == family.root || name == family.root_13) merge(e, root, family);
            else merge(e, child_named(root, name), family);
        }
    }

    // The dimensions a module declares, added to `out` (handles in order from 1); one declared again must
    // have the same upper bound.
    void dimensions(const Element& list, std::vector<std::pair<Dimension, Place>>& out) {
        for (const Element& e : list.children) {
            if (e.name != "dimension") continue;
            const std::string name = e.value("name"), bound = e.value("upperBound");
            if (name.empty()) fail(e, "a dimension without a name");
            std::uint64_t upper = 0;
            const auto [end, error] = std::from_chars(bound.data(), bound.data() + bound.size(), upper);
            if (bound.empty() || error != std::errc() || end != bound.data() + bound.size() || upper == 0 ||
                upper > 0xFFFFFFFFull)
                fail(e, "dimension '" + name + "' has no upper bound in 1.." + std::to_string(0xFFFFFFFFull) + " ('" + bound + "')");
            const auto same = std::find_if(out.begin(), out.end(), [&](const auto& d) { return d.first.name == name; });
            if (same == out.end()) out.push_back({Dimension{static_cast<Handle>(out.size() + 1), name, upper}, place(e)});
            else if (same->first.upper_bound != upper)
                contradict(e, "dimension '" + name + "' has another upper bound at " + same->second.text());
        }
    }

    // The update rates a module declares, added to `out`; one declared again must have the same rate.
    void update_rates(const Element& list, std::vector<std::pair<UpdateRate, Place>>& out) {
        for (const Element& e : list.children) {
            if (e.name != "updateRate") continue;
            const std::string name = e.value("name"), text = e.value("rate");
            if (name.empty()) fail(e, "an update rate without a name");
            char* end = nullptr;
            const double rate = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size() || !(rate > 0) || !std::isfinite(rate))
                fail(e, "update rate '" + name + "' has no positive rate ('" + text + "')");
            const auto same = std::find_if(out.begin(), out.end(), [&](const auto& r) { return r.first.name == name; });
            if (same == out.end()) out.push_back({UpdateRate{name, rate}, place(e)});
            else if (same->first.rate != rate) contradict(e, "update rate '" + name + "' has another rate at " + same->second.text());
        }
    }

private:
    [[noreturn]] void fail(const Element& e, const std::string& message) const {
        throw FedError(module_.file_name, e.line, e.column, message);
    }
    [[noreturn]] void contradict(const Element& e, const std::string& message) const {
        throw InconsistentModules(module_.file_name, e.line, e.column, message);
    }
    Place place(const Element& e) const { return {module_.file_name, e.line, e.column}; }

    std::optional<Delivery> delivery(const Element& e, const std::string& what) const {
        const std::string t = e.value("transportation"), o = e.value("order");
        const auto absent = [](const std::string& v) { return v.empty() || v == "NA"; };
        if (absent(t) && absent(o)) return std::nullopt;
        Delivery d;
        if (t == "HLAbestEffort") d.transport = Transport::BestEffort;
        else if (!absent(t) && t != "HLAreliable")
            fail(e, "unknown transportation '" + t + "' of " + what + " (HLAreliable, HLAbestEffort)");
        if (o == "TimeStamp") d.order = Order::Timestamp;
        else if (!absent(o) && o != "Receive") fail(e, "unknown order '" + o + "' of " + what + " (Receive, TimeStamp)");
        return d;
    }

    // Element `e`, a class of this module, into `node`: the same class, new or from an earlier module.
    void merge(const Element& e, ClassTree& node, const Family& family) {
        if (node.where.file.empty()) node.where = place(e);
        node.dirty = true;
        const std::string what = std::string(family.kind) + " '" + node.name + "'";
        if (!family.member_delivery) {
            if (!node.dimensions && names_dimensions(e)) {
                node.dimensions = true;
                node.dimensions_where = place(e);
            }
            if (const auto d = delivery(e, what)) {
                if (node.delivery && (node.delivery->transport != d->transport || node.delivery->order != d->order))
                    contradict(e, what + " has another transportation or order at " + node.delivery_where.text());
                node.delivery = d;
                node.delivery_where = place(e);
            }
        }
        for (const Element& c : e.children) {
            const std::string name = c.value("name");
            if (c.name == family.member) {
                if (name.empty()) fail(c, std::string("an ") + family.member + " of " + what + " without a name");
                const Delivery d = family.member_delivery ? delivery(c, family.member + (" '" + name + "'")).value_or(Delivery{})
                                                          : Delivery{};
                const auto same = std::find_if(node.members.begin(), node.members.end(),
                                               [&](const Member& m) { return m.name == name; });
                if (same == node.members.end()) {
                    node.members.push_back({name, d, place(c), names_dimensions(c)});
                } else if (name != "HLAprivilegeToDeleteObject" &&  // the MIM's, declared again as it likes
                           (same->delivery.transport != d.transport || same->delivery.order != d.order)) {
                    contradict(c, std::string(family.member) + " '" + name + "' of " + what + " is declared otherwise at " +
                                      same->where.text());
                }
            } else if (c.name == e.name) {
                if (name.empty()) fail(c, "a subclass of " + what + " without a name");
                merge(c, child_named(node, name), family);
            }
        }
    }

    static ClassTree& child_named(ClassTree& node, const std::string& name) {
        for (ClassTree& k : node.children)
            if (k.name == name) return k;
        node.children.push_back({});
        node.children.back().name = name;
        return node.children.back();
    }

    const FomModule& module_;
};

// ---- numbering, as parse_fed does; then, a module added at join at a time, what each adds ----

// What the numberings of one class tree keep track of: the qualified names (a root's subclass named like the
// root, or a name with a dot in it, could otherwise name two classes) and the members counted (of both trees,
// as parse_fed counts them).
struct Numbering {
    std::map<std::string, Place> qualified;
    std::size_t* total = nullptr;
};

[[noreturn]] void fail_at(const Place& where, const std::string& message) {
    throw FedError(where.file, where.line, where.column, message);
}

void count_members(std::size_t added, std::size_t& total, const Place& where) {
    total += added;
    if (total > kMaxClassMembers)
        fail_at(where, "too many attributes and parameters: more than " + std::to_string(kMaxClassMembers) +
                           ", counting the inherited ones in each subclass");
}

// The highest member handle of class `cls` and its subclasses: a member added to `cls` later goes above it, so
// that no subclass has two members with one handle.
template <class Cls, class M>
Handle last_member(const std::vector<Cls>& out, std::vector<M> Cls::*members, Handle cls) {
    const auto& own = out[cls - 1].*members;  // sorted by handle
    Handle last = own.empty() ? 0 : own.back().handle;
    for (Handle child : out[cls - 1].children) last = std::max(last, last_member(out, members, child));
    return last;
}

// `member` (declared as `declared`) into the numbered class of `node` and, inherited, into its numbered
// subclasses (the others copy it when numbered); the error names a subclass that declares it too. Returns
// the classes it went into.
template <class Cls, class M>
std::size_t add_member(const ClassTree& node, std::vector<Cls>& out, std::vector<M> Cls::*members, const M& member,
                       const Member& declared) {
    (out[node.handle - 1].*members).push_back(member);
    std::size_t classes = 1;
    for (const ClassTree& child : node.children) {
        if (!child.handle) continue;
        const auto again = std::find_if(child.members.begin(), child.members.end(),
                                        [&](const Member& m) { return m.name == member.name; });
        if (again != child.members.end())
            throw InconsistentModules(declared.where.file, declared.where.line, declared.where.column,
                                      "'" + member.name + "' is declared already by the subclass '" +
                                          out[child.handle - 1].qualified_name + "' at " + again->where.text());
        classes += add_member(child, out, members, member, declared);
    }
    return classes;
}

// An interaction class's delivery and space: its own, else its parent's.
void deliver(const ClassTree& node, const InteractionClass* parent, InteractionClass& cls) {
    const Delivery d = node.delivery.value_or(parent ? Delivery{parent->transport, parent->order} : Delivery{});
    cls.transport = d.transport;
    cls.order = d.order;
    cls.space = node.dimensions ? kOmtSpace : parent ? parent->space : std::string();
}

// What was merged into `node` and below since the last numbering, into `out`, in preorder (only down the
// paths the modules touched): a class not numbered yet gets the next class handle; a member not numbered yet
// the handle above every member of its class and of its subclasses (for a new class, the next after its
// inherited ones), inherited at once by the subclasses. `inherited` are the ancestors' members, for the error
// when a class declares again a member it inherits.
template <class Cls, class M>
void number(ClassTree& node, Handle parent, std::vector<Cls>& out, std::vector<M> Cls::*members,
            std::vector<const Member*> inherited, Numbering& n) {
    if (!node.dirty) return;
    node.dirty = false;
    if (!node.handle) {
        Cls cls;
        cls.handle = static_cast<Handle>(out.size() + 1);
        cls.name = node.name;
        cls.qualified_name = parent <= 1 ? node.name : out[parent - 1].qualified_name + "." + node.name;
        cls.parent = parent;
        if (const auto [first, added] = n.qualified.emplace(cls.qualified_name, node.where); !added)
            fail_at(node.where, "a second class named '" + cls.qualified_name + "' (the first at " + first->second.text() + ")");
        if (parent) cls.*members = out[parent - 1].*members;
        if constexpr (std::is_same_v<Cls, InteractionClass>) deliver(node, parent ? &out[parent - 1] : nullptr, cls);
        node.handle = cls.handle;
        if (parent) out[parent - 1].children.push_back(cls.handle);
        count_members((cls.*members).size(), *n.total, node.where);
        out.push_back(std::move(cls));
    } else if constexpr (std::is_same_v<Cls, InteractionClass>) {
        // A module added at join may not change how a class the federation has is delivered.
        InteractionClass now;
        deliver(node, parent ? &out[parent - 1] : nullptr, now);
        const InteractionClass& cls = out[node.handle - 1];
        if (now.transport != cls.transport || now.order != cls.order)
            fail_at(node.delivery_where, "interaction class '" + cls.qualified_name +
                                             "' has another transportation or order than the federation's FOM "
                                             "gives it (declared at " + node.where.text() + ")");
        if (now.space != cls.space)
            fail_at(node.dimensions_where, "interaction class '" + cls.qualified_name +
                                               "' names dimensions that the federation's FOM does not give it "
                                               "(declared at " + node.where.text() + ")");
    }
    for (Member& m : node.members) {
        if (!m.handle) {
            const auto clash =
                std::find_if(inherited.begin(), inherited.end(), [&](const Member* i) { return i->name == m.name; });
            if (clash != inherited.end()) {
                if (m.name == "HLAprivilegeToDeleteObject") continue;  // the MIM's, declared again
                fail_at(m.where, "'" + m.name + "' of '" + out[node.handle - 1].qualified_name + "' is inherited from " +
                                     (*clash)->where.text());
            }
            M member;
            member.handle = m.handle = last_member(out, members, node.handle) + 1;
            member.name = m.name;
            if constexpr (std::is_same_v<M, Attribute>) {
                member.transport = m.delivery.transport;
                member.order = m.delivery.order;
                if (m.dimensions) member.space = kOmtSpace;
            }
            count_members(add_member(node, out, members, member, m), *n.total, m.where);
        }
        inherited.push_back(&m);
    }
    for (ClassTree& child : node.children) number(child, node.handle, out, members, inherited, n);
}

ClassTree root(const char* name, std::optional<Member> mim) {
    ClassTree t;
    t.name = name;
    t.dirty = true;  // numbered even when no module names it
    if (mim) t.members.push_back(*mim);
    return t;
}

// A FOM's merged class trees, dimensions and update rates, numbered into `fom` a layer at a time: the
// creation's modules merged, then numbered; then each module added at join merged and numbered.
class Model {
public:
    void merge(const FomModule& m) {
        const Element document = read_xml(m);
        const Element* model = document.children.empty() ? nullptr : &document.children.front();
        if (!model || model->name != "objectModel")
            throw FedError(m.file_name, model ? model->line : 1, model ? model->column : 1,
                           "not an OMT FOM module: the document element is '" + (model ? model->name : "") +
                               "', not objectModel");
        if (fom_.source_name.empty()) fom_.source_name = m.file_name;
        if (fom_.federation_name.empty()) {
            const Element* id = model->child("modelIdentification");
            fom_.federation_name = id ? id->value("name") : model->value("name");
        }
        Merger merger(m);
        if (const Element* d = model->child("dimensions")) merger.dimensions(*d, dimensions_);
        if (const Element* r = model->child("updateRates")) merger.update_rates(*r, rates_);
        if (const Element* o = model->child("objects")) merger.classes(*o, "objectClass", kObjects, objects_);
        if (const Element* i = model->child("interactions")) merger.classes(*i, "interactionClass", kInteractions, interactions_);
    }

    // Numbers what was merged since the last numbering.
    void number_new() {
        fom_.spaces.clear();  // the dimensions keep their handles: new ones were appended
        if (!dimensions_.empty()) {
            RoutingSpace space;
            space.handle = 1;
            space.name = kOmtSpace;
            for (const auto& [d, where] : dimensions_) space.dimensions.push_back(d);
            fom_.spaces.push_back(std::move(space));
        }
        number(objects_, 0, fom_.object_classes, &ObjectClass::attributes, {}, object_numbering_);
        number(interactions_, 0, fom_.interaction_classes, &InteractionClass::parameters, {}, interaction_numbering_);
    }

    Fom take() {
        fom_.fed_version = "IEEE 1516-2010";
        for (auto& [r, where] : rates_) fom_.update_rates.push_back(std::move(r));
        fom_.reindex();
        return std::move(fom_);
    }

private:
    // The MIM: the roots, and the privilege to delete an object, reliable and timestamped as IEEE 1516 has it.
    ClassTree objects_ = root("HLAobjectRoot", Member{"HLAprivilegeToDeleteObject", {Transport::Reliable, Order::Timestamp},
                                                      {"the MIM", 0, 0}});
    ClassTree interactions_ = root("HLAinteractionRoot", std::nullopt);
    std::vector<std::pair<Dimension, Place>> dimensions_;
    std::vector<std::pair<UpdateRate, Place>> rates_;
    Fom fom_;
    std::size_t members_ = 0;  // of both trees: one bound, as parse_fed has
    Numbering object_numbering_{{}, &members_}, interaction_numbering_{{}, &members_};  // the names are apart
};

// A bundle's header line of a module: "<name length> <text length>[ added]\n".
constexpr std::string_view kAddedMark = " added\n";

}  // namespace

bool is_xml(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    return first != std::string_view::npos && text[first] == '<';
}

Fom parse_omt(const std::vector<FomModule>& modules) {
    Model model;
    std::size_t i = 0;
    for (; i < modules.size() && !modules[i].added; ++i) model.merge(modules[i]);
    model.number_new();
    for (; i < modules.size(); ++i) {
        if (!modules[i].added)
            throw FedError(modules[i].file_name, 1, 1, "a module of the federation's creation after one added at join");
        model.merge(modules[i]);
        model.number_new();
    }
    return model.take();
}

Fom parse_omt(std::string_view text, std::string_view file_name) {
    return parse_omt(std::vector<FomModule>{{std::string(text), std::string(file_name)}});
}

std::string bundle(const std::vector<FomModule>& modules) {
    std::string out(kBundleMagic);
    for (const FomModule& m : modules)
        out += std::to_string(m.file_name.size()) + ' ' + std::to_string(m.text.size()) +
               std::string(m.added ? kAddedMark : "\n") + m.file_name + m.text;
    return out;
}

std::vector<FomModule> unbundle(std::string_view text, std::string_view file_name) {
    auto fail = [&](const std::string& why) -> FedError {
        return FedError(std::string(file_name), 1, 1, "malformed bundle of FOM modules: " + why);
    };
    auto number = [&](std::string_view& rest) {
        std::size_t value = 0, digits = 0;
        for (; digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9'; ++digits) {
            if (value > (kMaxFedBytes - (rest[digits] - '0')) / 10) throw fail("a length beyond the limit");
            value = value * 10 + static_cast<std::size_t>(rest[digits] - '0');
        }
        if (digits == 0) throw fail("a length expected");
        rest.remove_prefix(digits);
        return value;
    };
    auto skip = [](std::string_view& rest, std::string_view what) {
        if (rest.substr(0, what.size()) != what) return false;
        rest.remove_prefix(what.size());
        return true;
    };
    if (!skip(text, kBundleMagic)) throw fail("it does not begin as one");
    std::vector<FomModule> modules;
    while (!text.empty()) {
        const std::size_t name_size = number(text);
        if (!skip(text, " ")) throw fail("a length expected");
        const std::size_t text_size = number(text);
        const bool added = skip(text, kAddedMark);
        if (!added && !skip(text, "\n")) throw fail("a length expected");
        if (text.size() < name_size || text.size() - name_size < text_size) throw fail("a module cut short");
        if (!added && !modules.empty() && modules.back().added) throw fail("a module of the creation after one added at join");
        modules.push_back({std::string(text.substr(name_size, text_size)), std::string(text.substr(0, name_size)), added});
        text.remove_prefix(name_size + text_size);
    }
    if (modules.empty()) throw fail("no module");
    return modules;
}

bool is_bundle(std::string_view text) { return text.substr(0, kBundleMagic.size()) == kBundleMagic; }

Fom parse_fom(std::string_view text, std::string_view file_name) {
    if (is_bundle(text)) return parse_omt(unbundle(text, file_name));
    return is_xml(text) ? parse_omt(text, file_name) : parse_fed(text, file_name);
}

std::vector<FomModule> fom_modules(std::string_view text, std::string_view file_name) {
    if (is_bundle(text)) return unbundle(text, file_name);
    if (!is_xml(text)) throw FedError(std::string(file_name), 1, 1, "an HLA 1.3 .fed, not FOM modules");
    return {{std::string(text), std::string(file_name)}};
}

ExtendedFom extend_fom(std::string_view fed_text, std::string_view file_name, const std::vector<FomModule>& added) {
    if (!is_bundle(fed_text) && !is_xml(fed_text))
        throw FedError(std::string(file_name), 1, 1,
                       "the federation was created from an HLA 1.3 .fed, which takes no FOM modules at join");
    std::vector<FomModule> modules = fom_modules(fed_text, file_name);
    for (const FomModule& m : added) modules.push_back({m.text, m.file_name, true});
    ExtendedFom extended{parse_omt(modules), bundle(modules)};
    return extended;
}

bool extends(std::string_view text, std::string_view base) {
    if (text == base) return true;
    std::vector<FomModule> ours, theirs;
    try {
        ours = fom_modules(text, "");
        theirs = fom_modules(base, "");
    } catch (const FedError&) {
        return false;
    }
    if (ours.size() < theirs.size()) return false;
    for (std::size_t i = 0; i < ours.size(); ++i) {
        if (i < theirs.size() ? ours[i].text != theirs[i].text || ours[i].added != theirs[i].added : !ours[i].added)
            return false;
    }
    return true;
}

}  // namespace hlacore::fom
