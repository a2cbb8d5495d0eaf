// Declaration management (HLA 1.3 §5).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"publishObjectClass", "Publish attributes of an object class (HLA 1.3 §5.2); owned attributes of its instances no longer published are divested unconditionally (privilegeToDelete counts as published with the class). Raises ObjectClassNotDefined, AttributeNotDefined."},
    {"unpublishObjectClass", "Stop publishing an object class (HLA 1.3 §5.3); the owned attributes of its instances are divested unconditionally. Raises ObjectClassNotPublished, OwnershipAcquisitionPending."},
    {"subscribeObjectClassAttributes", "Subscribe to attributes of an object class (HLA 1.3 §5.6); instances of it and its subclasses are discovered (discoverObjectInstance). Raises ObjectClassNotDefined, AttributeNotDefined."},
    {"unsubscribeObjectClass", "Stop subscribing to an object class (HLA 1.3 §5.7). Raises ObjectClassNotSubscribed."},
    {"publishInteractionClass", "Publish an interaction class (HLA 1.3 §5.4). Raises InteractionClassNotDefined."},
    {"unpublishInteractionClass", "Stop publishing an interaction class (HLA 1.3 §5.5). Raises InteractionClassNotPublished."},
    {"subscribeInteractionClass", "Subscribe to an interaction class and its subclasses (HLA 1.3 §5.8); leads to receiveInteraction. Raises InteractionClassNotDefined."},
    {"unsubscribeInteractionClass", "Stop subscribing to an interaction class (HLA 1.3 §5.9). Raises InteractionClassNotSubscribed."},
};

}  // namespace

void bind_declarations(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("publishObjectClass", forward<ObjectClassHandle, std::vector<AttributeHandle>>(&Client::publish_object_class),
             py::arg("objectClass"), py::arg("attributes"))
        .def("unpublishObjectClass", forward<ObjectClassHandle>(&Client::unpublish_object_class),
             py::arg("objectClass"))
        .def("subscribeObjectClassAttributes", request<wire::SubscribeObjectClass, ObjectClassHandle, std::vector<AttributeHandle>, bool>(),
             py::arg("objectClass"), py::arg("attributes"), py::arg("active") = true)
        .def("unsubscribeObjectClass", request<wire::UnsubscribeObjectClass, ObjectClassHandle>(),
             py::arg("objectClass"))
        .def("publishInteractionClass", request<wire::PublishInteractionClass, InteractionClassHandle>(),
             py::arg("interactionClass"))
        .def("unpublishInteractionClass", request<wire::UnpublishInteractionClass, InteractionClassHandle>(),
             py::arg("interactionClass"))
        .def("subscribeInteractionClass", request<wire::SubscribeInteractionClass, InteractionClassHandle, bool>(),
             py::arg("interactionClass"), py::arg("active") = true)
        .def("unsubscribeInteractionClass", request<wire::UnsubscribeInteractionClass, InteractionClassHandle>(),
             py::arg("interactionClass"))
        .def("_set_advisory_switch", request<wire::SetAdvisorySwitch, std::uint8_t, bool>())
        // IEEE 1516-2010's update rates, for hlacore.rti1516e
        .def("_subscription_rate", request<wire::SubscriptionRate, ObjectClassHandle, std::string>())
        .def("_update_rate", query<double, std::string>(&Client::update_rate))
        .def("_update_rate_for", query<double, ObjectHandle, AttributeHandle>(&Client::update_rate_for));
}

}  // namespace hlacore::bindings
