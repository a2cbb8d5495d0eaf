// RTIambassador: data distribution management (§9). hlacore's regions have one extent; a region's bounds,
// set on the Region, reach the gateway at notifyAboutRegionModification.
#include "ambassador.hpp"

using namespace hlacore;
using hlacore::hla13::FederateRegion;
using hlacore::hla13::guarded;
using hlacore::hla13::h32;
using hlacore::hla13::handles_of;
using hlacore::hla13::text;

hla13::FederateRegion& RTIambPrivateRefs::known(const RTI::Region& region) {
    const auto* ours = dynamic_cast<const FederateRegion*>(&region);
    const auto it = ours ? regions.find(ours->handle()) : regions.end();
    if (it == regions.end() || it->second != ours)
        throw RTI::RegionNotKnown("not a region this federate's createRegion made (or it was deleted)");
    return *it->second;
}

RTI::Region* RTI::RTIambassador::createRegion(SpaceHandle theSpace, ULong numberOfExtents) {
    return guarded([&]() -> Region* {
        if (numberOfExtents != 1)
            throw RTI::InvalidExtents(("hlacore's regions have one extent, not " + std::to_string(numberOfExtents)).c_str());
        Client& c = privateRefs->client;
        const std::uint32_t handle = c.create_region(h32(static_cast<ULong>(theSpace)), {});  // the whole space
        auto [space, extent] = c.region_extent(handle);
        auto region = std::make_unique<FederateRegion>(handle, space, extent);
        privateRefs->regions[handle] = region.get();
        return region.release();
    });
}

void RTI::RTIambassador::notifyAboutRegionModification(Region& theRegion) {
    guarded([&] {
        FederateRegion& region = privateRefs->known(theRegion);
        privateRefs->client.modify_region(region.handle(), region.extent());
    });
}

void RTI::RTIambassador::deleteRegion(Region* theRegion) {
    guarded([&] {
        if (!theRegion) throw RTI::RegionNotKnown("a null region");
        FederateRegion& region = privateRefs->known(*theRegion);
        privateRefs->client.delete_region(region.handle());
        privateRefs->regions.erase(region.handle());
        delete &region;
    });
}

RTI::ObjectHandle RTI::RTIambassador::registerObjectInstanceWithRegion(ObjectClassHandle theClass, const char* theObject,
                                                                      AttributeHandle theAttributes[],
                                                                      Region* theRegions[], ULong theNumberOfHandles) {
    return guarded([&] {
        std::vector<std::pair<fom::Handle, std::uint32_t>> pairs;
        for (ULong i = 0; i < theNumberOfHandles; ++i) {
            if (!theRegions[i]) throw RTI::RegionNotKnown("a null region");
            pairs.emplace_back(h32(theAttributes[i]), privateRefs->known(*theRegions[i]).handle());
        }
        return ObjectHandle{privateRefs->client.register_object_with_region(h32(theClass), pairs, text(theObject))};
    });
}

RTI::ObjectHandle RTI::RTIambassador::registerObjectInstanceWithRegion(ObjectClassHandle theClass,
                                                                      AttributeHandle theAttributes[],
                                                                      Region* theRegions[], ULong theNumberOfHandles) {
    return registerObjectInstanceWithRegion(theClass, nullptr, theAttributes, theRegions, theNumberOfHandles);
}

void RTI::RTIambassador::associateRegionForUpdates(Region& theRegion, ObjectHandle theObject,
                                                   const AttributeHandleSet& theAttributes) {
    guarded([&] {
        // adds false: the region replaces the attributes' previous one (HLA 1.3 §9.6).
        privateRefs->client.request(wire::AssociateRegion{privateRefs->known(theRegion).handle(), h32(theObject),
                                                          handles_of(theAttributes), false});
    });
}

void RTI::RTIambassador::unassociateRegionForUpdates(Region& theRegion, ObjectHandle theObject) {
    guarded([&] {
        // No attributes named: all of the object's associated with the region (HLA 1.3 §9.7).
        privateRefs->client.request(wire::UnassociateRegion{privateRefs->known(theRegion).handle(), h32(theObject), {}});
    });
}

void RTI::RTIambassador::subscribeObjectClassAttributesWithRegion(ObjectClassHandle theClass, Region& theRegion,
                                                                  const AttributeHandleSet& attributeList,
                                                                  Boolean active) {
    guarded([&] {
        privateRefs->client.request(wire::SubscribeObjectClassWithRegion{
            h32(theClass), privateRefs->known(theRegion).handle(), handles_of(attributeList), active != RTI_FALSE});
    });
}

void RTI::RTIambassador::unsubscribeObjectClassWithRegion(ObjectClassHandle theClass, Region& theRegion) {
    guarded([&] {
        privateRefs->client.request(
            wire::UnsubscribeObjectClassWithRegion{h32(theClass), privateRefs->known(theRegion).handle()});
    });
}

void RTI::RTIambassador::subscribeInteractionClassWithRegion(InteractionClassHandle theClass, Region& theRegion,
                                                             Boolean active) {
    guarded([&] {
        privateRefs->client.request(wire::SubscribeInteractionClassWithRegion{
            h32(theClass), privateRefs->known(theRegion).handle(), active != RTI_FALSE});
    });
}

void RTI::RTIambassador::unsubscribeInteractionClassWithRegion(InteractionClassHandle theClass, Region& theRegion) {
    guarded([&] {
        privateRefs->client.request(
            wire::UnsubscribeInteractionClassWithRegion{h32(theClass), privateRefs->known(theRegion).handle()});
    });
}

RTI::EventRetractionHandle RTI::RTIambassador::sendInteractionWithRegion(InteractionClassHandle theInteraction,
                                                                         const ParameterHandleValuePairSet& theParameters,
                                                                         const FedTime& theTime, const char* theTag,
                                                                         const Region& theRegion) {
    return guarded([&] {
        Client& c = privateRefs->client;
        const std::uint64_t serial = c.send_interaction_with_region(
            h32(theInteraction), hla13::values_of(theParameters), {privateRefs->known(theRegion).handle()}, text(theTag),
            hla13::time_of(theTime));
        return hla13::retraction(c.federate_handle(), serial);
    });
}

void RTI::RTIambassador::sendInteractionWithRegion(InteractionClassHandle theInteraction,
                                                   const ParameterHandleValuePairSet& theParameters, const char* theTag,
                                                   const Region& theRegion) {
    guarded([&] {
        privateRefs->client.send_interaction_with_region(h32(theInteraction), hla13::values_of(theParameters),
                                                         {privateRefs->known(theRegion).handle()}, text(theTag),
                                                         std::nullopt);
    });
}

void RTI::RTIambassador::requestClassAttributeValueUpdateWithRegion(ObjectClassHandle theClass,
                                                                    const AttributeHandleSet& theAttributes,
                                                                    const Region& theRegion) {
    guarded([&] {
        privateRefs->client.request(wire::RequestClassUpdateWithRegion{h32(theClass), handles_of(theAttributes),
                                                                       privateRefs->known(theRegion).handle()});
    });
}
