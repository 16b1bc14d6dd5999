// libFuzzer target for the scene parser: any byte string must either parse into a scene (and,
// when small enough, generate) or be rejected with a SceneError. Anything else — a crash, an
// uncaught exception of another type, a sanitizer report, a hang — is a bug.
//
//   cmake -B build/fuzz -DCOLLIDE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang
//   cmake --build build/fuzz --target fuzz_scene_parser
//   build/fuzz/tests/fuzz/fuzz_scene_parser -max_total_time=60 data/scenes
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const collide::Scene scene = collide::parse_scene(text, "fuzz.toml");
        // Generating is part of the attack surface too (counts, packings), but only for
        // scenes small enough that one input cannot take seconds.
        std::int64_t total = 0;
        for (const auto& g : scene.generators)
            total += g.kind == "list" ? std::int64_t(g.disks.size()) : g.count;
        if (total <= 2000) (void)collide::generate_initial_state(scene);
    } catch (const collide::SceneError&) {
        // The expected way to refuse bad input.
    }
    return 0;
}
