// FOM modules in OMT XML (IEEE 1516.2-2010, and 1516.2-2000's form with the names and deliveries as XML
// attributes), read into the same Fom as a `.fed` file: the object and interaction class trees under
// HLAobjectRoot and HLAinteractionRoot, attributes and parameters with their transportation and order.
// Several modules merge in the order given (IEEE 1516-2010 §4.1.4): a class may appear in several of them,
// its members and subclasses joined; an attribute or parameter, or an interaction class, declared again with
// another transportation or order is an error naming both places. The dimensions and the update rates are read
// too (one declared again must agree); data types and notes are not read here.
//
// Modules added at join (IEEE 1516-2010 §4.5) extend a federation's FOM without changing a handle given out:
// after the creation's modules are merged and numbered, each added module is merged in turn and only what it
// adds is numbered, beyond what is there. A new class takes the next class handle (the new ones in preorder),
// a new dimension the next dimension handle, a new attribute or parameter of a class the FOM had the handle
// above every member of that class and of all its subclasses (which inherit it with that handle), so that it
// collides with no subclass's own member. An added module may not change the delivery or the dimensions of
// an interaction class the FOM had.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fed_parser/fom.hpp"

namespace hlacore::fom {

struct FomModule {
    std::string text;
    std::string file_name;  // in error messages
    bool added = false;     // added at a join, after the federation's creation: numbered as such
};

// Whether `text` is XML rather than a `.fed` (its first character that is not blank is '<').
bool is_xml(std::string_view text);

// The merged FOM of `modules`, the creation's first, then those added at join (numbered as said above; a
// creation module after an added one is an error). FedError ("FILE:LINE:COL: message") for XML that is not well formed, a module
// that is not an objectModel, a class without a name, an unknown transportation or order, a conflict between
// modules; and for a module longer than kMaxFedBytes or nested deeper than the .fed parser allows.
Fom parse_omt(const std::vector<FomModule>& modules);
Fom parse_omt(std::string_view text, std::string_view file_name);

// Several modules as one text, the form in which the wire and the gateway carry a FOM given as modules:
// kBundleMagic, then each module as "<name length> <text length>\n<name><text>" (lengths in bytes, decimal),
// a module added at join as "<name length> <text length> added\n<name><text>". A bundle without added
// modules reads as it always did.
inline constexpr std::string_view kBundleMagic = "hlacore FOM modules\n";
std::string bundle(const std::vector<FomModule>& modules);
// The modules of a bundle; FedError at `file_name` for one that is cut short or malformed.
std::vector<FomModule> unbundle(std::string_view text, std::string_view file_name);
bool is_bundle(std::string_view text);

// A FOM from one text: a `.fed`, an OMT XML module or a bundle of modules, by what the text is.
Fom parse_fom(std::string_view text, std::string_view file_name);

// The modules of a FOM text: a bundle's, or the one XML module it is (named `file_name`); FedError for a .fed.
std::vector<FomModule> fom_modules(std::string_view text, std::string_view file_name);

// A federation's FOM (its text `fed_text`: an XML module or a bundle) with `added` merged after its modules,
// as modules added at join: the FOM, every handle of the federation's kept, and its text, a bundle marking the
// added modules, which parse_fom reads into the same handles. FedError ("FILE:LINE:COL: message") for an
// added module that does not read or contradicts the others (naming both places), and at `file_name` for a
// federation created from a .fed.
struct ExtendedFom {
    Fom fom;
    std::string text;
};
ExtendedFom extend_fom(std::string_view fed_text, std::string_view file_name, const std::vector<FomModule>& added);

// Whether FOM text `text` is `base` or `base` extended at joins (its modules, then only added ones), so that
// every handle of `base` means the same in `text`.
bool extends(std::string_view text, std::string_view base);

}  // namespace hlacore::fom
