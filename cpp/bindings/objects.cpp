// Object management (HLA 1.3 §6), with the transport and order changes (§6.19-6.22).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"registerObjectInstance", "Register an instance of a published class (HLA 1.3 §6.2), optionally named (names are unique in the federation); returns its ObjectHandle and makes this federate the owner of the published attributes. Subscribers get discoverObjectInstance. Raises ObjectClassNotDefined, ObjectClassNotPublished, ObjectAlreadyRegistered."},
    {"updateAttributeValues", "Update owned attributes {AttributeHandle: bytes} of an object (HLA 1.3 §6.4); subscribers get reflectAttributeValues with the attributes they subscribed. With a time, returns an EventRetractionHandle. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned."},
    {"sendInteraction", "Send an interaction {ParameterHandle: bytes} (HLA 1.3 §6.6); subscribers get receiveInteraction. With a time, returns an EventRetractionHandle. Raises InteractionClassNotDefined, InteractionClassNotPublished, InteractionParameterNotDefined."},
    {"deleteObjectInstance", "Delete an object this federate may delete (HLA 1.3 §6.8); the others get removeObjectInstance. Raises ObjectNotKnown, DeletePrivilegeNotHeld."},
    {"localDeleteObjectInstance", "Forget an object locally (HLA 1.3 §6.10); it may be discovered again. Raises ObjectNotKnown, FederateOwnsAttributes."},
    {"requestObjectAttributeValueUpdate", "Ask the owners of an object's attributes to update them (HLA 1.3 §6.15); they get provideAttributeValueUpdate. Raises ObjectNotKnown, AttributeNotDefined."},
    {"requestClassAttributeValueUpdate", "Ask the owners of attributes of every instance of a class to update them (HLA 1.3 §6.15). Raises ObjectClassNotDefined, AttributeNotDefined."},
    {"changeAttributeTransportationType", "Change the transportation of owned attributes (HLA 1.3 §6.19) for this federate's later updates of that object; reflectAttributeValues reports it. Forgotten when the attribute changes owner. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, InvalidTransportationHandle."},
    {"changeInteractionTransportationType", "Change the transportation of this federate's later interactions of a published class (HLA 1.3 §6.20), until it unpublishes the class; receiveInteraction reports it. Raises InteractionClassNotDefined, InteractionClassNotPublished, InvalidTransportationHandle."},
    {"changeAttributeOrderType", "Change the order (Receive or Timestamp) of owned attributes (HLA 1.3 §6.21) for this federate's later updates of that object: timestamp order still needs a time, a regulating sender and a constrained receiver; reflectAttributeValues reports the order used. Forgotten when the attribute changes owner. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, InvalidOrderingHandle."},
    {"changeInteractionOrderType", "Change the order (Receive or Timestamp) of this federate's later interactions of a published class (HLA 1.3 §6.22), until it unpublishes the class; receiveInteraction reports the order used. Raises InteractionClassNotDefined, InteractionClassNotPublished, InvalidOrderingHandle."},
};

}  // namespace

void bind_objects(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("registerObjectInstance",
             [](Client& c, ObjectClassHandle cls, std::optional<std::string> name) {
                 H32 h;
                 {
                     py::gil_scoped_release release;
                     h = c.register_object(cls.value, name.value_or(""));
                 }
                 return ObjectHandle{h};
             }, py::arg("objectClass"), py::arg("objectName") = py::none())
        .def("updateAttributeValues",
             [](Client& c, ObjectHandle obj, py::handle values, py::handle tag, std::optional<double> time) {
                 ValueViews attributes = to_value_views<AttributeHandle>(values, "AttributeHandle");
                 return serial_result(c.update_attributes(obj.value, std::move(attributes.views), raw(tag), time), time, c);
             }, py::arg("object"), py::arg("attributes"), py::arg("tag"), py::arg("time") = py::none())
        .def("sendInteraction",
             [](Client& c, InteractionClassHandle ic, py::handle values, py::handle tag, std::optional<double> time) {
                 ValueViews parameters = to_value_views<ParameterHandle>(values, "ParameterHandle");
                 return serial_result(c.send_interaction(ic.value, std::move(parameters.views), raw(tag), time), time, c);
             }, py::arg("interactionClass"), py::arg("parameters"), py::arg("tag"), py::arg("time") = py::none())
        .def("deleteObjectInstance", [](Client& c, ObjectHandle obj, py::handle tag, std::optional<double> time) {
                 return serial_result(c.delete_object(obj.value, raw(tag), time), time, c);
             }, py::arg("object"), py::arg("tag"), py::arg("time") = py::none())
        .def("localDeleteObjectInstance", request<wire::LocalDeleteObject, ObjectHandle>(), py::arg("object"))
        .def("requestObjectAttributeValueUpdate", request<wire::RequestObjectUpdate, ObjectHandle, std::vector<AttributeHandle>>(),
             py::arg("object"), py::arg("attributes"))
        .def("requestClassAttributeValueUpdate", request<wire::RequestClassUpdate, ObjectClassHandle, std::vector<AttributeHandle>>(),
             py::arg("objectClass"), py::arg("attributes"))
        // object instance names (IEEE 1516-2010 §6.2-6.7, for hlacore.rti1516e)
        .def("_reserve_names", request<wire::ReserveObjectNames, bool, std::vector<std::string>>(), py::arg("multiple"),
             py::arg("names"))
        .def("_release_names", request<wire::ReleaseObjectNames, std::vector<std::string>>(), py::arg("names"))
        // transport and order changes (HLA 1.3 §6.19-6.22)
        .def("changeAttributeTransportationType", forward<ObjectHandle, std::vector<AttributeHandle>, TransportationHandle>(&Client::change_attribute_transportation),
             py::arg("object"), py::arg("attributes"), py::arg("transportationHandle"))
        .def("changeInteractionTransportationType", forward<InteractionClassHandle, TransportationHandle>(&Client::change_interaction_transportation),
             py::arg("interactionClass"), py::arg("transportationHandle"))
        .def("changeAttributeOrderType", forward<ObjectHandle, std::vector<AttributeHandle>, OrderingHandle>(&Client::change_attribute_order),
             py::arg("object"), py::arg("attributes"), py::arg("orderingHandle"))
        .def("changeInteractionOrderType", forward<InteractionClassHandle, OrderingHandle>(&Client::change_interaction_order),
             py::arg("interactionClass"), py::arg("orderingHandle"))
        // IEEE 1516-2010's transportation queries, for hlacore.rti1516e
        .def("_query_attribute_transportation", request<wire::QueryAttributeTransportation, ObjectHandle, AttributeHandle>())
        .def("_query_interaction_transportation",
             request<wire::QueryInteractionTransportation, FederateHandle, InteractionClassHandle>());
}

}  // namespace hlacore::bindings
