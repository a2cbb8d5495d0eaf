// Declaration management (HLA 1.3 §5).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

void bind_declarations(Ambassador& rtia) {
    rtia
        .def("publishObjectClass",
             forward<ObjectClassHandle, std::vector<AttributeHandle>>(&Client::publish_object_class),
             py::arg("objectClass"), py::arg("attributes"),
             "Publish attributes of an object class (HLA 1.3 §5.2); owned attributes of its instances no longer published are divested unconditionally (privilegeToDelete counts as published with the class). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unpublishObjectClass", forward<ObjectClassHandle>(&Client::unpublish_object_class),
             py::arg("objectClass"),
             "Stop publishing an object class (HLA 1.3 §5.3); the owned attributes of its instances are divested unconditionally. Raises ObjectClassNotPublished, OwnershipAcquisitionPending.")
        .def("subscribeObjectClassAttributes",
             forward<ObjectClassHandle, std::vector<AttributeHandle>, bool>(&Client::subscribe_object_class),
             py::arg("objectClass"), py::arg("attributes"), py::arg("active") = true,
             "Subscribe to attributes of an object class (HLA 1.3 §5.6); instances of it and its subclasses are discovered (discoverObjectInstance). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unsubscribeObjectClass", forward<ObjectClassHandle>(&Client::unsubscribe_object_class),
             py::arg("objectClass"),
             "Stop subscribing to an object class (HLA 1.3 §5.7). Raises ObjectClassNotSubscribed.")
        .def("publishInteractionClass",
             forward<InteractionClassHandle>(&Client::publish_interaction_class),
             py::arg("interactionClass"),
             "Publish an interaction class (HLA 1.3 §5.4). Raises InteractionClassNotDefined.")
        .def("unpublishInteractionClass",
             forward<InteractionClassHandle>(&Client::unpublish_interaction_class),
             py::arg("interactionClass"),
             "Stop publishing an interaction class (HLA 1.3 §5.5). Raises InteractionClassNotPublished.")
        .def("subscribeInteractionClass",
             forward<InteractionClassHandle, bool>(&Client::subscribe_interaction_class),
             py::arg("interactionClass"), py::arg("active") = true,
             "Subscribe to an interaction class and its subclasses (HLA 1.3 §5.8); leads to receiveInteraction. Raises InteractionClassNotDefined.")
        .def("unsubscribeInteractionClass",
             forward<InteractionClassHandle>(&Client::unsubscribe_interaction_class),
             py::arg("interactionClass"),
             "Stop subscribing to an interaction class (HLA 1.3 §5.9). Raises InteractionClassNotSubscribed.")
        .def("_set_advisory_switch",
             [](Client& c, int which, bool on) { c.set_advisory_switch(static_cast<wire::AdvisorySwitch>(which), on); });
}

}  // namespace hlacore::bindings
