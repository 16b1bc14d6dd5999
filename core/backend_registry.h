// The registry of backends: how the command line, the validation runner, the benchmark and
// the conformance tests find every backend by name without knowing it in advance.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/solver.h"

namespace collide {

// What a solver claims about itself, as data (docs/validation.md, "What a solver claims").
// Every judgement reads these and none tests a backend's name: the limits of its checks
// (validation/record/tolerances.h), whether its statistics are held to a stepping rule's
// predicted bias, whether `collide explain` can look inside one of its steps.
struct BackendInfo {
    std::string name;         // its name in every output
    // The floating-point type it computes in: "double", "float", or "float|double" for a backend
    // that offers both and runs the first-listed one unless asked (a validation case does not ask).
    std::string precision;
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
    // Exact (event-driven): it jumps from collision to collision, resolves every contact at its
    // time and has no time step dt. Its conservation and overlap checks are held to rounding
    // (validation/record/exact_limits.h); `collide explain` (and so the report's energy jumps)
    // looks inside one step, so it refuses such a backend's cases.
    bool exact = false;
    // The stepping rule of docs/stepping-rules.md it implements: "" (none), "collide-first",
    // "integrate-first", or "collide-first|integrate-first" for one that runs the rule the
    // scene's [run] order names. Such a backend's statistics are judged against the rule's
    // predicted bias and its kinetic energy against the rule's energy-loss model.
    std::string rule = "";
    // The quantities its method conserves up to rounding ("momentum", "energy") where the
    // scene's physics conserves them.
    std::vector<std::string> conserves = {};
    // A backend that is neither exact nor a stepping rule may bring limits of its own, derived
    // for its method (tolerance key -> value; box2d: docs/validation.md). Empty: the loose
    // limits of a solver that claims nothing (tolerances.cpp).
    std::vector<std::pair<std::string, double>> limits = {};
    // A sampler (sampling/: `ecmc`, `metropolis`) draws configurations from the equilibrium
    // measure: it has no time and no velocities. The validation planner leaves out its energy,
    // momentum and trajectory checks with that reason (sampler_left_out), holds every sampled
    // configuration's overlaps to the rounding limits of an exact solver (exact_limits.h: a
    // lift leaves a pair touching to rounding), and its length is the scene's [run] chains or
    // sweeps. Samplers are not in a suite's "all" (in_all = false): suites name them.
    bool sampler = false;
    // Whether its cases should use its device one at a time when replayed side by side
    // (an OpenCL device: `collide report` explaining energy jumps).
    bool one_device = false;

    bool stepping_rule() const { return !rule.empty(); }
    // Why a check that reads time or velocities (energy, momentum, trajectories) does not
    // apply to this backend, or "" when it does.
    std::string sampler_left_out() const {
        return sampler ? "a sampler has no dynamics (no time, no velocities): " + name + " samples configurations" : "";
    }
    bool claims_to_conserve(const std::string& quantity) const {
        return std::find(conserves.begin(), conserves.end(), quantity) != conserves.end();
    }
    // The precision its validation cases run in: the first of `precision` ("float|double": float).
    bool single_precision() const { return precision.rfind("float", 0) == 0; }
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
