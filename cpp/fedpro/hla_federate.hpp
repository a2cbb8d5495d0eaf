// The inside of fedpro/federate.hpp: the session's 1516-2010 federate and the conversions between the protocol's
// messages and the C++ API's types. Not a public header.
#pragma once

#include <RTI/FederateAmbassador.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/RTIambassador.h>

#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "fedpro/proto/FederateAmbassador.pb.h"
#include "fedpro/proto/RTIambassador.pb.h"
#include "fedpro/proto/datatypes.pb.h"
#include "fedpro/federate.hpp"
#include "rti1516e/ambassador.hpp"
#include "rti1516e/text.hpp"

namespace hlacore::fedpro {

namespace pb = ::rti1516_2025::fedpro;
namespace api = ::rti1516e;
using namespace ::rti1516e;  // RTI1516E_CALLBACKS names the API's types unqualified

using rti1516e::utf8;
using rti1516e::wide;

// An exception of HLA 4 that the 1516-2010 API has no class for (Unauthorized), with the standard's name.
struct Hla4Exception : std::runtime_error {
    Hla4Exception(std::string name, std::string const& details) : std::runtime_error(details), name(std::move(name)) {}
    std::string name;
};

inline api::VariableLengthData data(std::string const& bytes) { return api::VariableLengthData(bytes.data(), bytes.size()); }
inline std::string bytes(api::VariableLengthData const& d) { return std::string(static_cast<const char*>(d.data()), d.size()); }

class HlaFederate : public Federate, public api::FederateAmbassador, public rti1516e::DirectedInteractionReceiver {
public:
    HlaFederate(std::string gateway, std::string password, std::function<void(std::string_view)> send_callback);
    ~HlaFederate() override;

    std::string call(std::string_view request) override;
    void answered(std::string_view response) override;
    void end() override;
    std::pair<std::string, std::string> member() const override;

#define HLACORE_FEDPRO_DECLARE(ret, name, params, qualifier) ret name params qualifier override;
    RTI1516E_CALLBACKS(HLACORE_FEDPRO_DECLARE)
#undef HLACORE_FEDPRO_DECLARE
    // HLA 4's, from the ambassador's extension.
    void receiveDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object, ParameterHandleValueMap const& values,
                                    VariableLengthData const& tag, TransportationType transport, FederateHandle producer) override;
    void receiveDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object, ParameterHandleValueMap const& values,
                                    VariableLengthData const& tag, TransportationType transport, FederateHandle producer,
                                    LogicalTime const& time, OrderType sent, OrderType received,
                                    MessageRetractionHandle const* retraction) override;

private:
    // calls.cpp: the call, onto the ambassador; throws the ambassador's exceptions.
    void serve(pb::CallRequest const& request, pb::CallResponse& response);
    // Connects when `credentials` (none: HLAnoCredentials) may: Unauthorized otherwise.
    void connect(pb::Credentials const* credentials);
    void declared(pb::RtiConfiguration const& configuration);  // what the client says of itself at connect
    void joined(api::FederateHandle const& handle, std::string const& federation, pb::JoinResult* result);
    void left();
    void list_members(std::string const& federation);
    // The session's ambassador as hlacore's, for HLA 4's services beyond 1516-2010 (not_served otherwise).
    rti1516e::Ambassador& hla4(const char* service) const;
    std::vector<std::wstring> modules(pb::FomModuleSet const& set);
    std::wstring module(pb::FomModule const& m);
    std::wstring module_file(std::string name, std::string const& content);
    static constexpr std::size_t kMaxModuleBytes = 64u << 20;  // a compressed module's file, inflated

    // Handles, from their encodings.
    api::FederateHandle federate(pb::FederateHandle const& h) const { return rti_->decodeFederateHandle(data(h.data())); }
    api::ObjectClassHandle object_class(pb::ObjectClassHandle const& h) const { return rti_->decodeObjectClassHandle(data(h.data())); }
    api::InteractionClassHandle interaction_class(pb::InteractionClassHandle const& h) const {
        return rti_->decodeInteractionClassHandle(data(h.data()));
    }
    api::ObjectInstanceHandle object(pb::ObjectInstanceHandle const& h) const { return rti_->decodeObjectInstanceHandle(data(h.data())); }
    api::AttributeHandle attribute(pb::AttributeHandle const& h) const { return rti_->decodeAttributeHandle(data(h.data())); }
    api::ParameterHandle parameter(pb::ParameterHandle const& h) const { return rti_->decodeParameterHandle(data(h.data())); }
    api::DimensionHandle dimension(pb::DimensionHandle const& h) const { return rti_->decodeDimensionHandle(data(h.data())); }
    api::RegionHandle region(pb::RegionHandle const& h) const { return rti_->decodeRegionHandle(data(h.data())); }
    api::MessageRetractionHandle retraction(pb::MessageRetractionHandle const& h) const {
        return rti_->decodeMessageRetractionHandle(data(h.data()));
    }
    api::AttributeHandleSet attributes(pb::AttributeHandleSet const& s) const;
    api::FederateHandleSet federates(pb::FederateHandleSet const& s) const;
    rti1516e::InteractionClassHandleSet interaction_classes(pb::InteractionClassHandleSet const& s) const;
    api::DimensionHandleSet dimensions(pb::DimensionHandleSet const& s) const;
    api::RegionHandleSet regions(pb::RegionHandleSet const& s) const;
    api::AttributeHandleSetRegionHandleSetPairVector pairs(pb::AttributeSetRegionSetPairList const& l) const;
    api::AttributeHandleValueMap values(pb::AttributeHandleValueMap const& m) const;
    api::ParameterHandleValueMap values(pb::ParameterHandleValueMap const& m) const;
    std::unique_ptr<api::LogicalTime> time(pb::LogicalTime const& t) const;
    std::unique_ptr<api::LogicalTimeInterval> interval(pb::LogicalTimeInterval const& t) const;
    api::TransportationType transportation(pb::TransportationTypeHandle const& h) const;
    api::LogicalTimeFactory& factory() const;

    // callbacks.cpp: a callback out, on the ambassador's thread.
    void send(pb::CallbackRequest const& request);

    std::string gateway_, password_;
    std::function<void(std::string_view)> send_callback_;
    std::unique_ptr<api::RTIambassador> rti_;
    std::unique_ptr<api::LogicalTimeFactory> factory_;
    std::string modules_dir_;  // the FOM modules sent by content, as files the ambassador reads
    bool joined_ = false;
    bool api_2010_ = false;  // the client's configuration says API.version=IEEE 1516-2010 (hla4_name)
    mutable std::mutex member_mutex_;
    std::pair<std::string, std::string> member_;  // the federation and the name it joined as
    // The advisory switches as this federate set them since it joined, from the core's defaults: HLA 4's getters
    // answer from them (Pitch's 1516-2010 adapter asks before each enable and disable). A federation restore that
    // brings back other values is not seen here.
    bool class_relevance_ = true, attribute_relevance_ = false, attribute_scope_ = false, interaction_relevance_ = true;
};

// A callback request of `field`, filled by the statements given (`m`: its message), sent to the federate.
#define HLACORE_FEDPRO_CALLBACK(field, ...)  \
    do {                                     \
        pb::CallbackRequest request;         \
        auto* m = request.mutable_##field(); \
        (void)m;                             \
        __VA_ARGS__;                         \
        send(request);                       \
    } while (0)

// Handles and values out.
template <class M, class H>
void put(M* out, H const& h) {
    out->set_data(bytes(h.encode()));
}
void put(pb::AttributeHandleSet* out, api::AttributeHandleSet const& s);
void put(pb::FederateHandleSet* out, api::FederateHandleSet const& s);
void put(pb::DimensionHandleSet* out, api::DimensionHandleSet const& s);
void put(pb::AttributeHandleValueMap* out, api::AttributeHandleValueMap const& m);
void put(pb::ParameterHandleValueMap* out, api::ParameterHandleValueMap const& m);
void put(pb::LogicalTime* out, api::LogicalTime const& t);
void put(pb::LogicalTimeInterval* out, api::LogicalTimeInterval const& t);
void put(pb::TransportationTypeHandle* out, api::TransportationType type);
inline pb::OrderType order(api::OrderType o) { return o == api::TIMESTAMP ? pb::TIMESTAMP : pb::RECEIVE; }
inline api::OrderType order(pb::OrderType o) { return o == pb::TIMESTAMP ? api::TIMESTAMP : api::RECEIVE; }

}  // namespace hlacore::fedpro
