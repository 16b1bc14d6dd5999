// Every path argument of the module (Scene.from_file, run's out, read_run, export, validate)
// arrives as a PathArgument: a str, bytes or os.PathLike, encoded as the file system encodes
// it (os.fsencode). A NUL character is refused with ValueError before any file is touched:
// the C library ends a path at its first NUL, so 'a\0b' would silently name the file 'a'
// (docs/refusals.md, "From Python").
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace collide::python {

struct PathArgument {
    std::string text;
    operator const std::string&() const { return text; }
};

// The path's bytes, or ValueError naming the path and where its NUL stands.
std::string path_bytes(pybind11::handle path);

}  // namespace collide::python

PYBIND11_NAMESPACE_BEGIN(PYBIND11_NAMESPACE)
PYBIND11_NAMESPACE_BEGIN(detail)

template <>
struct type_caster<collide::python::PathArgument> {
    PYBIND11_TYPE_CASTER(collide::python::PathArgument, const_name("os.PathLike"));

    // Not str, bytes or os.PathLike: false, so that pybind11's TypeError shows the signature.
    bool load(handle src, bool) {
        if (!isinstance<str>(src) && !isinstance<bytes>(src) && !hasattr(src, "__fspath__")) return false;
        value.text = collide::python::path_bytes(src);
        return true;
    }
};

PYBIND11_NAMESPACE_END(detail)
PYBIND11_NAMESPACE_END(PYBIND11_NAMESPACE)
