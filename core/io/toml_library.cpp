// toml++ compiled once, here, for the whole project (core/CMakeLists.txt, target collide_toml).
//
// Debian's shared toml++ is built to read and write floating-point numbers through iostreams
// (TOML_FLOAT_CHARCONV 0 under GCC). A case record holds the initial and final state of every
// disk, 10^4 numbers for a 1000-disk case, and through streams it took 15-40 ms to write and as
// long again to read, most of the suite's own overhead. Built here with TOML_FLOAT_CHARCONV 1,
// numbers go through std::to_chars / std::from_chars: the shortest text that reads back to the
// same double, and about five times faster (bench/journal.md). The values are unchanged; only
// their spelling is shorter.
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
