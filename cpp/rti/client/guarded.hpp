// A front end's service with its failures translated (cpp/hla13, cpp/rti1516e): `rethrow`, called inside the
// catch block, throws the front end's exception for the one being handled.
#pragma once

namespace hlacore {

template <class Rethrow, class F>
auto guarded_by(Rethrow rethrow, F&& service) -> decltype(service()) {
    try {
        return service();
    } catch (...) {
        rethrow();
        throw;  // not reached: rethrow throws
    }
}

}  // namespace hlacore
