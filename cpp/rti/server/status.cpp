// Introspection: the state of a federation as JSON, for `rtig --status` and hlacore.Gateway.status().
// Infinite times (no bound, nothing queued) are written as null, so the output stays plain JSON.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "rti/server/federation.hpp"
#include "rti/wire/json.hpp"

namespace hlacore {

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

void Federation::write_status(std::string& out, bool instances) {
    out += "{\"name\":";
    json_string(out, name_);
    out += ",\"fed\":";
    json_string(out, fed_name_);
    out += ",\"objects\":" + std::to_string(objects_.size());
    out += ",\"sync_points\":";
    sync_points_.write_status(out);
    out += ",\"federates\":";
    const auto now = std::chrono::steady_clock::now();
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
            out += ",\"waiting\":";  // seconds since the request
            json_number(out, std::chrono::duration<double>(now - f.requested_at).count());
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
        out += ",\"updates_sent\":" + std::to_string(f.updates_sent);
        out += ",\"interactions_sent\":" + std::to_string(f.interactions_sent);
        out += ",\"grants\":" + std::to_string(f.grants);
        out += '}';
    });
    write_save_status(out);
    if (instances) write_instances(out);
    out += '}';
}

}  // namespace hlacore
