// The Federation Object Model read from an HLA 1.3 `.fed` file: classes, attributes, interactions,
// parameters, routing spaces, each with the handle the whole federation uses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "fed_parser/name_index.hpp"

namespace hlacore::fom {

// Limits of parse_fed, far above any real FOM, so that a hostile .fed cannot make a gateway allocate
// without bound: the text's size (256 MiB; FedError at 1:1 beyond it); and, because every subclass holds
// its ancestors' qualified name and attributes (a Fom could otherwise grow with the square of the text),
// the classes' qualified names together (kMaxFedBytes too) and their attributes and parameters together,
// inherited ones counted in every subclass (4 Mi: more than a flat FED of one 64 MiB frame can declare).
constexpr std::size_t kMaxFedBytes = std::size_t{256} << 20;
constexpr std::size_t kMaxClassMembers = std::size_t{4} << 20;

// Values match CERTI's handles so getTransportationHandle/getOrderingHandle agree with it.
enum class Transport : std::uint8_t { Reliable = 1, BestEffort = 2 };
enum class Order : std::uint8_t { Receive = 1, Timestamp = 2 };

struct Attribute {
    Handle handle = 0;
    std::string name;
    Transport transport = Transport::Reliable;
    Order order = Order::Receive;
    std::string space;  // routing space name, empty if none
};

struct ObjectClass {
    Handle handle = 0;
    std::string name;            // leaf name, e.g. "robot"
    std::string qualified_name;  // CERTI form: root classes are not prepended ("robot", "robot.wheeled")
    Handle parent = 0;           // 0 for a top-level class
    std::vector<Handle> children;
    std::vector<Attribute> attributes;  // inherited ones first (with the parent's handles), sorted by handle
    NameIndex attribute_names;          // of `attributes`

    const Attribute* attribute(Handle h) const;
    const Attribute* attribute(std::string_view attribute_name) const;
    // The attribute that carries the privilege to delete (CERTI/Portico and OpenRTI spellings), or null.
    const Attribute* privilege_to_delete() const;
};

// A parameter of an interaction class: nothing but a handle and a name.
struct NamedHandle {
    Handle handle = 0;
    std::string name;
};
using Parameter = NamedHandle;

// A dimension of a routing space. An OMT module's dimensions (IEEE 1516-2010 DDM) are one routing space,
// kOmtSpace, and declare an upper bound: a range's bounds lie in [0, upper_bound]. A .fed's have none (0).
struct Dimension {
    Handle handle = 0;
    std::string name;
    std::uint64_t upper_bound = 0;
};
inline constexpr const char* kOmtSpace = "HLAdimensions";

struct InteractionClass {
    Handle handle = 0;
    std::string name;
    std::string qualified_name;
    Handle parent = 0;
    std::vector<Handle> children;
    Transport transport = Transport::Reliable;
    Order order = Order::Receive;
    std::string space;
    std::vector<Parameter> parameters;  // inherited ones first (with the parent's handles), sorted by handle
    NameIndex parameter_names;          // of `parameters`

    const Parameter* parameter(Handle h) const;
    const Parameter* parameter(std::string_view parameter_name) const;
};

struct RoutingSpace {
    Handle handle = 0;
    std::string name;
    std::vector<Dimension> dimensions;  // dimensions[h - 1] has handle h
    NameIndex dimension_names;          // of `dimensions`

    const Dimension* dimension(Handle h) const;
    const Dimension* dimension(std::string_view dimension_name) const;
};

// An update rate an OMT module declares (IEEE 1516.2-2010's updateRates): a subscriber names it to receive an
// attribute's receive-order updates at most `rate` times a second.
struct UpdateRate {
    std::string name;
    double rate = 0;  // per second, > 0
};

struct Fom {
    std::string source_name;  // file name given to the parser, used in messages
    std::string federation_name;
    std::string fed_version;
    std::vector<RoutingSpace> spaces;                   // spaces[h - 1] has handle h
    std::vector<ObjectClass> object_classes;            // object_classes[h - 1] has handle h
    std::vector<InteractionClass> interaction_classes;  // interaction_classes[h - 1] has handle h
    std::vector<UpdateRate> update_rates;               // OMT modules only, in the order declared

    // The name indexes (the classes' own included) behind every lookup by name. parse_fed keeps them; code
    // that builds or changes a Fom by hand calls reindex() before looking anything up by name.
    NameIndex space_names;
    NameIndex object_names, object_leaf_names;  // qualified names; leaf names (the first declared wins)
    NameIndex interaction_names, interaction_leaf_names;
    void reindex();

    // nullptr when the handle names nothing.
    const ObjectClass* object_class(Handle h) const;
    const InteractionClass* interaction_class(Handle h) const;
    const RoutingSpace* space(Handle h) const;

    // Name lookup with CERTI's rules: the qualified name, optionally preceded by a root class name
    // ("ObjectRoot.robot", "HLAobjectRoot.robot"), or a bare leaf name (first declared match).
    // nullptr when nothing matches.
    const ObjectClass* find_object_class(std::string_view class_name) const;
    const InteractionClass* find_interaction_class(std::string_view class_name) const;
    const RoutingSpace* find_space(std::string_view space_name) const;
    const UpdateRate* find_update_rate(std::string_view rate_name) const;  // by its exact name

    // True when `cls` is `ancestor` or one of its descendants.
    bool is_object_subclass(Handle cls, Handle ancestor) const;
    bool is_interaction_subclass(Handle cls, Handle ancestor) const;
};

// A malformed `.fed`: what() is "FILE:LINE:COL: message" (compiler form, 1-based line and column).
class FedError : public std::runtime_error {
public:
    FedError(std::string file, int line, int column, std::string message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }
    const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_;
    int column_;
    std::string message_;
};

// Modules that read but contradict each other (a class or a member with another transportation or order, a member
// a subclass declares already, a dimension with another upper bound, an update rate with another rate): IEEE
// 1516-2010's InconsistentFDD.
class InconsistentModules : public FedError {
public:
    using FedError::FedError;
};

// Parses the text of a `.fed` file; `file_name` only appears in error messages and Fom::source_name.
// Throws FedError on the first error, and for a text longer than kMaxFedBytes. Linear in the text's
// size plus the attributes and parameters the classes inherit.
Fom parse_fed(std::string_view text, std::string_view file_name);

}  // namespace hlacore::fom
