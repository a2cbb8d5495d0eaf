// The options' checks of a value's text, their error messages and the usage's layout (options.hpp).
#include "rti/options.hpp"

#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>

#include "rti/busy_poll.hpp"

namespace hlacore {

std::string refused(const char* name, Given given, const std::string& text, const std::string& why) {
    switch (given) {
        case Given::Flag: return "invalid " + std::string(name) + " '" + text + "': " + why;
        case Given::Keyword: return std::string(name) + "='" + text + "': " + why;
        case Given::Variable: return "$" + std::string(name) + "='" + text + "': " + why;
    }
    return why;
}

std::string wrap(const std::vector<std::string>& words, std::size_t first_room, std::size_t indent, std::size_t width) {
    std::string out;
    std::size_t room = first_room;
    std::size_t line = 0;
    for (const auto& word : words) {
        if (word.empty()) continue;
        if (line > 0 && line + 1 + word.size() > room) {
            out += "\n" + std::string(indent, ' ');
            room = width - indent;
            line = 0;
        }
        out += (line > 0 ? " " : "") + word;
        line += (line > 0 ? 1 : 0) + word.size();
    }
    return out;
}

std::string wrap(const std::string& text, std::size_t first_room, std::size_t indent, std::size_t width) {
    std::vector<std::string> words;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t space = std::min(text.find(' ', at), text.size());
        words.push_back(text.substr(at, space - at));
        at = space + 1;
    }
    return wrap(words, first_room, indent, width);
}

std::string help_entry(const std::string& head, const std::string& help, const std::string& shown_default) {
    constexpr std::size_t kColumn = 21, kWidth = 110;
    std::string text = help;
    if (!shown_default.empty()) text += " (default " + shown_default + ")";
    std::string out = "  " + head;
    if (out.size() + 1 >= kColumn) {
        out += "\n" + std::string(kColumn, ' ');
    } else {
        out += std::string(kColumn - out.size(), ' ');
    }
    return out + wrap(text, kWidth - kColumn, kColumn, kWidth) + "\n";
}

double number_above(const std::string& text, double low, bool low_ok, const char* unit) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || !(v > low || (low_ok && v == low)))
        throw OptionError(std::string("must be a finite number of ") + unit + (low_ok ? " >= " : " > ") +
                          std::to_string(static_cast<long long>(low)));
    return v;
}

std::uint64_t whole_number(const std::string& text, std::uint64_t low, std::uint64_t high, const char* unit) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] < '0' || text[0] > '9' || *end != '\0' || errno == ERANGE || v < low || v > high)
        throw OptionError("must be a whole number" + (*unit ? " of " + std::string(unit) : std::string()) + " between " +
                          std::to_string(low) + " and " + std::to_string(high));
    return v;
}

bool yes_or_no(const std::string& text) {
    if (text == "1" || text == "true") return true;
    if (text == "0" || text == "false") return false;
    throw OptionError("must be 0 or 1");
}

const std::string& not_empty(const std::string& text) {
    if (text.empty()) throw OptionError("must not be empty");
    return text;
}

std::uint32_t busy_poll_micros(const std::string& text) {
    try {
        return static_cast<std::uint32_t>(whole_number(text, 0, kMaxBusyPollUs, "µs"));
    } catch (const OptionError&) {
        throw OptionError("busy polling must be a whole number of µs between 0 and " + std::to_string(kMaxBusyPollUs));
    }
}

TimeSemantics time_semantics(const std::string& text) {
    if (text == "exact") return TimeSemantics::Exact;
    if (text == "certi") return TimeSemantics::Certi;
    throw OptionError("must be exact or certi (docs/time-management.md)");
}

}  // namespace hlacore
