// The HLA 1.3 exception classes of _core and the translation of C++ errors into them (convert.hpp).
#include "bindings/convert.hpp"

#include <array>
#include <iterator>
#include <string>

namespace hlacore::bindings {

namespace {

PyObject* g_base_exception = nullptr;
std::array<PyObject*, static_cast<std::size_t>(ErrorCode::Count)> g_exceptions{};

PyObject* exception_class(ErrorCode code) {
    auto i = static_cast<std::size_t>(code);
    return i < g_exceptions.size() && g_exceptions[i] ? g_exceptions[i] : g_base_exception;
}

// An exception's docstring; hlacore's own say what they mean where their name does not.
std::string exception_doc(ErrorCode code, const char* name) {
    if (base_of(code) == ErrorCode::None) return std::string("The HLA 1.3 exception ") + name + ".";
    return std::string("hlacore's exception ") + name + ", a kind of RTIinternalError" +
           (code == ErrorCode::InconsistentFDD ? ": FOM modules added at join (IEEE 1516-2010) that contradict the "
                                                 "federation's FOM, or a federation created from a .fed."
                                               : ".");
}

}  // namespace

void register_exceptions(py::module_& m) {
    g_base_exception = PyErr_NewExceptionWithDoc("hlacore._core.RTIexception",
                                                 "Base of every HLA 1.3 exception raised by hlacore.", nullptr, nullptr);
    m.add_object("RTIexception", py::handle(g_base_exception));
#define HLACORE_X(name)                                                                                   \
    g_exceptions[static_cast<std::size_t>(ErrorCode::name)] = PyErr_NewExceptionWithDoc(                  \
        "hlacore._core." #name, exception_doc(ErrorCode::name, #name).c_str(),                            \
        exception_class(base_of(ErrorCode::name)), nullptr);                                              \
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
            exc.attr("inconsistent") = dynamic_cast<const fom::InconsistentModules*>(&e) != nullptr;  // merge, not read
            PyErr_SetObject(cls.ptr(), exc.ptr());
        } catch (const wire::WireError& e) {
            PyErr_SetString(exception_class(ErrorCode::RTIinternalError), e.what());
        }
    });
}

void throw_wrong_handle(const char* expected, int kind, py::handle given) {
    std::string name(expected);
    name = name.substr(name.rfind('.') + 1);
    std::string given_repr;
    try {
        given_repr = py::repr(given).cast<std::string>();
    } catch (const py::error_already_set&) {
        given_repr = "?";
    }
    if (given_repr.size() > 60) given_repr = given_repr.substr(0, 57) + "...";
    std::string message = "expected " + name + ", got " + Py_TYPE(given.ptr())->tp_name + " " + given_repr;
    if (PyLong_Check(given.ptr()))
        message += ": hlacore's handles are typed, not integers (docs/pyhla.md)";
    if (kind > 0 && kind < static_cast<int>(std::size(kHandleSources)))
        message += std::string("; get one from ") + kHandleSources[kind];
    throw py::type_error(message);
}

}  // namespace hlacore::bindings
