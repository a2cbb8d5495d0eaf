#include "rti/server/recorder.hpp"

#include <algorithm>
#include <charconv>
#include <ctime>

#include "rti/server/federation.hpp"
#include "rti/wire/json.hpp"

namespace hlacore {

namespace {

constexpr std::int64_t kFlushIntervalNs = 500'000'000;

std::int64_t wall_ns() {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec;
}

// The JSON schemas (https://json-schema.org) of the topics, for tools that show them (Foxglove).
constexpr const char* kFederateProperties =
    R"("federate":{"type":"string","description":"the federate's name"},)"
    R"("handle":{"type":"integer","description":"the federate's handle"},)"
    R"("federate_time":{"type":["number","null"],"description":"the federate's logical time then"})";
constexpr const char* kTextOrBytes =
    R"({"oneOf":[{"type":"string"},{"type":"object","properties":{"base64":{"type":"string","contentEncoding":"base64"}}}]})";

std::string schema(const char* title, const std::string& properties) {
    return std::string(R"({"title":")") + title + R"(","type":"object","properties":{)" + kFederateProperties +
           (properties.empty() ? "" : ",") + properties + "}}";
}

template <class Members>
std::string values_schema(const char* kind_enum, const char* values_key, const Members& members) {
    std::string props = std::string(R"("kind":{"enum":[)") + kind_enum + R"(]},)" +
                        R"("time":{"type":["number","null"],"description":"the timestamp, if any"},)" +
                        R"("order":{"enum":["timestamp","receive"],"description":"as the sender sent it"},)" +
                        R"("serial":{"type":"integer"},"tag":)" + kTextOrBytes + ",\"" + values_key +
                        R"(":{"type":"object","properties":{)";
    bool first = true;
    for (const auto& member : members) {
        if (!first) props += ',';
        first = false;
        json_string(props, member.name);
        props += R"(:{"type":"string","contentEncoding":"base64"})";
    }
    return props + "}}";
}

const char* kFederationSchema = R"("event":{"enum":["created","joined","dropped"]},)"
                                R"("fed_name":{"type":"string"},"fed_text":{"type":"string"},)"
                                R"("reason":{"type":"string"})";
// A request, callback or refusal: `key` names its wire message, "fields" holds the message's fields.
std::string message_schema(const char* key) {
    return std::string("\"") + key + R"(":{"type":"string","description":"the wire message"},)" +
           R"("fields":{"type":"object","description":"its fields, as in cpp/rti/wire/messages.hpp"})";
}

template <class M>
const char* name_of(const M&) {
    if constexpr (std::is_same_v<M, std::monostate>) {
        return wire::message_name(wire::MessageType::Invalid);
    } else {
        return wire::message_name(M::kType);
    }
}

// `values` as a JSON object of base64 strings by the names `named(handle)` gives ("#handle" for none).
template <class Values, class Named>  // HandleValues, or HandleValueViews into the frame being served
void put_values(std::string& json, const char* key, const Values& values, Named&& named) {
    json += ",\"";
    json += key;
    json += "\":{";
    bool first = true;
    for (const auto& [handle, value] : values) {
        if (!first) json += ',';
        first = false;
        const auto* member = named(handle);
        json_string(json, member ? member->name : "#" + std::to_string(handle));
        json += ':';
        json_base64(json, value);
    }
    json += '}';
}

void put_uint(std::string& json, std::uint64_t v) {
    char text[24];
    json.append(text, std::to_chars(text, text + sizeof text, v).ptr);
}

// The timestamp, and the order the sender asked for: timestamp order needs one and a regulating sender (each
// receiver gets it so if it is constrained and the FOM or the sender's changeAttributeOrderType says so).
void put_time(std::string& json, const Federation& federation, FederateHandle from, const wire::OptionalTime& time) {
    json += ",\"time\":";
    wire::JsonWriter::put(json, time);
    json += time && federation.regulating(from) ? ",\"order\":\"timestamp\"" : ",\"order\":\"receive\"";
}

}  // namespace

Recorder::Recorder(const std::string& path)
    : writer_(std::make_unique<mcap::Writer>(path, "hlacore", "hlacore rtig")) {}

Recorder::~Recorder() {
    try {
        close();
    } catch (const std::exception&) {
    }
}

void Recorder::close() {
    if (writer_ && !writer_->closed()) writer_->close();
}

void Recorder::tick() {
    if (!writer_ || unflushed_since_ns_ < 0 || wall_ns() - unflushed_since_ns_ < kFlushIntervalNs) return;
    try {
        writer_->flush();
    } catch (const std::exception& e) {
        failure_ = e.what();
        writer_.reset();
    }
    unflushed_since_ns_ = -1;
}

void Recorder::attach(const Federation& federation, RecordTap& tap) {
    taps_[&federation].push_back(&tap);
    write_created(federation, &tap);
    for (FederateHandle federate : federation.federates()) write_joined(federation, federate, &tap);
}

void Recorder::detach(RecordTap& tap) {
    for (auto it = taps_.begin(); it != taps_.end();) {
        auto& taps = it->second;
        taps.erase(std::remove(taps.begin(), taps.end(), &tap), taps.end());
        it = taps.empty() ? taps_.erase(it) : std::next(it);
    }
}

void Recorder::forget(const Federation& federation) {
    taps_.erase(&federation);
    for (auto it = topics_.begin(); it != topics_.end();)
        it = std::get<0>(it->first) == &federation ? topics_.erase(it) : std::next(it);
}

Recorder::Topic& Recorder::topic(const Federation& federation, TopicKind kind, std::uint32_t cls) {
    auto [it, added] = topics_.try_emplace({&federation, kind, cls});
    Topic& t = it->second;
    if (!added) return t;
    const std::string prefix = "/" + federation.name();
    auto message_topic = [&](const char* leaf, const char* key) {
        t.name = prefix + "/hlacore/" + leaf;
        t.schema_name = std::string("hlacore.") + key;
        t.schema = schema(key, message_schema(key));
    };
    switch (kind) {
        case TopicKind::Federation:
            t.name = prefix + "/federation";
            t.schema_name = "hlacore.FederationEvent";
            t.schema = schema("a federation's membership", kFederationSchema);
            break;
        case TopicKind::Object: {
            const fom::ObjectClass& c = *federation.fom().object_class(cls);
            t.name = prefix + "/objects/" + c.qualified_name;
            t.schema_name = "hlacore.Object." + c.qualified_name;
            t.schema = schema(c.qualified_name.c_str(), values_schema(R"("register","update","delete")", "attributes", c.attributes));
            break;
        }
        case TopicKind::Interaction: {
            const fom::InteractionClass& c = *federation.fom().interaction_class(cls);
            t.name = prefix + "/interactions/" + c.qualified_name;
            t.schema_name = "hlacore.Interaction." + c.qualified_name;
            t.schema = schema(c.qualified_name.c_str(), values_schema(R"("interaction")", "parameters", c.parameters));
            break;
        }
        case TopicKind::Grants:
            t.name = prefix + "/hlacore/grants";
            t.schema_name = "hlacore.Grant";
            t.schema = schema("timeAdvanceGrant", R"("time":{"type":"number"})");
            break;
        case TopicKind::Requests: message_topic("requests", "request"); break;
        case TopicKind::Refusals: message_topic("refusals", "answer"); break;
        case TopicKind::Callbacks: message_topic("callbacks", "callback"); break;
    }
    return t;
}

void Recorder::write(const Federation& federation, Topic& topic, std::string& json, RecordTap* only) {
    json += '}';
    const std::uint32_t sequence = ++sequence_;
    const auto now = static_cast<std::uint64_t>(wall_ns());
    auto to_tap = [&](RecordTap& tap) {
        const bool first = tap.topics.insert(topic.name).second;
        tap.recorded(topic.name, topic.schema_name, first ? topic.schema : std::string(), sequence, now, json);
    };
    if (only) return to_tap(*only);
    if (auto taps = taps_.find(&federation); taps != taps_.end()) {
        for (RecordTap* tap : taps->second) to_tap(*tap);
    }
    if (!writer_) return;
    try {
        if (topic.channel == 0) topic.channel = writer_->channel(topic.name, topic.schema_name, topic.schema);
        writer_->message(topic.channel, sequence, now, json);
        if (unflushed_since_ns_ < 0) unflushed_since_ns_ = static_cast<std::int64_t>(now);
    } catch (const std::exception& e) {
        failure_ = e.what();  // the gateway logs it; serving goes on without the recording
        writer_.reset();
    }
}

void Recorder::begin(std::string& json, const Federation& federation, FederateHandle federate) const {
    json = "{\"federate\":";
    json_string(json, federation.federate_name(federate));
    json += ",\"handle\":";
    put_uint(json, federate);
    json += ",\"federate_time\":";
    json_number(json, federation.federate_time(federate));
}

void Recorder::created(const Federation& federation) {
    if (records(federation)) write_created(federation, nullptr);
}

void Recorder::write_created(const Federation& federation, RecordTap* only) {
    json_ = "{\"event\":\"created\",\"fed_name\":";
    json_string(json_, federation.fed_name());
    json_ += ",\"fed_text\":";
    json_string(json_, federation.fed_text());
    write(federation, topic(federation, TopicKind::Federation), json_, only);
}

void Recorder::joined(const Federation& federation, FederateHandle federate) {
    if (records(federation)) write_joined(federation, federate, nullptr);
}

void Recorder::write_joined(const Federation& federation, FederateHandle federate, RecordTap* only) {
    begin(json_, federation, federate);
    json_ += ",\"event\":\"joined\"";
    write(federation, topic(federation, TopicKind::Federation), json_, only);
}

void Recorder::dropped(const Federation& federation, FederateHandle federate, const std::string& why) {
    if (!records(federation)) return;
    begin(json_, federation, federate);
    json_ += ",\"event\":\"dropped\",\"reason\":";
    json_string(json_, why);
    write(federation, topic(federation, TopicKind::Federation), json_);
}

template <class M>
void Recorder::request(const Federation& federation, FederateHandle from, const M& m) {
    if (!records(federation)) return;
    if constexpr (std::is_same_v<M, wire::UpdateAttributesView> || std::is_same_v<M, wire::UpdateAttributes> ||
                  std::is_same_v<M, wire::DeleteObject>) {
        record_object_event(federation, from, m);
    } else if constexpr (std::is_same_v<M, wire::SendInteractionView> || std::is_same_v<M, wire::SendInteraction>) {
        record_interaction(federation, from, m.interaction_class, m.values, m.tag, m.time, nullptr);
    } else if constexpr (std::is_same_v<M, wire::SendInteractionWithRegion>) {
        record_interaction(federation, from, m.interaction_class, m.values, m.tag, m.time, &m.regions);
    } else if constexpr (std::is_same_v<M, wire::RegisterObject> || std::is_same_v<M, wire::RegisterObjectWithRegion>) {
        // Recorded with its outcome (answered): the object's handle and name.
    } else if constexpr (std::is_same_v<M, wire::QueryStatus> || std::is_same_v<M, wire::Ping> ||
                         std::is_same_v<M, wire::ClockProbe> || std::is_same_v<M, wire::QueryTime> ||
                         std::is_same_v<M, wire::DatagramPath> || std::is_same_v<M, wire::StartRecording>) {
        // Questions that change nothing in the federation.
    } else {
        record_fields(federation, from, TopicKind::Requests, "request", m);
    }
}
#define HLACORE_X(name) template void Recorder::request(const Federation&, FederateHandle, const wire::name&);
HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X
template void Recorder::request(const Federation&, FederateHandle, const wire::UpdateAttributesView&);
template void Recorder::request(const Federation&, FederateHandle, const wire::SendInteractionView&);

void Recorder::answered(const Federation& federation, FederateHandle to, const wire::Message& answer) {
    if (!records(federation)) return;
    if (const auto* registered = std::get_if<wire::ObjectRegistered>(&answer)) {
        const ObjectInstance* object = federation.object(registered->object);
        if (!object) return;
        begin(json_, federation, to);
        json_ += ",\"kind\":\"register\",\"object\":";
        json_string(json_, registered->name);
        json_ += ",\"object_handle\":";
        put_uint(json_, registered->object);
        write(federation, topic(federation, TopicKind::Object, object->object_class), json_);
    } else if (const auto* reply = std::get_if<wire::Reply>(&answer); reply && reply->error != 0) {
        record_message(federation, to, TopicKind::Refusals, "answer", answer);
    }
}

void Recorder::callback(const Federation& federation, FederateHandle to, const wire::Message& message) {
    if (!records(federation)) return;
    if (const auto* grant = std::get_if<wire::TimeAdvanceGrant>(&message)) {
        begin(json_, federation, to);
        json_ += ",\"time\":";
        json_number(json_, grant->time);
        write(federation, topic(federation, TopicKind::Grants), json_);
        return;
    }
    record_message(federation, to, TopicKind::Callbacks, "callback", message);
}

template <class M>
void Recorder::record_object_event(const Federation& federation, FederateHandle from, const M& m) {
    const ObjectInstance* object = federation.object(m.object);
    if (!object)  // refused as it is served, or an object deleted meanwhile: kept as the request it is
        return record_fields(federation, from, TopicKind::Requests, "request", m);
    begin(json_, federation, from);
    json_ += std::is_same_v<M, wire::DeleteObject> ? ",\"kind\":\"delete\",\"object\":" : ",\"kind\":\"update\",\"object\":";
    json_string(json_, object->name);
    json_ += ",\"object_handle\":";
    put_uint(json_, m.object);
    put_time(json_, federation, from, m.time);
    json_ += ",\"serial\":";
    put_uint(json_, m.serial);
    json_ += ",\"tag\":";
    json_text(json_, m.tag);
    if constexpr (!std::is_same_v<M, wire::DeleteObject>) {
        const fom::ObjectClass& cls = *federation.fom().object_class(object->object_class);
        put_values(json_, "attributes", m.values, [&](std::uint32_t h) { return cls.attribute(h); });
    }
    write(federation, topic(federation, TopicKind::Object, object->object_class), json_);
}

template <class Values>
void Recorder::record_interaction(const Federation& federation, FederateHandle from, std::uint32_t class_handle,
                                  const Values& values, const std::string& tag,
                                  const wire::OptionalTime& time, const wire::Handles* regions) {
    const fom::InteractionClass* cls = federation.fom().interaction_class(class_handle);
    if (!cls) return;  // refused as it is served; the drop is recorded
    begin(json_, federation, from);
    json_ += ",\"kind\":\"interaction\"";
    put_time(json_, federation, from, time);
    json_ += ",\"tag\":";
    json_text(json_, tag);
    if (regions) {
        json_ += ",\"regions\":";
        wire::JsonWriter::put(json_, *regions);
    }
    put_values(json_, "parameters", values, [&](std::uint32_t h) { return cls->parameter(h); });
    write(federation, topic(federation, TopicKind::Interaction, class_handle), json_);
}

void Recorder::record_message(const Federation& federation, FederateHandle federate, TopicKind kind, const char* key,
                              const wire::Message& message) {
    std::visit([&](const auto& m) { record_fields(federation, federate, kind, key, m); }, message);
}

template <class M>
void Recorder::record_fields(const Federation& federation, FederateHandle federate, TopicKind kind, const char* key,
                             const M& m) {
    begin(json_, federation, federate);
    json_ += ",\"";
    json_ += key;
    json_ += "\":\"";
    json_ += name_of(m);
    json_ += "\",\"fields\":";
    if constexpr (std::is_same_v<M, std::monostate>) json_ += "{}";
    else wire::to_json(json_, m);
    write(federation, topic(federation, kind), json_);
}

}  // namespace hlacore
