// What the binding's files share: the typed handles, the conversions between Python values and the wire's,
// and one bind_<group>() per HLA service group, each adding that group's services to RTIAmbassadorBase
// from the file of the same name (the groups of cpp/rti/server and cpp/rti/client). The PyHLA-shaped API
// and its docstrings live in python/hlacore/rti.py, which subclasses RTIAmbassadorBase.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fed_parser/fom.hpp"
#include "rti/client/client.hpp"

namespace py = pybind11;

namespace hlacore::bindings {

using Ambassador = py::class_<Client>;
using H32 = std::uint32_t;

// ---- typed handles: hashable, ordered, never interchangeable ----

template <int Kind>
struct Handle {
    static constexpr int kind = Kind;
    std::uint32_t value;
};
using ObjectClassHandle = Handle<1>;
using AttributeHandle = Handle<2>;
using InteractionClassHandle = Handle<3>;
using ParameterHandle = Handle<4>;
using ObjectHandle = Handle<5>;
using FederateHandle = Handle<6>;
using OrderingHandle = Handle<7>;
using TransportationHandle = Handle<8>;
using SpaceHandle = Handle<9>;
using DimensionHandle = Handle<10>;
using RegionHandle = Handle<11>;  // data distribution management: a region of the federate that created it

// Where a federate gets each kind of handle: the hint of the TypeError for a wrong argument.
constexpr const char* kHandleSources[] = {
    "",
    "getObjectClassHandle(name)",
    "getAttributeHandle(name, objectClass)",
    "getInteractionClassHandle(name)",
    "getParameterHandle(name, interactionClass)",
    "registerObjectInstance, discoverObjectInstance or getObjectInstanceHandle(name)",
    "joinFederationExecution or a callback",
    "getOrderingHandle(name)",
    "getTransportationHandle(name)",
    "getRoutingSpaceHandle(name)",
    "getDimensionHandle(name, space)",
    "createRegion",
};

// A PyHLA federate passes integers where hlacore's handles are typed; pybind11 would answer with the
// signature dump of "incompatible function arguments". This names what was expected, what came and where
// such a handle comes from.
[[noreturn]] void throw_wrong_handle(const char* expected, int kind, py::handle given);

// createRegion's extent, PyHLA's form: [(DimensionHandle, (lower, upper)), ...].
using PyExtent = std::vector<std::pair<DimensionHandle, std::pair<std::int64_t, std::int64_t>>>;
inline Client::Extent to_extent(const PyExtent& ranges) {
    Client::Extent extent;
    for (const auto& [dimension, bounds] : ranges) extent.push_back(Client::Range{dimension.value, bounds.first, bounds.second});
    return extent;
}

// The handle of kind H that a Python object holds, or null when it holds none.
template <class H>
const H* handle_in(PyObject* object) {
    py::detail::make_caster<H> caster;
    if (!caster.load(object, false)) return nullptr;
    return &py::detail::cast_op<const H&>(caster);
}

struct EventRetractionHandle {
    std::uint32_t sender;
    std::uint64_t serial;
};
// Its Python type (bindings/retraction.cpp): the handle a Python object holds, or null; a new object.
const EventRetractionHandle* retraction_in(PyObject* object);
py::object make_retraction(EventRetractionHandle h);
void bind_retraction(py::module_& m);

// Whether a and b are equal handles of kind H; nullopt when either is not one. Equality with anything but a
// handle of the same kind is NotImplemented (so `handle == 4` is False), never the wrong-handle TypeError that
// a handle argument raises; ordering another type is that TypeError.
template <class H>
std::optional<bool> equal_handles(py::handle a, py::handle b) {
    const H* x = handle_in<H>(a.ptr());
    const H* y = x ? handle_in<H>(b.ptr()) : nullptr;
    if (!y) return std::nullopt;
    return x->value == y->value;
}

// __eq__ (equal) and __ne__ as methods, for direct calls such as h.__eq__(x); operators go through the
// type's slot (HandleSlots::compare).
template <class H>
auto handle_equality(bool equal) {
    return [equal](py::handle self, py::handle other) -> py::object {
        const auto same = equal_handles<H>(self, other);
        if (!same) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(*same == equal);
    };
}

// The kind in the high bits: handles of two kinds with one value (never equal) rarely collide.
template <class H>
std::uint64_t handle_hash(const H& h) {
    return (static_cast<std::uint64_t>(H::kind) << 32) | h.value;
}

// Hashing and == / != in the type's slots, so that hash(), == and dict operations (each reflection's values,
// a federate's lookups) do not go through pybind11's calls of __hash__ and __eq__ (about 100 ns of 140 each,
// bench/test_handles.py). The orderings go on to pybind11's methods through the slot the type had.
template <class H>
struct HandleSlots {
    static inline richcmpfunc ordering = nullptr;

    static Py_hash_t hash(PyObject* self) {
        const H* handle = handle_in<H>(self);
        if (!handle) {
            PyErr_SetString(PyExc_TypeError, "not a handle");
            return -1;
        }
        return static_cast<Py_hash_t>(handle_hash(*handle));  // never -1: kind > 0
    }

    static PyObject* compare(PyObject* self, PyObject* other, int op) {
        if (op != Py_EQ && op != Py_NE) {
            if (!ordering) Py_RETURN_NOTIMPLEMENTED;
            return ordering(self, other, op);
        }
        const auto same = equal_handles<H>(self, other);
        if (!same) Py_RETURN_NOTIMPLEMENTED;
        return PyBool_FromLong(*same == (op == Py_EQ));
    }
};

template <class H>
void bind_handle(py::module_& m, const char* name) {
    const std::string repr_prefix = std::string("<rti.") + name + "=";
    py::class_<H> type(m, name, (std::string("An HLA ") + name + "; obtained from the RTI, never constructed.").c_str());
    type
        .def("__eq__", handle_equality<H>(true), py::is_operator())
        .def("__ne__", handle_equality<H>(false), py::is_operator())
        .def("__lt__", [](const H& a, const H& b) { return a.value < b.value; }, py::is_operator())
        .def("__le__", [](const H& a, const H& b) { return a.value <= b.value; }, py::is_operator())
        .def("__gt__", [](const H& a, const H& b) { return a.value > b.value; }, py::is_operator())
        .def("__ge__", [](const H& a, const H& b) { return a.value >= b.value; }, py::is_operator())
        .def("__hash__", [](const H& h) { return handle_hash(h); })
        .def("__int__", [](const H& h) { return h.value; })
        .def("__index__", [](const H& h) { return h.value; })
        .def("__repr__", [repr_prefix](const H& h) { return repr_prefix + std::to_string(h.value) + ">"; })
        .def_static("_from_int", [](std::uint32_t value) { return H{value}; },
                    "The handle numbered `value` (hlacore.rti1516e's decoding of an encoded handle).");
    auto* slots = reinterpret_cast<PyTypeObject*>(type.ptr());
    HandleSlots<H>::ordering = slots->tp_richcompare;
    slots->tp_hash = &HandleSlots<H>::hash;
    slots->tp_richcompare = &HandleSlots<H>::compare;
    PyType_Modified(slots);
}

// ---- value conversions ----

// Tags and labels are bytes on the wire; str goes through UTF-8 with surrogateescape so nothing is lost.
inline std::string to_bytes(const py::handle& value, const char* what) {
    if (PyBytes_Check(value.ptr())) return std::string(PyBytes_AS_STRING(value.ptr()), PyBytes_GET_SIZE(value.ptr()));
    if (PyUnicode_Check(value.ptr())) {
        Py_ssize_t size = 0;
        // UTF-8 kept in the str (made once, often already there): no bytes object per call. A lone surrogate
        // has none, and takes the encoding with surrogateescape below.
        if (const char* utf8 = PyUnicode_AsUTF8AndSize(value.ptr(), &size)) return std::string(utf8, static_cast<std::size_t>(size));
        PyErr_Clear();
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

inline py::str to_str(const std::string& s) {
    return py::reinterpret_steal<py::str>(PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "surrogateescape"));
}

// A mapping's values viewed for one call that encodes them (updateAttributeValues, sendInteraction): bytes
// where they are, kept alive by `keep` (the call may release the GIL while it waits for the gateway); str
// encoded once; other buffers copied, as they may change meanwhile (into `copies`, reserved for all at the
// first so that the views stay valid).
struct ValueViews {
    wire::HandleValueViews views;
    // The values' objects, the first few without a heap block of their own (an update often has one value).
    class Kept {
    public:
        void push_back(py::object value) {
            if (first_count_ < first_.size()) {
                first_[first_count_++] = std::move(value);
            } else {
                more_.push_back(std::move(value));
            }
        }

    private:
        std::array<py::object, 4> first_;
        std::size_t first_count_ = 0;
        std::vector<py::object> more_;
    } keep;
    std::vector<std::string> copies;
};

template <class H>
ValueViews to_value_views(const py::handle& mapping, const char* key_name) {
    if (!PyDict_Check(mapping.ptr()) && !PyMapping_Check(mapping.ptr()))
        throw py::type_error(std::string("a mapping {") + key_name + ": bytes} is required");
    py::dict d = py::reinterpret_borrow<py::object>(mapping).cast<py::dict>();
    ValueViews values;
    values.views.reserve(d.size());
    for (auto item : d) {
        const H* key = handle_in<H>(item.first.ptr());
        if (!key) throw py::type_error(std::string(key_name) + " object required as key");
        const std::uint32_t handle = key->value;
        py::object value = py::reinterpret_borrow<py::object>(item.second);
        if (PyUnicode_Check(value.ptr())) {
            value = py::reinterpret_steal<py::object>(PyUnicode_AsEncodedString(value.ptr(), "utf-8", "surrogateescape"));
            if (!value) throw py::error_already_set();
        }
        if (PyBytes_Check(value.ptr())) {
            values.views.emplace_back(handle, std::string_view(PyBytes_AS_STRING(value.ptr()),
                                                               static_cast<std::size_t>(PyBytes_GET_SIZE(value.ptr()))));
            values.keep.push_back(std::move(value));
        } else {
            if (values.copies.empty()) values.copies.reserve(d.size());
            values.views.emplace_back(handle, values.copies.emplace_back(to_bytes(value, "a value")));
        }
    }
    return values;
}

// The same, copied: for a request that keeps them.
template <class H>
wire::HandleValues to_handle_values(const py::handle& mapping, const char* key_name) {
    const ValueViews values = to_value_views<H>(mapping, key_name);
    return wire::HandleValues(values.views.begin(), values.views.end());
}

template <class H>
std::vector<std::uint32_t> to_handles(const std::vector<H>& handles) {
    std::vector<std::uint32_t> out;
    out.reserve(handles.size());
    for (const auto& h : handles) out.push_back(h.value);
    return out;
}

// Handle objects are immutable values, so callbacks share them: creating a pybind11 instance costs about
// as much as the rest of a reflection's conversion. The caches live as long as the interpreter. The RTI
// numbers each kind of handle from 1 up, so a cache is an array indexed by the value (a hash map's lookup was
// 5 % of a subscriber's CPU), up to kHandleCacheSize values of each kind.
inline constexpr std::uint32_t kHandleCacheSize = 1u << 16;

template <class H>
py::object handle_of(std::uint32_t value) {
    static auto* cache = new std::vector<py::object>();
    if (value >= kHandleCacheSize) return py::cast(H{value});
    if (value >= cache->size()) cache->resize(value + 1);
    py::object& cached = (*cache)[value];
    if (!cached) cached = py::cast(H{value});
    return cached;
}

template <class H>
py::dict to_dict(const wire::HandleValues& values) {
    py::dict d;
    for (const auto& [h, v] : values) d[handle_of<H>(h)] = py::bytes(v.data(), v.size());
    return d;
}

template <class H>
py::tuple to_tuple(const wire::Handles& handles) {
    py::tuple t(handles.size());
    for (std::size_t i = 0; i < handles.size(); ++i) t[i] = py::cast(H{handles[i]});
    return t;
}

// The raw value a client service takes for each typed argument of its Python method.
template <int Kind>
std::uint32_t raw(Handle<Kind> h) {
    return h.value;
}
template <int Kind>
std::vector<std::uint32_t> raw(const std::vector<Handle<Kind>>& handles) {
    return to_handles(handles);
}
inline std::string raw(const py::handle& tag) { return to_bytes(tag, "tag"); }
inline const std::string& raw(const std::string& name) { return name; }
inline const std::vector<std::string>& raw(const std::vector<std::string>& names) { return names; }
inline bool raw(bool flag) { return flag; }
inline std::uint8_t raw(std::uint8_t value) { return value; }

// A Python method whose arguments (typed handles, lists of them, a tag) go to the client service `f` as
// their raw values: the binding of every service that needs no other conversion.
template <class... Py, class... Raw>
auto forward(void (Client::*f)(Raw...)) {
    return [f](Client& c, Py... args) { (c.*f)(raw(args)...); };
}

// A Python method that sends the request M of HLACORE_CLIENT_REQUESTS (wire/message_list.hpp), its fields the
// raw values of the method's arguments in order; Client::request runs the service's check first.
template <class M, class... Py>
auto request() {
    return [](Client& c, Py... args) { c.request(M{raw(args)...}); };
}

// The same for a query answered from the client's state: its result becomes an Out (a typed handle, a name).
template <class Out, class... Py, class Result, class... Raw>
auto query(Result (Client::*f)(Raw...) const) {
    return [f](Client& c, Py... args) { return Out{(c.*f)(raw(args)...)}; };
}

// A timestamped send returns its EventRetractionHandle, an untimed one None (PyHLA).
inline py::object serial_result(std::uint64_t serial, const std::optional<double>& time, const Client& c) {
    if (!time) return py::none();
    return make_retraction({c.federate_handle(), serial});
}

// ---- docstrings ----

// What help() shows for one method. Each service group keeps its docstrings in a table beside its bindings
// (the split pybind11_mkdoc makes): the .def lines map Python names to client methods, the table says what
// they do.
struct Doc {
    const char* name;
    const char* text;
};

// Binds methods with the docstrings of a group's table; a public method missing from it fails the import.
class Documented {
public:
    template <std::size_t N>
    Documented(Ambassador& cls, const Doc (&docs)[N]) : cls_(cls), docs_(docs), count_(N) {}

    template <class F, class... Extra>
    Documented& def(const char* name, F&& f, const Extra&... extra) {
        if (name[0] == '_')
            cls_.def(name, std::forward<F>(f), extra...);
        else
            cls_.def(name, std::forward<F>(f), extra..., text_of(name));
        return *this;
    }

private:
    const char* text_of(const char* name) const {
        for (std::size_t i = 0; i < count_; ++i)
            if (std::strcmp(docs_[i].name, name) == 0) return docs_[i].text;
        throw std::logic_error(std::string("no docstring for RTIAmbassador.") + name);
    }
    Ambassador& cls_;
    const Doc* docs_;
    std::size_t count_;
};

// One Python class per HLA 1.3 exception, all under RTIexception, and the translation of RtiError,
// fom::FedError and wire::WireError into them.
void register_exceptions(py::module_& m);

void bind_federation(Ambassador& rtia);
void bind_sync_points(Ambassador& rtia);
void bind_save_restore(Ambassador& rtia);
void bind_declarations(Ambassador& rtia);
void bind_objects(Ambassador& rtia);
void bind_ownership(Ambassador& rtia);
void bind_time(Ambassador& rtia);
void bind_regions(Ambassador& rtia);
void bind_support(Ambassador& rtia);
void bind_callbacks(Ambassador& rtia);  // tick's machinery: waiting, popping and dispatching callbacks

}  // namespace hlacore::bindings

namespace pybind11::detail {

// Loads an argument of a bound class (a handle, the ambassador itself) from an instance of that class or of
// a Python subclass directly where pybind11 keeps its value. pybind11's own caster looks the class up by
// std::type_index, which hashes the type's name, as it is constructed: for the ambassador and a handle, with a
// handle's hash, that was a fifth of a sender's CPU per update. Anything else (None, another type, an
// instance of two bound classes) goes through pybind11's caster; C++ values to Python always do.
template <class T>
class held_value_caster {
public:
    static constexpr auto name = const_name<T>();
    template <class U>
    using cast_op_type = detail::cast_op_type<U>;

    bool load(handle src, bool convert) {
        if ((value_ = held_value(src.ptr()))) return true;
        type_caster_base<T> caster;
        if (!caster.load(src, convert)) return false;
        value_ = static_cast<T*>(caster);
        return true;
    }

    template <class Source>
    static handle cast(Source&& src, return_value_policy policy, handle parent) {
        return type_caster_base<T>::cast(std::forward<Source>(src), policy, parent);
    }

    operator T*() { return value_; }  // NOLINT: the interface pybind11 expects of a caster
    operator T&() {                   // NOLINT
        if (!value_) throw reference_cast_error();
        return *value_;
    }

private:
    static T* held_value(PyObject* object) {
        static PyTypeObject* bound = nullptr;  // set under the GIL, once the class is registered
        if (!bound) {
            const type_info* info = get_type_info(typeid(T));
            if (!info) return nullptr;
            bound = info->type;
        }
        if (!object || (Py_TYPE(object) != bound && !PyType_IsSubtype(Py_TYPE(object), bound))) return nullptr;
        auto* held = reinterpret_cast<instance*>(object);
        if (!held->simple_layout || !held->simple_holder_constructed) return nullptr;
        return static_cast<T*>(held->simple_value_holder[0]);
    }

    T* value_ = nullptr;
};

template <>
class type_caster<hlacore::Client> : public held_value_caster<hlacore::Client> {};

template <>
class type_caster<hlacore::bindings::EventRetractionHandle> {
public:
    PYBIND11_TYPE_CASTER(hlacore::bindings::EventRetractionHandle, const_name("EventRetractionHandle"));
    bool load(handle source, bool) {
        const auto* held = hlacore::bindings::retraction_in(source.ptr());
        if (held) value = *held;
        return held != nullptr;
    }
    static handle cast(const hlacore::bindings::EventRetractionHandle& h, return_value_policy, handle) {
        return hlacore::bindings::make_retraction(h).release();
    }
};

// Handle arguments: loaded as above, and the typed error above instead of "incompatible function arguments".
// No binding overloads a name, so no later overload is hidden by the throw.
template <int Kind>
class type_caster<hlacore::bindings::Handle<Kind>> : public held_value_caster<hlacore::bindings::Handle<Kind>> {
public:
    bool load(handle source, bool convert) {
        if (held_value_caster<hlacore::bindings::Handle<Kind>>::load(source, convert)) return true;
        if (!convert) return false;
        const auto* registered = get_type_info(typeid(hlacore::bindings::Handle<Kind>));
        hlacore::bindings::throw_wrong_handle(registered ? registered->type->tp_name : "handle", Kind, source);
    }
};
}  // namespace pybind11::detail

namespace hlacore::bindings {
// The client of an ambassador given as its Python object, for a method that needs the object itself too (its
// federate ambassador); read where pybind11 holds it, as an argument's is.
inline Client& client_of(py::handle ambassador) {
    py::detail::make_caster<Client> caster;
    if (!caster.load(ambassador, true)) throw py::type_error("expected an RTIAmbassador");
    return caster;
}
}  // namespace hlacore::bindings
