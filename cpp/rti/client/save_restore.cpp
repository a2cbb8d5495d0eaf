// The federate side of federation save and restore (HLA 1.3 §4.11-4.22): the services with their
// exceptions, and the save/restore state that the callbacks change when popped (as time state does in
// client/time.cpp). initiateFederateRestore carries the restored federate's handle, time state,
// declarations, known objects and regions, which replace what this client mirrors. docs/save-restore.md.
#include <algorithm>
#include <cmath>

#include "rti/client/client.hpp"

namespace hlacore {

namespace {

// federateSaveComplete, federateRestoreComplete: a federate reports once what it was asked to do; refused
// with `code` otherwise, saying whether it was never asked or has reported already.
template <class Phase>
void report_once(Phase& phase, bool asked, ErrorCode code, const char* never_asked, const char* reported) {
    if (!asked) raise(code, phase == Phase::Answered ? reported : never_asked);
    phase = Phase::Answered;
}

}  // namespace

void Client::require_idle(const char* service) const {
    require_joined();
    check_not_saving_or_restoring(service);
}

void Client::check_not_saving_or_restoring(const char* service) const {
    if (save_restore_.save != SavePhase::None)
        raise(ErrorCode::SaveInProgress, std::string(service) + " refused: the federation save '" + save_restore_.label +
                                             "' is in progress (until federationSaved or federationNotSaved)");
    if (save_restore_.restore != RestorePhase::None)
        raise(ErrorCode::RestoreInProgress,
              std::string(service) +
                  " refused: a federation restore is in progress (until federationRestored or federationNotRestored)");
}

// §4.11. The gateway refuses too when another federate's save or restore is under way.
void Client::request_federation_save(const std::string& label, const wire::OptionalTime& time) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("requestFederationSave");
        if (time && !std::isfinite(*time))
            raise(ErrorCode::InvalidFederationTime, "the save time is not finite");
    }
    const auto id = next_request();
    call(wire::RequestFederationSave{id, label, time}, id);
}

// §4.13: only noted here; the gateway needs nothing before federateSaveComplete.
void Client::federate_save_begun() {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    if (save_restore_.save != SavePhase::Initiated)
        raise(ErrorCode::SaveNotInitiated, save_restore_.save == SavePhase::None
                                               ? "no initiateFederateSave was delivered to this federate"
                                               : "federateSaveBegun was already called for this save");
    save_restore_.save = SavePhase::Begun;
}

// §4.14-4.15.
void Client::federate_save_complete(bool success) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        report_once(save_restore_.save, save_restore_.save == SavePhase::Initiated || save_restore_.save == SavePhase::Begun,
                    ErrorCode::SaveNotInitiated, "no initiateFederateSave was delivered to this federate",
                    "this federate already reported its save");
    }
    send(wire::FederateSaveComplete{success});
}

// §4.17: requestFederationRestoreSucceeded/Failed follows.
void Client::request_federation_restore(const std::string& label) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("requestFederationRestore");
    }
    const auto id = next_request();
    call(wire::RequestFederationRestore{id, label}, id);
}

// §4.21.
void Client::federate_restore_complete(bool success) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        report_once(save_restore_.restore, save_restore_.restore == RestorePhase::Initiated, ErrorCode::RestoreNotRequested,
                    "no initiateFederateRestore was delivered to this federate",
                    "this federate already reported its restore");
    }
    send(wire::FederateRestoreComplete{success});
}

void Client::abort_federation_save() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    const auto id = next_request();
    call(wire::AbortFederationSave{id}, id);
}

void Client::abort_federation_restore() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    const auto id = next_request();
    call(wire::AbortFederationRestore{id}, id);
}

std::uint8_t Client::last_failure_reason() const {
    std::lock_guard<std::mutex> lock(mu_);
    return save_restore_.failure;
}

void Client::delivered(const wire::InitiateFederateSave& m) {
    save_restore_.save = SavePhase::Initiated;
    save_restore_.label = m.label;
}

void Client::delivered(const wire::FederationSaved& m) {
    save_restore_.save = SavePhase::None;
    save_restore_.failure = m.reason;
}

void Client::delivered(const wire::FederationRestoreBegun&) {
    save_restore_.restore = RestorePhase::Begun;
    save_restore_.save = SavePhase::None;
}

void Client::delivered(const wire::FederationRestored& m) {
    save_restore_.restore = RestorePhase::None;
    save_restore_.failure = m.reason;
}

void Client::delivered(const wire::InitiateFederateRestore& m) {
    save_restore_.restore = RestorePhase::Initiated;
    // The federation as it was saved: this federate's handle, declarations, objects and time state.
    const wire::RestoredState& saved = *m.state;
    federate_ = m.federate;
    declarations_.published.clear();
    for (const auto& [cls, attrs] : saved.published) declarations_.published[cls] = std::set<fom::Handle>(attrs.begin(), attrs.end());
    declarations_.subscribed.clear();
    for (const auto& [cls, attrs] : saved.subscribed) declarations_.subscribed[cls] = std::set<fom::Handle>(attrs.begin(), attrs.end());
    declarations_.published_interactions =
        std::set<fom::Handle>(saved.published_interactions.begin(), saved.published_interactions.end());
    declarations_.subscribed_interactions =
        std::set<fom::Handle>(saved.subscribed_interactions.begin(), saved.subscribed_interactions.end());
    for (auto [declared, records] : {std::pair{&declarations_.published_directed, &saved.published_directed},
                                     std::pair{&declarations_.subscribed_directed, &saved.subscribed_directed},
                                     std::pair{&declarations_.subscribed_directed_universally,
                                               &saved.subscribed_directed_universally}}) {
        declared->clear();
        for (const auto& [oc, ics] : *records) (*declared)[oc] = std::set<fom::Handle>(ics.begin(), ics.end());
    }
    objects_.clear();
    for (const auto& known : saved.objects) {
        LocalObject obj = make_local_object(known.known_class, known.name);
        obj.owned = std::set<fom::Handle>(known.owned.begin(), known.owned.end());
        obj.privilege_to_delete = known.may_delete;
        objects_[known.object] = std::move(obj);
    }
    announced_.clear();  // synchronization points are not saved
    restore_regions(saved);
    const wire::SavedTime& st = saved.time_state;
    TimeState t;
    t.time = st.time;
    t.lookahead = st.lookahead;
    t.enable_lookahead = st.lookahead;
    t.regulating = st.regulating;
    t.constrained = st.constrained;
    t.asynchronous_delivery = st.asynchronous_delivery;
    t.strict = st.strict_after_grant;
    t.floor = st.regulating ? st.promise : -kInfinity;
    time_ = std::move(t);
    // Restored queues hold messages with serials up to next_serial: new ones must not collide.
    serial_ = std::max(serial_, saved.next_serial);
}

}  // namespace hlacore
