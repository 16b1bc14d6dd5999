// Where the program finds the files it ships beside itself (the scene library, the suites, the
// report renderer, the GSD writer): installed, under <prefix>/share/collide/ next to
// <prefix>/bin/collide; run from a build tree, in the source tree it was built from.
#pragma once

#include <string>

namespace collide::cli {

// `relative` is the path in the source tree, e.g. "data/scenes" or "validation/report".
std::string resource_path(const std::string& relative);

}  // namespace collide::cli
