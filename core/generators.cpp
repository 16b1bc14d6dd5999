// PLACEHOLDER: being written (generators). Replaced before the foundation lands.
#include "scene_loader.h"
namespace collide {
ParticleState<double> generate_initial_state(const Scene& scene) {
    ParticleState<double> s;
    for (const auto& g : scene.generators)
        for (const auto& d : g.disks) {
            s.x.push_back(d.x); s.y.push_back(d.y); s.vx.push_back(d.vx); s.vy.push_back(d.vy);
            s.radius.push_back(d.radius); s.mass.push_back(d.mass);
            s.inv_mass.push_back(d.stone ? 0.0 : 1.0 / d.mass);
        }
    return s;
}
}  // namespace collide
