#include "validation/record/check_table.h"

namespace collide::validation {
std::vector<std::string> check_names(CheckKind kind) {
    std::vector<std::string> names;
    for (const CheckDefinition& c : check_table)
        if (c.kind == kind) names.push_back(c.name);
    return names;
}

}  // namespace collide::validation
