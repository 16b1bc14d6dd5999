#include "core/scene/toml_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/scene/scene_loader.h"

namespace collide {

std::string location(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

// Floats with 15 significant digits: a decimal literal from the file (-0.1) reads back as
// written instead of as its binary neighbour (-0.10000000000000001). Strings in double
// quotes, as a user writes them in a scene file.
static void write_value(std::ostream& out, const toml::node& n) {
    if (auto s = n.as_string()) {
        out << '"' << s->get() << '"';
    } else if (auto f = n.as_floating_point()) {
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

std::string shortened(std::string_view text) {
    std::string line(text.substr(0, std::min<std::size_t>(text.size(), 61)));
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    if (text.size() > 60) line = line.substr(0, 57) + "...";
    return line;
}

std::string toml_value_text(const toml::node& n) {
    std::ostringstream out;
    write_value(out, n);
    return shortened(out.str());
}

TomlFields::TomlFields(const toml::table& table, std::string path, const std::string& file)
    : table_(table), path_(std::move(path)), file_(file) {}

int TomlFields::line() const { return static_cast<int>(table_.source().begin.line); }

// Shortened: a hostile file's 10 MB key must not become a 10 MB error message.
std::string TomlFields::key_name(std::string_view key) const {
    return path_.empty() ? shortened(key) : path_ + "." + shortened(key);
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
    std::size_t index = 0;
    for (std::string_view c : choices) {
        const char* separator = index == 0 ? "" : index + 1 == choices.size() ? " or " : ", ";
        expected.append(separator).append("\"").append(c).append("\"");
        ++index;
    }
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

namespace collide {
namespace {

// Index of the last character of the string that opens at text[start] (a quote), counting
// the lines a multi-line string spans. A single-line string ends at the end of its line at
// the latest, and an unterminated one at the end of the text: the parser reports both.
std::size_t end_of_string(std::string_view text, std::size_t start, int& line) {
    const char quote = text[start];
    const std::string triple(3, quote);
    const bool multi_line = text.substr(start, 3) == triple;
    const bool escapes = quote == '"';  // literal strings ('...') have no escapes
    for (std::size_t i = start + (multi_line ? 3 : 1); i < text.size(); ++i) {
        if (text[i] == '\n') {
            if (!multi_line) return i - 1;
            ++line;
        } else if (escapes && text[i] == '\\') {
            if (i + 1 < text.size() && text[i + 1] == '\n') ++line;
            ++i;
        } else if (text[i] == quote && (!multi_line || text.substr(i, 3) == triple)) {
            if (!multi_line) return i;
            std::size_t end = i + 2;  // """a""""" : up to two more quotes belong to the content
            while (end + 1 < text.size() && text[end + 1] == quote && end < i + 4) ++end;
            return end;
        }
    }
    return text.size();
}

}  // namespace

// A small state machine over the raw text that knows just enough TOML to tell keys from
// values: strings and comments are skipped; a key runs from the start of a top-level line,
// or from '{' or ',' inside an inline table, to its '='; a table header runs from '[' at
// the start of a line to ']'. Dots in a key or header separate its parts; '[' in a value
// opens an array and '{' an inline table.
void check_toml_nesting(std::string_view text, const std::string& file) {
    int line = 1;
    std::string open;        // the open arrays '[' and inline tables '{', innermost last
    bool in_key = true;      // reading a key or a table header (else a value)
    bool in_header = false;
    bool line_start = true;  // nothing but whitespace yet on this top-level line
    int key_parts = 1;
    const auto start_key = [&] { in_key = true, in_header = false, key_parts = 1; };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            if (open.empty()) start_key(), line_start = true;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') continue;
        const bool first_on_line = line_start;
        line_start = false;
        if (c == '#') {
            i = std::min(text.find('\n', i), text.size()) - 1;
        } else if (c == '"' || c == '\'') {
            i = end_of_string(text, i, line);
        } else if (in_key) {
            if (c == '[' && first_on_line && open.empty()) in_header = true;
            else if (c == '.' && ++key_parts > max_key_parts)
                throw SceneError(location(file, line) + "a table header or key with more than " +
                                 std::to_string(max_key_parts) + " dotted parts: expected at most " +
                                 std::to_string(max_key_parts) + " (a scene needs 2)");
            else if (c == '=' || (c == ']' && in_header)) in_key = false;
            else if (c == '}' && !open.empty()) open.pop_back(), in_key = false;  // an empty {}
        } else if (c == '[' || c == '{') {
            open.push_back(c);
            if (open.size() > std::size_t(max_brackets))
                throw SceneError(location(file, line) + "arrays or inline tables nested more than " +
                                 std::to_string(max_brackets) + " deep: expected at most " +
                                 std::to_string(max_brackets) + " (a scene needs 2)");
            if (c == '{') start_key();
        } else if ((c == ']' || c == '}') && !open.empty()) {
            open.pop_back();
        } else if (c == ',' && !open.empty() && open.back() == '{') {
            start_key();
        }
    }
}

}  // namespace collide
