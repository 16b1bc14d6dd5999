// candidate_mask: the contact pass's broad-phase test on four candidate slots at once.
//
// The contact pass (collide_range in phase_kernels.h) asks, for disk i and every slot b of its
// 3x3 neighbourhood, whether sep_x^2 + sep_y^2 >= (r_i + r_j)^2, and skips the pair if so. At
// area fraction 0.3 a neighbourhood holds about 3.4 disks in three slot ranges of about one
// disk each, and fewer than one candidate in a hundred is a contact: a scalar loop spends its
// time on loop control and on branches whose outcome (range length 0, 1, 2, ...) the
// processor cannot predict. Here one SSE2 test covers a block of four consecutive slots and
// returns a bit mask of the slots that pass; the caller then runs the contact law, in scalar
// and in slot order, for the set bits only (almost never any). A range of up to four slots is
// one block, whatever its length: no branch on the length.
//
// Bitwise the same decisions as the scalar test: subtraction, product, sum and comparison are
// the same IEEE single-precision operations in the same order (no fused multiply-add: none is
// enabled), and the comparison is "not >=", so that a NaN distance is a candidate, as in the
// scalar loop. The minimum image of periodic walls, d - L rint(d / L), takes rint as
// (v + 2^23) - 2^23 with v's sign, exact for |v| < 2^23 (larger floats are integers already):
// the same magnitude as std::rint; only the sign of a zero may differ, which the squares below
// do not see. Without SSE2 (not an x86-64 build) the same mask is computed lane by lane.
#pragma once

#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "physics/stepping_laws.h"

namespace collide::cpu {

// The data a block test reads: disk i and the arrays of the state (in cell order).
struct CandidateQuery {
    float xi, yi, ri;         // disk i (ri: its radius, or the common radius)
    float contact2;           // (2 r)^2 for equal radii
    float width, height;      // periodic box lengths
    const float *x, *y, *radius;
    std::uint32_t n;          // slots in the arrays: a block never reads at or past n
};

// Bit l (l = 0..3) set when slot b + l is a candidate partner of disk i: b + l < end, b + l is
// not disk i's own slot `self`, and the scalar loop would not skip it for distance. Slots at or
// past `end` are not tested.
template <bool UniformRadius, bool Periodic>
[[gnu::always_inline]] inline unsigned candidate_mask(const CandidateQuery& q, std::uint32_t b, std::uint32_t end, std::uint32_t self) {
#if defined(__SSE2__)
    __m128 xj, yj, rj = _mm_setzero_ps();
    if (b + 4 <= q.n) [[likely]] {
        xj = _mm_loadu_ps(q.x + b);
        yj = _mm_loadu_ps(q.y + b);
        if constexpr (!UniformRadius) rj = _mm_loadu_ps(q.radius + b);
    } else {  // the last slots of the arrays: copy what exists (the rest is masked below)
        alignas(16) float bx[4] = {0, 0, 0, 0}, by[4] = {0, 0, 0, 0}, br[4] = {0, 0, 0, 0};
        for (std::uint32_t l = 0; b + l < q.n; ++l) {
            bx[l] = q.x[b + l];
            by[l] = q.y[b + l];
            br[l] = q.radius ? q.radius[b + l] : 0.0f;
        }
        xj = _mm_load_ps(bx);
        yj = _mm_load_ps(by);
        rj = _mm_load_ps(br);
    }
    __m128 sx = _mm_sub_ps(_mm_set1_ps(q.xi), xj), sy = _mm_sub_ps(_mm_set1_ps(q.yi), yj);
    if constexpr (Periodic) {
        auto minimum_image = [](__m128 d, float length) {
            const __m128 l = _mm_set1_ps(length);
            const __m128 v = _mm_div_ps(d, l);
            const __m128 sign = _mm_and_ps(v, _mm_set1_ps(-0.0f));
            const __m128 magic = _mm_or_ps(_mm_set1_ps(8388608.0f), sign);  // 2^23 with v's sign
            const __m128 rounded = _mm_sub_ps(_mm_add_ps(v, magic), magic);
            // |v| >= 2^23 (or NaN): v itself, as rint gives.
            const __m128 small = _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), v), _mm_set1_ps(8388608.0f));
            const __m128 r = _mm_or_ps(_mm_and_ps(small, rounded), _mm_andnot_ps(small, v));
            return _mm_sub_ps(d, _mm_mul_ps(l, r));
        };
        sx = minimum_image(sx, q.width);
        sy = minimum_image(sy, q.height);
    }
    __m128 contact2;
    if constexpr (UniformRadius) {
        contact2 = _mm_set1_ps(q.contact2);
    } else {
        const __m128 c = _mm_add_ps(_mm_set1_ps(q.ri), rj);
        contact2 = _mm_mul_ps(c, c);
    }
    const __m128 dist2 = _mm_add_ps(_mm_mul_ps(sx, sx), _mm_mul_ps(sy, sy));
    const __m128i near = _mm_castps_si128(_mm_cmpnge_ps(dist2, contact2));
    // Lane l counts if l < end - b and l != self - b (signed: a negative difference matches no lane).
    const __m128i lane = _mm_setr_epi32(0, 1, 2, 3);
    const __m128i in_range = _mm_cmplt_epi32(lane, _mm_set1_epi32(std::int32_t(end - b)));
    const __m128i is_self = _mm_cmpeq_epi32(lane, _mm_set1_epi32(std::int32_t(self - b)));
    return unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_andnot_si128(is_self, _mm_and_si128(near, in_range)))));
#else
    unsigned mask = 0;
    for (std::uint32_t l = 0; l < 4 && b + l < end; ++l) {
        float sep_x = q.xi - q.x[b + l], sep_y = q.yi - q.y[b + l];
        if constexpr (Periodic) {
            sep_x = WallLaw<float>::minimum_image(sep_x, q.width);
            sep_y = WallLaw<float>::minimum_image(sep_y, q.height);
        }
        const float contact2 = UniformRadius ? q.contact2 : (q.ri + q.radius[b + l]) * (q.ri + q.radius[b + l]);
        if (!(sep_x * sep_x + sep_y * sep_y >= contact2) && b + l != self) mask |= 1u << l;
    }
    return mask;
#endif
}

}  // namespace collide::cpu
