// OptionReader: the one typed reader of a backend's options (in the spirit of pbrt-v4's
// ParameterDictionary, GetOneFloat and ReportUnused). A backend's options come from two
// places, as text: the scene's [backend.NAME] table (Scene::backend_options; a scene file,
// `--set`, or Python keywords) and the options its caller gave (BackendOptions::extra: a
// suite's sweep, a benchmark), which win over the table. The backend asks for each key it
// knows with a typed getter (a default, a range), which marks the key as used; then
// refuse_unknown() refuses any key nobody asked for, listing the known ones. Every refusal
// names where the key was set, as the scene reader does (core/scene/toml_fields.h):
//   FILE:LINE: BACKEND: scene 'NAME' [backend.BACKEND] KEY = 'VALUE': expected WHAT
// (the "FILE:LINE: " only for a key read from a scene file; "--set backend.B.K: " for one
// set on the command line; for a caller's option, "option" stands for the table).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/scene.h"

namespace collide {

// A backend option refused: unknown, of the wrong type or out of range.
class BackendOptionError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

class OptionReader {
public:
    // The options of `backend` in `scene` (nullptr: none), and the caller's `given` ones.
    OptionReader(std::string backend, const Scene* scene, const std::map<std::string, std::string>& given = {});

    bool has(std::string_view key) const;
    // Typed getters: the value of `key`, or `fallback` when it is not set. `expected` is what
    // the refusal says after "expected" when the text is not such a value or is out of range.
    std::int64_t get_int(std::string_view key, std::int64_t fallback, std::int64_t min, std::int64_t max,
                         std::string_view expected);
    // A finite number >= min (> min with `above`).
    double get_double(std::string_view key, double fallback, double min, std::string_view expected, bool above = false);
    bool get_bool(std::string_view key, bool fallback);  // "true" or "false"
    std::string get_string(std::string_view key, std::string_view fallback);
    // One of `choices`; the refusal lists them.
    std::string get_choice(std::string_view key, std::initializer_list<std::string_view> choices,
                           std::string_view fallback);
    // The same getters for an option without a default: nullopt when it is not set.
    std::optional<std::int64_t> find_int(std::string_view key, std::int64_t min, std::int64_t max,
                                         std::string_view expected);
    std::optional<double> find_double(std::string_view key, double min, std::string_view expected, bool above = false);

    // Throws BackendOptionError for the first key no getter asked for, naming it and listing
    // the keys that were asked for.
    void refuse_unknown() const;
    // Throws BackendOptionError for `key`'s value: "...KEY = 'VALUE': expected WHAT".
    [[noreturn]] void fail(std::string_view key, std::string_view expected) const;

private:
    struct Value {
        std::string text;
        std::string origin;  // "FILE:LINE", "--set backend.B.K", "" (Python, code) or "option"
        bool given = false;  // from the caller, not the scene's table
    };
    const Value* use(std::string_view key);
    // "[ORIGIN: ]BACKEND: scene 'NAME' [backend.BACKEND]" or "BACKEND: option" for a caller's.
    std::string where(const Value* v) const;

    std::string backend_;
    std::string scene_name_;
    std::map<std::string, Value, std::less<>> values_;
    std::vector<std::string> asked_;  // the keys asked for, in the order asked (no repeats)
};

}  // namespace collide
