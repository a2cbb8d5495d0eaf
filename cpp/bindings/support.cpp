// Support services (HLA 1.3 §10): names and handles, answered from the FOM.
#include "bindings/convert.hpp"

namespace hlacore::bindings {

void bind_support(Ambassador& rtia) {
    rtia
        .def("getObjectClassHandle", [](Client& c, const std::string& n) { return ObjectClassHandle{c.object_class_handle(n)}; },
             py::arg("name"),
             "Handle of an object class by qualified or bare name ('ObjectRoot.robot', 'robot'). Raises NameNotFound.")
        .def("getObjectClassName", [](Client& c, ObjectClassHandle h) { return c.object_class_name(h.value); },
             py::arg("objectClass"),
             "Name of an object class, qualified as CERTI does ('robot', 'robot.turtlebot': root classes are not prepended). Raises ObjectClassNotDefined.")
        .def("getAttributeHandle",
             [](Client& c, const std::string& n, ObjectClassHandle cls) { return AttributeHandle{c.attribute_handle(n, cls.value)}; },
             py::arg("name"), py::arg("objectClass"),
             "Handle of an attribute of an object class. Raises ObjectClassNotDefined, NameNotFound.")
        .def("getAttributeName",
             [](Client& c, AttributeHandle a, ObjectClassHandle cls) { return c.attribute_name(a.value, cls.value); },
             py::arg("attribute"), py::arg("objectClass"),
             "Name of an attribute of an object class. Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("getInteractionClassHandle",
             [](Client& c, const std::string& n) { return InteractionClassHandle{c.interaction_class_handle(n)}; },
             py::arg("name"),
             "Handle of an interaction class by name. Raises NameNotFound.")
        .def("getInteractionClassName", [](Client& c, InteractionClassHandle h) { return c.interaction_class_name(h.value); },
             py::arg("interactionClass"),
             "Qualified name of an interaction class. Raises InteractionClassNotDefined.")
        .def("getParameterHandle",
             [](Client& c, const std::string& n, InteractionClassHandle ic) {
                 return ParameterHandle{c.parameter_handle(n, ic.value)};
             }, py::arg("name"), py::arg("interactionClass"),
             "Handle of a parameter of an interaction class. Raises InteractionClassNotDefined, NameNotFound.")
        .def("getParameterName",
             [](Client& c, ParameterHandle p, InteractionClassHandle ic) { return c.parameter_name(p.value, ic.value); },
             py::arg("parameter"), py::arg("interactionClass"),
             "Name of a parameter. Raises InteractionClassNotDefined, InteractionParameterNotDefined.")
        .def("getObjectInstanceHandle",
             [](Client& c, const std::string& n) { return ObjectHandle{c.object_instance_handle(n)}; }, py::arg("name"),
             "Handle of an object known to this federate, by name. Raises ObjectNotKnown.")
        .def("getObjectInstanceName", [](Client& c, ObjectHandle o) { return c.object_instance_name(o.value); },
             py::arg("object"),
             "Name of an object known to this federate. Raises ObjectNotKnown.")
        .def("getObjectClass", [](Client& c, ObjectHandle o) { return ObjectClassHandle{c.object_class_of(o.value)}; },
             py::arg("object"),
             "Class of a known object (for a discovered one, the class it was discovered as). Raises ObjectNotKnown.")
        .def("getRoutingSpaceHandle",
             [](Client& c, const std::string& n) { return SpaceHandle{c.routing_space_handle(n)}; }, py::arg("name"),
             "Handle of a routing space of the FOM. Raises NameNotFound.")
        .def("getRoutingSpaceName", [](Client& c, SpaceHandle s) { return c.routing_space_name(s.value); },
             py::arg("space"),
             "Name of a routing space. Raises SpaceNotDefined.")
        .def("getDimensionHandle",
             [](Client& c, const std::string& n, SpaceHandle s) { return DimensionHandle{c.dimension_handle(n, s.value)}; },
             py::arg("name"), py::arg("space"),
             "Handle of a dimension of a routing space. Raises SpaceNotDefined, NameNotFound.")
        .def("getDimensionName",
             [](Client& c, DimensionHandle d, SpaceHandle s) { return c.dimension_name(d.value, s.value); },
             py::arg("dimension"), py::arg("space"),
             "Name of a dimension. Raises SpaceNotDefined, DimensionNotDefined.")
        .def("getAttributeRoutingSpaceHandle",
             [](Client& c, AttributeHandle a, ObjectClassHandle cls) {
                 return SpaceHandle{c.attribute_routing_space(a.value, cls.value)};
             }, py::arg("attribute"), py::arg("objectClass"),
             "Routing space of an attribute (handle 0 when it has none).")
        .def("getInteractionRoutingSpaceHandle",
             [](Client& c, InteractionClassHandle ic) { return SpaceHandle{c.interaction_routing_space(ic.value)}; },
             py::arg("interactionClass"),
             "Routing space of an interaction class (handle 0 when it has none).")
        .def("_federate_handle", [](Client& c) { return FederateHandle{c.federate_handle()}; });
}

}  // namespace hlacore::bindings
