// Random scenes with numbers anywhere in double's range (masses, radii, speeds, box, dt from
// about 1e-300 to 1e300), and the property every backend must keep on them: refuse before
// starting with a message that names the quantity, its value and the limit, or run and keep
// the scene's disks intact (finite state, no silent stones, no zeroed velocities).
// docs/refusals.md, "Numbers a backend cannot represent".
#pragma once

#include <cstdint>
#include <string>

#include "core/backend_registry.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::test {

struct ExtremeCase {
    Scene scene;
    ParticleState<double> state;
    std::string summary;  // the magnitudes drawn, for failure messages
};

// Case `index` of the sequence for `seed`: 4 disks in a box [0, L] x [0, L], one step of dt.
// The magnitudes come from 10^[-3, 3], 10^[-30, 30] or 10^[-300, 300] (index % 3), so that
// cases run and cases are refused on every backend.
ExtremeCase extreme_case(std::uint64_t seed, int index);

// What happened to one case on one backend.
struct ExtremeOutcome {
    bool refused = false;    // refused before starting, with a message that names the limit
    std::string violation;   // empty if the property holds, else what broke it
};

ExtremeOutcome run_extreme_case(const BackendInfo& backend, const BackendOptions& options, const ExtremeCase& c);

}  // namespace collide::test
