// Declaration management (HLA 1.3 §5): publications, subscriptions and the advisories that follow them.
#include "rti/server/federation.hpp"

namespace hlacore {

using wire::WireError;

namespace {

fom::Handle class_of(fom::Handle published_interaction) { return published_interaction; }
template <class Attributes>
fom::Handle class_of(const std::pair<const fom::Handle, Attributes>& published_class) { return published_class.first; }

}  // namespace

// Start/stop registration and turn interactions on/off follow real subscriber changes (HLA 1.3 §5.10-5.13):
// a published class is relevant when another federate would discover (receive) its instances (interactions).
void Federation::update_advisories() {
    for (auto& [ph, p] : federates_) {
        if (p.declarations.class_relevance) {
            advise<wire::StartRegistration, wire::StopRegistration>(
                ph, p.declarations.published, p.declarations.registration_started,
                [&](const FederateState& g, fom::Handle cls) { return known_class(g, cls) != 0; });
        }
        if (p.declarations.interaction_relevance) {
            advise<wire::TurnInteractionsOn, wire::TurnInteractionsOff>(
                ph, p.declarations.published_interactions, p.declarations.interactions_turned_on,
                [&](const FederateState& g, fom::Handle ic) { return receiving_interaction_class(g, ic) != 0; });
        }
    }
}

template <class On, class Off, class Published, class Receives>
void Federation::advise(FederateHandle ph, const Published& published, std::set<fom::Handle>& announced,
                        Receives receives) {
    std::set<fom::Handle> relevant;
    for (const auto& entry : published) {
        const fom::Handle cls = class_of(entry);
        for (const auto& [gh, g] : federates_) {
            if (gh != ph && receives(g, cls)) {
                relevant.insert(cls);
                break;
            }
        }
    }
    for (fom::Handle cls : relevant)
        if (!announced.count(cls)) outbox_.send(ph, On{cls});
    for (fom::Handle cls : announced)
        if (!relevant.count(cls) && published.count(cls)) outbox_.send(ph, Off{cls});
    announced = std::move(relevant);
}

void Federation::on(FederateHandle from, const wire::PublishObjectClass& m) {
    auto& f = federate(from);
    check_attributes(object_class(m.object_class), m.attributes);
    if (m.attributes.empty()) {
        f.declarations.published.erase(m.object_class);
    } else {
        f.declarations.published[m.object_class] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
    }
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnpublishObjectClass& m) {
    object_class(m.object_class);
    federate(from).declarations.published.erase(m.object_class);
    federate(from).declarations.registration_started.erase(m.object_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SubscribeObjectClass& m) {
    auto& f = federate(from);
    check_attributes(object_class(m.object_class), m.attributes);
    if (m.attributes.empty()) {
        f.declarations.subscribed.erase(m.object_class);
    } else {
        f.declarations.subscribed[m.object_class] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
        discover_all_for(from);
    }
    update_advisories();
}

// IEEE 1516-2010: the update rate of the federate's subscriptions of the class, from its next one on.
void Federation::on(FederateHandle from, const wire::SubscriptionRate& m) {
    auto& f = federate(from);
    object_class(m.object_class);
    const fom::UpdateRate* rate = m.designator.empty() ? nullptr : fom_.find_update_rate(m.designator);
    if (!m.designator.empty() && !rate) throw WireError("no update rate is named '" + m.designator + "'");
    if (rate && !f.rates) f.rates.emplace();
    if (f.rates) f.rates->set(m.object_class, rate ? rate->rate : 0);
}

void Federation::on(FederateHandle from, const wire::UnsubscribeObjectClass& m) {
    object_class(m.object_class);
    federate(from).declarations.subscribed.erase(m.object_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::PublishInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).declarations.published_interactions.insert(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnpublishInteractionClass& m) {
    interaction_class(m.interaction_class);
    auto& f = federate(from);
    f.declarations.published_interactions.erase(m.interaction_class);
    f.declarations.interactions_turned_on.erase(m.interaction_class);
    f.interaction_order.erase(m.interaction_class);
    f.interaction_transport.erase(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SubscribeInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).declarations.subscribed_interactions.insert(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnsubscribeInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).declarations.subscribed_interactions.erase(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SetAdvisorySwitch& m) {
    auto& f = federate(from);
    switch (static_cast<wire::AdvisorySwitch>(m.which)) {
        case wire::AdvisorySwitch::ClassRelevance:
            f.declarations.class_relevance = m.on;
            if (!m.on) f.declarations.registration_started.clear();
            break;
        case wire::AdvisorySwitch::InteractionRelevance:
            f.declarations.interaction_relevance = m.on;
            if (!m.on) f.declarations.interactions_turned_on.clear();
            break;
        case wire::AdvisorySwitch::AttributeRelevance: f.declarations.attribute_relevance = m.on; break;
        case wire::AdvisorySwitch::AttributeScope: f.declarations.attribute_scope = m.on; break;
        default: throw WireError("unknown advisory switch " + std::to_string(m.which));
    }
    count_scope_watchers();
    update_advisories();
}

}  // namespace hlacore
