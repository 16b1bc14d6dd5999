// Conformance tests: one test body, run on every backend in the registry (OpenMM's pattern of
// tests/TestXxx.h instantiated per platform). A backend that does not support a case's scene
// is skipped with its own stated reason; a new backend joins by being registered.
//
// The few-body cases are data (conformance_cases()): the bodies in test_conformance.cpp check
// each against its exact answer on every backend, and test_exact_solvers.cpp runs every one of
// them on both exact solvers (`event` and `event-plain`) and compares their trajectories.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "core/run_driver.h"

namespace collide::test {

// Relative accuracy expected of a backend on quantities that the exact dynamics conserves
// over a short run. Derived from the backend's arithmetic, not tuned:
//   double backends: ~1e3 roundings of 2.2e-16 -> 1e-12;
//   float backends:  ~1e2 roundings of 6e-8    -> 1e-5;
//   box2d (float):   the cases are isolated binary contacts; one contact is one constraint,
//                    which its sequential-impulse solver solves exactly in the first iteration
//                    (restitution threshold 0), so only float rounding remains -> 1e-5 too
//                    (docs/box2d-baseline.md). Its errors in dense scenes belong to validation.
double conformance_tolerance(const std::string& backend);

// Whether the backend solves the exact hard-disk dynamics (event-driven: the only errors are
// rounding errors), so that positions and collision times have exact expected values. The
// stepped backends meet the same collisions up to O(dt) late.
bool is_exact(const std::string& backend);

// A few-body case with an exact answer: scene (run settings included) and initial state.
struct ConformanceCase {
    std::string name;
    Scene scene;
    ParticleState<double> initial;
};
const std::vector<ConformanceCase>& conformance_cases();
const ConformanceCase& conformance_case(const std::string& name);

class Conformance : public ::testing::TestWithParam<std::string> {
protected:
    const BackendInfo& backend() const { return find_backend(GetParam()); }
    // Skips the test (with the backend's reason) if the backend cannot run the scene.
    bool skip_unless_supported(const Scene& scene) const;
    // The same, and skips stepped backends where the case checks exact event times.
    bool skip_unless_exact(const Scene& scene) const;
    RunResult run(const Scene& scene, const ParticleState<double>& initial) const;
    RunResult run(const ConformanceCase& c) const { return run(c.scene, c.initial); }
    double tolerance() const { return conformance_tolerance(GetParam()); }
};

std::vector<std::string> backend_names();
// A backend's name as a test name ("event-plain" -> "event_plain": gtest allows no '-').
std::string test_name(const std::string& backend);

}  // namespace collide::test
