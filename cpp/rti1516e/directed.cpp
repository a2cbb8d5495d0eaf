// HLA 4's directed interactions (IEEE 1516.1-2025 §5.6-5.13, §6.14), not of IEEE 1516-2010: the extension the
// Federate Protocol's door calls, one line per service onto the client (rti/client/directed.cpp).
#include "ambassador.hpp"

namespace hlacore::rti1516e {

using Receipt = Client::DirectedReceipt;

void Ambassador::publishObjectClassDirectedInteractions(ObjectClassHandle cls, InteractionClassHandleSet const& interactions) {
    guarded([&] { client().publish_directed(core(cls), cores(interactions), true); });
}
void Ambassador::unpublishObjectClassDirectedInteractions(ObjectClassHandle cls) {
    guarded([&] { client().publish_directed(core(cls), {}, false); });
}
void Ambassador::unpublishObjectClassDirectedInteractions(ObjectClassHandle cls, InteractionClassHandleSet const& interactions) {
    guarded([&] {
        if (interactions.empty()) return client().check_directed_declaration(core(cls));  // nothing to withdraw
        client().publish_directed(core(cls), cores(interactions), false);
    });
}
void Ambassador::subscribeObjectClassDirectedInteractions(ObjectClassHandle cls, InteractionClassHandleSet const& interactions,
                                                          bool universally) {
    guarded([&] {
        client().subscribe_directed(core(cls), cores(interactions), universally ? Receipt::Universally : Receipt::Owned);
    });
}
void Ambassador::unsubscribeObjectClassDirectedInteractions(ObjectClassHandle cls) {
    guarded([&] { client().subscribe_directed(core(cls), {}, Receipt::None); });
}
void Ambassador::unsubscribeObjectClassDirectedInteractions(ObjectClassHandle cls, InteractionClassHandleSet const& interactions) {
    guarded([&] {
        if (interactions.empty()) return client().check_directed_declaration(core(cls));  // nothing to withdraw
        client().subscribe_directed(core(cls), cores(interactions), Receipt::None);
    });
}

void Ambassador::sendDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object,
                                         ParameterHandleValueMap const& values, VariableLengthData const& tag) {
    guarded([&] { client().send_directed_interaction(core(cls), core(object), copies(values), bytes(tag), std::nullopt); });
}
MessageRetractionHandle Ambassador::sendDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object,
                                                            ParameterHandleValueMap const& values,
                                                            VariableLengthData const& tag, LogicalTime const& time) {
    return guarded([&] {
        Client& c = client();
        return retraction(c.federate_handle(),
                          c.send_directed_interaction(core(cls), core(object), copies(values), bytes(tag), time_in(time)));
    });
}

}  // namespace hlacore::rti1516e
