// The recording of a gateway's federations (`rtig --record FILE`, `hlacore.Gateway(record=FILE)`;
// docs/record-replay.md): an MCAP file (rti/record/mcap.hpp) of JSON messages, one per event, in the order
// the gateway saw them (the MCAP sequence number), each stamped with the wall clock (CLOCK_REALTIME, to
// align recordings made on several hosts). Topics, for a federation F:
//
//   /F/federation               created (the FED file's name and text), joined, dropped (why)
//   /F/objects/CLASS            register, update, delete of instances of object class CLASS (qualified name)
//   /F/interactions/CLASS       the interactions of class CLASS
//   /F/hlacore/requests         every other request a federate made, as its wire message's fields
//   /F/hlacore/refusals         the requests refused with an exception, and why
//   /F/hlacore/grants           timeAdvanceGrant, per federate
//   /F/hlacore/callbacks        every other callback except reflections and received interactions (their
//                               content is their sender's update or interaction)
//
// Requests are recorded before the gateway serves them, so what they cause (a grant, a discovery) comes
// after them. Attribute and parameter values are base64 of their bytes, decodable with hlacore.omt.
//
// Besides the file (or without one), a federation's records go to its taps: the connections of recorder
// federates (python -m hlacore.record, wire::StartRecording), which write the same records into their own
// file.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rti/record/mcap.hpp"
#include "rti/server/outbox.hpp"
#include "rti/wire/codec.hpp"

namespace hlacore {

class Federation;

// Where a recorder federate's connection takes its federation's records.
class RecordTap {
public:
    virtual ~RecordTap() = default;
    // One record; `schema` is the topic's JSON schema the first time this tap gets the topic, "" after.
    virtual void recorded(const std::string& topic, const std::string& schema_name, const std::string& schema,
                          std::uint32_t sequence, std::uint64_t log_ns, const std::string& json) = 0;
    std::set<std::string> topics;  // those it got the schema of
};

class Recorder {
public:
    Recorder() = default;  // records for taps only
    // Records into `path` too: creates (truncates) it; throws std::runtime_error when it cannot.
    explicit Recorder(const std::string& path);
    ~Recorder();

    // From now on `tap` gets the records of `federation`, beginning with its creation (the FOM) and the
    // federates joined so far.
    void attach(const Federation& federation, RecordTap& tap);
    void detach(RecordTap& tap);
    // The federation is being destroyed: forgets what it knew of it.
    void forget(const Federation& federation);
    // Whether anything records `federation`'s events (the file, or a tap of it).
    bool records(const Federation& federation) const { return writer_ || taps_.count(&federation); }

    void created(const Federation& federation);
    void joined(const Federation& federation, FederateHandle federate);
    // The federate's connection ended without a resign (`why`); its resign request is recorded otherwise.
    void dropped(const Federation& federation, FederateHandle federate, const std::string& why);
    // A request of a joined federate as the gateway serves it (Gateway::tap), before it is served: any message of
    // HLACORE_MESSAGES, updates and interactions as views into their frame (recorder.cpp instantiates them).
    template <class M>
    void request(const Federation& federation, FederateHandle from, const M& m);
    // The gateway's answer to a request: a registration's object, or a refusal.
    void answered(const Federation& federation, FederateHandle to, const wire::Message& answer);
    // A callback sent to a federate (Outbox::send: every kind but reflections and received interactions).
    void callback(const Federation& federation, FederateHandle to, const wire::Message& message);

    // Once per turn of the gateway's loop: writes out what waited longer than the flush interval, so that a
    // recording cut short (a killed gateway) still holds all but its last half second.
    void tick();
    bool pending() const { return unflushed_since_ns_ >= 0; }
    // Writes the summary and closes the file (the destructor does it too).
    void close();
    // Empty, or why recording into the file stopped (a write error: the gateway goes on without it); once.
    std::string take_failure() { return std::exchange(failure_, std::string()); }

private:
    // Where a record goes: its topic, the topic's schema, and its channel in the file (0: not written yet).
    enum class TopicKind : std::uint8_t { Federation, Object, Interaction, Requests, Refusals, Callbacks, Grants };
    struct Topic {
        std::string name;
        std::string schema_name;
        std::string schema;
        std::uint16_t channel = 0;
    };
    Topic& topic(const Federation& federation, TopicKind kind, std::uint32_t cls = 0);
    // Writes `json` (an object without its closing brace) on `topic` to the file and `federation`'s taps, or
    // to `only` that tap.
    void write(const Federation& federation, Topic& topic, std::string& json, RecordTap* only = nullptr);
    void write_created(const Federation& federation, RecordTap* only);
    void write_joined(const Federation& federation, FederateHandle federate, RecordTap* only);
    void begin(std::string& json, const Federation& federation, FederateHandle federate) const;
    template <class M>  // UpdateAttributes(View) or DeleteObject
    void record_object_event(const Federation& federation, FederateHandle from, const M& m);
    template <class Values>  // HandleValues, or HandleValueViews into the frame being served
    void record_interaction(const Federation& federation, FederateHandle from, std::uint32_t cls, const Values& values,
                            const std::string& tag, const wire::OptionalTime& time, const wire::Handles* regions);
    // A request, refusal or callback: `key` names the wire message, "fields" holds its fields.
    void record_message(const Federation& federation, FederateHandle federate, TopicKind kind, const char* key,
                        const wire::Message& message);
    template <class M>
    void record_fields(const Federation& federation, FederateHandle federate, TopicKind kind, const char* key,
                       const M& m);

    std::unique_ptr<mcap::Writer> writer_;
    std::map<const Federation*, std::vector<RecordTap*>> taps_;
    std::map<std::tuple<const Federation*, TopicKind, std::uint32_t>, Topic> topics_;
    std::uint32_t sequence_ = 0;
    std::int64_t unflushed_since_ns_ = -1;
    std::string failure_;
    std::string json_;  // reused for each message
};

// What a federation's outbox hands the recorder: the callbacks it sends (see Recorder::callback).
class FederationRecording : public CallbackRecorder {
public:
    FederationRecording(Recorder& recorder, const Federation& federation) : recorder_(recorder), federation_(federation) {}
    void callback(FederateHandle to, const wire::Message& message) override {
        recorder_.callback(federation_, to, message);
    }

private:
    Recorder& recorder_;
    const Federation& federation_;
};

}  // namespace hlacore
