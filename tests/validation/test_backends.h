// Test doubles for the validation runner: small solvers registered only in these tests, each
// broken in one known way, so that the runner's verdicts can be checked against the fault.
#pragma once

#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "validation/plan/suite.h"

namespace collide::test {

enum class Fault {
    none,          // straight flight with reflecting walls: exact for disks that never meet
    adds_energy,   // scales every velocity by 1.01 at each advance: breaks energy conservation
    throws,        // throws std::runtime_error in advance_to
    crashes,       // calls std::abort() in advance_to
    hangs,         // sleeps far past any time limit
    produces_nan,  // writes NaN into a position
};

BackendInfo test_backend(const std::string& name, Fault fault, const std::string& refuses = "");

// Two disks in a 10 x 10 reflecting box that do not meet during the short run; e = 1.
Scene two_disk_scene(const std::string& name = "two_disks");

// A suite over `scene` with `backends`, seeds 1 and 2, no HDF5 output, short time limit.
validation::Suite test_suite(const Scene& scene, const std::vector<std::string>& backends);

// A fresh, empty directory for one test's output (per process; removed when the process ends).
std::string fresh_output_dir(const std::string& name);

}  // namespace collide::test
