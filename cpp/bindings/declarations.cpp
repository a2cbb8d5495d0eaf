// Declaration management (HLA 1.3 §5).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

void bind_declarations(Ambassador& rtia) {
    rtia
        .def("publishObjectClass",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs) {
                 c.publish_object_class(cls.value, to_handles(attrs));
             }, py::arg("objectClass"), py::arg("attributes"),
             "Publish attributes of an object class (HLA 1.3 §5.2); owned attributes of its instances no longer published are divested unconditionally (privilegeToDelete counts as published with the class). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unpublishObjectClass", [](Client& c, ObjectClassHandle cls) { c.unpublish_object_class(cls.value); },
             py::arg("objectClass"),
             "Stop publishing an object class (HLA 1.3 §5.3); the owned attributes of its instances are divested unconditionally. Raises ObjectClassNotPublished, OwnershipAcquisitionPending.")
        .def("subscribeObjectClassAttributes",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs, bool active) {
                 c.subscribe_object_class(cls.value, to_handles(attrs), active);
             }, py::arg("objectClass"), py::arg("attributes"), py::arg("active") = true,
             "Subscribe to attributes of an object class (HLA 1.3 §5.6); instances of it and its subclasses are discovered (discoverObjectInstance). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unsubscribeObjectClass", [](Client& c, ObjectClassHandle cls) { c.unsubscribe_object_class(cls.value); },
             py::arg("objectClass"),
             "Stop subscribing to an object class (HLA 1.3 §5.7). Raises ObjectClassNotSubscribed.")
        .def("publishInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.publish_interaction_class(ic.value); }, py::arg("interactionClass"),
             "Publish an interaction class (HLA 1.3 §5.4). Raises InteractionClassNotDefined.")
        .def("unpublishInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.unpublish_interaction_class(ic.value); }, py::arg("interactionClass"),
             "Stop publishing an interaction class (HLA 1.3 §5.5). Raises InteractionClassNotPublished.")
        .def("subscribeInteractionClass",
             [](Client& c, InteractionClassHandle ic, bool active) { c.subscribe_interaction_class(ic.value, active); },
             py::arg("interactionClass"), py::arg("active") = true,
             "Subscribe to an interaction class and its subclasses (HLA 1.3 §5.8); leads to receiveInteraction. Raises InteractionClassNotDefined.")
        .def("unsubscribeInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.unsubscribe_interaction_class(ic.value); },
             py::arg("interactionClass"),
             "Stop subscribing to an interaction class (HLA 1.3 §5.9). Raises InteractionClassNotSubscribed.")
        .def("_set_advisory_switch",
             [](Client& c, int which, bool on) { c.set_advisory_switch(static_cast<wire::AdvisorySwitch>(which), on); });
}

}  // namespace hlacore::bindings
