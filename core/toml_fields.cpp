#include "toml_fields.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "scene_loader.h"

namespace collide {

std::string location(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

// Floats with 15 significant digits: a decimal literal from the file (-0.1) reads back as
// written instead of as its binary neighbour (-0.10000000000000001).
static void write_value(std::ostream& out, const toml::node& n) {
    if (auto f = n.as_floating_point()) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.15g", f->get());
        out << buffer;
    } else if (auto a = n.as_array()) {
        out << "[";
        for (std::size_t i = 0; i < a->size(); ++i) {
            out << (i ? ", " : "");
            write_value(out, *a->get(i));
        }
        out << "]";
    } else {
        n.visit([&out](const auto& v) { out << v; });
    }
}

std::string toml_value_text(const toml::node& n) {
    std::ostringstream out;
    write_value(out, n);
    std::string text = out.str();
    for (char& c : text)
        if (c == '\n') c = ' ';
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

TomlFields::TomlFields(const toml::table& table, std::string path, const std::string& file)
    : table_(table), path_(std::move(path)), file_(file) {}

int TomlFields::line() const { return static_cast<int>(table_.source().begin.line); }

std::string TomlFields::key_name(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TomlFields::fail(std::string_view key, std::string_view expected) const {
    const toml::node* n = table_.get(key);
    if (!n) throw SceneError(location(file_, line()) + key_name(key) + " is missing: expected " + std::string(expected));
    throw SceneError(location(file_, static_cast<int>(n->source().begin.line)) + key_name(key) + " = " +
                     toml_value_text(*n) + ": expected " + std::string(expected));
}

void TomlFields::fail_here(std::string_view what) const {
    throw SceneError(location(file_, line()) + (path_.empty() ? std::string("scene") : path_) + ": " +
                     std::string(what));
}

void TomlFields::require(bool ok, std::string_view key, std::string_view expected) const {
    if (!ok) fail(key, expected);
}

void TomlFields::allow_only(std::initializer_list<std::string_view> keys) const {
    for (const auto& [key, value] : table_) {
        bool known = false;
        for (std::string_view k : keys) known = known || key.str() == k;
        if (known) continue;
        std::string list;
        for (std::string_view k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
        throw SceneError(location(file_, static_cast<int>(value.source().begin.line)) + "unknown key " +
                         key_name(key.str()) + ": expected one of " + list);
    }
}

double TomlFields::number_from(const toml::node& n, std::string_view key) const {
    double v = 0;
    if (auto i = n.as_integer()) v = static_cast<double>(i->get());
    else if (auto f = n.as_floating_point()) v = f->get();
    else fail(key, "a number");
    if (!std::isfinite(v)) fail(key, "a finite number");
    return v;
}

double TomlFields::number(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) fail(key, "a number");
    return number_from(*n, key);
}

double TomlFields::number(std::string_view key, double fallback) const {
    return has(key) ? number(key) : fallback;
}

std::int64_t TomlFields::integer(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n || !n->is_integer()) fail(key, "an integer");
    return n->as_integer()->get();
}

std::int64_t TomlFields::integer(std::string_view key, std::int64_t fallback) const {
    return has(key) ? integer(key) : fallback;
}

bool TomlFields::boolean(std::string_view key, bool fallback) const {
    const toml::node* n = table_.get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(key, "true or false");
    return n->as_boolean()->get();
}

std::string TomlFields::string(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n || !n->is_string()) fail(key, "a string");
    return n->as_string()->get();
}

std::string TomlFields::choice(std::string_view key, std::initializer_list<std::string_view> choices,
                               std::string_view fallback) const {
    std::string expected;
    for (std::string_view c : choices) expected += (expected.empty() ? "\"" : " or \"") + std::string(c) + "\"";
    if (!has(key)) {
        if (fallback.empty()) fail(key, expected);
        return std::string(fallback);
    }
    const toml::node* n = table_.get(key);
    if (!n->is_string()) fail(key, expected);
    const std::string value = n->as_string()->get();
    for (std::string_view c : choices)
        if (value == c) return value;
    fail(key, expected);
}

std::vector<double> TomlFields::numbers(std::string_view key, std::size_t count) const {
    const std::string expected = "an array of " + std::to_string(count) + " finite numbers";
    const toml::node* n = table_.get(key);
    if (!n || !n->is_array() || n->as_array()->size() != count) fail(key, expected);
    std::vector<double> out;
    for (const toml::node& element : *n->as_array()) {
        double v = 0;
        if (auto i = element.as_integer()) v = static_cast<double>(i->get());
        else if (auto f = element.as_floating_point()) v = f->get();
        else fail(key, expected);
        if (!std::isfinite(v)) fail(key, expected);
        out.push_back(v);
    }
    return out;
}

TomlFields TomlFields::table(std::string_view key) const {
    const toml::node* n = table_.get(key);
    // Named as written in the file: [physics], [backend.box2d], [[particles]][1].radius.
    std::string name;
    if (path_.empty()) name.append("[").append(key).append("]");
    else if (path_.front() == '[' && path_.back() == ']' && path_.rfind("[[", 0) != 0)
        name.append(path_, 0, path_.size() - 1).append(".").append(key).append("]");
    else name = key_name(key);
    if (!n || !n->is_table()) fail(key, path_.empty() ? "a table " + name : std::string("a table"));
    return TomlFields(*n->as_table(), name, file_);
}

}  // namespace collide
