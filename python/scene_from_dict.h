// A Python dict with the same keys as a scene file, as TOML text (see scene_from_dict.cpp).
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace collide::python {

// Nested dicts become tables, lists of dicts arrays of tables ([[particles]]), None leaves a
// key out. Throws TypeError (naming the key) for a value with no TOML form.
std::string toml_text_from_dict(const pybind11::dict& dict);

}  // namespace collide::python
