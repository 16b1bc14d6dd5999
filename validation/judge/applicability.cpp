#include "validation/judge/applicability.h"

#include <sstream>

#include "validation/record/check_table.h"

namespace collide::validation {

std::optional<std::string> momentum_left_out(const SceneFeatures& f) {
    if (f.reflecting_walls) return "reflecting walls exchange momentum with the disks";
    if (f.gravity) return "gravity is an external force";
    if (f.damping) return "damping (drag) removes momentum";
    if (f.stones) return "stones have infinite mass and absorb momentum";
    return std::nullopt;
}

EnergyCheck energy_check(const SceneFeatures& f) {
    std::ostringstream why;
    if (f.restitution != 1) why << "restitution e = " << f.restitution << " < 1 dissipates energy";
    else if (f.reflecting_walls && f.wall_restitution != 1)
        why << "wall restitution " << f.wall_restitution << " < 1 dissipates energy";
    else if (f.damping) why << "damping dissipates energy";
    else if (f.friction) why << "Coulomb friction dissipates energy";
    else if (f.moving_stones) why << "moving stones do work on the disks";
    if (!why.str().empty()) return {EnergyKind::none, why.str()};
    if (f.gravity) return {EnergyKind::total, "gravity: total (kinetic + potential) energy is checked"};
    return {EnergyKind::kinetic, ""};
}

std::optional<std::string> wall_penetration_left_out(const SceneFeatures& f) {
    if (!f.reflecting_walls) return "periodic boundaries: there are no walls";
    return std::nullopt;
}

std::optional<std::string> overlapping_pairs_too_few(std::size_t disks, double limit_per_disk) {
    const double allowed = limit_per_disk * double(disks);  // overlapping pairs the limit allows
    if (allowed >= overlapping_pairs_counted_from) return std::nullopt;
    const double most = disks > 1 ? double(disks - 1) / 2 : 0;
    std::ostringstream why;
    if (most <= limit_per_disk)
        why << "cannot fail: " << disks << " disks overlap in at most " << most << " pairs per disk, within the limit "
            << limit_per_disk;
    else
        why << "a count of single pairs: the limit " << limit_per_disk << " per disk allows " << allowed << " of "
            << disks << " disks' pairs, fewer than " << overlapping_pairs_counted_from
            << ", so one pair met in the last step would fail it";
    why << "; overlap_beyond_step judges in its place";
    return why.str();
}

std::optional<std::string> overlap_beyond_step_left_out(std::size_t disks, double limit_per_disk) {
    if (overlapping_pairs_too_few(disks, limit_per_disk)) return std::nullopt;
    return "overlapping_pairs judges this case; among many disks a stepped rule's Jacobi pass resolves a disk "
           "with several contacts only in part, so pairs stay overlapped over steps by design";
}

std::optional<std::string> pressure_left_out(const SceneFeatures& f) {
    if (!f.uniform_radius) return "polydisperse disks: the contact-value pressure needs one diameter";
    return std::nullopt;
}

}  // namespace collide::validation
