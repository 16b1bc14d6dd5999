// C++ access to the shared stepping-rule laws (contact_law.cl.h, wall_law.cl.h) for any real type:
//     auto d = collide::ContactLaw<float>::delta(...);
//     collide::WallLaw<double>::reflect_axis(&x, &vx, r, lo, hi, e_wall);
// The C-subset headers are included once per scalar type, each time in its own namespace
// with `Real` bound to that type. The OpenCL kernels include the same text.
#pragma once

#include <cmath>

namespace collide {
namespace contact_law_double {
using Real = double;
using std::floor;
using std::rint;
using std::sqrt;
#undef COLLIDE_CONTACT_LAW_H
#undef COLLIDE_WALL_LAW_H
#include "contact_law.cl.h"
#include "wall_law.cl.h"
}  // namespace contact_law_double
namespace contact_law_float {
using Real = float;
using std::floor;
using std::rint;
using std::sqrt;
#undef COLLIDE_CONTACT_LAW_H
#undef COLLIDE_WALL_LAW_H
#include "contact_law.cl.h"
#include "wall_law.cl.h"
}  // namespace contact_law_float

template <typename Real> struct ContactLaw;
template <typename Real> struct WallLaw;

template <> struct ContactLaw<double> {
    using Delta = contact_law_double::ContactDelta;
    static Delta delta(double sep_x, double sep_y, double rel_vx, double rel_vy, double contact_distance,
                       double inv_mass_i, double inv_mass_j, double restitution, double friction) {
        return contact_law_double::contact_delta(sep_x, sep_y, rel_vx, rel_vy, contact_distance, inv_mass_i,
                                   inv_mass_j, restitution, friction);
    }
};
template <> struct ContactLaw<float> {
    using Delta = contact_law_float::ContactDelta;
    static Delta delta(float sep_x, float sep_y, float rel_vx, float rel_vy, float contact_distance,
                       float inv_mass_i, float inv_mass_j, float restitution, float friction) {
        return contact_law_float::contact_delta(sep_x, sep_y, rel_vx, rel_vy, contact_distance, inv_mass_i,
                                   inv_mass_j, restitution, friction);
    }
};

template <> struct WallLaw<double> {
    static int reflect_axis(double* pos, double* vel, double r, double lo, double hi, double e) {
        return contact_law_double::reflect_axis(pos, vel, r, lo, hi, e);
    }
    static double wrap(double pos, double lo, double length) {
        return contact_law_double::wrap_periodic(pos, lo, length);
    }
    static double minimum_image(double d, double length) {
        return contact_law_double::minimum_image(d, length);
    }
};
template <> struct WallLaw<float> {
    static int reflect_axis(float* pos, float* vel, float r, float lo, float hi, float e) {
        return contact_law_float::reflect_axis(pos, vel, r, lo, hi, e);
    }
    static float wrap(float pos, float lo, float length) {
        return contact_law_float::wrap_periodic(pos, lo, length);
    }
    static float minimum_image(float d, float length) {
        return contact_law_float::minimum_image(d, length);
    }
};

}  // namespace collide
