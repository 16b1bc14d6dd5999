// Provenance: where a number came from. Every output file carries these key/value pairs so
// that a result can be traced to a commit, a build, a machine, a scene file and a seed.
#pragma once

#include <map>
#include <string>

#include "core/scene/scene.h"
#include "core/solver.h"

namespace collide {

// Build and environment facts: git commit and dirty flag (at build time), compiler, flags,
// build type, library versions (HDF5, GSL, toml++, CLI11, Box2D, OpenCL headers), host name,
// date of the run. Keys are stable; docs/architecture.md lists them.
std::map<std::string, std::string> build_provenance();

// The root attributes of a run's output file (docs/output-format.md): build_provenance(), the
// backend's own provenance (prefixed "backend_"), the backend name, the scene's name, path, full
// text (after its --set overrides, listed in scene_overrides), seed, time step and sub-steps, and
// the command line.
std::map<std::string, std::string> run_provenance(const Scene& scene, const std::string& backend,
                                                  const Solver& solver);

// The command line of this process, as one string (set once by main()).
void set_command_line(int argc, char** argv);
const std::string& command_line();

}  // namespace collide
