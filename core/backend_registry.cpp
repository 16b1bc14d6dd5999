#include "backend_registry.h"

#include <stdexcept>

namespace collide {

const BackendInfo& find_backend(const std::string& name) {
    std::string names;
    for (const auto& b : all_backends()) {
        if (b.name == name) return b;
        names += (names.empty() ? "" : ", ") + b.name;
    }
    throw std::invalid_argument("unknown backend '" + name + "'; available: " + names);
}

}  // namespace collide
