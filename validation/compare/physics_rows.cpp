#include "validation/compare/physics_rows.h"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/thermo/pressure_estimator.h"
#include "core/thermo/velocity_sphere.h"
#include "validation/compare/published_rows.h"
#include "validation/judge/checks.h"
#include "core/scene/scene_loader.h"
#include "validation/judge/statistics.h"

namespace collide::validation {

const std::vector<PhysicsRowKind>& physics_row_kinds() {
    static const std::vector<PhysicsRowKind> kinds = {
        {"equation_of_state", "kolafa_rottner_2006", "compressibility factor Z = P / (rho kT)"},
        {"collision_rate", "enskog_collision_rate", "collisions per disk per time unit"},
        {"speed_distribution", "maxwell_boltzmann", "speed distribution of the final states"},
        {"galperin", "galperin_2003", "collisions (disk-disk and disk-wall) until the disks separate"},
        {"haff", "haff_1983", "cooling time tau of T(t) = T0 / (1 + t / tau)^2"},
        // Not [[scene]] keys: a scene's `published = "KEY:ID"` makes this row (published_rows.h),
        {"published_finite_n", "li_2022", "pressure beta P d^2 at the published N and box shape"},
        // and this one is made from the rows above wherever two exact solvers ran a case.
        {"exact_agreement", "", "difference between two exact solvers' values of the same row"},
    };
    return kinds;
}

const char* to_string(PhysicsVerdict v) {
    switch (v) {
        case PhysicsVerdict::pass: return "pass";
        case PhysicsVerdict::fail: return "fail";
        default: return "shown";
    }
}

// --- Per-case measurements ----------------------------------------------------------------

KineticTemperature case_temperature(const CaseResult& r, std::size_t moving_disks, bool conserved) {
    if (r.series.empty()) return {};
    const Metrics& first = r.series.front();
    return kinetic_temperature(first.kinetic_energy, first.momentum_x, first.momentum_y, r.total_mass, moving_disks,
                               conserved);
}

double virial_compressibility(const CaseResult& r, const KineticTemperature& t) {
    const double dt = r.duration - r.counter("time_at_half");
    const double dv = r.counter("virial_sum") - r.counter("virial_sum_at_half");
    return compressibility_factor(dv / (2 * dt), t);
}

double second_half_collision_rate(const CaseResult& r) {
    const double dt = r.duration - r.counter("time_at_half");
    return 2 * (double(r.contacts) - r.counter("contacts_at_half")) / (double(r.disks) * dt);
}

double haff_cooling_time(const CaseResult& r, double t_max, std::size_t moving_disks, bool conserved) {
    std::vector<double> t, y;
    for (const Metrics& row : r.series) {
        const double k = kinetic_temperature(row.kinetic_energy, row.momentum_x, row.momentum_y, r.total_mass,
                                             moving_disks, conserved).internal_kinetic_energy;
        if (row.time <= t_max && k > 0) {
            t.push_back(row.time);
            y.push_back(1 / std::sqrt(k));  // T^(-1/2) up to a constant
        }
    }
    if (t.size() < 3) return std::nan("");
    const auto mt = mean_and_error(t).mean, my = mean_and_error(y).mean;
    double sty = 0, stt = 0;
    for (std::size_t i = 0; i < t.size(); ++i) sty += (t[i] - mt) * (y[i] - my), stt += (t[i] - mt) * (t[i] - mt);
    const double slope = sty / stt, intercept = my - slope * mt;
    return intercept / slope;
}

std::vector<double> scaled_speeds(const Snapshot& s, double mass, bool conserved) {
    double k = 0, px = 0, py = 0;
    for (std::size_t i = 0; i < s.vx.size(); ++i) {
        k += 0.5 * mass * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
        px += mass * s.vx[i], py += mass * s.vy[i];
    }
    const double total_mass = mass * double(s.vx.size());
    const KineticTemperature t = kinetic_temperature(k, px, py, total_mass, s.vx.size(), conserved);
    // The centre of mass's velocity where it is a constant of the motion (else the frame stays).
    const bool rest_frame = t.degrees_of_freedom < double(t.moving_disks);
    const double ux = rest_frame ? px / total_mass : 0, uy = rest_frame ? py / total_mass : 0;
    const double scale = std::sqrt(t.kT() / mass);
    std::vector<double> u;
    for (std::size_t i = 0; i < s.vx.size(); ++i) u.push_back(std::hypot(s.vx[i] - ux, s.vy[i] - uy) / scale);
    return u;
}

ChiSquare maxwell_boltzmann_chi_square(const std::vector<double>& u, int bins) {
    // Equiprobable bins of the Rayleigh distribution with unit scale: F(u) = 1 - exp(-u^2 / 2).
    std::vector<double> edges;
    for (int k = 1; k < bins; ++k) edges.push_back(std::sqrt(-2 * std::log(1 - double(k) / bins)));
    std::vector<double> observed(std::size_t(bins), 0.0);
    for (double v : u) observed[std::size_t(std::upper_bound(edges.begin(), edges.end(), v) - edges.begin())] += 1;
    ChiSquare c;
    const double expected = double(u.size()) / bins;
    for (double o : observed) c.chi2 += (o - expected) * (o - expected) / expected;
    // One degree of freedom for the total, one for kT fixed by each replicate's own energy.
    c.dof = bins - 2;
    c.p_value = gsl_cdf_chisq_Q(c.chi2, c.dof);
    return c;
}

// --- Groups and the facts of their scene ---------------------------------------------------

namespace {

struct Group {
    std::size_t scene_index = 0;
    std::string scene, backend, group;
    std::vector<const CaseResult*> cases;  // finished replicates only
    std::size_t planned = 0;
    bool exact() const {  // an event-driven solver: counts collisions and their virial
        return !cases.empty() && cases.front()->counters.count("virial_sum");
    }
};

std::vector<Group> physics_groups(const Suite& suite, const std::vector<CaseResult>& results) {
    std::vector<Group> groups;
    std::map<std::string, std::size_t> index;
    for (const CaseResult& r : results) {
        if (suite.scenes[r.spec.scene_index].physics.empty() || r.status == RunStatus::left_out) continue;
        const std::string id = group_id(r.spec);
        auto [it, inserted] = index.emplace(id, groups.size());
        if (inserted) groups.push_back({r.spec.scene_index, r.spec.scene, r.spec.backend, id, {}, 0});
        Group& g = groups[it->second];
        ++g.planned;
        if (r.finished()) g.cases.push_back(&r);
    }
    return groups;
}

struct SceneFacts {
    double area = 0, eta = 0, density = 0, sigma = 0, mass = 1, mass_ratio = 1, restitution = 1;
    std::size_t mobile = 0;
    bool momentum_conserved = false;  // a periodic box without gravity (kinetic_temperature.h)
};

SceneFacts facts_of(const Scene& scene) {
    const ParticleState<double> s = generate_initial_state(scene);
    SceneFacts f;
    f.area = scene.world.width() * scene.world.height();
    f.restitution = scene.physics.restitution;
    f.momentum_conserved = momentum_conserved(scene);
    double covered = 0, mmin = INFINITY, mmax = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        covered += M_PI * s.radius[i] * s.radius[i];
        if (s.is_stone(i)) continue;
        ++f.mobile;
        mmin = std::min(mmin, s.mass[i]), mmax = std::max(mmax, s.mass[i]);
    }
    f.eta = covered / f.area;
    f.density = double(s.size()) / f.area;
    f.sigma = s.size() ? 2 * s.radius[0] : 0;
    f.mass_ratio = f.mobile ? mmax / mmin : 1;
    f.mass = f.mobile ? mmin : 1;  // the rows that use it (gases) have equal masses
    return f;
}

// The names of the scores; strings made once (GCC 12 warns falsely, -Wrestrict, on assigning
// a short literal to a std::string member at -O3).
const std::string& statistic_name(char kind) {
    static const std::string z = "z", p = "p", exact = "exact";
    return kind == 'z' ? z : kind == 'p' ? p : exact;
}

PhysicsRow row_for(const Group& g, const char* kind, const PublishedReference& ref) {
    PhysicsRow row;
    row.row = kind;
    row.scene = g.scene, row.backend = g.backend, row.group = g.group;
    row.replicates = g.cases.size();
    row.reference_name = ref.name, row.citation = ref.citation;
    for (const auto& k : physics_row_kinds())
        if (row.row == k.name) row.measured = k.measures;
    return row;
}

// The judged score of `m` about the row's reference: z = |mean - reference| / sqrt(se^2 + u^2)
// when the SE is a batch-means error (dof 0); when it is the scatter of m.count replicates the
// quotient is Student's t with m.count - 1 dof, converted to the normal score of equal tail
// probability so that |score| <= 3 means the same 0.27 % either way (statistics.h).
void judge_score(PhysicsRow& row, const MeanAndError& m, double dof, bool judged) {
    row.value = m.mean, row.standard_error = m.standard_error;
    row.statistic = statistic_name('z');
    const double t = std::abs(m.mean - row.reference) / std::hypot(m.standard_error, row.reference_uncertainty);
    row.score = normal_equivalent_of_t(t, dof);
    row.score_from = {row.estimator, m.mean, m.standard_error, row.reference, row.reference_uncertainty, dof};
    if (m.count < 1 || (dof > 0 && m.count < 2)) {
        row.verdict = PhysicsVerdict::fail;
        row.detail = "needs at least 2 finished replicates for an error bar";
        return;
    }
    row.verdict = !judged ? PhysicsVerdict::shown : row.score <= physics_z_max ? PhysicsVerdict::pass : PhysicsVerdict::fail;
    row.judged_by_score = judged;
}

// Replicate values `v`: their mean with the SE of their scatter, judged through Student's t.
void judge_z(PhysicsRow& row, const std::vector<double>& v, bool judged) {
    const MeanAndError m = mean_and_error(v);
    judge_score(row, m, m.count >= 2 ? double(m.count - 1) : 0, judged);
    if (m.count < 2) row.verdict = PhysicsVerdict::fail, row.detail = "needs at least 2 finished replicates for an error bar";
}

// Replicates' batch-means estimates pooled by inverse variance (published_rows.h).
MeanAndError pooled(const std::vector<Estimate>& estimates) {
    const PooledEstimate p = pool_inverse_variance(estimates);
    return {p.mean, p.standard_error, p.count};
}

// Each replicate's own batch-means estimate (counters `mean_name`, `error_name`), or nothing
// when a replicate lacks them (a run without a pressure record).
std::optional<std::vector<Estimate>> recorded_estimates(const Group& g, const char* mean_name, const char* error_name) {
    std::vector<Estimate> e;
    for (const CaseResult* r : g.cases) {
        const double mean = r->counter(mean_name), error = r->counter(error_name);
        if (!std::isfinite(mean) || !(error > 0)) return std::nullopt;
        e.push_back({mean, error});
    }
    return e;
}

// A measured quantity against a predicted one, replicate by replicate (the prediction depends
// on each replicate's own temperature): judged by the score of the ratios measured / predicted
// about 1, with the prediction's relative uncertainty u; shown as the means of the two. With
// each replicate's batch-means estimate the ratios are pooled by inverse variance (a normal
// error); with bare values, their scatter through Student's t (judge_z).
void judge_ratio(PhysicsRow& row, const std::vector<Estimate>& measured, const std::vector<double>& predicted, double u,
                 bool batch_means, bool judged) {
    std::vector<Estimate> ratio;
    std::vector<double> values, ratio_values;
    for (std::size_t k = 0; k < measured.size(); ++k) {
        ratio.push_back({measured[k].value / predicted[k], measured[k].standard_error / predicted[k]});
        values.push_back(measured[k].value), ratio_values.push_back(ratio.back().value);
    }
    row.reference = 1, row.reference_uncertainty = u;
    if (batch_means) judge_score(row, pooled(ratio), 0, judged);
    else judge_z(row, ratio_values, judged);
    row.score_from.estimator = row.estimator + (batch_means ? ", per-replicate ratio measured / predicted pooled by inverse variance"
                                                            : ", per-replicate ratio measured / predicted; SE from " +
                                                                  std::to_string(values.size()) + " replicates, Student t");
    const MeanAndError m = batch_means ? pooled(measured) : mean_and_error(values);
    row.value = m.mean, row.standard_error = m.standard_error;
    row.reference = mean_and_error(predicted).mean;
    row.reference_uncertainty = u * row.reference;
}

std::vector<Estimate> bare(const std::vector<double>& values) {
    std::vector<Estimate> e;
    for (double v : values) e.push_back({v, 0});
    return e;
}

// Enskog's collision rate at the case's kinetic temperature, times the finite-N factor of the
// velocity sphere (core/thermo/velocity_sphere.h): what N disks with that K_int collide at.
double predicted_collision_rate(const SceneFacts& f, double g_contact, const KineticTemperature& t) {
    return enskog_collision_rate(f.density, f.sigma, g_contact, t.kT() / f.mass) *
           collision_rate_finite_n_factor(t.degrees_of_freedom);
}

// --- The rows ------------------------------------------------------------------------------

PhysicsRow equation_of_state_row(const Group& g, const SceneFacts& f, const PublishedReference& eos,
                                 const PublishedReference& second) {
    PhysicsRow row = row_for(g, "equation_of_state", eos);
    row.parameter_name = "area fraction", row.parameter = f.eta;
    row.reference = compressibility_factor(eos, f.eta);
    row.reference_uncertainty = eos.numbers.count("relative_uncertainty") ? eos.number("relative_uncertainty") * row.reference : 0;
    row.second_reference = compressibility_factor(second, f.eta), row.second_reference_name = second.name;
    // beta P d^2 of each replicate's pressure record (batch means over its windows), as Z.
    if (const auto recorded = g.exact() ? recorded_estimates(g, "beta_pressure", "beta_pressure_error") : std::nullopt) {
        std::vector<Estimate> z;
        const double rho_d2 = f.density * f.sigma * f.sigma;
        for (const Estimate& e : *recorded) z.push_back({e.value / rho_d2, e.standard_error / rho_d2});
        row.estimator = "collision virial, batch means per replicate, pooled by inverse variance";
        judge_score(row, pooled(z), 0, true);
    } else {
        std::vector<double> z;
        for (const CaseResult* r : g.cases)
            z.push_back(g.exact() ? virial_compressibility(*r, case_temperature(*r, f.mobile, f.momentum_conserved))
                                  : mean_and_error(r->compressibility).mean);
        row.estimator = std::string(g.exact() ? "collision virial of the second half"
                                              : "contact shell (pairs within sigma (1 + 0.05))") +
                        ", SE from " + std::to_string(z.size()) + " replicates, Student t";
        judge_z(row, z, g.exact());
    }
    row.resolved = std::abs(row.reference - row.second_reference) > 1.96 * row.standard_error;
    if (!g.exact()) row.detail = "not judged: the contact-shell estimator is biased by O(shell) and this backend's rule by O(dt)";
    return row;
}

PhysicsRow collision_rate_row(const Group& g, const SceneFacts& f, const PublishedReference& enskog,
                              const PublishedReference& eos) {
    PhysicsRow row = row_for(g, "collision_rate", enskog);
    row.parameter_name = "area fraction", row.parameter = f.eta;
    const double g_contact = contact_value(compressibility_factor(eos, f.eta), f.eta);
    std::vector<double> nu, nu_enskog;
    for (const CaseResult* r : g.cases) {
        nu.push_back(second_half_collision_rate(*r));
        nu_enskog.push_back(predicted_collision_rate(f, g_contact, case_temperature(*r, f.mobile, f.momentum_conserved)));
    }
    const double u = enskog.numbers.count("relative_uncertainty") ? enskog.number("relative_uncertainty") : 0;
    // The collision-rate series of each replicate's pressure record (batch means), else the
    // collisions counted in the second half of each replicate.
    const auto recorded = recorded_estimates(g, "collision_rate_mean", "collision_rate_error");
    row.estimator = recorded ? "collisions per window, batch means" : "collisions counted in the second half";
    judge_ratio(row, recorded ? *recorded : bare(nu), nu_enskog, u, recorded.has_value(), true);
    std::ostringstream d;
    d << "g(sigma) = " << g_contact << " from " << eos.name
      << "; kT from each replicate's conserved energy (K_int / (N - 1) periodic), times the finite-N factor "
         "Gamma(f) sqrt(f) / Gamma(f + 1/2) of the velocity sphere";
    row.detail = d.str();
    return row;
}

PhysicsRow speed_distribution_row(const Group& g, const SceneFacts& f, const PublishedReference& mb) {
    PhysicsRow row = row_for(g, "speed_distribution", mb);
    row.estimator = "Pearson chi-square, equiprobable bins, speeds in the centre-of-mass frame, kT from each replicate's energy";
    std::vector<double> u;
    for (const CaseResult* r : g.cases) {
        const std::vector<double> speeds = scaled_speeds(r->final_state, f.mass, f.momentum_conserved);
        u.insert(u.end(), speeds.begin(), speeds.end());
    }
    const ChiSquare c = maxwell_boltzmann_chi_square(u, int(mb.number("bins")));
    row.value = c.chi2, row.reference = c.dof;
    row.statistic = statistic_name('p'), row.score = c.p_value;
    const bool ok = c.p_value >= mb.number("minimum_p_value") && !u.empty();
    row.verdict = !g.exact() ? PhysicsVerdict::shown : ok ? PhysicsVerdict::pass : PhysicsVerdict::fail;
    std::ostringstream d;
    d << u.size() << " speeds pooled over " << g.cases.size() << " replicates; chi2 = " << c.chi2 << " on " << c.dof
      << " degrees of freedom";
    row.detail = d.str();
    return row;
}

PhysicsRow galperin_row(const Group& g, const SceneFacts& f, const PublishedReference& ref) {
    PhysicsRow row = row_for(g, "galperin", ref);
    row.parameter_name = "mass ratio", row.parameter = f.mass_ratio;
    row.estimator = "pair collisions + wall collisions";
    row.statistic = statistic_name('e');
    for (const auto& [ratio, count] : ref.counts)
        if (std::abs(ratio - f.mass_ratio) <= 1e-9 * ratio) row.reference = double(count);
    std::vector<double> counts;
    for (const CaseResult* r : g.cases) counts.push_back(double(r->contacts) + r->counter("events_wall"));
    const bool all_equal = !counts.empty() && std::all_of(counts.begin(), counts.end(), [&](double c) { return c == counts[0]; });
    row.value = counts.empty() ? std::nan("") : counts[0];
    row.standard_error = 0;
    row.score = std::abs(row.value - row.reference);
    const bool ok = all_equal && row.score == 0;
    row.verdict = !g.exact() ? PhysicsVerdict::shown : ok ? PhysicsVerdict::pass : PhysicsVerdict::fail;
    if (std::isnan(row.reference)) row.verdict = PhysicsVerdict::fail, row.detail = "no published count for this mass ratio";
    else if (!all_equal) row.detail = "replicates disagree";
    return row;
}

PhysicsRow haff_row(const Group& g, const SceneFacts& f, const PublishedReference& haff, const PublishedReference& eos) {
    PhysicsRow row = row_for(g, "haff", haff);
    row.parameter_name = "restitution", row.parameter = f.restitution;
    row.estimator = "least-squares line through T^(-1/2) for t <= min(tau, run)";
    const double g_contact = contact_value(compressibility_factor(eos, f.eta), f.eta);
    std::vector<double> tau, tau_haff;
    for (const CaseResult* r : g.cases) {
        const double nu0 = predicted_collision_rate(f, g_contact, case_temperature(*r, f.mobile, f.momentum_conserved));
        tau_haff.push_back(4 / ((1 - f.restitution * f.restitution) * nu0));  // 1/tau = (1 - e^2) nu0 / 4 (2-D)
        tau.push_back(haff_cooling_time(*r, tau_haff.back(), f.mobile, f.momentum_conserved));
    }
    judge_ratio(row, bare(tau), tau_haff, haff.number("model_uncertainty"), false, g.exact());
    std::ostringstream d;
    d << "tau = 4 / ((1 - e^2) nu0), nu0 Enskog's rate at T0 with g(sigma) = " << g_contact << " (" << eos.name
      << "); the law's own accuracy " << haff.number("model_uncertainty") * 100 << " % counts in the error";
    row.detail = d.str();
    return row;
}

// The degrees of freedom of a difference of two rows' means (Welch 1947, Satterthwaite 1946):
// (sa^2 + sb^2)^2 / (sa^4 / fa + sb^4 / fb), a batch-means SE (dof 0) counting as infinite
// dof; 0 (normal) when both are.
double welch_degrees_of_freedom(const PhysicsRow& a, const PhysicsRow& b) {
    const double fa = a.score_from.degrees_of_freedom, fb = b.score_from.degrees_of_freedom;
    if (fa == 0 && fb == 0) return 0;
    const double va = a.standard_error * a.standard_error, vb = b.standard_error * b.standard_error;
    const double denominator = (fa > 0 ? va * va / fa : 0) + (fb > 0 ? vb * vb / fb : 0);
    return denominator > 0 ? (va + vb) * (va + vb) / denominator : 0;
}

// Two independent exact solvers (`event` and `event-plain`) on the same cases must agree within
// their error bars: for each judged z row of a second exact backend, the difference from the
// first backend's row at the same scene and parameter, judged as a z-score about 0.
void add_exact_agreement(std::vector<PhysicsRow>& rows) {
    std::vector<PhysicsRow> added;
    for (const PhysicsRow& a : rows) {
        if (a.verdict == PhysicsVerdict::shown || a.statistic != "z") continue;
        for (const PhysicsRow& b : rows) {
            if (&a == &b || b.row != a.row || b.scene != a.scene || b.verdict == PhysicsVerdict::shown ||
                b.backend <= a.backend || !(b.parameter == a.parameter || (std::isnan(a.parameter) && std::isnan(b.parameter))))
                continue;
            PhysicsRow d = a;
            d.row = "exact_agreement";
            d.backend = b.backend + " - " + a.backend;
            d.measured = "difference of " + a.measured;
            d.value = b.value - a.value;
            d.standard_error = std::hypot(a.standard_error, b.standard_error);
            d.reference = 0, d.reference_uncertainty = 0, d.second_reference = std::nan("");
            d.reference_name = "the two exact solvers agree", d.citation = "";
            const double dof = welch_degrees_of_freedom(a, b);
            d.score = normal_equivalent_of_t(std::abs(d.value) / d.standard_error, dof);
            d.score_from = {dof > 0 ? "difference of the two rows' means, Student t (Welch-Satterthwaite dof)"
                                    : "difference of the two rows' means",
                            d.value, d.standard_error, 0, 0, dof};
            d.verdict = d.score <= physics_z_max ? PhysicsVerdict::pass : PhysicsVerdict::fail;
            d.judged_by_score = true;
            d.detail = b.backend + " " + std::to_string(b.value) + " against " + a.backend + " " + std::to_string(a.value);
            added.push_back(std::move(d));
        }
    }
    rows.insert(rows.end(), added.begin(), added.end());
}

ReferenceCurve sampled_curve(const PublishedReference& eos) {
    ReferenceCurve c{eos.name, eos.citation, {}, {}};
    for (int k = 0; k <= 140; ++k) {
        const double eta = k * 0.005;
        if (eta > eos.valid_below) break;
        c.eta.push_back(eta), c.z.push_back(compressibility_factor(eos, eta));
    }
    return c;
}

}  // namespace

double family_z_max(std::size_t rows) {
    if (rows <= 1) return physics_z_max;
    return gsl_cdf_ugaussian_Qinv(gsl_cdf_ugaussian_Q(physics_z_max) / double(rows));
}

namespace {

// Every row judged by its score is held to the threshold of the rows judged together.
void hold_to_the_family_threshold(PhysicsComparison& out) {
    std::size_t judged = 0;
    for (const PhysicsRow& r : out.rows) judged += r.judged_by_score;
    out.z_max = family_z_max(judged);
    for (PhysicsRow& r : out.rows)
        if (r.judged_by_score) r.verdict = r.score <= out.z_max ? PhysicsVerdict::pass : PhysicsVerdict::fail;
}

}  // namespace

PhysicsComparison compare_with_physics(const Suite& suite, const std::vector<CaseResult>& results,
                                       const std::function<const Scene&(const CaseSpec&)>& scene_of) {
    PhysicsComparison out;
    out.rows = published_finite_n_rows(suite, results, scene_of);
    const std::vector<Group> groups = physics_groups(suite, results);
    if (groups.empty()) return out;
    std::map<std::string, PublishedReference> refs;
    auto ref = [&](const std::string& key) -> const PublishedReference& {
        if (!refs.count(key)) refs.emplace(key, load_reference(suite.reference_dir, key));
        return refs.at(key);
    };
    const PublishedReference& eos = ref("kolafa_rottner_2006");
    for (const Group& g : groups) {
        if (g.cases.empty()) continue;  // every replicate failed: its run checks say why
        const SceneFacts f = facts_of(scene_of(g.cases.front()->spec));
        for (const std::string& kind : suite.scenes[g.scene_index].physics) {
            if (kind == "equation_of_state") out.rows.push_back(equation_of_state_row(g, f, eos, ref("henderson_1975")));
            else if (kind == "collision_rate" && g.exact()) out.rows.push_back(collision_rate_row(g, f, ref("enskog_collision_rate"), eos));
            else if (kind == "speed_distribution") out.rows.push_back(speed_distribution_row(g, f, ref("maxwell_boltzmann")));
            else if (kind == "galperin") out.rows.push_back(galperin_row(g, f, ref("galperin_2003")));
            else if (kind == "haff") out.rows.push_back(haff_row(g, f, ref("haff_1983"), eos));
        }
    }
    add_exact_agreement(out.rows);
    hold_to_the_family_threshold(out);
    out.curves = {sampled_curve(eos), sampled_curve(ref("henderson_1975"))};
    return out;
}

}  // namespace collide::validation
