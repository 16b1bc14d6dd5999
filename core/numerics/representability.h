// Representability: whether a scene's numbers fit the floating-point type a backend computes in.
//
// A number outside a type's range does not stop a computation: IEEE 754 rounds it to infinity
// (overflow) or, below the smallest normal number, to a subnormal with fewer digits or to 0
// (underflow). Then a heavy disk's inverse mass becomes 0 and the disk a silent "stone", a
// tiny speed becomes 0, a squared distance 0 hides an overlap. So every backend asks, before
// it starts, whether the quantities it will compute from the scene lie in its type's normal
// range, and refuses with the quantity, its value and the limit if one does not
// (docs/refusals.md lists them).
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

enum class Precision { single, double_ };  // IEEE 754 binary32 (float) and binary64 (double)

const char* to_string(Precision p);  // "float", "double"

// Which formulas a backend evaluates, so that only the quantities it computes are checked.
enum class Method {
    stepping_rules,  // step, cpu, opencl: contact law, grid, time step dt (physics/contact_law.cl.h)
    event_driven,    // event: contact law without dt, plus the collision-time quadratic
    metrics_only,    // box2d: the adapter checks Box2D's own (rescaled) units itself
};

// Whether the quantities `method` computes from `scene` and `state` are representable in
// `precision`, and the metrics (core/metrics.cpp, always double) too. Nothing if they are;
// otherwise one line such as
//   "cpu computes in float: inverse mass 1/m = 1e-46 of disk 3 underflows below float's
//    smallest normal number 1.18e-38".
std::optional<std::string> representability_problem(const Scene& scene, const ParticleState<double>& state,
                                                    Precision precision, Method method, const std::string& backend);

// For an adapter that hands values to a library with units of its own (box2d): nothing if the
// product of `factors` (e.g. {scale, g}) is 0 or lies in `precision`'s normal range, else a
// line like representability_problem's ("<who> in float: <quantity> = 5e-101 for disk 0
// underflows below ..."), with the product's true size even beyond double. disk < 0: none.
std::optional<std::string> value_problem(const std::string& who, Precision precision, const std::string& quantity,
                                         std::initializer_list<double> factors, long long disk = -1);

// Throws std::runtime_error with representability_problem's line, prefixed by
// "<backend>: scene '<name>': ".
void require_representable(const Scene& scene, const ParticleState<double>& state, Precision precision,
                           Method method, const std::string& backend);

}  // namespace collide
