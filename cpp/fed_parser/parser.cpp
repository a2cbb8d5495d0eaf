// Recursive-descent parser for the union of the CERTI, OpenRTI and Portico `.fed` dialects, numbering
// handles the way CERTI does.
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "fed_parser/fom.hpp"
#include "fed_parser/lexer.hpp"

namespace hlacore::fom {
namespace {

using detail::Lexer;
using detail::Token;
using detail::TokenKind;
using detail::quote_for_message;

enum class Kw : std::uint8_t {
    Unknown, FED, Federation, FEDversion, Federate, Spaces, Space, Dimension, Objects, Class, Attribute,
    Interactions, Parameter, SecLevel
};

struct KeywordName {
    Kw kw;
    std::string_view name;
};

constexpr KeywordName kKeywords[] = {
    {Kw::FED, "FED"},          {Kw::Federation, "Federation"},     {Kw::FEDversion, "FEDversion"},
    {Kw::Federate, "Federate"}, {Kw::Spaces, "spaces"},            {Kw::Space, "space"},
    {Kw::Dimension, "dimension"}, {Kw::Objects, "objects"},        {Kw::Class, "class"},
    {Kw::Attribute, "attribute"}, {Kw::Interactions, "interactions"}, {Kw::Parameter, "parameter"},
    {Kw::SecLevel, "sec_level"},
};

inline char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
}

Kw keyword_of(std::string_view word) {
    for (const auto& k : kKeywords) {
        if (iequals(word, k.name)) return k.kw;
    }
    return Kw::Unknown;
}

std::string_view name_of(Kw kw) {
    for (const auto& k : kKeywords) {
        if (k.kw == kw) return k.name;
    }
    return "?";
}

bool is_root_name(std::string_view n) {
    return n == "ObjectRoot" || n == "HLAobjectRoot" || n == "InteractionRoot" || n == "HLAinteractionRoot";
}

constexpr const char* transport_list = "reliable or best_effort";
constexpr const char* order_list = "timestamp or receive";

bool parse_transport(std::string_view w, Transport& out) {
    if (iequals(w, "reliable") || iequals(w, "HLAreliable")) {
        out = Transport::Reliable;
        return true;
    }
    if (iequals(w, "best_effort") || iequals(w, "HLAbestEffort")) {
        out = Transport::BestEffort;
        return true;
    }
    return false;
}

bool parse_order(std::string_view w, Order& out) {
    if (iequals(w, "timestamp")) {
        out = Order::Timestamp;
        return true;
    }
    if (iequals(w, "receive")) {
        out = Order::Receive;
        return true;
    }
    return false;
}

// An opened "(keyword": what a missing ')' message names.
struct Open {
    Kw kw;
    std::size_t offset;  // of the '('
};

// Deep enough for any real FOM, shallow enough that recursion cannot exhaust the stack.
constexpr int kMaxClassDepth = 256;

// Object classes with their attributes, or interaction classes with their parameters: both are read by
// the same rules (nesting, inheritance, handles), only where they go and how messages name them differ.
template <class Cls, class Member>
struct ClassFamily {
    std::vector<Cls>& classes;
    NameIndex& names;       // by qualified name
    NameIndex& leaf_names;
    std::vector<Member> Cls::*members;
    NameIndex Cls::*member_names;
    Kw member;               // Kw::Attribute or Kw::Parameter
    const char* kind;        // "object class", "interaction class"
    const char* owner;       // the class as member messages name it: "class", "interaction class"
    std::vector<std::size_t> offsets{};  // offsets[h - 1]: where class h's name is, for duplicate messages
};

class Parser {
public:
    Parser(std::string_view text, std::string_view file_name) : lex_(text, file_name) {
        fom_.source_name = std::string(file_name);
    }

    Fom run();

private:
    [[noreturn]] void fail(std::size_t offset, const std::string& message) const { lex_.fail(offset, message); }
    [[noreturn]] void fail(const Token& t, const std::string& message) const { lex_.fail(t.offset, message); }

    std::string at(std::size_t offset) const {
        const auto p = lex_.position(offset);
        return std::to_string(p.line) + ":" + std::to_string(p.column);
    }

    std::string opened(const Open& o) const {
        return "'(" + std::string(name_of(o.kw)) + "' opened at " + at(o.offset);
    }

    static std::string describe(const Token& t) {
        switch (t.kind) {
            case TokenKind::LParen: return "'('";
            case TokenKind::RParen: return "')'";
            case TokenKind::Word: return "'" + quote_for_message(t.text) + "'";
            case TokenKind::String: return "\"" + quote_for_message(t.text) + "\"";
            case TokenKind::End: return "end of file";
        }
        return "?";
    }

    // Next token inside `o`; the end of the file there is always an unclosed parenthesis.
    Token next_in(const Open& o) {
        Token t = lex_.next();
        if (t.kind == TokenKind::End) fail(t, "missing ')' to close " + opened(o));
        return t;
    }

    // After '(' inside `o`: the keyword.
    Kw keyword_in(const Open& o, const Token& paren, Token& word) {
        word = next_in(o);
        if (word.kind != TokenKind::Word) {
            fail(word, "expected a keyword after '(' at " + at(paren.offset) + ", found " + describe(word));
        }
        return keyword_of(word.text);
    }

    void expect_close(const Open& o) {
        const Token t = next_in(o);
        if (t.kind != TokenKind::RParen) {
            fail(t, "unexpected " + describe(t) + " (expected ')' to close " + opened(o) + ")");
        }
    }

    // A name or value: a word or a quoted string. `identifier` applies CERTI's name rule to words.
    std::string_view read_value(const Open& o, std::string_view what, bool identifier, Token* where = nullptr) {
        const Token t = next_in(o);
        if (t.kind == TokenKind::Word) {
            const char c = t.text[0];
            if (identifier && !((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_')) {
                fail(t, "invalid " + std::string(what) + " '" + quote_for_message(t.text) +
                            "' (names start with a letter or '_')");
            }
        } else if (t.kind == TokenKind::String) {
            if (t.text.empty()) fail(t, "empty " + std::string(what));
        } else {
            const bool vowel = what[0] == 'a' || what[0] == 'e' || what[0] == 'i' || what[0] == 'o';
            fail(t, std::string(vowel ? "expected an " : "expected a ") + std::string(what) + " after '(" +
                        std::string(name_of(o.kw)) + "', found " + describe(t));
        }
        if (where) *where = t;
        return t.text;
    }

    // A keyword that is valid somewhere, but not inside `context`; `allowed` lists what is.
    [[noreturn]] void misplaced(Kw kw, const Token& paren, const Token& word, Kw context, const char* allowed) const {
        if (kw == context) {  // e.g. a space inside a space: the specific messages below would mislead
            fail(paren, "'(" + std::string(name_of(kw)) + "' is not allowed inside '(" +
                            std::string(name_of(context)) + "'");
        }
        switch (kw) {
            case Kw::Attribute: fail(paren, "attribute outside an object class");
            case Kw::Parameter: fail(paren, "parameter outside an interaction class");
            case Kw::Class: fail(paren, "class outside (objects ...) or (interactions ...)");
            case Kw::Space: fail(paren, "space outside (spaces ...)");
            case Kw::Dimension: fail(paren, "dimension outside a (space ...)");
            case Kw::SecLevel: fail(paren, "sec_level outside a class");
            case Kw::Unknown:
                fail(word, "unknown keyword '" + quote_for_message(word.text) + "' (expected " + allowed + ")");
            default:
                fail(paren, "'(" + std::string(name_of(kw)) + "' is not allowed inside '(" +
                                std::string(name_of(context)) + "'");
        }
    }

    // Each "(keyword ...)" inside `o` up to its ')', which is returned: `entry(keyword, paren, word)` reads
    // the rest of it. Anything else there fails with "unexpected ..." followed by `where`.
    template <class Entry>
    Token entries(const Open& o, const std::string& where, Entry&& entry) {
        for (;;) {
            const Token t = next_in(o);
            if (t.kind == TokenKind::RParen) return t;
            if (t.kind != TokenKind::LParen) fail(t, "unexpected " + describe(t) + where);
            Token word;
            const Kw kw = keyword_in(o, t, word);
            entry(kw, t, word);
        }
    }

    // Entries inside `o` that may only be "(kw ...)", each read by `entry(open)`.
    template <class Entry>
    void entries_of(Kw kw, const Open& o, Entry&& entry) {
        const std::string name(name_of(kw));
        entries(o, " (expected '(" + name + "' or ')')", [&](Kw found, const Token& paren, const Token& word) {
            if (found != kw) misplaced(found, paren, word, o.kw, name.c_str());
            entry(Open{found, paren.offset});
        });
    }

    void parse_federate(const Open& o);
    void parse_sec_level(const Open& o);
    void parse_spaces(const Open& o);
    void parse_space(const Open& o);
    template <class Cls, class Member>
    void parse_class(ClassFamily<Cls, Member>& family, const Open& o, Handle parent, int depth);
    template <class Cls, class Member>
    void parse_member(ClassFamily<Cls, Member>& family, const Open& o, Handle cls);
    // The transport, order and optional routing space of an attribute or interaction class (`what`).
    template <class Declared>
    void read_delivery(const Open& o, const std::string& what, Declared& out);
    void space_reference(const Token& t, std::string& out);
    std::string qualify(const std::string& parent_qualified, std::string_view name) const;
    // Adds `added` to the attributes and parameters held, failing at `where` beyond kMaxClassMembers.
    void count_members(const Token& where, std::size_t added);

    Lexer lex_;
    Fom fom_;
    ClassFamily<ObjectClass, Attribute> objects_{
        fom_.object_classes, fom_.object_names, fom_.object_leaf_names, &ObjectClass::attributes,
        &ObjectClass::attribute_names, Kw::Attribute, "object class", "class"};
    ClassFamily<InteractionClass, Parameter> interactions_{
        fom_.interaction_classes, fom_.interaction_names, fom_.interaction_leaf_names, &InteractionClass::parameters,
        &InteractionClass::parameter_names, Kw::Parameter, "interaction class", "interaction class"};
    std::size_t class_members_ = 0;    // attributes and parameters so far, inherited ones counted in each class
    std::size_t qualified_bytes_ = 0;  // the classes' qualified names so far
    bool spaces_done_ = false;
    std::vector<Token> pending_spaces_;  // references made before (spaces ...) was read
};

std::string Parser::qualify(const std::string& parent_qualified, std::string_view name) const {
    if (parent_qualified.empty() || is_root_name(parent_qualified)) return std::string(name);
    std::string q;
    q.reserve(parent_qualified.size() + 1 + name.size());
    q += parent_qualified;
    q += '.';
    q += name;
    return q;
}

Fom Parser::run() {
    const Token first = lex_.next();
    if (first.kind == TokenKind::End) fail(std::size_t{0}, "empty file");
    if (first.kind != TokenKind::LParen) fail(first, "expected '(' to start the file, found " + describe(first));
    const Token fed = lex_.next();
    if (fed.kind != TokenKind::Word || keyword_of(fed.text) != Kw::FED) {
        fail(fed, "expected keyword FED after '(', found " + describe(fed));
    }
    const Open fed_open{Kw::FED, first.offset};

    bool seen_federation = false, seen_version = false, seen_spaces = false, seen_objects = false,
         seen_interactions = false;
    const Token close = entries(fed_open, " (expected '(' or ')')", [&](Kw kw, const Token& t, const Token& word) {
        const Open o{kw, t.offset};
        auto once = [&](bool& seen, const char* what) {
            if (seen) fail(t, std::string("duplicate ") + what);
            seen = true;
        };
        switch (kw) {
            case Kw::Federation:
                once(seen_federation, "(Federation ...) entry");
                fom_.federation_name = std::string(read_value(o, "federation name", true));
                expect_close(o);
                break;
            case Kw::FEDversion:
                once(seen_version, "(FEDversion ...) entry");
                fom_.fed_version = std::string(read_value(o, "version", false));
                expect_close(o);
                break;
            case Kw::Federate: parse_federate(o); break;
            case Kw::Spaces:
                once(seen_spaces, "section 'spaces'");
                parse_spaces(o);
                break;
            case Kw::Objects:
                once(seen_objects, "section 'objects'");
                entries_of(Kw::Class, o, [&](const Open& c) { parse_class(objects_, c, 0, 1); });
                break;
            case Kw::Interactions:
                once(seen_interactions, "section 'interactions'");
                entries_of(Kw::Class, o, [&](const Open& c) { parse_class(interactions_, c, 0, 1); });
                break;
            default:
                misplaced(kw, t, word, Kw::FED, "Federation, FEDversion, Federate, spaces, objects or interactions");
        }
    });
    if (!seen_federation) fail(close, "the FED has no (Federation NAME) entry");
    if (!seen_version) fail(close, "the FED has no (FEDversion VERSION) entry");

    const Token trailing = lex_.next();
    if (trailing.kind == TokenKind::RParen) {
        fail(trailing, "unexpected ')' after the end of the FED (closed at " + at(close.offset) + ")");
    }
    if (trailing.kind != TokenKind::End) {
        fail(trailing, "unexpected text after the end of the FED (closed at " + at(close.offset) + ")");
    }

    for (const Token& ref : pending_spaces_) {
        if (fom_.find_space(ref.text) == nullptr) {
            fail(ref, "unknown routing space '" + quote_for_message(ref.text) + "'");
        }
    }
    return std::move(fom_);
}

void Parser::parse_federate(const Open& o) {
    // CERTI's security extension: (Federate "name" "level"); accepted and ignored.
    read_value(o, "federate name", false);
    read_value(o, "security level", false);
    expect_close(o);
}

void Parser::parse_sec_level(const Open& o) {
    read_value(o, "security level", false);
    expect_close(o);
}

void Parser::parse_spaces(const Open& o) {
    entries_of(Kw::Space, o, [&](const Open& space) { parse_space(space); });
    spaces_done_ = true;
}

void Parser::parse_space(const Open& o) {
    Token name_token;
    const std::string_view name = read_value(o, "space name", true, &name_token);
    if (fom_.find_space(name) != nullptr) fail(name_token, "duplicate routing space '" + quote_for_message(name) + "'");
    RoutingSpace space;
    space.handle = static_cast<Handle>(fom_.spaces.size() + 1);
    space.name = std::string(name);
    auto dimension_name_of = [&](Handle h) { return std::string_view(space.dimensions[h - 1].name); };
    entries_of(Kw::Dimension, o, [&](const Open& d) {
        Token dim_token;
        const std::string_view dim = read_value(d, "dimension name", true, &dim_token);
        if (space.dimension_names.find(dim, dimension_name_of) != 0) {
            fail(dim_token, "duplicate dimension '" + quote_for_message(dim) + "' in space '" + space.name + "'");
        }
        const auto h = static_cast<Handle>(space.dimensions.size() + 1);
        space.dimensions.push_back(Dimension{h, std::string(dim)});
        space.dimension_names.add(space.dimensions.back().name, h, dimension_name_of);
        expect_close(d);
    });
    fom_.spaces.push_back(std::move(space));
    fom_.space_names.add(fom_.spaces.back().name, fom_.spaces.back().handle,
                         [&](Handle h) { return std::string_view(fom_.spaces[h - 1].name); });
}

void Parser::space_reference(const Token& t, std::string& out) {
    out = std::string(t.text);
    if (!spaces_done_) {
        pending_spaces_.push_back(t);
    } else if (fom_.find_space(t.text) == nullptr) {
        fail(t, "unknown routing space '" + quote_for_message(t.text) + "'");
    }
}

template <class Declared>
void Parser::read_delivery(const Open& o, const std::string& what, Declared& out) {
    Token t = next_in(o);
    if (t.kind != TokenKind::Word && t.kind != TokenKind::String) fail(t, what + " needs a transport and an order");
    if (!parse_transport(t.text, out.transport)) {
        fail(t, "unknown transport '" + quote_for_message(t.text) + "' (expected " + transport_list + ")");
    }
    t = next_in(o);
    if (t.kind != TokenKind::Word && t.kind != TokenKind::String) {
        fail(t, what + " needs an order (" + order_list + ") after its transport");
    }
    if (!parse_order(t.text, out.order)) {
        fail(t, "unknown order '" + quote_for_message(t.text) + "' (expected " + order_list + ")");
    }
    if (lex_.peek().kind == TokenKind::Word || lex_.peek().kind == TokenKind::String) {
        space_reference(lex_.next(), out.space);
    }
}

template <class Cls, class Member>
void Parser::parse_class(ClassFamily<Cls, Member>& family, const Open& o, Handle parent, int depth) {
    if (depth > kMaxClassDepth) fail(o.offset, "classes nested more than " + std::to_string(kMaxClassDepth) + " deep");
    Token name_token;
    const std::string_view name = read_value(o, "class name", true, &name_token);

    Cls cls;
    cls.name = std::string(name);
    cls.qualified_name = qualify(parent ? family.classes[parent - 1].qualified_name : std::string(), name);
    auto qualified_name_of = [&](Handle h) { return std::string_view(family.classes[h - 1].qualified_name); };
    if (const Handle first = family.names.find(cls.qualified_name, qualified_name_of)) {
        fail(name_token, "duplicate " + std::string(family.kind) + " '" + quote_for_message(cls.qualified_name) +
                             "' (first declared at " + at(family.offsets[first - 1]) + ")");
    }
    // Subclasses repeat their ancestors' names and members: bound what a small text can make us hold
    // (kMaxFedBytes of qualified names, kMaxClassMembers).
    qualified_bytes_ += cls.qualified_name.size();
    if (qualified_bytes_ > kMaxFedBytes) {
        fail(name_token, "too many nested classes: their qualified names exceed " + std::to_string(kMaxFedBytes) +
                             " bytes together");
    }
    if (parent) count_members(name_token, (family.classes[parent - 1].*family.members).size());
    // An interaction class declares its own delivery; an object class's attributes each do.
    if constexpr (std::is_same_v<Cls, InteractionClass>) {
        read_delivery(o, "interaction class '" + cls.qualified_name + "'", cls);
    }
    const Handle h = static_cast<Handle>(family.classes.size() + 1);
    cls.handle = h;
    cls.parent = parent;
    if (parent) {
        cls.*family.members = family.classes[parent - 1].*family.members;
        cls.*family.member_names = family.classes[parent - 1].*family.member_names;
        family.classes[parent - 1].children.push_back(h);
    }
    family.classes.push_back(std::move(cls));
    family.offsets.push_back(name_token.offset);
    family.names.add(family.classes[h - 1].qualified_name, h, qualified_name_of);
    family.leaf_names.add(family.classes[h - 1].name, h,
                          [&](Handle k) { return std::string_view(family.classes[k - 1].name); });

    const std::string member(name_of(family.member));
    const std::string where = " in " + std::string(family.kind) + " '" + family.classes[h - 1].qualified_name +
                              "' (expected '(" + member + "', '(class' or ')')";
    bool seen_subclass = false;
    entries(o, where, [&](Kw kw, const Token& t, const Token& word) {
        const Open inner{kw, t.offset};
        if (kw == family.member) {
            // A later member would be missing from the subclasses already numbered.
            if (seen_subclass) {
                fail(t, member + "s of " + family.owner + " '" + family.classes[h - 1].qualified_name +
                            "' must come before its subclasses");
            }
            parse_member(family, inner, h);
        } else if (kw == Kw::Class) {
            seen_subclass = true;
            parse_class(family, inner, h, depth + 1);
        } else if (kw == Kw::SecLevel) {
            parse_sec_level(inner);
        } else {
            misplaced(kw, t, word, Kw::Class, (member + ", class or sec_level").c_str());
        }
    });
}

template <class Cls, class Member>
void Parser::parse_member(ClassFamily<Cls, Member>& family, const Open& o, Handle cls) {
    const std::string what(name_of(family.member));
    Token name_token;
    const std::string_view name = read_value(o, what + " name", true, &name_token);
    const Cls& c = family.classes[cls - 1];
    const auto& existing = c.*family.members;
    auto member_name_of = [&](Handle h) { return std::string_view(existing[h - 1].name); };
    if (const Handle clash = (c.*family.member_names).find(name, member_name_of)) {
        const Member& m = existing[clash - 1];
        std::string msg = "duplicate " + what + " '" + quote_for_message(name) + "' in " + family.owner + " '" +
                          c.qualified_name + "'";
        // Name the class the clashing member comes from when it is inherited (members keep their handles).
        Handle owner = cls;
        for (Handle p = c.parent; p != 0; p = family.classes[p - 1].parent) {
            const auto& inherited = family.classes[p - 1].*family.members;
            if (m.handle <= inherited.size() && inherited[m.handle - 1].handle == m.handle) owner = p;
        }
        if (owner != cls) msg += " (inherited from '" + family.classes[owner - 1].qualified_name + "')";
        fail(name_token, msg);
    }

    count_members(name_token, 1);

    Member member;
    member.name = std::string(name);
    if constexpr (std::is_same_v<Member, Attribute>) read_delivery(o, "attribute '" + member.name + "'", member);
    expect_close(o);
    auto& members = family.classes[cls - 1].*family.members;
    member.handle = static_cast<Handle>(members.size() + 1);
    members.push_back(std::move(member));
    (family.classes[cls - 1].*family.member_names).add(members.back().name, members.back().handle, member_name_of);
}

void Parser::count_members(const Token& where, std::size_t added) {
    class_members_ += added;
    if (class_members_ > kMaxClassMembers) {
        fail(where, "too many attributes and parameters: more than " + std::to_string(kMaxClassMembers) +
                        ", counting the inherited ones in each subclass");
    }
}

}  // namespace

Fom parse_fed(std::string_view text, std::string_view file_name) {
    if (text.size() > kMaxFedBytes) {
        throw FedError(std::string(file_name), 1, 1,
                       "the FED is " + std::to_string(text.size()) + " bytes, more than the limit of " +
                           std::to_string(kMaxFedBytes) + " (" + std::to_string(kMaxFedBytes >> 20) + " MiB)");
    }
    return Parser(text, file_name).run();
}

}  // namespace hlacore::fom
