// Scene.from_dict: a Python dict with the keys of a scene file becomes TOML text, which then
// goes through the one scene reader (parse_scene), so a dict is checked exactly like a file.
//
// The conversion meets arbitrary Python objects, so it trusts none of them: it looks at types
// through the C API's type checks (which run no Python code), calls Python code only where a
// value must be converted (__index__, __float__, NumPy's tolist) and checks every result, stops
// at a depth no scene needs (the recursion would otherwise overflow the C stack) and at a
// container that contains itself, and refuses integers beyond 64 bits (TOML's integers).
#include "scene_from_dict.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include "core/scene/toml_fields.h"

namespace collide::python {
namespace {

namespace py = pybind11;

// A scene needs 4 levels (particles[0].velocity.maxwell); the scene reader refuses more than 8.
// This limit only has to stop a hostile value before the recursion exhausts the stack.
constexpr int max_depth = 64;

std::string type_name(PyObject* o) { return Py_TYPE(o)->tp_name; }

// str(o), or "?" where str itself raises: used only inside error messages.
std::string safe_str(PyObject* o) {
    py::object s = py::reinterpret_steal<py::object>(PyObject_Str(o));
    const char* text = s ? PyUnicode_AsUTF8(s.ptr()) : nullptr;
    if (!text) {
        PyErr_Clear();
        return "?";
    }
    return shortened(text);
}

// A Python call made for the value at `where` failed (its error is set): raises it again as
// TypeError (for a TypeError) or ValueError naming the key, chained to the original. Errors
// that are no Exception (KeyboardInterrupt, SystemExit) pass through unchanged.
// A key as a path names it: bare where TOML writes it bare, else quoted with escapes, so that
// a path holds no control character (a NUL would cut the message short) and the key "a.b"
// differs from the path a.b.
std::string key_text(const std::string& key) {
    const auto bare = [](unsigned char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    };
    if (!key.empty() && std::all_of(key.begin(), key.end(), bare)) return shortened(key);
    std::string out = "\"";
    for (const unsigned char c : key) {
        if (c == '"' || c == '\\') {
            out += std::string("\\") + char(c);
        } else if (c < 0x20 || c == 0x7f) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += char(c);
        }
    }
    return shortened(out + "\"");
}

// Message text without NULs (from str() of a value): Python reads messages as C strings.
std::string without_nul(std::string text) {
    for (std::size_t at = text.find('\0'); at != std::string::npos; at = text.find('\0', at))
        text.replace(at, 1, "\\x00");
    return text;
}

[[noreturn]] void fail_from_python(const std::string& where, const std::string& doing) {
    py::error_already_set error;
    if (!error.matches(PyExc_Exception)) throw error;
    const std::string message = without_nul(where + ": " + doing + " raised " + type_name(error.value().ptr()) +
                                            ": " + safe_str(error.value().ptr()));
    py::raise_from(error, error.matches(PyExc_TypeError) ? PyExc_TypeError : PyExc_ValueError, message.c_str());
    throw py::error_already_set();
}

[[noreturn]] void fail(PyObject* type, const std::string& where, const std::string& what) {
    PyErr_SetString(type, without_nul(where + ": " + what).c_str());
    throw py::error_already_set();
}

class Converter {
public:
    std::unique_ptr<toml::node> node(PyObject* value, const std::string& where, int depth);
    toml::table table(PyObject* dict, const std::string& where, int depth);

private:
    std::unique_ptr<toml::node> integer(PyObject* value, const std::string& where);
    std::unique_ptr<toml::node> array(PyObject* sequence, const std::string& where, int depth);
    std::unique_ptr<toml::node> via_python(PyObject* value, const std::string& where, int depth);

    // Containers being converted, outermost first: one met again inside itself is a cycle.
    std::vector<PyObject*> open_;
    struct Opened {
        std::vector<PyObject*>& open;
        ~Opened() { open.pop_back(); }
    };
    Opened enter(PyObject* container, const std::string& where, int depth) {
        if (depth > max_depth)
            fail(PyExc_ValueError, where, "nested more than " + std::to_string(max_depth) +
                                              " levels deep (a scene needs 4): expected a scene's tables and arrays");
        if (std::find(open_.begin(), open_.end(), container) != open_.end())
            fail(PyExc_ValueError, where, "a " + type_name(container) + " that contains itself has no TOML form");
        open_.push_back(container);
        return Opened{open_};
    }
};

// Integers must fit TOML's signed 64 bits; a bigger one is refused, never wrapped or rounded.
// -2^63 is refused too: toml++'s writer negates an integer to print it, and -(-2^63) has no
// 64-bit form (undefined behaviour, found by UBSan), so the range is symmetric.
std::unique_ptr<toml::node> Converter::integer(PyObject* value, const std::string& where) {
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(value, &overflow);
    if (v == -1 && PyErr_Occurred()) fail_from_python(where, "reading a " + type_name(value));
    if (overflow != 0 || v == std::numeric_limits<long long>::min()) {
        const std::size_t bits = _PyLong_NumBits(value);  // str() of a huge int may itself be refused
        const std::string text = bits <= 256 ? "integer " + safe_str(value) : "an integer of " + std::to_string(bits) + " bits";
        fail(PyExc_ValueError, where, text + " does not fit in 64 bits: expected an integer in [-(2^63 - 1), 2^63 - 1] "
                                             "(TOML's integers)");
    }
    return std::make_unique<toml::value<std::int64_t>>(v);
}

// Lists and tuples, read through a tuple copy: the copy holds its items even if converting one
// of them runs Python code that changes the list.
std::unique_ptr<toml::node> Converter::array(PyObject* sequence, const std::string& where, int depth) {
    const Opened opened = enter(sequence, where, depth);
    py::object items = py::reinterpret_steal<py::object>(PySequence_Tuple(sequence));
    if (!items) fail_from_python(where, "reading a " + type_name(sequence));
    auto out = std::make_unique<toml::array>();
    for (Py_ssize_t k = 0; k < PyTuple_GET_SIZE(items.ptr()); ++k) {
        auto node = this->node(PyTuple_GET_ITEM(items.ptr(), k), where + "[" + std::to_string(k) + "]", depth + 1);
        std::move(*node).visit([&out](auto&& v) { out->push_back(std::move(v)); });
    }
    return out;
}

// Values of other types that stand for a number or an array: NumPy arrays and scalars (as
// their tolist() gives them: nested lists, or a Python bool, int, float or str), then any
// integer-like object (__index__) and any real (__float__).
std::unique_ptr<toml::node> Converter::via_python(PyObject* value, const std::string& where, int depth) {
    const std::string type = type_name(value);
    if (type.rfind("numpy.", 0) == 0) {
        const Opened opened = enter(value, where, depth);  // an object array may hold itself
        py::object plain = py::reinterpret_steal<py::object>(PyObject_CallMethod(value, "tolist", nullptr));
        if (!plain) fail_from_python(where, "tolist() of a " + type);
        return node(plain.ptr(), where, depth + 1);
    }
    if (PyIndex_Check(value)) {
        py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value));
        if (!index) fail_from_python(where, "__index__ of a " + type);
        return integer(index.ptr(), where);
    }
    if (Py_TYPE(value)->tp_as_number && Py_TYPE(value)->tp_as_number->nb_float) {
        const double v = PyFloat_AsDouble(value);
        if (v == -1.0 && PyErr_Occurred()) fail_from_python(where, "__float__ of a " + type);
        return std::make_unique<toml::value<double>>(v);
    }
    if (value == Py_None)  // a key's None leaves the key out; in an array there is nothing to leave out
        fail(PyExc_TypeError, where, "None has no TOML form in an array: expected bool, int, float, str, list, tuple or dict");
    fail(PyExc_TypeError, where, "a " + type + " has no TOML form: expected bool, int, float, str, list, tuple or dict");
}

// One Python value as a TOML node. bool before int: Python's True is also an int.
std::unique_ptr<toml::node> Converter::node(PyObject* value, const std::string& where, int depth) {
    if (PyBool_Check(value)) return std::make_unique<toml::value<bool>>(value == Py_True);
    if (PyLong_Check(value)) return integer(value, where);
    if (PyFloat_Check(value)) return std::make_unique<toml::value<double>>(PyFloat_AS_DOUBLE(value));
    if (PyUnicode_Check(value)) {
        Py_ssize_t size = 0;
        const char* text = PyUnicode_AsUTF8AndSize(value, &size);  // fails on lone surrogates
        if (!text) fail_from_python(where, "encoding a str as UTF-8");
        return std::make_unique<toml::value<std::string>>(std::string(text, std::size_t(size)));
    }
    if (PyDict_Check(value)) return std::make_unique<toml::table>(table(value, where, depth));
    if (PyList_Check(value) || PyTuple_Check(value)) return array(value, where, depth);
    return via_python(value, where, depth);
}

// Keys must be str; None values are left out (the key's default applies). The items are read
// into a list first, for the same reason as array().
toml::table Converter::table(PyObject* dict, const std::string& where, int depth) {
    const Opened opened = enter(dict, where.empty() ? "the dict" : where, depth);
    py::object items = py::reinterpret_steal<py::object>(PyDict_Items(dict));
    if (!items) fail_from_python(where, "reading a dict");
    toml::table out;
    for (Py_ssize_t k = 0; k < PyList_GET_SIZE(items.ptr()); ++k) {
        PyObject* item = PyList_GET_ITEM(items.ptr(), k);
        PyObject* key = PyTuple_GET_ITEM(item, 0);
        PyObject* value = PyTuple_GET_ITEM(item, 1);
        const std::string parent = where.empty() ? "the dict" : where;
        if (!PyUnicode_Check(key))
            fail(PyExc_TypeError, parent, "key " + safe_str(key) + " (type " + type_name(key) + "): keys must be strings");
        Py_ssize_t size = 0;
        const char* utf8 = PyUnicode_AsUTF8AndSize(key, &size);
        if (!utf8) fail_from_python(parent, "encoding a key as UTF-8");
        const std::string name(utf8, std::size_t(size));
        const std::string path = where.empty() ? key_text(name) : where + "." + key_text(name);
        // No scene key holds a control character, and toml++ 3.3's writer puts a tab or a line
        // break into a table header unquoted, which its own reader then rejects (with an
        // assertion in a debug build): such a key is refused here, by its path.
        if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
            fail(PyExc_ValueError, path, "a key must not hold control characters");
        if (value == Py_None) continue;
        auto node = this->node(value, path, depth + 1);
        std::move(*node).visit([&out, &name](auto&& v) { out.insert_or_assign(name, std::move(v)); });
    }
    return out;
}

}  // namespace

std::unique_ptr<toml::node> toml_value_from_python(const py::handle& value, const std::string& where) {
    return Converter{}.node(value.ptr(), where, 1);
}

std::string toml_text_from_dict(const py::dict& dict) {
    const toml::table table = Converter{}.table(dict.ptr(), "", 0);
    std::ostringstream text;
    text << toml::toml_formatter(table);
    text << "\n";
    return text.str();
}

}  // namespace collide::python
