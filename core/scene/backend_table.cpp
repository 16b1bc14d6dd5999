#include "core/scene/backend_table.h"

#include "core/scene/toml_fields.h"

namespace collide {

std::string backend_key_problem(std::string_view backend, std::string_view /*key*/) {
    // The stepping rules take all their settings from [run] and [physics]; a key here would be
    // silently ignored, which is worse than refused.
    if (backend == "step")
        return "no key here: the step backend has no options (its settings are [run] dt, substeps, order and "
               "the [physics] table)";
    return "";
}

std::optional<std::string> backend_value_text(const toml::node& value) {
    if (value.is_string()) return value.as_string()->get();  // whole: toml_value_text shortens
    if (value.is_number() || value.is_boolean()) return toml_value_text(value);
    return std::nullopt;
}

}  // namespace collide
