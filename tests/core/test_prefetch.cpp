// prefetch_line (core/numerics/prefetch.h): a cache-line request that the compiler cannot delete.
#include "core/numerics/prefetch.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace collide {
namespace {

// A hint only: requesting the lines of an array changes no value.
TEST(PrefetchLine, RequestsChangeNoValue) {
    std::vector<double> values(1000);
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = double(k) * 0.5;
    for (std::size_t k = 0; k < values.size(); k += 7) prefetch_line(&values[k]);
    for (std::size_t k = 0; k < values.size(); ++k) ASSERT_EQ(values[k], double(k) * 0.5) << k;
}

// GCC 12 at -O3 silently deleted __builtin_prefetch calls whose address came out of a loop
// over linked records (the event solver's prefetch pipeline did nothing for a whole release):
// every prefetch in the sources goes through prefetch_line, which writes the instruction
// itself. This looks for the builtin anywhere else.
TEST(PrefetchLine, SourcesUseItInsteadOfTheCompilerBuiltin) {
    const std::filesystem::path root = COLLIDE_SOURCE_DIR;
    const std::filesystem::path allowed = root / "core" / "numerics" / "prefetch.h";
    std::vector<std::string> offenders;
    for (const char* dir : {"core", "physics", "reference", "cpu", "opencl", "box2d", "bench", "apps", "validation"}) {
        if (!std::filesystem::exists(root / dir)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root / dir)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".h" && ext != ".hpp" && ext != ".cpp")) continue;
            if (std::filesystem::equivalent(entry.path(), allowed)) continue;
            std::ifstream in(entry.path());
            std::stringstream text;
            text << in.rdbuf();
            if (text.str().find("__builtin_prefetch") != std::string::npos) offenders.push_back(entry.path().string());
        }
    }
    EXPECT_TRUE(offenders.empty()) << "use prefetch_line (core/numerics/prefetch.h) in: " << ::testing::PrintToString(offenders);
    EXPECT_TRUE(std::filesystem::exists(allowed));
}

}  // namespace
}  // namespace collide
