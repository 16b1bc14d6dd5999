// The global bond-orientational order psi6 of a configuration, and the mixing check that
// reads the series of its phases. docs/validation.md, "Error bars and mixing", explains both.
//
//  - psi6 = (1/N) sum_j (1/n_j) sum_k exp(6 i theta_jk): theta_jk the angle of the bond from
//    disk j to its neighbour k, n_j the number of j's neighbours (a disk without neighbours adds
//    0). Neighbours are the disks whose centres lie within a cutoff of 1.4 diameters (minimum
//    image in a periodic box): in the dense fluid and the hexatic (eta 0.65 to 0.72) the nearest
//    shell sits near 1.0 to 1.2 d, the first minimum of g(r) near 1.6 d at 0.65 (the course's
//    figure, docs/course/2-many-disks-exactly.md) and the second shell near 1.9 to 2.1 d, so a
//    cutoff of 1.4 d takes most of each disk's first shell and nothing of the second. (Bernard &
//    Krauth, PRL 107, 155704 (2011) use Voronoi neighbours; the cutoff is simpler and gives the
//    same phase where the phase matters.) A perfect hexagonal lattice has |psi6| = 1, and turning
//    it by alpha turns psi6's phase by 6 alpha.
//  - Mixing (B. Li et al., J. Chem. Phys. 157, 234111 (2022), sec. II): a run samples the
//    equilibrium of a dense system only if the phase of psi6 (the orientation of the local
//    crystal order, arg in (-pi, pi], a turn of the lattice by 60 degrees) has wandered over its
//    whole range several times. Here a traversal is counted each time the unwrapped phase has
//    swept a span of 2 pi since the previous traversal ended (phase_traversals); a run is mixed
//    with at least 3 traversals.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

// The neighbour cutoff of psi6, in disk diameters (see above).
constexpr double psi6_cutoff_diameters = 1.4;
// Traversals of the full phase range a mixed run needs (Li et al. 2022).
constexpr std::size_t psi6_traversals_to_mix = 3;

// The local psi6 of every disk j, (1/n_j) sum_k exp(6 i theta_jk) over its neighbours within
// `cutoff` (centre distance; 0 for a disk without neighbours), in the state's disk order.
std::vector<std::complex<double>> local_psi6(const World& world, const ParticleState<double>& state, double cutoff);

// psi6 of the disks of `state` in `world`: the mean of their local psi6 (neighbours within `cutoff`).
std::complex<double> global_psi6(const World& world, const ParticleState<double>& state, double cutoff);

// psi6 with the cutoff of 1.4 mean diameters.
std::complex<double> global_psi6(const World& world, const ParticleState<double>& state);

// Traversals of the full range in a series of phases (each in (-pi, pi]): the series is
// unwrapped (each step taken as the change of least magnitude, so the samples must be close
// enough that the phase moves by less than pi between them), and a traversal is counted each
// time the unwrapped phase's span (max - min) since the end of the previous traversal reaches
// 2 pi; the next one starts from that sample.
std::size_t phase_traversals(const std::vector<double>& phases);

inline bool phase_mixed(std::size_t traversals) { return traversals >= psi6_traversals_to_mix; }

}  // namespace collide
