// The Client's own services: federation management, the status query, the recorder federate, and the checks
// the service groups share. Its connection is connect.cpp, writer.cpp and reader.cpp; each group's services
// are client/<group>.cpp.
#include "rti/client/client.hpp"

#include "fed_parser/omt.hpp"
#include "rti/auth.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

#include <openssl/err.h>
#include <openssl/x509_vfy.h>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

std::string Client::query_status(std::uint64_t events_after, bool instances) {
    const auto id = next_request();
    return call<wire::StatusReport>(wire::QueryStatus{id, events_after, instances}, id).json;
}

void Client::start_recording(const std::string& path) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (recording_) throw RtiError(ErrorCode::RTIinternalError, "this federate records already");
        recording_ = std::make_unique<mcap::Writer>(path, "hlacore", "hlacore recorder federate");
        recording_failure_.clear();
    }
    const auto id = next_request();
    try {
        call<wire::Reply>(wire::StartRecording{id}, id);
    } catch (...) {
        std::lock_guard<std::mutex> lock(mu_);
        recording_.reset();
        throw;
    }
}

std::uint64_t Client::stop_recording() {
    std::unique_ptr<mcap::Writer> writer;
    std::string failure;
    {
        std::lock_guard<std::mutex> lock(mu_);
        writer = std::move(recording_);
        failure = std::move(recording_failure_);
    }
    if (!failure.empty()) throw std::runtime_error(failure);
    if (!writer) return 0;
    writer->close();
    return writer->messages();
}

template <class Write>
void Client::write_recorded(Write write) {
    if (!recording_) return;  // stopped: the gateway's last records before it heard of it
    try {
        write();
    } catch (const std::exception& e) {
        recording_failure_ = e.what();
        recording_.reset();
    }
}

// A topic or a record of the recording this federate asked for (start_recording), written as it comes.
bool Client::arrived(wire::RecordedTopic& topic) {
    write_recorded([&] { recording_->channel(topic.topic, topic.schema_name, topic.schema); });
    return false;
}

bool Client::arrived(wire::Recorded& r) {
    write_recorded([&] {
        if (!recording_->has_channel(r.topic))
            throw std::runtime_error("the gateway sent a record on '" + r.topic + "' before announcing the topic");
        recording_->message(recording_->channel_id(r.topic), r.sequence, r.log_ns, r.data);
    });
    return false;
}


void Client::connection_lost() const { raise(closed_code_, lost_text()); }

std::string Client::lost_text() const { return "connection to rtig at " + address_ + " lost: " + closed_reason_; }

std::optional<std::string> Client::lost() const {
    std::lock_guard<std::mutex> lock(mu_);
    if (!closed_) return std::nullopt;
    return lost_text();
}

// ---- checks ----

void Client::require_joined() const {
    if (!fom_) raise(ErrorCode::FederateNotExecutionMember, "the federate is not joined to a federation execution");
    if (closed_) connection_lost();
}

void Client::too_long(const char* service, std::size_t length) const {
    raise(ErrorCode::ValueLengthExceeded,
          std::string(service) + ": the values and tag make a message of " + std::to_string(length) +
              " bytes as the gateway forwards it, over its frame limit of " + std::to_string(max_frame_bytes_) +
              " bytes (rtig --max-frame)");
}

const fom::ObjectClass& Client::defined_object_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->object_class(cls);
    if (!c) raise(ErrorCode::ObjectClassNotDefined, "object class handle " + std::to_string(cls) + " is not defined");
    return *c;
}

const fom::InteractionClass& Client::defined_interaction_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->interaction_class(cls);
    if (!c)
        raise(ErrorCode::InteractionClassNotDefined, "interaction class handle " + std::to_string(cls) + " is not defined");
    return *c;
}

const Client::LocalObject& Client::known_object(std::uint32_t object) const {
    require_joined();
    auto it = objects_.find(object);
    if (it == objects_.end()) raise(ErrorCode::ObjectNotKnown, "object " + std::to_string(object) + " is not known");
    return it->second;
}

void Client::check_attributes(const fom::ObjectClass& cls, const std::vector<fom::Handle>& attributes) {
    for (auto a : attributes) {
        if (!cls.attribute(a))
            raise(ErrorCode::AttributeNotDefined,
                  "attribute handle " + std::to_string(a) + " is not defined for class '" + cls.qualified_name + "'");
    }
}

// ---- federation management ----

std::string Client::federation_proof(const char* action, const std::string& federation) const {
    if (options_.federation_secret.empty() || nonce_.empty()) return "";
    return auth::federation_proof(options_.federation_secret, nonce_, action, federation);
}

void Client::create_federation(const std::string& name, const std::string& fed_name, const std::string& fed_text,
                               TimeType time_type) {
    const auto id = next_request();
    call(wire::CreateFederation{id, static_cast<std::uint8_t>(options_.time_semantics),
                                static_cast<std::uint8_t>(time_type), name, fed_name, fed_text,
                                federation_proof("create", name)},
         id);
}

void Client::destroy_federation(const std::string& name) {
    const auto id = next_request();
    call(wire::DestroyFederation{id, name, federation_proof("destroy", name)}, id);
}

std::uint32_t Client::join(const std::string& federate, const std::string& federation, const std::string& fom_modules,
                           const std::string& federate_type) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (fom_) raise(ErrorCode::FederateAlreadyExecutionMember, "this ambassador is already joined");
        early_fom_.reset();
    }
    const auto id = next_request();
    wire::JoinFederation join{id, federate, federation, federation_proof("join", federation), {}};
    join.joining.edit() = {fom_modules, federate_type};
    auto joined = call<wire::FederationJoined>(join, id);
    auto parsed = std::make_unique<fom::Fom>(fom::parse_fom(joined.fed_text, joined.fed_name));
    {
        auto sending = lock_send();
        member_ = true;
    }
    std::lock_guard<std::mutex> lock(mu_);
    fom_ = std::move(parsed);
    if (early_fom_) {  // another federate extended the FOM right after this one joined
        take_fom(early_fom_->fed_text, early_fom_->fed_name);
        early_fom_.reset();
    }
    federate_ = joined.federate;
    time_type_ = static_cast<TimeType>(joined.time_type);
    return joined.federate;
}

// Another federate joined with FOM modules of its own (IEEE 1516-2010 §4.5): from now on lookups find what
// they added, every handle known before meaning the same. At arrival, under mu_: the gateway sends it before
// anything that names a new class or member.
bool Client::arrived(wire::FomExtended& m) {
    if (fom_) take_fom(m.fed_text, m.fed_name);
    else early_fom_ = std::move(m);  // join() has the FederationJoined and not yet its FOM
    return false;
}

void Client::take_fom(const std::string& fed_text, const std::string& fed_name) {
    try {
        fom_ = std::make_unique<fom::Fom>(fom::parse_fom(fed_text, fed_name));
    } catch (const fom::FedError& e) {
        close_locked(ErrorCode::RTIinternalError, std::string("protocol error from the gateway: its extended FOM "
                                                              "does not read here: ") + e.what());
        return;
    }
    widen_regions();
}

void Client::resign(std::uint8_t action) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("resignFederationExecution");
        if (action < 1 || action > 4)
            raise(ErrorCode::InvalidResignAction, "resign action " + std::to_string(action) + " is not one of 1-4");
    }
    // Other threads may still be sending (a bridge shutting down): from the resign on, in the socket's order,
    // their federation messages raise FederateNotExecutionMember here instead of reaching the gateway after
    // it, where they would be a protocol error. Until the reply, also when the resign is then refused.
    const auto id = next_request();
    {
        auto sending = lock_send();
        if (!member_) raise(ErrorCode::FederateNotExecutionMember, "the federate is already resigning");
        member_ = false;
        send_buffer_.clear();
        wire::encode(send_buffer_, wire::ResignFederation{id, action});
        send_encoded(sending);
    }
    try {
        await_reply(id);
    } catch (const RtiError&) {
        bool closed;
        {
            std::lock_guard<std::mutex> lock(mu_);
            closed = closed_;
        }
        if (!closed) {
            auto sending = lock_send();
            member_ = true;  // refused (FederateOwnsAttributes ...): still joined
        }
        throw;
    }
    std::lock_guard<std::mutex> lock(mu_);
    callbacks_ = CallbackQueue{};  // what the federation sent before the resign: no callback after it
    fom_.reset();
    federate_ = 0;
    declarations_ = DeclarationState{};
    objects_.clear();
    announced_.clear();
    time_ = TimeState{};
    save_restore_.save = SavePhase::None;
    save_restore_.restore = RestorePhase::None;
    ddm_ = DdmState{};
}

}  // namespace hlacore
