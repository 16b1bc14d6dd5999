// A Python dict with the same keys as a scene file, as TOML text (see scene_from_dict.cpp).
#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

namespace collide::python {

// Nested dicts become tables, lists and tuples arrays (a list of dicts: [[particles]]), NumPy
// arrays and scalars what their tolist() gives, None leaves a key out. Any value the
// conversion refuses, and any Python error raised while reading one (an __index__ that
// raises), becomes a TypeError or ValueError whose text starts with the value's key path,
// e.g. "particles[0].count: ..."; nothing the caller passes can crash the interpreter.
std::string toml_text_from_dict(const pybind11::dict& dict);

// One Python value as a TOML value under the same rules, for the key path `where`.
std::unique_ptr<toml::node> toml_value_from_python(const pybind11::handle& value, const std::string& where);

}  // namespace collide::python
