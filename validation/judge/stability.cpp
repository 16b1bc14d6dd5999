#include "validation/judge/stability.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "core/numerics/median.h"
#include "validation/judge/tunnelling.h"

namespace collide::validation {

const char* to_string(Outcome o) {
    switch (o) {
        case Outcome::stable: return "stable";
        case Outcome::crash: return "crash";
        case Outcome::hang: return "hang";
        case Outcome::nan: return "nan";
        case Outcome::stalled: return "stalled";
        case Outcome::tunnelling: return "tunnelling";
        case Outcome::excessive_overlap: return "excessive_overlap";
        case Outcome::energy_growth: return "energy_growth";
        case Outcome::left_out: return "left_out";
    }
    return "crash";
}

double energy_growth(const MetricSeries& m, bool total) {
    if (m.empty()) return 0;
    auto energy = [total](const Metrics& row) { return total ? row.total_energy() : row.kinetic_energy; };
    double scale = m.front().kinetic_energy;
    if (!(scale > 0))
        scale = std::max_element(m.begin(), m.end(), [](const Metrics& a, const Metrics& b) {
                    return a.kinetic_energy < b.kinetic_energy;
                })->kinetic_energy;
    double rise = 0;
    for (const Metrics& row : m) rise = std::max(rise, energy(row) - energy(m.front()));  // NaN never wins; `nan` comes first
    return scale > 0 ? rise / scale : rise;
}

double median_displacement(const CaseResult& r) {
    const Snapshot &a = r.initial, &b = r.final_state;
    const std::size_t n = std::min({a.x.size(), a.y.size(), b.x.size(), b.y.size()});
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = std::hypot(b.x[i] - a.x[i], b.y[i] - a.y[i]);
    return median(std::move(d));
}

namespace {

// The reference must have moved its median disk by at least this fraction of the median
// radius for `stalled` to be judged (a packing at rest, a Newton's cradle whose middle disks
// never move, are not stalled), and the backend by less than stalled_fraction of that.
constexpr double min_reference_motion = 0.01, stalled_fraction = 0.1;

std::string text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// A disk with a NaN/Inf state, or a NaN/Inf metric (an energy overflowing double while every
// disk is finite is no more stable than a NaN position).
bool any_nonfinite(const MetricSeries& m) {
    for (const Metrics& row : m)
        if (row.nonfinite > 0 || !std::isfinite(row.kinetic_energy) || !std::isfinite(row.total_energy()) ||
            !std::isfinite(row.momentum_x) || !std::isfinite(row.momentum_y) || !std::isfinite(row.max_overlap))
            return true;
    return false;
}

}  // namespace

Classification classify(const CaseResult& r, const CaseResult* reference, const SceneFeatures& f,
                        const Tolerances& tol) {
    switch (r.status) {
        case RunStatus::left_out: return {Outcome::left_out, r.diagnostic};
        case RunStatus::crashed: return {Outcome::crash, r.diagnostic};
        case RunStatus::timed_out: return {Outcome::hang, r.diagnostic};
        case RunStatus::error:
            // run_scene stops with an error at the first NaN/Inf state (run_driver.cpp); any
            // other exception is the solver giving up, counted with the crashes.
            if (r.diagnostic.find("NaN/Inf") != std::string::npos || any_nonfinite(r.series))
                return {Outcome::nan, r.diagnostic};
            return {Outcome::crash, "threw: " + r.diagnostic};
        case RunStatus::completed: break;
    }
    if (any_nonfinite(r.series)) return {Outcome::nan, "NaN/Inf in the state"};

    std::string notes;
    if (reference && reference->finished() && !r.spec.reference) {
        const double moved = median_displacement(r), expected = median_displacement(*reference);
        if (expected > min_reference_motion * median(reference->initial.radius) && moved < stalled_fraction * expected)
            return {Outcome::stalled, "median displacement " + text(moved) + " where the reference's is " +
                                          text(expected) + ": the disks barely moved"};
        const TunnellingCount t = count_tunnelling(r, *reference, !f.reflecting_walls);
        if (t.pairs > 0)
            return {Outcome::tunnelling, std::to_string(t.pairs) + " pair(s) passed through each other (first: " +
                                             t.first + ") where the reference has them apart"};
        if (!t.evaluated) notes = "tunnelling not evaluated: " + t.not_evaluated;
    } else if (!r.spec.reference) {
        notes = "tunnelling not evaluated: no finished reference run";
    }

    double overlap = 0;
    for (const Metrics& row : r.series) overlap = std::max(overlap, row.max_overlap);
    if (overlap > tol.max_overlap)
        return {Outcome::excessive_overlap,
                "max relative overlap " + text(overlap) + " > tolerance " + text(tol.max_overlap)};

    const bool may_not_grow = f.restitution <= 1 && f.wall_restitution <= 1 && !f.moving_stones;
    if (may_not_grow) {
        const double growth = energy_growth(r.series, f.gravity);
        if (growth > tol.energy_drift)
            return {Outcome::energy_growth, std::string(f.gravity ? "total" : "kinetic") + " energy rose by " +
                                                text(growth) + " x K(0) > tolerance " + text(tol.energy_drift)};
    } else {
        notes += std::string(notes.empty() ? "" : "; ") + "energy growth not evaluated (energy may grow here)";
    }
    return {Outcome::stable, notes.empty() ? "no failure mode found" : "no failure mode found; " + notes};
}

std::vector<std::string> unexpected_outcomes(const std::vector<CaseResult>& cases,
                                             const std::vector<Classification>& classifications) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const CaseResult& c = cases[i];
        if (i >= classifications.size()) {
            out.push_back(c.spec.id + ": not classified");
            continue;
        }
        const Classification& k = classifications[i];
        if (c.spec.reference && k.outcome != Outcome::stable && k.outcome != Outcome::left_out)
            out.push_back(c.spec.id + ": the reference backend is not stable: " + to_string(k.outcome) + ": " + k.reason);
        else if (k.outcome == Outcome::crash)
            out.push_back(c.spec.id + ": crash: " + k.reason);
    }
    return out;
}

}  // namespace collide::validation
