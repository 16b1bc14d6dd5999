// The registry of backends: how the command line, the validation runner, the benchmark and
// the conformance tests find every backend by name without knowing it in advance.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/solver.h"

namespace collide {

struct BackendInfo {
    std::string name;         // "event", "step", ...
    std::string precision;    // "double", "float", "float|double"
    std::string description;  // one line
    // Empty if the backend can run the scene, otherwise the reason it cannot
    // (e.g. box2d has no periodic boundaries). The scene is then left out, not faked.
    std::function<std::optional<std::string>(const Scene&)> supports;
    std::function<std::unique_ptr<Solver>(const BackendOptions&)> create;
    // Whether the backend has an iterative contact solver that takes a suite's `iterations`
    // sweep (option "iterations"). The others run once per sweep instead of repeating
    // identical cases under different names.
    bool sweeps_iterations = false;
    // Whether a suite's `backends = "all"` includes it. `event-plain` is left out: the suites
    // measure every backend against the exact dynamics once (`event`), and the conformance
    // tests hold the plain exact solver against the tuned one. A suite that names it runs it.
    bool in_all = true;
    // Whether the backend is event-driven: it jumps from collision to collision and has no time
    // step dt. `collide explain` (and so the report's energy jumps) looks inside one step, so it
    // refuses such a backend's cases; summary.json records it per backend (`event_driven`).
    bool event_driven = false;
};

// Every backend compiled into this build, in a fixed order (event first: the reference).
// Both functions are defined beside the list itself, in apps/all_backends.cpp (library
// collide_registry), so that linking the registry is all a program needs.
const std::vector<BackendInfo>& all_backends();

// The backend called `name`, or nullptr if this build has none of that name (a backend whose
// library was not found is simply not compiled in).
const BackendInfo* backend_if_built(const std::string& name);
// The backend called `name`; throws std::invalid_argument listing the valid names.
const BackendInfo& find_backend(const std::string& name);

}  // namespace collide
