#include "validation/summary/verdict_facts.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace collide::validation {
namespace {

bool judged(const CheckResult& c) { return c.status != CheckStatus::left_out; }

// A tolerance that can be compared: a finite, non-zero number (summary.json's null or 0 is none).
bool has_tolerance(const CheckResult& c) { return std::isfinite(c.tolerance) && c.tolerance != 0; }

// The median the report names is the upper one of an even count (the element at n / 2).
double upper_median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

std::optional<LoosestTolerance> loosest_tolerance(const std::string& backend, const std::string& reference,
                                                  const std::vector<CheckResult>& checks, double threshold) {
    std::map<std::string, std::map<std::string, double>> others;  // check -> backend -> tolerance (the last)
    for (const CheckResult& c : checks)
        if (c.backend != backend && c.backend != reference && judged(c) && has_tolerance(c))
            others[c.check][c.backend] = c.tolerance;
    std::optional<LoosestTolerance> worst;
    for (const CheckResult& c : checks) {
        if (c.backend != backend || !judged(c) || c.comparison != "<=" || !has_tolerance(c)) continue;
        const auto it = others.find(c.check);
        if (it == others.end()) continue;
        std::vector<double> values;
        for (const auto& [other, tolerance] : it->second) values.push_back(tolerance);
        const double median = upper_median(values);
        if (median > 0 && (!worst || c.tolerance / median > worst->ratio))
            worst = LoosestTolerance{c.tolerance / median, c.check, c.tolerance, false};
    }
    if (worst) worst->named = worst->ratio >= threshold;
    return worst;
}

std::optional<LargestEnergyDrift> largest_energy_drift(const std::string& backend, const std::vector<CheckResult>& checks,
                                                       double threshold) {
    std::optional<LargestEnergyDrift> largest;
    for (const CheckResult& c : checks) {
        if (c.backend != backend || c.check != "energy_drift" || !judged(c) || !std::isfinite(c.value)) continue;
        // The largest value; between equal values, the last scene by name (as a tuple compares).
        if (!largest || c.value > largest->value || (c.value == largest->value && c.scene > largest->scene))
            largest = LargestEnergyDrift{c.value, c.scene, false};
    }
    if (largest) largest->named = largest->value >= threshold;
    return largest;
}

PressureOffset pressure_offset(const std::string& backend, const std::vector<CheckResult>& checks,
                               const std::vector<WorkPrecisionLine>& lines, bool stepping_rule, double threshold) {
    PressureOffset p;
    for (const WorkPrecisionLine& line : lines)
        if (line.backend == backend)
            for (const WorkPrecisionPoint& point : line.points)
                if (point.pressure && point.pressure->resolved && std::isfinite(point.pressure->sigmas))
                    p.sigmas = std::max(p.sigmas.value_or(point.pressure->sigmas), point.pressure->sigmas);
    std::size_t pressure_checks = 0, left_out = 0;
    for (const CheckResult& c : checks)
        if (c.backend == backend && c.check == "pressure") {
            ++pressure_checks;
            if (!judged(c)) ++left_out;
        }
    p.left_out = pressure_checks > 0 && left_out == pressure_checks;
    p.named = p.sigmas && (p.left_out || !stepping_rule) && *p.sigmas >= threshold;
    return p;
}

}  // namespace

std::map<std::string, VerdictFacts> verdict_facts(const std::string& reference, const std::vector<CheckResult>& checks,
                                                  const std::vector<WorkPrecisionLine>& lines,
                                                  const VerdictThresholds& thresholds,
                                                  const std::map<std::string, bool>& stepping_rule) {
    std::set<std::string> backends;
    for (const CheckResult& c : checks) backends.insert(c.backend);
    std::map<std::string, VerdictFacts> out;
    for (const std::string& b : backends) {
        VerdictFacts& f = out[b];
        if (b != reference) f.loosest_tolerance = loosest_tolerance(b, reference, checks, thresholds.loose_tolerance_ratio);
        f.largest_energy_drift = largest_energy_drift(b, checks, thresholds.energy_drift);
        const auto rule = stepping_rule.find(b);
        f.pressure_offset = pressure_offset(b, checks, lines, rule != stepping_rule.end() && rule->second,
                                            thresholds.pressure_sigmas);
    }
    return out;
}

}  // namespace collide::validation
