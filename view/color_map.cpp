#include "color_map.h"

#include <algorithm>
#include <cmath>

namespace collide::view {

Rgb viridis(double s) {
    // matplotlib's viridis at 0, 1/8, ..., 1; between samples the map is close to linear in
    // RGB, so nine samples keep it perceptually uniform to the eye.
    static constexpr std::uint8_t samples[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                                   {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                                   {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
    if (!(s >= 0)) s = 0;  // also NaN
    s = std::min(s, 1.0) * 8;
    const int k = std::min(int(s), 7);
    const double f = s - k;
    // Rounded to nearest by + 0.5 (the values are in [0, 255]): no library call per channel.
    auto mix = [&](int c) { return std::uint8_t(samples[k][c] + f * (samples[k + 1][c] - samples[k][c]) + 0.5); };
    return {mix(0), mix(1), mix(2)};
}

}  // namespace collide::view
