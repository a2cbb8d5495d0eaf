// What the gateway serves itself rather than a federation: creating, destroying, joining and resigning
// federation executions, and the requests answered with a result (registering an object, a release
// response, a time query, save and restore requests, a recording).
#include "rti/server/gateway.hpp"
#include "rti/server/gateway_internal.hpp"
#include "fed_parser/omt.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace hlacore {

namespace {

// Reads at most `limit` bytes: parse_fed refuses a longer text anyway, and one byte more is enough for it
// to say so.
bool read_file(const std::string& path, std::string& text, std::size_t limit) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    text.clear();
    char buf[1 << 16];
    while (text.size() < limit) {
        in.read(buf, static_cast<std::streamsize>(std::min(sizeof buf, limit - text.size())));
        text.append(buf, static_cast<std::size_t>(in.gcount()));
        if (!in) break;
    }
    return !in.bad();
}

// The federation's FOM with the modules a federate adds at join (IEEE 1516-2010 §4.5): ErrorReadingFED for
// modules that do not read on their own, InconsistentFDD for ones that contradict each other or the federation's
// FOM (or for a federation created from a .fed, which takes none).
fom::ExtendedFom extended_fom(const Federation& federation, const std::string& modules) {
    std::vector<fom::FomModule> added;
    try {
        added = fom::unbundle(modules, "the FOM modules added at join");
        fom::parse_omt(added);
    } catch (const fom::InconsistentModules& e) {
        throw RtiError(ErrorCode::InconsistentFDD, e.what());
    } catch (const fom::FedError& e) {
        throw RtiError(ErrorCode::ErrorReadingFED, e.what());
    }
    try {
        return fom::extend_fom(federation.fed_text(), federation.fed_name(), added);
    } catch (const fom::FedError& e) {
        throw RtiError(ErrorCode::InconsistentFDD, e.what());
    }
}

}  // namespace

void Gateway::serve(Connection& c, const wire::CreateFederation& m) {
    answer(c, m.request, [&] {
        require_federation_secret(c, "create", m.federation, m.proof);
        if (federations_.count(m.federation))
            throw RtiError(ErrorCode::FederationExecutionAlreadyExists, "federation '" + m.federation + "' already exists");
        std::string text = m.fed_text;
        std::string source = m.fed_name;
        if (text.empty()) {
            source = find_fed_file(m.fed_name);
            if (source.empty() || !read_file(source, text, fom::kMaxFedBytes + 1))
                throw RtiError(ErrorCode::CouldNotOpenFED, "FED file '" + m.fed_name +
                                                               "' was not found by the client nor in the gateway's "
                                                               "--fom-path");
        }
        fom::Fom fom;
        try {
            fom = fom::parse_fom(text, m.fed_name);
        } catch (const fom::InconsistentModules& e) {  // modules that read but contradict each other
            throw RtiError(ErrorCode::InconsistentFDD, e.what());
        } catch (const fom::FedError& e) {
            throw RtiError(ErrorCode::ErrorReadingFED, e.what());
        }
        auto& entry = federations_[m.federation] =
            std::make_unique<FederationEntry>(*this, m.federation, std::move(fom), m.fed_name, std::move(text));
        entry->federation.set_save_dir(options_.save_dir);
        const auto asked = static_cast<TimeSemantics>(m.time_semantics);
        if (asked != TimeSemantics::Default && asked != TimeSemantics::Exact && asked != TimeSemantics::Certi)
            throw RtiError(ErrorCode::RTIinternalError, "time semantics " + std::to_string(m.time_semantics));
        entry->federation.set_time_semantics(asked == TimeSemantics::Default ? options_.time_semantics : asked);
        if (m.time_type > static_cast<std::uint8_t>(TimeType::Integer64))
            throw RtiError(ErrorCode::RTIinternalError, "time type " + std::to_string(m.time_type));
        entry->federation.set_time_type(static_cast<TimeType>(m.time_type));
        if (recorder_) {
            record_federation(*entry);
            recorder_->created(entry->federation);
        }
        events_.add("created", m.federation, 0, m.fed_name);
        if (options_.verbose) log("created federation '" + m.federation + "' from " + source);
    });
}

void Gateway::serve(Connection& c, const wire::DestroyFederation& m) {
    answer(c, m.request, [&] {
        require_federation_secret(c, "destroy", m.federation, m.proof);
        auto it = federations_.find(m.federation);
        if (it == federations_.end())
            throw RtiError(ErrorCode::FederationExecutionDoesNotExist, "federation '" + m.federation + "' does not exist");
        if (it->second->federation.has_federates())
            throw RtiError(ErrorCode::FederatesCurrentlyJoined, std::to_string(it->second->federation.federate_count()) +
                                                                    " federate(s) still joined to '" + m.federation + "'");
        if (recorder_) recorder_->forget(it->second->federation);
        federations_.erase(it);
        events_.add("destroyed", m.federation, 0, "");
        if (options_.verbose) log("destroyed federation '" + m.federation + "'");
    });
}

void Gateway::serve(Connection& c, const wire::JoinFederation& m) {
    FederationEntry* entered = nullptr;
    answer(c, m.request, [&] {
        if (c.federation)
            throw RtiError(ErrorCode::FederateAlreadyExecutionMember,
                           "this ambassador is already joined to '" + c.federation->federation.name() + "'");
        require_federation_secret(c, "join", m.federation, m.proof);
        auto it = federations_.find(m.federation);
        if (it == federations_.end())
            throw RtiError(ErrorCode::FederationExecutionDoesNotExist, "federation '" + m.federation + "' does not exist");
        FederationEntry& entry = *it->second;
        entry.federation.check_membership_change("joinFederationExecution");
        std::optional<fom::ExtendedFom> extended;
        if (!m.joining->fom_modules.empty()) extended = extended_fom(entry.federation, m.joining->fom_modules);
        const FederateHandle h = entry.federation.join(m.federate, m.joining->federate_type);
        if (extended) entry.federation.extend_fom(std::move(*extended), h);
        c.federation = entered = &entry;
        c.federate = h;
        entry.outbox.peers_[h] = &c;
        return wire::FederationJoined{m.request, h, static_cast<std::uint8_t>(entry.federation.time_type()),
                                      entry.federation.fed_text(), entry.federation.fed_name()};
    });
    if (!entered) return;
    if (recorder_) recorder_->joined(entered->federation, c.federate);
    events_.add("joined", m.federation, c.federate, m.federate);
    entered->federation.announce_pending(c.federate);  // after the reply: the client is joined by then
    if (trace_) trace_->joined(m.federation, c.federate, m.federate, c.read_ns);
    if (options_.verbose)
        log("'" + m.federate + "' joined '" + m.federation + "' as federate " + std::to_string(c.federate) +
            (m.joining->fom_modules.empty() ? "" : ", adding FOM modules"));
}

void Gateway::serve(Connection& c, const wire::ResignFederation& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        federation.check_membership_change("resignFederationExecution");
        const std::string name = federation.federate_name(c.federate);
        federation.resign(c.federate, static_cast<wire::ResignAction>(m.action));
        events_.add("resigned", federation.name(), c.federate, name);
        if (c.tap) recorder_->detach(*c.tap);
        c.tap.reset();
        c.federation->outbox.peers_.erase(c.federate);
        c.federation = nullptr;
        c.federate = 0;
        memory_freed_ = true;
    });
}

void Gateway::serve(Connection& c, const wire::RegisterObject& m) {
    answer(c, m.request, [&] {
        auto [handle, name] = joined(c).register_object(c.federate, m.object_class, m.name);
        return wire::ObjectRegistered{m.request, handle, std::move(name)};
    });
}

void Gateway::serve(Connection& c, const wire::RegisterObjectWithRegion& m) {
    answer(c, m.request, [&] {
        auto [handle, name] = joined(c).register_object_with_region(c.federate, m);
        return wire::ObjectRegistered{m.request, handle, std::move(name)};
    });
}

// Save/restore requests (HLA 1.3 §4.11, §4.17): the outcome comes as callbacks, refusals in the Reply.
void Gateway::serve(Connection& c, const wire::RequestFederationSave& m) {
    answer(c, m.request, [&] { joined(c).request_save(c.federate, m.label, m.time); });
}

void Gateway::serve(Connection& c, const wire::RequestFederationRestore& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        federation.request_restore(c.federate, m.label);
        if (options_.verbose) log("federation '" + federation.name() + "' restore '" + m.label + "' requested");
    });
}

void Gateway::serve(Connection& c, const wire::AbortFederationSave& m) {
    answer(c, m.request, [&] { joined(c).abort_save(c.federate); });
}

void Gateway::serve(Connection& c, const wire::AbortFederationRestore& m) {
    answer(c, m.request, [&] { joined(c).abort_restore(c.federate); });
}

void Gateway::serve(Connection& c, const wire::ReleaseResponse& m) {
    answer(c, m.request, [&] {
        return wire::AttributesReleased{m.request, joined(c).release_response(c.federate, m)};
    });
}

void Gateway::serve(Connection& c, const wire::QueryTime& m) {
    answer(c, m.request, [&] {
        return wire::TimeQueried{m.request, joined(c).query_time(c.federate, static_cast<wire::TimeQuery>(m.which))};
    });
}

std::string Gateway::find_fed_file(const std::string& name) const {
    // Only regular files inside --fom-path: a client must not make the gateway open arbitrary paths, and
    // opening a FIFO or a device would block the whole gateway.
    auto readable = [](const std::string& p) {
        struct stat st {};
        return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), R_OK) == 0;
    };
    const auto slash = name.find_last_of('/');
    const std::string base = slash == std::string::npos ? name : name.substr(slash + 1);
    if (base.empty() || base == "." || base == "..") return "";
    for (const auto& dir : options_.fom_path) {
        if (name[0] != '/' && name.find("..") == std::string::npos && readable(dir + "/" + name)) return dir + "/" + name;
        if (readable(dir + "/" + base)) return dir + "/" + base;
    }
    return "";
}

void Gateway::record_federation(FederationEntry& entry) {
    if (!recorder_) recorder_ = std::make_unique<Recorder>();
    if (entry.recording) return;
    entry.recording = std::make_unique<FederationRecording>(*recorder_, entry.federation);
    entry.outbox.recorder = entry.recording.get();
}

void Gateway::recorder_failed() {
    const std::string failure = recorder_->take_failure();
    if (!failure.empty()) log("recording into " + options_.record_path + " stopped: " + failure);
}

void Gateway::serve(Connection& c, const wire::StartRecording& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        if (c.tap) throw RtiError(ErrorCode::RTIinternalError, "this federate records already");
        record_federation(*c.federation);
        c.tap = std::make_unique<ConnectionTap>(*this, c);
        recorder_->attach(federation, *c.tap);
        if (options_.verbose) log("'" + federation.federate_name(c.federate) + "' records '" + federation.name() + "'");
    });
}

}  // namespace hlacore
