// ParticleState: the positions, velocities and properties of N disks, stored as a
// structure of arrays (one contiguous array per quantity). Every backend reads its
// initial state from, and writes its current state back into, a ParticleState<double>;
// the float backends keep a ParticleState<float> internally.
#pragma once

#include <cmath>

#include <cstddef>
#include <vector>

namespace collide {

template <typename Real>
struct ParticleState {
    std::vector<Real> x, y;        // centre position
    std::vector<Real> vx, vy;      // velocity
    std::vector<Real> radius;      // disk radius (> 0)
    std::vector<Real> mass;        // mass as given in the scene (> 0), also for stones
    std::vector<Real> inv_mass;    // 1/mass, or exactly 0 for a kinematic "stone"

    std::size_t size() const { return x.size(); }

    void resize(std::size_t n) {
        for (auto* a : arrays()) a->resize(n);
    }

    bool is_stone(std::size_t i) const { return inv_mass[i] == Real(0); }
    // Position and velocity are finite (metrics and overlap searches skip other disks).
    bool is_finite(std::size_t i) const {
        return std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(vx[i]) && std::isfinite(vy[i]);
    }

    // Appends one disk; a stone keeps its mass but gets inverse mass 0 (kinematic).
    void append_disk(Real x0, Real y0, Real vx0, Real vy0, Real r, Real m, bool stone) {
        x.push_back(x0);
        y.push_back(y0);
        vx.push_back(vx0);
        vy.push_back(vy0);
        radius.push_back(r);
        mass.push_back(m);
        inv_mass.push_back(stone ? Real(0) : Real(1) / m);
    }

    // Converts every array to another real type (double -> float on load, float -> double on read-back).
    template <typename Other>
    ParticleState<Other> as() const {
        ParticleState<Other> out;
        out.x.assign(x.begin(), x.end());
        out.y.assign(y.begin(), y.end());
        out.vx.assign(vx.begin(), vx.end());
        out.vy.assign(vy.begin(), vy.end());
        out.radius.assign(radius.begin(), radius.end());
        out.mass.assign(mass.begin(), mass.end());
        out.inv_mass.assign(inv_mass.begin(), inv_mass.end());
        return out;
    }

    std::vector<std::vector<Real>*> arrays() {
        return {&x, &y, &vx, &vy, &radius, &mass, &inv_mass};
    }
};

}  // namespace collide
