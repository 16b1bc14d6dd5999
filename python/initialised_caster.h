// Every method and property of collide.Scene and collide.Simulation checks that its object was
// initialised. `Simulation.__new__(Simulation)` makes an object whose C++ value was never
// constructed; pybind11 would hand raw memory to the bound method (a crash: docs/refusals.md,
// "From Python"). The check sits in the one place every call goes through, the conversion of
// the Python object to the C++ one (for `self` and for arguments alike): pybind11 uses the
// type_caster specialised here for each class named at the end of this file. None is refused
// there too: `Simulation.time.fget(None)` handed the method a null pointer.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include "core/scene/scene.h"

namespace collide::python {
class Simulation;
}

PYBIND11_NAMESPACE_BEGIN(PYBIND11_NAMESPACE)
PYBIND11_NAMESPACE_BEGIN(detail)

// pybind11 would not see the fault itself: it allocates raw memory for an object without a
// value (for __init__ to construct into) and hands that out. What tells an initialised object
// is its holder, constructed by __init__ (or when C++ returns the object).
template <typename T>
class initialised_caster : public type_caster_base<T> {
public:
    bool load(handle src, bool convert) {
        if (!src || src.is_none()) return false;  // a method's self as None: a null pointer too
        if (isinstance<T>(src)) {
            const value_and_holder v_h = reinterpret_cast<instance*>(src.ptr())->get_value_and_holder(
                get_type_info(typeid(T)), false);
            if (!v_h || !v_h.holder_constructed())
                throw type_error(str(type::handle_of(src).attr("__name__")).cast<std::string>() +
                                 " object is not initialised (made by __new__ without __init__): create it as "
                                 "docs/python.md shows");
        }
        return type_caster_base<T>::load(src, convert);
    }
};

template <>
class type_caster<collide::Scene> : public initialised_caster<collide::Scene> {};
template <>
class type_caster<collide::python::Simulation> : public initialised_caster<collide::python::Simulation> {};

PYBIND11_NAMESPACE_END(detail)
PYBIND11_NAMESPACE_END(PYBIND11_NAMESPACE)
