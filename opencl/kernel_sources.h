// The OpenCL program text, embedded into the binary at build time (opencl/embed_kernels.cmake
// writes kernel_sources.cpp into the build directory). The pieces come in program order:
// kernels/prelude.cl, physics/contact_law.cl.h, physics/wall_law.cl.h, particle_layout.cl.h, then the
// kernels; the two core headers are the same files the C++ backends compile.
#pragma once

#include <string>
#include <vector>

namespace collide::opencl {

struct KernelSource {
    const char* name;  // path in the source tree, e.g. "physics/contact_law.cl.h"
    const char* text;
};

const std::vector<KernelSource>& kernel_sources();

// All pieces joined into one program text, each preceded by a #line directive so that the
// compiler's build log names the file and line in the source tree.
std::string program_text();

}  // namespace collide::opencl
