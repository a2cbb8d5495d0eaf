// Introspection: the state of a federation as JSON, for `rtig --status` and hlacore.Gateway.status().
// Infinite times (no bound, nothing queued) are written as null, so the output stays plain JSON.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <sys/resource.h>
#include <unistd.h>

#include "rti/server/federation.hpp"
#include "rti/server/gateway.hpp"
#include "rti/server/gateway_internal.hpp"
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

void Federation::write_status(std::string& out, bool instances,
                              const std::function<void(FederateHandle, std::string&)>& more) {
    out += "{\"name\":";
    json_string(out, name_);
    out += ",\"fed\":";
    json_string(out, fed_name_);
    out += std::string(",\"time_semantics\":\"") + name_of(time_.semantics()) + '"';
    out += std::string(",\"time_type\":\"") + name_of(time_type_) + '"';
    out += ",\"objects\":" + std::to_string(objects_.size());
    out += ",\"sync_points\":";
    sync_points_.write_status(out);
    out += ",\"federates\":";
    const auto now = std::chrono::steady_clock::now();
    json_array(out, time_.status(), [&](const TimeFederateStatus& t) {
        const auto& f = federates_.at(t.federate);
        out += "{\"handle\":" + std::to_string(t.federate) + ",\"name\":";
        json_string(out, f.name);
        out += ",\"type\":";
        json_string(out, f.type);
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
        out += ",\"held_by\":";  // who keeps it waiting: each may still send at or below what it waits for
        json_array(out, t.held_by, [&](std::uint32_t g) {
            out += "{\"handle\":" + std::to_string(g) + ",\"name\":";
            json_string(out, federates_.at(g).name);
            out += ",\"output_bound\":";
            json_number(out, time_.output_bound(g));
            out += '}';
        });
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
        if (more) more(t.federate, out);
        out += '}';
    });
    write_save_status(out);
    if (instances) write_instances(out);
    out += '}';
}

namespace {

// ,"process":{...}: the gateway's process (for an in-process gateway, the federate's program that runs it).
void write_process_status(std::string& json) {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    const double cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    long long resident_pages = 0;  // now, not the peak that ru_maxrss gives
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%*s %lld", &resident_pages) != 1) resident_pages = 0;
        std::fclose(statm);
    }
    json += ",\"process\":{\"pid\":" + std::to_string(::getpid()) + ",\"rss_bytes\":" +
            std::to_string(resident_pages * ::sysconf(_SC_PAGESIZE)) + ",\"cpu_seconds\":";
    json_number(json, cpu);
    json += '}';
}

}  // namespace
void Gateway::serve(Connection& c, const wire::QueryStatus& m) {
    answer(c, m.request, [&] {
        std::string json = "{\"server\":\"hlacore rtig\",\"address\":";
        json_string(json, options_.host + ":" + std::to_string(port_));
        json += tls_ ? ",\"tls\":true" : ",\"tls\":false";
        json += ",\"connections\":" + std::to_string(connections_.size()) + ",\"federations\":[";
        bool first = true;
        for (auto& [name, entry] : federations_) {
            if (!first) json += ',';
            first = false;
            // Each federate's backlog: the bytes held for it in memory and spilled to disk (flow_control.cpp).
            const auto& peers = entry->outbox.peers_;  // (clang's C++17 lambdas take no structured bindings)
            entry->federation.write_status(json, m.instances, [&](FederateHandle f, std::string& out) {
                const auto peer = peers.find(f);
                if (peer == peers.end()) return;
                const Connection& fc = *peer->second;
                out += ",\"backlog\":{\"memory\":" + std::to_string(held_for(fc)) +
                       ",\"disk\":" + std::to_string((fc.spill ? fc.spill->size() : 0) + (fc.parked ? fc.parked->size() : 0)) + '}';
            });
        }
        json += "],\"spill\":{\"directory\":";
        json_string(json, spill_budget_.on() ? SpillFile::directory_for(spill_budget_) : "");
        json += ",\"budget\":" + std::to_string(spill_budget_.limit) + ",\"used\":" + std::to_string(spill_budget_.used) + '}';
        json += ",\"datagrams\":";
        write_datagram_status(json);
        write_process_status(json);
        for (auto const& section : status_sections_) json += ',' + section();
        events_.write_after(m.events_after, json);
        json += '}';
        return wire::StatusReport{m.request, std::move(json)};
    });
}

}  // namespace hlacore
