#include "validation/record/case_spec.h"

#include "external/sha256.h"

namespace collide::validation {

std::string group_id(const CaseSpec& spec) {
    const auto at = spec.id.rfind("__seed");
    return at == std::string::npos ? spec.id : spec.id.substr(0, at);
}

std::string definition_hash(const std::map<std::string, std::string>& parts) {
    std::string text;
    for (const auto& [name, part] : parts) text += name + "=" + part + "\n";
    return external::sha256_hex(text);
}

}  // namespace collide::validation
