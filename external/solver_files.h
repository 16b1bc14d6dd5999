// The files an outside solver's command names ("numpy_stepper.py", "./a.out", a data file it
// reads), hashed: the provenance of every case the solver runs names them (solver_files_sha256),
// and the definition of its cases holds them (`validate --resume` reruns a case whose solver
// files changed, validation/plan/case_definition.h).
//
// A file is hashed once per process (keyed by its device, inode, size and modification time):
// the suite runner hashes before the first case, and its case workers are forks of it that
// find the hash made. A file over 64 MiB is hashed in its first 16 MiB only, with its size and
// modification time beside the hash, and the text says so; a 3 GiB data file, hashed whole in
// every solver call, had every case run into its time limit.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "external/external_solver.h"

namespace collide::external {

// Files up to this size are hashed whole; larger ones in their first `hashed_prefix_bytes`.
inline constexpr std::uintmax_t whole_hash_limit_bytes = std::uintmax_t(64) << 20;
inline constexpr std::uintmax_t hashed_prefix_bytes = std::uintmax_t(16) << 20;

// "WORD HEX; WORD HEX" for every word of the command that names a regular file (relative to the
// solver's directory), or the Python class's file; a large file as "WORD sha256 of the first
// 16 MiB HEX, size N bytes, modified 2026-11-27T17:00:00Z". "" when no word names a file.
// `progress` (may be null) gets a line before a file over 16 MiB is read.
std::string solver_files_digest(const ExternalSolverSpec& spec, std::FILE* progress = nullptr);

}  // namespace collide::external
