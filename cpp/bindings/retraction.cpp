// EventRetractionHandle as a plain CPython type: every timestamped reflection and interaction carries a new
// one, and a pybind11 instance (made, registered in pybind11's instance map, unregistered, freed) was 7 % of a
// federate's CPU in the 32-federate lockstep (docs/performance.md). This one is two numbers in a PyObject.
#include "bindings/convert.hpp"

#include <cstddef>
#include <string>

namespace hlacore::bindings {

namespace {

struct RetractionObject {
    PyObject_HEAD
    EventRetractionHandle handle;
};

PyTypeObject* retraction_type = nullptr;  // made once by bind_retraction(), kept for the interpreter's life

const EventRetractionHandle& handle_of(PyObject* self) { return reinterpret_cast<RetractionObject*>(self)->handle; }

PyObject* sending_federate(PyObject* self, void*) { return PyLong_FromUnsignedLong(handle_of(self).sender); }

PyObject* serial(PyObject* self, void*) { return PyLong_FromUnsignedLongLong(handle_of(self).serial); }

PyObject* repr(PyObject* self) {
    const EventRetractionHandle& h = handle_of(self);
    const std::string text = "<rti.EventRetractionHandle=" + std::to_string(h.sender) + ":" + std::to_string(h.serial) + ">";
    return PyUnicode_FromStringAndSize(text.data(), static_cast<Py_ssize_t>(text.size()));
}

Py_hash_t hash(PyObject* self) {
    const EventRetractionHandle& h = handle_of(self);
    const Py_hash_t mixed = static_cast<Py_hash_t>((h.serial * 0x9E3779B97F4A7C15ull) ^ h.sender);
    return mixed == -1 ? -2 : mixed;  // -1 means an error to Python
}

PyObject* compare(PyObject* a, PyObject* b, int op) {
    const EventRetractionHandle* x = retraction_in(a);
    const EventRetractionHandle* y = retraction_in(b);
    if (!x || !y || (op != Py_EQ && op != Py_NE)) Py_RETURN_NOTIMPLEMENTED;
    const bool equal = x->sender == y->sender && x->serial == y->serial;
    return PyBool_FromLong((op == Py_EQ) == equal);
}

PyGetSetDef fields[] = {
    {"sendingFederate", sending_federate, nullptr, "The handle of the federate that sent the message, as an int.", nullptr},
    {"serial", serial, nullptr, "The message's serial number at its sender.", nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};

PyType_Slot slots[] = {
    {Py_tp_doc, const_cast<char*>("Names a timestamped message so that its sender can retract it.")},
    {Py_tp_repr, reinterpret_cast<void*>(repr)},
    {Py_tp_hash, reinterpret_cast<void*>(hash)},
    {Py_tp_richcompare, reinterpret_cast<void*>(compare)},
    {Py_tp_getset, fields},
    {0, nullptr},
};

// Made by the RTI only (Py_TPFLAGS_DISALLOW_INSTANTIATION), as the pybind11 class without a constructor was.
PyType_Spec spec = {"hlacore._core.EventRetractionHandle", sizeof(RetractionObject), 0,
                    Py_TPFLAGS_DEFAULT | Py_TPFLAGS_DISALLOW_INSTANTIATION, slots};

}  // namespace

const EventRetractionHandle* retraction_in(PyObject* object) {
    if (!retraction_type || !PyObject_TypeCheck(object, retraction_type)) return nullptr;
    return &handle_of(object);
}

py::object make_retraction(EventRetractionHandle h) {
    PyObject* made = retraction_type->tp_alloc(retraction_type, 0);
    if (!made) throw py::error_already_set();
    reinterpret_cast<RetractionObject*>(made)->handle = h;
    return py::reinterpret_steal<py::object>(made);
}

void bind_retraction(py::module_& m) {
    retraction_type = reinterpret_cast<PyTypeObject*>(PyType_FromSpec(&spec));
    if (!retraction_type) throw py::error_already_set();
    m.attr("EventRetractionHandle") = py::handle(reinterpret_cast<PyObject*>(retraction_type));
    // The handle an encoding names (hlacore.rti1516e's decodeMessageRetractionHandle); only the RTI makes others.
    m.def("_retraction_handle", [](std::uint32_t sender, std::uint64_t serial) {
        return make_retraction(EventRetractionHandle{sender, serial});
    }, py::arg("sender"), py::arg("serial"), "The EventRetractionHandle of `sender`'s message `serial` (for decoding one).");
}

}  // namespace hlacore::bindings
