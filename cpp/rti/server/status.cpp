// Introspection: the state of a federation as JSON, for `rtig --status` and hlacore.Gateway.status().
// Infinite times (no bound, nothing queued) are written as null, so the output stays plain JSON.
#include <cmath>
#include <cstdio>

#include "rti/server/federation.hpp"
#include "rti/server/status.hpp"

namespace hlacore {

void json_string(std::string& out, const std::string& s) {
    out += '"';
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += static_cast<char>(c);
        }
    }
    out += '"';
}

void json_number(std::string& out, double v) {
    if (!std::isfinite(v)) {
        out += "null";
        return;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    out += text;
}

namespace {

const char* request_name(AdvanceKind kind) {
    switch (kind) {
        case AdvanceKind::TimeAdvanceRequest: return "TAR";
        case AdvanceKind::TimeAdvanceRequestAvailable: return "TARA";
        case AdvanceKind::NextEventRequest: return "NER";
        case AdvanceKind::NextEventRequestAvailable: return "NERA";
        case AdvanceKind::FlushQueueRequest: return "FQR";
        case AdvanceKind::None: break;
    }
    return nullptr;
}

}  // namespace

void Federation::write_status(std::string& out) {
    out += "{\"name\":";
    json_string(out, name_);
    out += ",\"fed\":";
    json_string(out, fed_name_);
    out += ",\"objects\":" + std::to_string(objects_.size());
    out += ",\"sync_points\":";
    sync_points_.write_status(out);
    out += ",\"federates\":";
    json_array(out, time_.status(), [&](const TimeFederateStatus& t) {
        const auto& f = federates_.at(t.federate);
        out += "{\"handle\":" + std::to_string(t.federate) + ",\"name\":";
        json_string(out, f.name);
        out += ",\"time\":";
        json_number(out, t.time);
        out += ",\"lookahead\":";
        json_number(out, t.lookahead);
        out += std::string(",\"regulating\":") + (t.regulating ? "true" : "false");
        out += std::string(",\"enabling_regulation\":") + (t.enabling_regulation ? "true" : "false");
        out += std::string(",\"constrained\":") + (t.constrained ? "true" : "false");
        out += std::string(",\"asynchronous_delivery\":") + (t.asynchronous_delivery ? "true" : "false");
        out += ",\"pending\":";
        if (const char* kind = request_name(t.pending)) {
            out += "{\"request\":\"" + std::string(kind) + "\",\"time\":";
            json_number(out, t.pending_time);
            out += '}';
        } else {
            out += "null";
        }
        out += ",\"queued_tso\":" + std::to_string(t.queued_tso);
        out += ",\"queued_ro\":" + std::to_string(t.queued_ro);
        out += ",\"regions\":" + std::to_string(f.ddm.regions.size());  // data distribution management
        out += ",\"lbts\":";
        json_number(out, t.lbts);
        out += ",\"output_bound\":";
        json_number(out, t.output_bound);
        out += '}';
    });
    write_save_status(out);
    out += '}';
}

}  // namespace hlacore
