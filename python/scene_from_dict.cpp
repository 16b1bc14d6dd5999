// Scene.from_dict: a Python dict with the keys of a scene file becomes TOML text, which then
// goes through the one scene reader (parse_scene), so a dict is checked exactly like a file.
#include "scene_from_dict.h"

#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

namespace collide::python {
namespace {

namespace py = pybind11;

toml::table to_table(const py::dict& dict, const std::string& where);

// One Python value as a TOML node. bool before int: Python's True is also an int.
std::unique_ptr<toml::node> to_node(const py::handle& value, const std::string& where) {
    if (py::isinstance<py::bool_>(value)) return std::make_unique<toml::value<bool>>(value.cast<bool>());
    if (py::isinstance<py::int_>(value)) return std::make_unique<toml::value<std::int64_t>>(value.cast<std::int64_t>());
    if (py::isinstance<py::float_>(value)) return std::make_unique<toml::value<double>>(value.cast<double>());
    if (py::isinstance<py::str>(value)) return std::make_unique<toml::value<std::string>>(value.cast<std::string>());
    if (py::isinstance<py::dict>(value)) return std::make_unique<toml::table>(to_table(value.cast<py::dict>(), where));
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        auto array = std::make_unique<toml::array>();
        std::size_t k = 0;
        for (const py::handle item : value) {
            auto node = to_node(item, where + "[" + std::to_string(k++) + "]");
            if (auto* t = node->as_table()) array->push_back(std::move(*t));
            else if (auto* a = node->as_array()) array->push_back(std::move(*a));
            else if (auto* i = node->as_integer()) array->push_back(i->get());
            else if (auto* f = node->as_floating_point()) array->push_back(f->get());
            else if (auto* b = node->as_boolean()) array->push_back(b->get());
            else if (auto* s = node->as_string()) array->push_back(s->get());
        }
        return array;
    }
    // NumPy scalars and other numbers: integers through __index__, reals through __float__.
    if (py::hasattr(value, "__index__"))
        return std::make_unique<toml::value<std::int64_t>>(py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr())).cast<std::int64_t>());
    if (py::hasattr(value, "__float__")) return std::make_unique<toml::value<double>>(py::reinterpret_borrow<py::object>(value).cast<double>());
    throw py::type_error(where + ": a " + std::string(py::str(value.get_type().attr("__name__"))) +
                         " has no TOML form: expected bool, int, float, str, list or dict");
}

toml::table to_table(const py::dict& dict, const std::string& where) {
    toml::table table;
    for (const auto& [k, v] : dict) {
        if (!py::isinstance<py::str>(k)) throw py::type_error(where + ": keys must be strings");
        const std::string key = k.cast<std::string>();
        const std::string path = where.empty() ? key : where + "." + key;
        if (v.is_none()) continue;  // None: leave the key out (its default applies)
        auto node = to_node(v, path);
        if (auto* t = node->as_table()) table.insert(key, std::move(*t));
        else if (auto* a = node->as_array()) table.insert(key, std::move(*a));
        else if (auto* i = node->as_integer()) table.insert(key, i->get());
        else if (auto* f = node->as_floating_point()) table.insert(key, f->get());
        else if (auto* b = node->as_boolean()) table.insert(key, b->get());
        else if (auto* s = node->as_string()) table.insert(key, s->get());
    }
    return table;
}

}  // namespace

std::string toml_text_from_dict(const py::dict& dict) {
    std::ostringstream text;
    text << toml::toml_formatter(to_table(dict, ""));
    text << "\n";
    return text.str();
}

}  // namespace collide::python
