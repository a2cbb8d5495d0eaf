// Options declared once. Each is a row of a table: its spelling on a command line, as a Python keyword and
// in the environment, its help, and one function that checks a value given as text and sets it. The gateway's
// table (server/options.hpp) makes rtig's parsing and usage and hlacore.Gateway's keywords and docs; the
// client's (client/options.hpp) makes hlacore.rti.RTIAmbassador's keywords and docs and the environment both
// it and the HLA 1.3 C++ API read. A value is checked in one place whoever gives it, and refused with a
// message that names the option as it was given.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "rti/time.hpp"

namespace hlacore {

// A value an option refuses; what() says what it must be ("must be at least 65536 bytes").
class OptionError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

template <class Settings>
struct Option {
    const char* flag;      // on a command line, "--client-budget"
    const char* keyword;   // the Python keyword, "client_budget"; nullptr: the command line's only
    const char* variable;  // the environment variable, "HLACORE_TIMEOUT"; nullptr: none
    const char* metavar;   // the value's placeholder in the usage, "B"; nullptr: a switch, given as "1" or "0"
    bool repeated;         // each time it is given adds a value
    void (*set)(Settings&, const std::string& text);  // checks and sets; OptionError saying why not
    std::string (*shown)(const Settings&);            // the value as text, "" for none (Settings{}: the default)
    const char* help;
};
template <class Settings>
using Options = std::vector<Option<Settings>>;

// How a value was given, to name the option in an error as its giver spells it.
enum class Given { Flag, Keyword, Variable };

// "invalid --port 'abc': must be ...", "port='abc': must be ...", "HLACORE_TIMEOUT='soon': must be ...".
std::string refused(const char* name, Given given, const std::string& text, const std::string& why);

template <class Settings>
std::string refused(const Option<Settings>& option, Given given, const std::string& text, const std::string& why) {
    const char* name = given == Given::Flag ? option.flag : given == Given::Keyword ? option.keyword : option.variable;
    return refused(name, given, text, why);
}

// The row spelled `name` as `given` spells it, or nullptr.
template <class Settings>
const Option<Settings>* find_option(const Options<Settings>& table, const std::string& name, Given given) {
    for (const auto& option : table) {
        const char* spelled = given == Given::Flag ? option.flag : given == Given::Keyword ? option.keyword : option.variable;
        if (spelled && name == spelled) return &option;
    }
    return nullptr;
}

// Sets `option` from `text`; OptionError's why becomes the whole message, naming the option as given.
template <class Settings>
void apply(Settings& settings, const Option<Settings>& option, Given given, const std::string& text) {
    try {
        option.set(settings, text);
    } catch (const OptionError& e) {
        throw OptionError(refused(option, given, text, e.what()));
    }
}

// A command line's synopsis of the table ("[--port PORT]", "[--fom-path DIR]...", "[--verbose]") and its help, one
// entry per option ("  --port PORT  TCP port ... (default 60400)"), wrapped to `width` columns.
template <class Settings>
std::vector<std::string> synopsis(const Options<Settings>& table) {
    std::vector<std::string> out;
    for (const auto& o : table)
        out.push_back("[" + std::string(o.flag) + (o.metavar ? std::string(" ") + o.metavar : "") + "]" + (o.repeated ? "..." : ""));
    return out;
}
std::string help_entry(const std::string& head, const std::string& help, const std::string& shown_default);
template <class Settings>
std::string help_entries(const Options<Settings>& table) {
    std::string out;
    const Settings defaults{};
    for (const auto& o : table)
        out += help_entry(std::string(o.flag) + (o.metavar ? std::string(" ") + o.metavar : ""), o.help,
                          o.metavar && o.shown ? o.shown(defaults) : "");
    return out;
}
// Lays `words` out in lines of `width` columns (the first has `first_room`), the others `indent` spaces in.
std::string wrap(const std::vector<std::string>& words, std::size_t first_room, std::size_t indent, std::size_t width);
std::string wrap(const std::string& text, std::size_t first_room, std::size_t indent, std::size_t width);

// The checks of a value's text, each throwing OptionError with what it must be.
double number_above(const std::string& text, double low, bool low_ok, const char* unit);  // finite
std::uint64_t whole_number(const std::string& text, std::uint64_t low, std::uint64_t high, const char* unit);
bool yes_or_no(const std::string& text);  // "1"/"true" or "0"/"false"
const std::string& not_empty(const std::string& text);
std::uint32_t busy_poll_micros(const std::string& text);  // rti/busy_poll.hpp's bounds
TimeSemantics time_semantics(const std::string& text);     // "exact" or "certi" (rti/time.hpp)

}  // namespace hlacore
