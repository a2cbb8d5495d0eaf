// Support services (HLA 1.3 §10): names and handles, answered from the FOM.
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"getObjectClassHandle", "Handle of an object class by qualified or bare name ('ObjectRoot.robot', 'robot'). Raises NameNotFound."},
    {"getObjectClassName", "Name of an object class, qualified as CERTI does ('robot', 'robot.turtlebot': root classes are not prepended). Raises ObjectClassNotDefined."},
    {"getAttributeHandle", "Handle of an attribute of an object class. Raises ObjectClassNotDefined, NameNotFound."},
    {"getAttributeName", "Name of an attribute of an object class. Raises ObjectClassNotDefined, AttributeNotDefined."},
    {"getInteractionClassHandle", "Handle of an interaction class by name. Raises NameNotFound."},
    {"getInteractionClassName", "Qualified name of an interaction class. Raises InteractionClassNotDefined."},
    {"getParameterHandle", "Handle of a parameter of an interaction class. Raises InteractionClassNotDefined, NameNotFound."},
    {"getParameterName", "Name of a parameter. Raises InteractionClassNotDefined, InteractionParameterNotDefined."},
    {"getObjectInstanceHandle", "Handle of an object known to this federate, by name. Raises ObjectNotKnown."},
    {"getObjectInstanceName", "Name of an object known to this federate. Raises ObjectNotKnown."},
    {"getObjectClass", "Class of a known object (for a discovered one, the class it was discovered as). Raises ObjectNotKnown."},
    {"getRoutingSpaceHandle", "Handle of a routing space of the FOM. Raises NameNotFound."},
    {"getRoutingSpaceName", "Name of a routing space. Raises SpaceNotDefined."},
    {"getDimensionHandle", "Handle of a dimension of a routing space. Raises SpaceNotDefined, NameNotFound."},
    {"getDimensionName", "Name of a dimension. Raises SpaceNotDefined, DimensionNotDefined."},
    {"getAttributeRoutingSpaceHandle", "Routing space of an attribute (handle 0 when it has none)."},
    {"getInteractionRoutingSpaceHandle", "Routing space of an interaction class (handle 0 when it has none)."},
};

}  // namespace

void bind_support(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("getObjectClassHandle", query<ObjectClassHandle, std::string>(&Client::object_class_handle),
             py::arg("name"))
        .def("getObjectClassName", query<std::string, ObjectClassHandle>(&Client::object_class_name),
             py::arg("objectClass"))
        .def("getAttributeHandle", query<AttributeHandle, std::string, ObjectClassHandle>(&Client::attribute_handle),
             py::arg("name"), py::arg("objectClass"))
        .def("getAttributeName", query<std::string, AttributeHandle, ObjectClassHandle>(&Client::attribute_name),
             py::arg("attribute"), py::arg("objectClass"))
        .def("getInteractionClassHandle", query<InteractionClassHandle, std::string>(&Client::interaction_class_handle),
             py::arg("name"))
        .def("getInteractionClassName", query<std::string, InteractionClassHandle>(&Client::interaction_class_name),
             py::arg("interactionClass"))
        .def("getParameterHandle", query<ParameterHandle, std::string, InteractionClassHandle>(&Client::parameter_handle),
             py::arg("name"), py::arg("interactionClass"))
        .def("getParameterName", query<std::string, ParameterHandle, InteractionClassHandle>(&Client::parameter_name),
             py::arg("parameter"), py::arg("interactionClass"))
        .def("getObjectInstanceHandle", query<ObjectHandle, std::string>(&Client::object_instance_handle),
             py::arg("name"))
        .def("getObjectInstanceName", query<std::string, ObjectHandle>(&Client::object_instance_name),
             py::arg("object"))
        .def("getObjectClass", query<ObjectClassHandle, ObjectHandle>(&Client::object_class_of), py::arg("object"))
        .def("getRoutingSpaceHandle", query<SpaceHandle, std::string>(&Client::routing_space_handle), py::arg("name"))
        .def("getRoutingSpaceName", query<std::string, SpaceHandle>(&Client::routing_space_name), py::arg("space"))
        .def("getDimensionHandle", query<DimensionHandle, std::string, SpaceHandle>(&Client::dimension_handle),
             py::arg("name"), py::arg("space"))
        .def("_dimension_upper_bound", [](const Client& c, DimensionHandle d, SpaceHandle s) {
            return c.dimension_upper_bound(d.value, s.value);
        })
        .def("getDimensionName", query<std::string, DimensionHandle, SpaceHandle>(&Client::dimension_name),
             py::arg("dimension"), py::arg("space"))
        .def("getAttributeRoutingSpaceHandle", query<SpaceHandle, AttributeHandle, ObjectClassHandle>(&Client::attribute_routing_space),
             py::arg("attribute"), py::arg("objectClass"))
        .def("getInteractionRoutingSpaceHandle", query<SpaceHandle, InteractionClassHandle>(&Client::interaction_routing_space),
             py::arg("interactionClass"))
        .def("_federate_handle", query<FederateHandle>(&Client::federate_handle));
}

}  // namespace hlacore::bindings
