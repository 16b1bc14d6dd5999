// The rules of a [backend.NAME] table that hold before any backend reads it. The scene reader
// applies them to a file's tables and the Python module to its keyword options, so that both
// refuse the same keys with the same words; each backend then checks the meaning of its own
// keys and values when it loads the scene (docs/refusals.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace collide {

// What is expected instead of `key` in [backend.NAME] ("" when the key may appear): the step
// backend has no options at all.
std::string backend_key_problem(std::string_view backend, std::string_view key);

// The text a backend reads for a value: a string as it is, a number or boolean as a scene file
// writes it ("1e-3" becomes "0.001", true "true"); nullopt for an array or table.
std::optional<std::string> backend_value_text(const toml::node& value);

// The words after "expected" for a value backend_value_text refuses.
inline constexpr std::string_view backend_value_expected = "a string, number or boolean";

}  // namespace collide
