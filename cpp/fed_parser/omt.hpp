// FOM modules in OMT XML (IEEE 1516.2-2010, and 1516.2-2000's form with the names and deliveries as XML
// attributes), read into the same Fom as a `.fed` file: the object and interaction class trees under
// HLAobjectRoot and HLAinteractionRoot, attributes and parameters with their transportation and order.
// Several modules merge in the order given (IEEE 1516-2010 §4.1.4): a class may appear in several of them,
// its members and subclasses joined; an attribute or parameter, or an interaction class, declared again with
// another transportation or order is an error naming both places. The dimensions and the update rates are read
// too (one declared again must agree); data types and notes are not read here.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fed_parser/fom.hpp"

namespace hlacore::fom {

struct FomModule {
    std::string text;
    std::string file_name;  // in error messages
};

// Whether `text` is XML rather than a `.fed` (its first character that is not blank is '<').
bool is_xml(std::string_view text);

// The merged FOM of `modules`. FedError ("FILE:LINE:COL: message") for XML that is not well formed, a module
// that is not an objectModel, a class without a name, an unknown transportation or order, a conflict between
// modules; and for a module longer than kMaxFedBytes or nested deeper than the .fed parser allows.
Fom parse_omt(const std::vector<FomModule>& modules);
Fom parse_omt(std::string_view text, std::string_view file_name);

// Several modules as one text, the form in which the wire and the gateway carry a FOM given as modules:
// kBundleMagic, then each module as "<name length> <text length>\n<name><text>" (lengths in bytes, decimal).
inline constexpr std::string_view kBundleMagic = "hlacore FOM modules\n";
std::string bundle(const std::vector<FomModule>& modules);
// The modules of a bundle; FedError at `file_name` for one that is cut short or malformed.
std::vector<FomModule> unbundle(std::string_view text, std::string_view file_name);

// A FOM from one text: a `.fed`, an OMT XML module or a bundle of modules, by what the text is.
Fom parse_fom(std::string_view text, std::string_view file_name);

}  // namespace hlacore::fom
