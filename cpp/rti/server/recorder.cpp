#include "rti/server/recorder.hpp"

#include <algorithm>
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
                        R"("time":{"type":["number","null"],"description":"the timestamp; null: receive order"},)" +
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

template <class Schema>
void Recorder::write(const Federation& federation, const std::string& topic, const std::string& schema_name,
                     Schema&& make_schema, std::string& json, RecordTap* only) {
    json += '}';
    const std::uint32_t sequence = ++sequence_;
    const std::int64_t now = wall_ns();
    auto to_tap = [&](RecordTap& tap) {
        const bool first = tap.topics.insert(topic).second;
        tap.recorded(topic, schema_name, first ? make_schema() : std::string(), sequence,
                     static_cast<std::uint64_t>(now), json);
    };
    if (only) return to_tap(*only);
    if (auto taps = taps_.find(&federation); taps != taps_.end()) {
        for (RecordTap* tap : taps->second) to_tap(*tap);
    }
    if (!writer_) return;
    try {
        const std::uint16_t channel =
            writer_->has_channel(topic) ? writer_->channel_id(topic) : writer_->channel(topic, schema_name, make_schema());
        writer_->message(channel, sequence, static_cast<std::uint64_t>(now), json);
        if (unflushed_since_ns_ < 0) unflushed_since_ns_ = now;
    } catch (const std::exception& e) {
        failure_ = e.what();  // the gateway logs it; serving goes on without the recording
        writer_.reset();
    }
}

void Recorder::begin(std::string& json, const Federation& federation, FederateHandle federate) const {
    json = "{\"federate\":";
    json_string(json, federation.federate_name(federate));
    json += ",\"handle\":" + std::to_string(federate) + ",\"federate_time\":";
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
    write(federation, "/" + federation.name() + "/federation", "hlacore.FederationEvent",
          [] { return schema("a federation's membership", kFederationSchema); }, json_, only);
}

void Recorder::joined(const Federation& federation, FederateHandle federate) {
    if (records(federation)) write_joined(federation, federate, nullptr);
}

void Recorder::write_joined(const Federation& federation, FederateHandle federate, RecordTap* only) {
    begin(json_, federation, federate);
    json_ += ",\"event\":\"joined\"";
    write(federation, "/" + federation.name() + "/federation", "hlacore.FederationEvent",
          [] { return schema("a federation's membership", kFederationSchema); }, json_, only);
}

void Recorder::dropped(const Federation& federation, FederateHandle federate, const std::string& why) {
    if (!records(federation)) return;
    begin(json_, federation, federate);
    json_ += ",\"event\":\"dropped\",\"reason\":";
    json_string(json_, why);
    write(federation, "/" + federation.name() + "/federation", "hlacore.FederationEvent",
          [] { return schema("a federation's membership", kFederationSchema); }, json_);
}

void Recorder::request(const Federation& federation, FederateHandle from, const wire::Message& message) {
    if (!records(federation)) return;
    std::visit(
        [&](const auto& m) {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, wire::UpdateAttributes>) {
                record_update(federation, from, m);
            } else if constexpr (std::is_same_v<M, wire::SendInteraction>) {
                record_interaction(federation, from, m.interaction_class, m.values, m.tag, m.time, nullptr);
            } else if constexpr (std::is_same_v<M, wire::SendInteractionWithRegion>) {
                record_interaction(federation, from, m.interaction_class, m.values, m.tag, m.time, &m.region);
            } else if constexpr (std::is_same_v<M, wire::DeleteObject>) {
                record_delete(federation, from, m);
            } else if constexpr (std::is_same_v<M, wire::RegisterObject> ||
                                 std::is_same_v<M, wire::RegisterObjectWithRegion>) {
                // Recorded with its outcome (answered): the object's handle and name.
            } else if constexpr (std::is_same_v<M, wire::QueryStatus> || std::is_same_v<M, wire::Ping> ||
                                 std::is_same_v<M, wire::ClockProbe> || std::is_same_v<M, wire::QueryTime> ||
                                 std::is_same_v<M, wire::DatagramPath> || std::is_same_v<M, wire::StartRecording>) {
                // Questions that change nothing in the federation.
            } else {
                record_generic(federation, from, "requests", "request", name_of(m), message);
            }
        },
        message);
}

void Recorder::answered(const Federation& federation, FederateHandle to, const wire::Message& answer) {
    if (!records(federation)) return;
    if (const auto* registered = std::get_if<wire::ObjectRegistered>(&answer)) {
        const ObjectInstance* object = federation.object(registered->object);
        const fom::ObjectClass* cls = object ? federation.fom().object_class(object->object_class) : nullptr;
        if (!cls) return;
        begin(json_, federation, to);
        json_ += ",\"kind\":\"register\",\"object\":";
        json_string(json_, registered->name);
        json_ += ",\"object_handle\":" + std::to_string(registered->object);
        write(federation, "/" + federation.name() + "/objects/" + cls->qualified_name, "hlacore.Object." + cls->qualified_name,
              [&] { return schema(cls->qualified_name.c_str(), values_schema(R"("register","update","delete")", "attributes", cls->attributes)); },
              json_);
    } else if (const auto* reply = std::get_if<wire::Reply>(&answer); reply && reply->error != 0) {
        record_generic(federation, to, "refusals", "answer", "Reply", answer);
    }
}

void Recorder::callback(const Federation& federation, FederateHandle to, const wire::Message& message) {
    if (!records(federation)) return;
    if (const auto* grant = std::get_if<wire::TimeAdvanceGrant>(&message)) {
        begin(json_, federation, to);
        json_ += ",\"time\":";
        json_number(json_, grant->time);
        write(federation, "/" + federation.name() + "/hlacore/grants", "hlacore.Grant",
              [] { return schema("timeAdvanceGrant", R"("time":{"type":"number"})"); }, json_);
        return;
    }
    std::visit([&](const auto& m) { record_generic(federation, to, "callbacks", "callback", name_of(m), message); },
               message);
}

void Recorder::record_update(const Federation& federation, FederateHandle from, const wire::UpdateAttributes& m) {
    const ObjectInstance* object = federation.object(m.object);
    const fom::ObjectClass* cls = object ? federation.fom().object_class(object->object_class) : nullptr;
    if (!cls) return record_generic(federation, from, "requests", "request", "UpdateAttributes", m);
    begin(json_, federation, from);
    json_ += ",\"kind\":\"update\",\"object\":";
    json_string(json_, object->name);
    json_ += ",\"object_handle\":" + std::to_string(m.object) + ",\"time\":";
    wire::JsonWriter::put(json_, m.time);
    json_ += ",\"serial\":" + std::to_string(m.serial) + ",\"tag\":";
    json_text(json_, m.tag);
    json_ += ",\"attributes\":{";
    bool first = true;
    for (const auto& [handle, value] : m.values) {
        const fom::Attribute* attribute = cls->attribute(handle);
        if (!first) json_ += ',';
        first = false;
        json_string(json_, attribute ? attribute->name : "#" + std::to_string(handle));
        json_ += ':';
        json_base64(json_, value);
    }
    json_ += '}';
    write(federation, "/" + federation.name() + "/objects/" + cls->qualified_name, "hlacore.Object." + cls->qualified_name,
          [&] { return schema(cls->qualified_name.c_str(), values_schema(R"("register","update","delete")", "attributes", cls->attributes)); },
          json_);
}

void Recorder::record_interaction(const Federation& federation, FederateHandle from, std::uint32_t class_handle,
                                  const wire::HandleValues& values, const std::string& tag,
                                  const wire::OptionalTime& time, const std::uint32_t* region) {
    const fom::InteractionClass* cls = federation.fom().interaction_class(class_handle);
    if (!cls) return;  // refused as it is served; the drop is recorded
    begin(json_, federation, from);
    json_ += ",\"kind\":\"interaction\",\"time\":";
    wire::JsonWriter::put(json_, time);
    json_ += ",\"tag\":";
    json_text(json_, tag);
    if (region) json_ += ",\"region\":" + std::to_string(*region);
    json_ += ",\"parameters\":{";
    bool first = true;
    for (const auto& [handle, value] : values) {
        const fom::Parameter* parameter = cls->parameter(handle);
        if (!first) json_ += ',';
        first = false;
        json_string(json_, parameter ? parameter->name : "#" + std::to_string(handle));
        json_ += ':';
        json_base64(json_, value);
    }
    json_ += '}';
    write(federation, "/" + federation.name() + "/interactions/" + cls->qualified_name,
          "hlacore.Interaction." + cls->qualified_name,
          [&] { return schema(cls->qualified_name.c_str(), values_schema(R"("interaction")", "parameters", cls->parameters)); },
          json_);
}

void Recorder::record_delete(const Federation& federation, FederateHandle from, const wire::DeleteObject& m) {
    const ObjectInstance* object = federation.object(m.object);
    const fom::ObjectClass* cls = object ? federation.fom().object_class(object->object_class) : nullptr;
    if (!cls) return record_generic(federation, from, "requests", "request", "DeleteObject", m);
    begin(json_, federation, from);
    json_ += ",\"kind\":\"delete\",\"object\":";
    json_string(json_, object->name);
    json_ += ",\"object_handle\":" + std::to_string(m.object) + ",\"time\":";
    wire::JsonWriter::put(json_, m.time);
    json_ += ",\"serial\":" + std::to_string(m.serial) + ",\"tag\":";
    json_text(json_, m.tag);
    write(federation, "/" + federation.name() + "/objects/" + cls->qualified_name, "hlacore.Object." + cls->qualified_name,
          [&] { return schema(cls->qualified_name.c_str(), values_schema(R"("register","update","delete")", "attributes", cls->attributes)); },
          json_);
}

void Recorder::record_generic(const Federation& federation, FederateHandle federate, const char* topic_leaf,
                              const char* key, const char* name, const wire::Message& message) {
    begin(json_, federation, federate);
    json_ += ",\"";
    json_ += key;
    json_ += "\":\"";
    json_ += name;
    json_ += "\",\"fields\":";
    std::visit(
        [&](const auto& m) {
            if constexpr (std::is_same_v<std::decay_t<decltype(m)>, std::monostate>) json_ += "{}";
            else wire::to_json(json_, m);
        },
        message);
    write(federation, "/" + federation.name() + "/hlacore/" + topic_leaf, std::string("hlacore.") + key,
          [&] { return schema(key, message_schema(key)); }, json_);
}

}  // namespace hlacore
