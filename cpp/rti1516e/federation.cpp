// Federation management (IEEE 1516.1-2010 §4): connecting, creating from FOM modules, joining, resigning,
// synchronization points, save and restore.
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "ambassador.hpp"
#include "fed_parser/omt.hpp"

namespace hlacore::rti1516e {

namespace {

// A FOM module's path from its designator (a path, or a file: URL).
std::string module_path(std::wstring const& designator) {
    std::string path = utf8(designator);
    for (const char* prefix : {"file://", "file:"})
        if (path.rfind(prefix, 0) == 0) return path.substr(std::string(prefix).size());
    return path;
}

// The modules' texts, read here. `gateway_may_look`: one name this process cannot read gives none, for the
// gateway to look up in its --fom-path (at creation; modules added at join are read here or not at all).
std::vector<fom::FomModule> read_modules(std::vector<std::wstring> const& designators, bool gateway_may_look) {
    std::vector<fom::FomModule> modules;
    for (const auto& designator : designators) {
        const std::string path = module_path(designator);
        std::ifstream file{path, std::ios::binary};
        if (!file) {
            if (gateway_may_look && designators.size() == 1) return {};
            raise("CouldNotOpenFDD", "cannot open '" + path + "'");
        }
        std::ostringstream text;
        text << file.rdbuf();
        modules.push_back({text.str(), path});
    }
    return modules;
}

// ErrorReadingFDD (FILE:LINE:COL) unless the modules read, InconsistentFDD unless they merge, here at the caller.
void check_modules(std::vector<fom::FomModule> const& modules) {
    try {
        fom::parse_omt(modules);
    } catch (const fom::InconsistentModules& e) {
        raise("InconsistentFDD", e.what());
    } catch (const fom::FedError& e) {
        raise("ErrorReadingFDD", e.what());
    }
}

std::map<std::string, std::string> designated(std::string text) {
    std::map<std::string, std::string> given;
    if (text.find('=') == std::string::npos) {
        if (text.rfind("rti://", 0) == 0) text = text.substr(6);
        if (!text.empty() && text.back() == '/') text.pop_back();
        if (!text.empty()) given["address"] = text;
        return given;
    }
    std::size_t from = 0;
    while (from <= text.size()) {
        const std::size_t end = std::min(text.find_first_of(",\n", from), text.size());
        std::string item = text.substr(from, end - from);
        from = end + 1;
        item.erase(0, item.find_first_not_of(" \t\r"));
        item.erase(item.find_last_not_of(" \t\r") + 1);
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string::npos || equals == 0) raise("InvalidLocalSettingsDesignator", "'" + item + "' is not KEY=VALUE");
        const std::string key = item.substr(0, equals);
        given[key == "crcAddress" ? "address" : key] = item.substr(equals + 1);
    }
    return given;
}

TimeType time_type(std::wstring const& name) {
    if (name.empty() || name == L"HLAfloat64Time") return TimeType::Float64;
    if (name == L"HLAinteger64Time") return TimeType::Integer64;
    raise("CouldNotCreateLogicalTimeFactory", "'" + utf8(name) + "' (hlacore serves HLAfloat64Time, HLAinteger64Time)");
}

}  // namespace

Ambassador::~Ambassador() { stop_immediate(); }

Client& Ambassador::client() const {
    if (!client_) raise("NotConnected", "connect first");
    if (client_->closed()) raise("NotConnected", client_->lost().value_or("the connection is closed"));
    return *client_;
}

void Ambassador::connect(FederateAmbassador& federate, CallbackModel model, std::wstring const& settings) {
    guarded([&] {
        if (client_) raise("AlreadyConnected", "this ambassador is connected");
        if (raw(model) != HLA_EVOKED && raw(model) != HLA_IMMEDIATE)
            raise("UnsupportedCallbackModel", std::to_string(raw(model)));
        // "host:port", "rti://host:port" or "rti://host:port/"; empty: $HLACORE_RTIG, else 127.0.0.1:60400 (as
        // hlacore.rti1516e). Or the client's options as KEY=VALUE, one a line or comma-separated
        // ("address=host:port,secret_file=FILE"; Pitch's "crcAddress" names the address). A designator that
        // names no address, or an option the client does not have, is InvalidLocalSettingsDesignator.
        const std::map<std::string, std::string> given = designated(utf8(settings));
        ClientSettings c;
        try {
            c = client_settings(given);
        } catch (const RtiError& e) {
            raise("InvalidLocalSettingsDesignator", e.what());
        }
        try {
            client_ = std::make_unique<Client>(c.host, c.port, std::move(c.options));
        } catch (const RtiError& e) {
            raise("ConnectionFailed", e.what());
        }
        federate_ = &federate;
        directed_ = dynamic_cast<DirectedInteractionReceiver*>(&federate);
        immediate_ = raw(model) == HLA_IMMEDIATE;
        if (immediate_) {
            stop_ = false;
            immediate_thread_ = std::thread([this] {
                try {
                    while (!stop_) {
                        if (client_->closed()) break;
                        const auto status = client_->wait_for_callback(Client::Clock::now() + std::chrono::milliseconds(100));
                        if (status == Client::WaitStatus::Ready) deliver_one();
                    }
                } catch (const RtiError& e) {  // the gateway is gone: the standard's callback says so, once
                    std::lock_guard<std::recursive_mutex> lock(mu_);
                    if (federate_) federate_->connectionLost(wide(e.what()));
                }
            });
        }
    });
}

void Ambassador::stop_immediate() {
    stop_ = true;
    if (immediate_thread_.joinable()) immediate_thread_.join();
}

void Ambassador::disconnect() {
    guarded([&] {
        if (joined_) raise("FederateIsExecutionMember", "resign first");
        stop_immediate();
        client_.reset();
        federate_ = nullptr;
        directed_ = nullptr;
    });
}

void Ambassador::createFederationExecution(std::wstring const& federation, std::wstring const& module,
                                           std::wstring const& timeType) {
    createFederationExecution(federation, std::vector<std::wstring>{module}, timeType);
}

void Ambassador::createFederationExecution(std::wstring const& federation, std::vector<std::wstring> const& modules,
                                           std::wstring const& timeType) {
    guarded([&] {
        const TimeType type = time_type(timeType);
        if (modules.empty()) raise("CouldNotOpenFDD", "no FOM module given");
        std::vector<fom::FomModule> read = read_modules(modules, true);
        if (read.empty()) {  // one name this process cannot read: the gateway's --fom-path
            client().create_federation(utf8(federation), module_path(modules[0]), "", type);
            return;
        }
        check_modules(read);
        std::string names;
        for (const auto& m : read) names += (names.empty() ? "" : ", ") + m.file_name;
        client().create_federation(utf8(federation), names, read.size() == 1 ? read[0].text : fom::bundle(read), type);
    });
}

void Ambassador::createFederationExecutionWithMIM(std::wstring const& federation,
                                                  std::vector<std::wstring> const& modules, std::wstring const& mim,
                                                  std::wstring const& timeType) {
    std::vector<std::wstring> all{mim};  // merged first; hlacore's MIM is always there
    all.insert(all.end(), modules.begin(), modules.end());
    createFederationExecution(federation, all, timeType);
}

void Ambassador::destroyFederationExecution(std::wstring const& federation) {
    guarded([&] { client().destroy_federation(utf8(federation)); });
}

FederateHandle Ambassador::joinFederationExecution(std::wstring const& type, std::wstring const& federation,
                                                   std::vector<std::wstring> const& modules) {
    // Without a name the federate gets a unique one: its type, this process and this ambassador.
    std::ostringstream name;
    name << utf8(type) << "-" << ::getpid() << "-" << static_cast<const void*>(this);
    return joinFederationExecution(wide(name.str()), type, federation, modules);
}

FederateHandle Ambassador::joinFederationExecution(std::wstring const& name, std::wstring const& type,
                                                   std::wstring const& federation,
                                                   std::vector<std::wstring> const& modules) {
    return guarded([&] {
        // Modules added to the federation's FOM (IEEE 1516-2010 §4.5): InconsistentFDD from the gateway for
        // one that contradicts it.
        const std::vector<fom::FomModule> added = read_modules(modules, false);
        if (!added.empty()) check_modules(added);
        std::lock_guard<std::recursive_mutex> lock(mu_);
        std::uint32_t handle = 0;
        try {
            handle = client().join(utf8(name), utf8(federation), added.empty() ? "" : fom::bundle(added), utf8(type));
        } catch (const RtiError& e) {
            if (e.code() != ErrorCode::FederateAlreadyExecutionMember) throw;
            raise(joined_ ? "FederateAlreadyExecutionMember" : "FederateNameAlreadyInUse", e.what());
        }
        joined_ = true;
        integer_time_ = client().time_type() == TimeType::Integer64;
        federate_name_ = utf8(name);
        return rti1516e::handle<FederateHandle>(handle);
    });
}

void Ambassador::resignFederationExecution(ResignAction action) {
    guarded([&] {
        // 1516-2010's actions as HLA 1.3's (wire::ResignAction, PyHLA's values).
        static const std::map<long long, wire::ResignAction> kActions{
            {UNCONDITIONALLY_DIVEST_ATTRIBUTES, wire::ResignAction::ReleaseAttributes},
            {DELETE_OBJECTS, wire::ResignAction::DeleteObjects},
            {CANCEL_PENDING_OWNERSHIP_ACQUISITIONS, wire::ResignAction::NoAction},
            {DELETE_OBJECTS_THEN_DIVEST, wire::ResignAction::DeleteObjectsAndReleaseAttributes},
            {CANCEL_THEN_DELETE_THEN_DIVEST, wire::ResignAction::DeleteObjectsAndReleaseAttributes},
            {NO_ACTION, wire::ResignAction::NoAction}};
        const auto it = kActions.find(raw(action));
        if (it == kActions.end()) raise("InvalidResignAction", std::to_string(raw(action)));
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().resign(static_cast<std::uint8_t>(it->second));
        joined_ = false;
        reserved_.clear();  // the gateway dropped them, and the regions
        published_.clear();
        subscribed_.clear();
        regions_.clear();
    });
}

void Ambassador::registerFederationSynchronizationPoint(std::wstring const& label, VariableLengthData const& tag) {
    registerFederationSynchronizationPoint(label, tag, FederateHandleSet{});
}

void Ambassador::registerFederationSynchronizationPoint(std::wstring const& label, VariableLengthData const& tag,
                                                        FederateHandleSet const& set) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        sync_sets_[utf8(label)] = !set.empty();
        client().request(wire::RegisterSyncPoint{utf8(label), bytes(tag), set.empty(), cores(set)});
    });
}

void Ambassador::synchronizationPointAchieved(std::wstring const& label, bool successfully) {
    guarded([&] {
        if (!successfully)
            not_served("an unsuccessful synchronizationPointAchieved", "the core has no failed set");
        client().request(wire::SyncPointAchieved{utf8(label)});
    });
}

void Ambassador::requestFederationSave(std::wstring const& label) {
    guarded([&] { client().request_federation_save(utf8(label), std::nullopt); });
}

void Ambassador::requestFederationSave(std::wstring const& label, LogicalTime const& time) {
    guarded([&] { client().request_federation_save(utf8(label), time_in(time)); });
}

void Ambassador::federateSaveBegun() {
    guarded([&] {
        client().federate_save_begun();
        saving_ = true;
    });
}

void Ambassador::federateSaveComplete() {
    guarded([&] {
        client().federate_save_complete(true);
        saving_ = false;
    });
}

void Ambassador::federateSaveNotComplete() {
    guarded([&] {
        client().federate_save_complete(false);
        saving_ = false;
    });
}

void Ambassador::abortFederationSave() {
    guarded([&] { client().abort_federation_save(); });
}

void Ambassador::requestFederationRestore(std::wstring const& label) {
    guarded([&] { client().request_federation_restore(utf8(label)); });
}

void Ambassador::federateRestoreComplete() {
    guarded([&] { client().federate_restore_complete(true); });
}

void Ambassador::federateRestoreNotComplete() {
    guarded([&] { client().federate_restore_complete(false); });
}

void Ambassador::abortFederationRestore() {
    guarded([&] { client().abort_federation_restore(); });
}

}  // namespace hlacore::rti1516e
