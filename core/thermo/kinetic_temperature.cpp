#include "core/thermo/kinetic_temperature.h"

#include "core/metrics.h"
#include "core/numerics/compensated_sum.h"

namespace collide {

bool momentum_conserved(const Scene& scene) { return scene.periodic() && !scene.has_gravity(); }

KineticTemperature kinetic_temperature(double kinetic_energy, double momentum_x, double momentum_y,
                                       double total_mass, std::size_t moving_disks, bool conserved) {
    KineticTemperature t;
    t.kinetic_energy = kinetic_energy;
    t.moving_disks = moving_disks;
    if (conserved && moving_disks > 1 && total_mass > 0) {
        // K = K_int + |P|^2 / (2 M): Koenig's theorem.
        t.internal_kinetic_energy = kinetic_energy - (momentum_x * momentum_x + momentum_y * momentum_y) / (2 * total_mass);
        t.degrees_of_freedom = double(moving_disks) - 1;
    } else {
        t.internal_kinetic_energy = kinetic_energy;
        t.degrees_of_freedom = double(moving_disks);
    }
    return t;
}

KineticTemperature kinetic_temperature(const Scene& scene, const ParticleState<double>& s) {
    CompensatedSum k, px, py, m;
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.is_stone(i)) continue;
        ++n;
        k.add(disk_kinetic_energy(s.mass[i], s.vx[i], s.vy[i]));
        px.add(s.mass[i] * s.vx[i]);
        py.add(s.mass[i] * s.vy[i]);
        m.add(s.mass[i]);
    }
    return kinetic_temperature(k.value(), px.value(), py.value(), m.value(), n, momentum_conserved(scene));
}

}  // namespace collide
