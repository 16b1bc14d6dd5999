// Strict reading of one TOML table of a scene file (toml++). Every accessor checks the
// value's type and finiteness; every failure throws SceneError with a message of the form
//   FILE:LINE: KEY = VALUE: expected WHAT
// so a user can go straight to the offending line. Used only by the scene loader.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/scene/scene.h"

namespace collide {

class TomlFields {
public:
    // `path` is how the table is named in messages: "" for the file's top level,
    // "[physics]", "[[particles]][2]", "[[particles]][1].disks[3]", ...
    TomlFields(const toml::table& table, std::string path, const std::string& file);

    // Unknown keys are errors: a misspelt key must never be silently ignored.
    void allow_only(std::initializer_list<std::string_view> keys) const;

    bool has(std::string_view key) const { return table_.contains(key); }
    const toml::node* node(std::string_view key) const { return table_.get(key); }

    // Numbers: TOML integers and floats are both accepted; NaN and infinity are not.
    double number(std::string_view key) const;                  // required
    double number(std::string_view key, double fallback) const; // optional
    std::int64_t integer(std::string_view key) const;
    std::int64_t integer(std::string_view key, std::int64_t fallback) const;
    bool boolean(std::string_view key, bool fallback) const;
    std::string string(std::string_view key) const;
    // A string that must be one of `choices`.
    std::string choice(std::string_view key, std::initializer_list<std::string_view> choices,
                       std::string_view fallback) const;
    // An array of exactly `count` numbers, e.g. box = [xmin, ymin, xmax, ymax].
    std::vector<double> numbers(std::string_view key, std::size_t count) const;
    // A sub-table (inline or not), read with the same strictness.
    TomlFields table(std::string_view key) const;

    // Throws `expected` for `key` unless `ok`: for range checks after reading a value.
    void require(bool ok, std::string_view key, std::string_view expected) const;

    [[noreturn]] void fail(std::string_view key, std::string_view expected) const;
    [[noreturn]] void fail_here(std::string_view what) const;  // about the table itself

    std::string key_name(std::string_view key) const;
    const std::string& path() const { return path_; }
    const std::string& file() const { return file_; }
    int line() const;
    const toml::table& raw() const { return table_; }

private:
    double number_from(const toml::node& n, std::string_view key) const;

    const toml::table& table_;
    std::string path_;
    std::string file_;
};

// "FILE:LINE: " (or "FILE: " when the line is unknown): the prefix of every scene error.
std::string location(const std::string& file, int line);
// A value as it appears in TOML, shortened to one line for messages.
std::string toml_value_text(const toml::node& n);
// Text cut to one line of at most 60 characters ("..." marks a cut), for messages.
std::string shortened(std::string_view text);

// toml++ builds and destroys nested tables and arrays recursively, so a hostile file such as
// [a.a.a. ... .a] with 10^5 levels overflows the stack inside the parser, before any check
// of ours can run. No scene needs more than 4 levels: this scans the raw text first and
// throws SceneError at the first table header or key with more than `max_key_parts` dotted
// parts, or the first array or inline table nested deeper than `max_brackets`.
constexpr int max_key_parts = 8;
constexpr int max_brackets = 8;
void check_toml_nesting(std::string_view text, const std::string& file);

// The scene a parsed scene file's table describes, with every check parse_scene makes (for a
// table changed after parsing: core/scene/scene_overrides.h). Nodes keep the lines they were read
// from, so messages point into the file; a node added later has no line.
Scene read_scene_table(const toml::table& root, const std::string& file);

// Follows a dotted path ("particles.0.disks.1.mass": tables by key, arrays by index) from
// `root` to the node it names; `fail(why)` (which must throw) is called where the path leads
// nowhere, and for a path of more than max_key_parts parts (check_path_depth). With
// `add_tables`, a missing key on the way becomes an empty table.
using TomlPathFail = std::function<void(const std::string&)>;
// The bound a scene file's keys have (max_key_parts), for the dotted paths of `--set`,
// Scene.with_overrides and a suite's `set`: a path of 150,000 parts would add as many nested
// tables, which toml++ destroys recursively (a stack overflow). Calls `fail` beyond it.
void check_path_depth(const std::string& path, const TomlPathFail& fail);
toml::node* find_toml_path(toml::table& root, const std::string& path, const TomlPathFail& fail,
                           bool add_tables = false);

// `original` with its table changed to `root`: read again with every scene rule (messages name
// original's file), the changed TOML as source_text, original's name and source_path.
Scene scene_from_changed_table(const toml::table& root, const Scene& original);

}  // namespace collide
