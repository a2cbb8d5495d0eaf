// Ownership management (HLA 1.3 §7).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"unconditionalAttributeOwnershipDivestiture", "Give up owned attributes at once (HLA 1.3 §7.2): they become unowned, or go to a federate waiting to acquire them. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned."},
    {"negotiatedAttributeOwnershipDivestiture", "Offer owned attributes (HLA 1.3 §7.3): the federates publishing them get requestAttributeOwnershipAssumption; this federate owns them until attributeOwnershipDivestitureNotification. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, AttributeAlreadyBeingDivested."},
    {"attributeOwnershipAcquisition", "Ask for published attributes (HLA 1.3 §7.7): unowned or divested ones come at once, owned ones after their owner gets requestAttributeOwnershipRelease and releases them; attributeOwnershipAcquisitionNotification tells. Raises ObjectNotKnown, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, FederateOwnsAttributes."},
    {"attributeOwnershipAcquisitionIfAvailable", "Take published attributes that are unowned or being divested (HLA 1.3 §7.8): attributeOwnershipAcquisitionNotification, else attributeOwnershipUnavailable. Raises ObjectNotKnown, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, FederateOwnsAttributes, AttributeAlreadyBeingAcquired."},
    {"attributeOwnershipReleaseResponse", "Release attributes this federate was asked for by requestAttributeOwnershipRelease (HLA 1.3 §7.11); returns the tuple of AttributeHandles actually released (those a federate still waits for), the others stay owned. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, FederateWasNotAskedToReleaseAttribute."},
    {"cancelNegotiatedAttributeOwnershipDivestiture", "Withdraw a negotiated divestiture (HLA 1.3 §7.12). Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, AttributeDivestitureWasNotRequested."},
    {"cancelAttributeOwnershipAcquisition", "Withdraw an attributeOwnershipAcquisition (HLA 1.3 §7.13): confirmAttributeOwnershipAcquisitionCancellation follows for what was still awaited. Raises ObjectNotKnown, AttributeNotDefined, AttributeAlreadyOwned, AttributeAcquisitionWasNotRequested."},
    {"queryAttributeOwnership", "Ask who owns an attribute (HLA 1.3 §7.15): informAttributeOwnership(object, attribute, owner) or attributeIsNotOwned(object, attribute) follows. Raises ObjectNotKnown, AttributeNotDefined."},
    {"isAttributeOwnedByFederate", "Whether this federate owns the attribute (HLA 1.3 §7.17), as of the ownership notifications delivered so far; answered locally. Raises ObjectNotKnown, AttributeNotDefined."},
};

}  // namespace

void bind_ownership(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("unconditionalAttributeOwnershipDivestiture", forward<ObjectHandle, std::vector<AttributeHandle>>(&Client::unconditional_divestiture),
             py::arg("object"), py::arg("attributes"))
        .def("negotiatedAttributeOwnershipDivestiture", forward<ObjectHandle, std::vector<AttributeHandle>, py::handle>(&Client::negotiated_divestiture),
             py::arg("object"), py::arg("attributes"), py::arg("tag"))
        .def("attributeOwnershipAcquisition", forward<ObjectHandle, std::vector<AttributeHandle>, py::handle>(&Client::ownership_acquisition),
             py::arg("object"), py::arg("attributes"), py::arg("tag"))
        .def("attributeOwnershipAcquisitionIfAvailable", forward<ObjectHandle, std::vector<AttributeHandle>>(&Client::ownership_acquisition_if_available),
             py::arg("object"), py::arg("attributes"))
        .def("attributeOwnershipReleaseResponse",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 std::vector<H32> released;
                 {
                     py::gil_scoped_release release;
                     released = c.release_response(obj.value, to_handles(attrs));
                 }
                 return to_tuple<AttributeHandle>(released);
             }, py::arg("object"), py::arg("attributes"))
        .def("cancelNegotiatedAttributeOwnershipDivestiture", request<wire::CancelNegotiatedDivestiture, ObjectHandle, std::vector<AttributeHandle>>(),
             py::arg("object"), py::arg("attributes"))
        .def("cancelAttributeOwnershipAcquisition", request<wire::CancelOwnershipAcquisition, ObjectHandle, std::vector<AttributeHandle>>(),
             py::arg("object"), py::arg("attributes"))
        .def("queryAttributeOwnership", request<wire::QueryOwnership, ObjectHandle, AttributeHandle>(),
             py::arg("object"), py::arg("attribute"))
        .def("isAttributeOwnedByFederate",
             [](Client& c, ObjectHandle obj, AttributeHandle attr) { return c.is_owned(obj.value, attr.value); },
             py::arg("object"), py::arg("attribute"));
}

}  // namespace hlacore::bindings
