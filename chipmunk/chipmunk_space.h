// A new cpSpace, with Chipmunk's one-time banner kept off standard output. Debian builds
// libchipmunk with its debug checks on, and its first cpSpaceNew in a process prints
// "Initializing cpSpace - Chipmunk v7.0.3 (Debug Enabled)" with printf: on stdout it would
// land inside output a program or script reads (`collide bench --json`), so the first space
// is made with stdout pointed at stderr.
#pragma once

struct cpSpace;

namespace collide {

cpSpace* new_chipmunk_space();

}  // namespace collide
