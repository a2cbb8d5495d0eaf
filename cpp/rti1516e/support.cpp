// Support services (IEEE 1516.1-2010 §10): names and handles, the advisory switches, handle decoding,
// and the update rates.
#include <algorithm>
#include <cctype>

#include "ambassador.hpp"
#include "encoding/Octets.h"

namespace hlacore::rti1516e {

namespace {
void set_switch(Client& c, wire::AdvisorySwitch which, bool on) {
    c.request(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(which), on});
}

std::string lower(std::wstring const& name) {
    std::string s = utf8(name);
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return s;
}

// A handle's encoding: 4 bytes big-endian (a retraction handle 12: the sender's 4, the serial's 8).
unsigned long long number(VariableLengthData const& encoded, size_t length) {
    if (encoded.size() != length)
        raise("CouldNotDecode", std::to_string(encoded.size()) + " bytes, not " + std::to_string(length));
    return hlacore_rti1516e::loadBigEndian(encoded.data(), length);
}
}  // namespace

// ---- update rates (the FOM's, and the one this federate's subscription asks for) ----

double Ambassador::getUpdateRateValue(std::wstring const& designator) {
    return guarded([&] { return client().update_rate(utf8(designator)); });
}
double Ambassador::getUpdateRateValueForAttribute(ObjectInstanceHandle object, AttributeHandle attribute) {
    return guarded([&] { return client().update_rate_for(core(object), core(attribute)); });
}
// ---- what the gateway's status report says (asked on this connection: after everything sent before) ----

namespace {
std::vector<JsonValue> const& list(JsonValue const& v, const char* key) { return v.at(key).items; }
bool contains(JsonValue const* numbers, double n) {
    if (!numbers) return false;
    for (const auto& item : numbers->items)
        if (item.number == n) return true;
    return false;
}
}  // namespace

JsonValue Ambassador::report() const { return parse_json(client().query_status(0, false)); }

JsonValue Ambassador::federation() const {
    const double me = client().federate_handle();
    const JsonValue all = report();  // kept: the loops below look into it
    for (const auto& f : list(all, "federations"))
        for (const auto& member : list(f, "federates"))
            if (member.at("handle").number == me && member.at("name").text == federate_name_) return f;
    raise("FederateNotExecutionMember", "not in the gateway's report");
}

bool Ambassador::federationMembers(std::wstring const& federation, std::vector<std::pair<std::wstring, std::wstring>>& members) {
    return guarded([&] {
        const JsonValue all = report();
        for (const auto& f : list(all, "federations")) {
            if (f.at("name").text != utf8(federation)) continue;
            for (const auto& member : list(f, "federates")) {
                const JsonValue* type = member.find("type");
                members.emplace_back(wide(member.at("name").text), wide(type ? type->text : ""));
            }
            return true;
        }
        return false;
    });
}

void Ambassador::listFederationExecutions() {
    guarded([&] {
        FederationExecutionInformationVector found;
        const JsonValue all = report();
        for (const auto& f : list(all, "federations")) {
            const JsonValue* type = f.find("time_type");
            found.emplace_back(wide(f.at("name").text), wide(type ? type->text : ""));
        }
        std::lock_guard<std::recursive_mutex> lock(mu_);
        local_.push_back([found](FederateAmbassador& fa) { fa.reportFederationExecutions(found); });
    });
}

// Each federate's save or restore status, `status(h)` from the gateway's record of the run (`run`): the answer
// the ambassador gets, as a callback of this layer's own.
template <class Status, class Answer>
void Ambassador::answer_statuses(Status status, Answer answer) {
    const JsonValue f = federation();
    const JsonValue& run = f.at("save_restore");
    std::vector<decltype(status(run, 0.0))> statuses;
    for (const auto& member : list(f, "federates")) statuses.push_back(status(run, member.at("handle").number));
    std::lock_guard<std::recursive_mutex> lock(mu_);
    local_.push_back([statuses, answer](FederateAmbassador& fa) { answer(fa, statuses); });
}

// NO_SAVE_IN_PROGRESS, FEDERATE_INSTRUCTED_TO_SAVE (this federate: FEDERATE_SAVING after federateSaveBegun),
// FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE once it completed.
void Ambassador::queryFederationSaveStatus() {
    guarded([&] {
        const double me = client().federate_handle();
        answer_statuses(
            [&](JsonValue const& save, double h) {
                const auto state = save.at("state").text;
                SaveStatus status = NO_SAVE_IN_PROGRESS;
                if (state == "saving" || state == "waiting for the save time") {
                    if (contains(save.find("answered"), h)) status = FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE;
                    else if (contains(save.find("told"), h))
                        status = h == me && saving_ ? FEDERATE_SAVING : FEDERATE_INSTRUCTED_TO_SAVE;
                }
                return FederateHandleSaveStatusPair(handle<FederateHandle>(static_cast<unsigned long long>(h)), status);
            },
            [](FederateAmbassador& fa, FederateHandleSaveStatusPairVector const& s) { fa.federationSaveStatusResponse(s); });
    });
}

// NO_RESTORE_IN_PROGRESS, FEDERATE_RESTORING, FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE once it completed; the
// core keeps each federate's handle across a restore.
void Ambassador::queryFederationRestoreStatus() {
    guarded([&] {
        answer_statuses(
            [](JsonValue const& restore, double h) {
                const auto federate = handle<FederateHandle>(static_cast<unsigned long long>(h));
                const RestoreStatus status = restore.at("state").text != "restoring" ? NO_RESTORE_IN_PROGRESS
                                             : contains(restore.find("answered"), h)
                                                 ? FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE
                                                 : FEDERATE_RESTORING;
                return FederateRestoreStatus(federate, federate, status);
            },
            [](FederateAmbassador& fa, FederateRestoreStatusVector const& s) { fa.federationRestoreStatusResponse(s); });
    });
}

FederateHandle Ambassador::getFederateHandle(std::wstring const& name) {
    return guarded([&] {
        const JsonValue f = federation();
        for (const auto& member : list(f, "federates"))
            if (member.at("name").text == utf8(name))
                return handle<FederateHandle>(static_cast<unsigned long long>(member.at("handle").number));
        raise("NameNotFound", "no federate named '" + utf8(name) + "' is joined");
    });
}

std::wstring Ambassador::getFederateName(FederateHandle federate) {
    return guarded([&] {
        const JsonValue f = federation();
        for (const auto& member : list(f, "federates"))
            if (member.at("handle").number == core(federate)) return wide(member.at("name").text);
        raise("FederateHandleNotKnown", "no federate " + std::to_string(core(federate)) + " is joined");
    });
}

// ---- automatic resign: the gateway deletes what a vanished federate may delete and divests the rest ----

ResignAction Ambassador::getAutomaticResignDirective() {
    return guarded([&] {
        client();
        return resign_directive_;
    });
}

void Ambassador::setAutomaticResignDirective(ResignAction action) {
    guarded([&] {
        client();
        if (raw(action) < UNCONDITIONALLY_DIVEST_ATTRIBUTES || raw(action) > NO_ACTION)
            raise("InvalidResignAction", std::to_string(raw(action)));
        if (raw(action) != CANCEL_THEN_DELETE_THEN_DIVEST)
            not_served("another automatic resign action", "the gateway deletes and divests a vanished federate");
        resign_directive_ = action;
    });
}

// ---- names and handles ----

// Each lookup, one line: the service, what it gives (a handle kind, or a name), its parameters, the client's call.
#define HLACORE_HANDLE(Service, Kind, params, call) \
    Kind Ambassador::Service params { return guarded([&] { return handle<Kind>(client().call); }); }
#define HLACORE_NAME(Service, params, call) \
    std::wstring Ambassador::Service params { return guarded([&] { return wide(client().call); }); }
HLACORE_HANDLE(getObjectClassHandle, ObjectClassHandle, (std::wstring const& name), object_class_handle(utf8(name)))
HLACORE_NAME(getObjectClassName, (ObjectClassHandle h), object_class_name(core(h)))
HLACORE_HANDLE(getKnownObjectClassHandle, ObjectClassHandle, (ObjectInstanceHandle object), object_class_of(core(object)))
HLACORE_HANDLE(getObjectInstanceHandle, ObjectInstanceHandle, (std::wstring const& name), object_instance_handle(utf8(name)))
HLACORE_NAME(getObjectInstanceName, (ObjectInstanceHandle h), object_instance_name(core(h)))
HLACORE_HANDLE(getAttributeHandle, AttributeHandle, (ObjectClassHandle cls, std::wstring const& name),
               attribute_handle(utf8(name), core(cls)))
HLACORE_NAME(getAttributeName, (ObjectClassHandle cls, AttributeHandle h), attribute_name(core(h), core(cls)))
HLACORE_HANDLE(getInteractionClassHandle, InteractionClassHandle, (std::wstring const& name),
               interaction_class_handle(utf8(name)))
HLACORE_NAME(getInteractionClassName, (InteractionClassHandle h), interaction_class_name(core(h)))
HLACORE_HANDLE(getParameterHandle, ParameterHandle, (InteractionClassHandle cls, std::wstring const& name),
               parameter_handle(utf8(name), core(cls)))
HLACORE_NAME(getParameterName, (InteractionClassHandle cls, ParameterHandle h), parameter_name(core(h), core(cls)))
#undef HLACORE_HANDLE
#undef HLACORE_NAME

OrderType Ambassador::getOrderType(std::wstring const& name) {
    return guarded([&] {
        const std::string n = lower(name);
        if (n == "receive") return RECEIVE;
        if (n == "timestamp") return TIMESTAMP;
        raise("InvalidOrderName", "'" + utf8(name) + "' (Receive, TimeStamp)");
    });
}
std::wstring Ambassador::getOrderName(OrderType type) {
    return guarded([&]() -> std::wstring {
        if (raw(type) == RECEIVE) return L"Receive";
        if (raw(type) == TIMESTAMP) return L"TimeStamp";
        raise("InvalidOrderType", std::to_string(raw(type)));
    });
}
TransportationType Ambassador::getTransportationType(std::wstring const& name) {
    return guarded([&] {
        try {
            return static_cast<TransportationType>(Client::transportation_handle(utf8(name)));
        } catch (const RtiError& e) {
            raise("InvalidTransportationName", e.what());
        }
    });
}
std::wstring Ambassador::getTransportationName(TransportationType type) {
    return guarded([&] { return wide(Client::transportation_name(static_cast<std::uint64_t>(raw(type)))); });
}

unsigned long Ambassador::normalizeFederateHandle(FederateHandle federate) {
    return guarded([&] {
        if (!federate.isValid()) raise("InvalidFederateHandle", "an invalid handle");
        return static_cast<unsigned long>(core(federate));
    });
}
unsigned long Ambassador::normalizeServiceGroup(ServiceGroup group) {
    return guarded([&] {
        if (raw(group) < FEDERATION_MANAGEMENT || raw(group) > SUPPORT_SERVICES)
            raise("InvalidServiceGroup", std::to_string(raw(group)));
        return static_cast<unsigned long>(raw(group));
    });
}

// ---- the advisory switches ----

#define HLACORE_SWITCH(Name, Which)                                                                     \
    void Ambassador::enable##Name##AdvisorySwitch() {                                                   \
        guarded([&] { set_switch(client(), wire::AdvisorySwitch::Which, true); });                      \
    }                                                                                                   \
    void Ambassador::disable##Name##AdvisorySwitch() {                                                  \
        guarded([&] { set_switch(client(), wire::AdvisorySwitch::Which, false); });                     \
    }
HLACORE_SWITCH(ObjectClassRelevance, ClassRelevance)
HLACORE_SWITCH(AttributeRelevance, AttributeRelevance)
HLACORE_SWITCH(AttributeScope, AttributeScope)
HLACORE_SWITCH(InteractionRelevance, InteractionRelevance)
#undef HLACORE_SWITCH

// ---- decoding handles ----

#define HLACORE_X(Kind)                                                                                   \
    Kind Ambassador::decode##Kind(VariableLengthData const& encoded) const {                             \
        return guarded([&] { return handle<Kind>(number(encoded, 4)); });                                \
    }
HLACORE_X(FederateHandle) HLACORE_X(ObjectClassHandle) HLACORE_X(InteractionClassHandle)
HLACORE_X(ObjectInstanceHandle) HLACORE_X(AttributeHandle) HLACORE_X(ParameterHandle) HLACORE_X(DimensionHandle)
HLACORE_X(RegionHandle)
#undef HLACORE_X

MessageRetractionHandle Ambassador::decodeMessageRetractionHandle(VariableLengthData const& encoded) const {
    return guarded([&] {
        if (encoded.size() != 12) raise("CouldNotDecode", std::to_string(encoded.size()) + " bytes, not 12");
        const char* in = static_cast<const char*>(encoded.data());
        const auto sender = number(VariableLengthData(in, 4), 4);
        return retraction(static_cast<std::uint32_t>(sender), number(VariableLengthData(in + 4, 8), 8));
    });
}

}  // namespace hlacore::rti1516e
