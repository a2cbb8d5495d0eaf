// Data distribution management (HLA 1.3 §9; routing by extent overlap in the gateway, docs/ddm.md).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"createRegion", "Create a region of a routing space (HLA 1.3 §9.2) with one extent [(DimensionHandle, (lower, upper)), ...]: closed ranges within [MIN_EXTENT, MAX_EXTENT]; dimensions not given span the whole axis. The region belongs to this federate. Raises SpaceNotDefined, DimensionNotDefined, InvalidExtents."},
    {"notifyAboutRegionModification", "Apply a region's new extent (HLA 1.3 §9.3): given here in createRegion's form (the dimensions not given span the whole axis), it is used for every message routed from now on. Raises RegionNotKnown, DimensionNotDefined, InvalidExtents."},
    {"deleteRegion", "Delete a region (HLA 1.3 §9.4). Raises RegionNotKnown, RegionInUse (a subscription or an update association uses it)."},
    {"getRegionExtent", "(SpaceHandle, [(DimensionHandle, (lower, upper)), ...]) of a region of this federate, every dimension listed. Raises RegionNotKnown."},
    {"getRegions", "hlacore extension: the RegionHandles of the regions this federate holds, in creation order. After a restore they are the saved regions, so a federate restored in a new process (rtig restarted on its --save-dir) gets handles for them here."},
    {"registerObjectInstanceWithRegion", "registerObjectInstance with update regions [(AttributeHandle, RegionHandle), ...] in place before any subscriber can discover the instance (HLA 1.3 §9.5). Raises ObjectClassNotDefined, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, RegionNotKnown, InvalidRegionContext, ObjectAlreadyRegistered."},
    {"associateRegionForUpdates", "This federate's updates of these attributes of the object reach only the subscribers whose regions overlap `region` (HLA 1.3 §9.6); replaces the attribute's previous update region. Raises ObjectNotKnown, AttributeNotDefined, RegionNotKnown, InvalidRegionContext (an attribute of another routing space)."},
    {"unassociateRegionForUpdates", "The object's attributes associated with `region` go back to the default region, the whole space (HLA 1.3 §9.7). Raises ObjectNotKnown, RegionNotKnown, InvalidRegionContext (not associated)."},
    {"subscribeObjectClassAttributesWithRegion", "Subscribe to attributes of a class through a region (HLA 1.3 §9.8): reflected only when the updater's region overlaps it; replaces the attributes subscribed with this class and region. Raises ObjectClassNotDefined, AttributeNotDefined, RegionNotKnown, InvalidRegionContext."},
    {"unsubscribeObjectClassWithRegion", "End the subscription to a class through a region (HLA 1.3 §9.9). Raises ObjectClassNotDefined, RegionNotKnown, ObjectClassNotSubscribed."},
    {"subscribeInteractionClassWithRegion", "Subscribe to an interaction class through a region (HLA 1.3 §9.10): received when sent without region or with an overlapping one. Raises InteractionClassNotDefined, RegionNotKnown, InvalidRegionContext."},
    {"unsubscribeInteractionClassWithRegion", "End the subscription to an interaction class through a region (HLA 1.3 §9.11). Raises InteractionClassNotDefined, RegionNotKnown, InteractionClassNotSubscribed."},
    {"sendInteractionWithRegion", "Send an interaction that reaches the plain subscribers and those subscribed through a region overlapping `region` (HLA 1.3 §9.12). With a time, returns an EventRetractionHandle. Raises InteractionClassNotDefined, InteractionClassNotPublished, InteractionParameterNotDefined, RegionNotKnown, InvalidRegionContext, InvalidFederationTime."},
    {"requestClassAttributeValueUpdateWithRegion", "Ask the owners to provide the attributes of instances of the class whose update region overlaps `region` (HLA 1.3 §9.13); unassociated attributes are in the whole space. Raises ObjectClassNotDefined, AttributeNotDefined, RegionNotKnown."},
};

// registerObjectInstanceWithRegion: `adds` as in Client::register_object_with_region.
auto register_with_regions(bool adds) {
    return [adds](Client& c, ObjectClassHandle cls, std::vector<std::pair<AttributeHandle, RegionHandle>> pairs,
                  std::optional<std::string> name) {
        std::vector<std::pair<H32, H32>> regions;
        for (const auto& [a, r] : pairs) regions.emplace_back(a.value, r.value);
        H32 h;
        {
            py::gil_scoped_release release;
            h = c.register_object_with_region(cls.value, regions, name.value_or(""), adds);
        }
        return ObjectHandle{h};
    };
}

}  // namespace

void bind_regions(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("createRegion",
             [](Client& c, SpaceHandle space, const PyExtent& extent) {
                 return RegionHandle{c.create_region(space.value, to_extent(extent))};
             }, py::arg("space"), py::arg("extent"))
        .def("notifyAboutRegionModification",
             [](Client& c, RegionHandle r, std::optional<PyExtent> extent) {
                 std::optional<Client::Extent> e;
                 if (extent) e = to_extent(*extent);
                 c.modify_region(r.value, e);
             }, py::arg("region"), py::arg("extent") = py::none())
        .def("deleteRegion", forward<RegionHandle>(&Client::delete_region), py::arg("region"))
        .def("getRegionExtent",
             [](Client& c, RegionHandle r) {
                 auto [space, extent] = c.region_extent(r.value);
                 py::list ranges;
                 for (const auto& range : extent)
                     ranges.append(py::make_tuple(DimensionHandle{range.dimension}, py::make_tuple(range.lower, range.upper)));
                 return py::make_tuple(SpaceHandle{space}, ranges);
             }, py::arg("region"))
        .def("getRegions",
             [](Client& c) {
                 py::list out;
                 for (auto handle : c.regions()) out.append(RegionHandle{handle});
                 return out;
             })
        .def("registerObjectInstanceWithRegion", register_with_regions(false),
             py::arg("objectClass"), py::arg("attributes"), py::arg("objectName") = py::none())
        // IEEE 1516-2010's several regions an attribute, for hlacore.rti1516e: an attribute named with several
        // regions has them all, an association adds to the attribute's regions, an unassociation names its
        // attributes, an interaction goes in any number of regions.
        .def("_register_object_with_regions", register_with_regions(true),
             py::arg("objectClass"), py::arg("attributes"), py::arg("objectName") = py::none())
        .def("_associate_region",
             [](Client& c, RegionHandle r, ObjectHandle object, std::vector<AttributeHandle> attributes) {
                 c.request(wire::AssociateRegion{r.value, object.value, raw(attributes), true});
             }, py::arg("region"), py::arg("object"), py::arg("attributes"))
        .def("_unassociate_region", request<wire::UnassociateRegion, RegionHandle, ObjectHandle, std::vector<AttributeHandle>>(),
             py::arg("region"), py::arg("object"), py::arg("attributes"))
        .def("associateRegionForUpdates", request<wire::AssociateRegion, RegionHandle, ObjectHandle, std::vector<AttributeHandle>>(),
             py::arg("region"), py::arg("object"), py::arg("attributes"))
        .def("unassociateRegionForUpdates", request<wire::UnassociateRegion, RegionHandle, ObjectHandle>(),
             py::arg("region"), py::arg("object"))
        .def("subscribeObjectClassAttributesWithRegion", request<wire::SubscribeObjectClassWithRegion, ObjectClassHandle, RegionHandle, std::vector<AttributeHandle>, bool>(),
             py::arg("objectClass"), py::arg("region"), py::arg("attributes"), py::arg("active") = true)
        .def("unsubscribeObjectClassWithRegion", request<wire::UnsubscribeObjectClassWithRegion, ObjectClassHandle, RegionHandle>(),
             py::arg("objectClass"), py::arg("region"))
        .def("subscribeInteractionClassWithRegion", request<wire::SubscribeInteractionClassWithRegion, InteractionClassHandle, RegionHandle, bool>(),
             py::arg("interactionClass"), py::arg("region"), py::arg("active") = true)
        .def("unsubscribeInteractionClassWithRegion", request<wire::UnsubscribeInteractionClassWithRegion, InteractionClassHandle, RegionHandle>(),
             py::arg("interactionClass"), py::arg("region"))
        .def("sendInteractionWithRegion",
             [](Client& c, InteractionClassHandle ic, py::handle values, RegionHandle r, py::handle tag,
                std::optional<double> time) {
                 auto serial = c.send_interaction_with_region(
                     ic.value, to_handle_values<ParameterHandle>(values, "ParameterHandle"), {r.value}, to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("interactionClass"), py::arg("parameters"), py::arg("region"), py::arg("tag"),
             py::arg("time") = py::none())
        .def("_send_interaction_with_regions",
             [](Client& c, InteractionClassHandle ic, py::handle values, std::vector<RegionHandle> regions,
                py::handle tag, std::optional<double> time) {
                 auto serial = c.send_interaction_with_region(
                     ic.value, to_handle_values<ParameterHandle>(values, "ParameterHandle"), raw(regions), to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("interactionClass"), py::arg("parameters"), py::arg("regions"), py::arg("tag"),
             py::arg("time") = py::none())
        .def("requestClassAttributeValueUpdateWithRegion", request<wire::RequestClassUpdateWithRegion, ObjectClassHandle, std::vector<AttributeHandle>, RegionHandle>(),
             py::arg("objectClass"), py::arg("attributes"), py::arg("region"));
}

}  // namespace hlacore::bindings
