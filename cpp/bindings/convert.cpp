// The conversions and exceptions every binding file uses (convert.hpp).
#include "bindings/convert.hpp"

#include <array>

namespace hlacore::bindings {

namespace {

PyObject* g_base_exception = nullptr;
std::array<PyObject*, static_cast<std::size_t>(ErrorCode::Count)> g_exceptions{};

PyObject* exception_class(ErrorCode code) {
    auto i = static_cast<std::size_t>(code);
    return i < g_exceptions.size() && g_exceptions[i] ? g_exceptions[i] : g_base_exception;
}

}  // namespace

void register_exceptions(py::module_& m) {
    g_base_exception = PyErr_NewExceptionWithDoc("hlacore._core.RTIexception",
                                                 "Base of every HLA 1.3 exception raised by hlacore.", nullptr, nullptr);
    m.add_object("RTIexception", py::handle(g_base_exception));
#define HLACORE_X(name)                                                                                   \
    g_exceptions[static_cast<std::size_t>(ErrorCode::name)] =                                             \
        PyErr_NewExceptionWithDoc("hlacore._core." #name, "The HLA 1.3 exception " #name ".", g_base_exception, \
                                  nullptr);                                                               \
    m.add_object(#name, py::handle(g_exceptions[static_cast<std::size_t>(ErrorCode::name)]));
    HLACORE_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const RtiError& e) {
            PyErr_SetString(exception_class(e.code()), e.what());
        } catch (const fom::FedError& e) {
            py::object cls = py::reinterpret_borrow<py::object>(exception_class(ErrorCode::ErrorReadingFED));
            py::object exc = cls(e.what());
            exc.attr("file") = e.file();
            exc.attr("line") = e.line();
            exc.attr("column") = e.column();
            PyErr_SetObject(cls.ptr(), exc.ptr());
        } catch (const wire::WireError& e) {
            PyErr_SetString(exception_class(ErrorCode::RTIinternalError), e.what());
        }
    });
}

// Tags and labels are bytes on the wire; str goes through UTF-8 with surrogateescape so nothing is lost.
std::string to_bytes(const py::handle& value, const char* what) {
    if (PyBytes_Check(value.ptr())) return std::string(PyBytes_AS_STRING(value.ptr()), PyBytes_GET_SIZE(value.ptr()));
    if (PyUnicode_Check(value.ptr())) {
        py::object encoded = py::reinterpret_steal<py::object>(
            PyUnicode_AsEncodedString(value.ptr(), "utf-8", "surrogateescape"));
        if (!encoded) throw py::error_already_set();
        return std::string(PyBytes_AS_STRING(encoded.ptr()), PyBytes_GET_SIZE(encoded.ptr()));
    }
    if (PyObject_CheckBuffer(value.ptr())) {
        py::buffer_info info = py::reinterpret_borrow<py::buffer>(value).request();
        if (info.itemsize * info.size < 0) throw py::value_error("bad buffer");
        return std::string(static_cast<const char*>(info.ptr), static_cast<std::size_t>(info.itemsize * info.size));
    }
    throw py::type_error(std::string(what) + " must be bytes or str, not " + std::string(py::str(py::type::handle_of(value).attr("__name__"))));
}

py::str to_str(const std::string& s) {
    return py::reinterpret_steal<py::str>(PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "surrogateescape"));
}

py::object serial_result(std::uint64_t serial, const std::optional<double>& time, const Client& c) {
    if (!time) return py::none();
    return py::cast(EventRetractionHandle{c.federate_handle(), serial});
}

}  // namespace hlacore::bindings
