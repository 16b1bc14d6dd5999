#include "path_argument.h"

namespace py = pybind11;

namespace collide::python {

std::string path_bytes(py::handle path) {
    const py::object os = py::module_::import("os");
    const py::object native = os.attr("fspath")(path);  // raises TypeError for a bad __fspath__
    const std::string bytes = os.attr("fsencode")(native).cast<py::bytes>();
    const auto nul = bytes.find('\0');
    if (nul == std::string::npos) return bytes;
    const py::object start = native[py::slice(0, 60, 1)];
    throw py::value_error("the path " + py::repr(start).cast<std::string>() +
                          (py::len(native) > 60 ? "..." : "") + " holds a NUL character (at byte " +
                          std::to_string(nul) + "): a file name cannot hold one, and the system would cut "
                          "the path there");
}

}  // namespace collide::python
