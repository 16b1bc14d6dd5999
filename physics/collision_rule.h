// The collision rule of smooth hard disks, for both event-driven solvers (`event` and
// `event-plain`): what a collision does, given that it happens now. collision_time.h says when.
// docs/event-driven.md derives it.
#pragma once

namespace collide::event_rule {

// Disks i and j touch along the line of centres d = x_i - x_j (minimum image) with relative
// velocity u = v_i - v_j, approaching (b = d.u < 0); w = 1/m are the inverse masses (0 for a
// stone). Conservation of momentum and Newton's restitution law u.n' = -e u.n, n = d / |d|,
// give the normal impulse J = -(1 + e) (u.n) / (w_i + w_j) (Alder & Wainwright, J. Chem.
// Phys. 31 (1959) 459; Allen & Tildesley, Computer Simulation of Liquids, 2nd ed., §3.7).
// Written as J n = g d, it needs no square root:
//   g = -(1 + e) (d.u) / (|d|^2 (w_i + w_j)),   v_i' = v_i + w_i g d,   v_j' = v_j - w_j g d.
// The collision virial d.(J n) = g |d|^2 enters the pressure (virial theorem, Allen &
// Tildesley §2.4 and §3.7).
inline double impulse_factor(double b, double d2, double w_sum, double e) { return -(1 + e) * b / (d2 * w_sum); }

}  // namespace collide::event_rule
