#include "validation/compare/published_rows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/scene/scene_loader.h"
#include "validation/judge/statistics.h"

namespace collide::validation {

namespace {

// Mixed unless the run says it is not: the check applies at eta >= 0.69 only, and a run below
// that records psi6_mixed = 1 or nothing.
bool mixed(const CaseResult& r) { return !(r.counter("psi6_mixed") == 0); }

struct PublishedGroup {
    std::size_t scene_index = 0;
    std::string scene, backend, group;
    std::vector<const CaseResult*> cases;  // finished replicates only
};

std::vector<PublishedGroup> published_groups(const Suite& suite, const std::vector<CaseResult>& results) {
    std::vector<PublishedGroup> groups;
    std::map<std::string, std::size_t> index;
    for (const CaseResult& r : results) {
        if (suite.scenes[r.spec.scene_index].published.empty() || !r.finished()) continue;
        const std::string id = group_id(r.spec);
        auto [it, inserted] = index.emplace(id, groups.size());
        if (inserted) groups.push_back({r.spec.scene_index, r.spec.scene, r.spec.backend, id, {}});
        groups[it->second].cases.push_back(&r);
    }
    return groups;
}

// What the scene simulates, to hold against what the published row simulated.
struct SystemFacts {
    long long disks = 0;
    double aspect_ratio = 0, eta = 0;
    std::string boundary;
};

SystemFacts system_of(const Scene& scene) {
    const ParticleState<double> s = generate_initial_state(scene);
    SystemFacts f;
    f.disks = (long long)s.size();
    f.aspect_ratio = scene.world.height() / scene.world.width();
    double covered = 0;
    for (std::size_t i = 0; i < s.size(); ++i) covered += M_PI * s.radius[i] * s.radius[i];
    f.eta = covered / (scene.world.width() * scene.world.height());
    f.boundary = scene.world.boundary == Boundary::periodic ? "periodic" : "reflect";
    return f;
}

// "" when the scene is the published system; else what differs. The area fraction must agree
// to 1e-9: near eta = 0.7, d(beta P d^2)/d eta is about 50, so 1e-6 in eta would already shift
// the pressure by a published error bar.
std::string system_mismatch(const SystemFacts& f, const FiniteNPoint& p) {
    std::ostringstream d;
    d.precision(10);
    if (f.disks != p.disks) d << "the scene has N = " << f.disks << ", the published row N = " << p.disks << "; ";
    if (std::abs(f.aspect_ratio - p.aspect_ratio) > 1e-9 * p.aspect_ratio)
        d << "the scene's box has height / width " << f.aspect_ratio << ", the published " << p.aspect_ratio << " (" << p.box
          << "); ";
    if (std::abs(f.eta - p.eta) > 1e-9 * p.eta)
        d << "the scene's area fraction is " << f.eta << ", the published " << p.eta << "; ";
    if (f.boundary != p.boundary) d << "the scene's boundary is " << f.boundary << ", the published " << p.boundary << "; ";
    return d.str();
}

double mean_of(const std::vector<const CaseResult*>& cases, const char* name) {
    double sum = 0;
    for (const CaseResult* r : cases) sum += r->counter(name);
    return sum / double(cases.size());
}

// The facts of the estimate the report shows beside the value (means over the replicates).
void record_facts(PhysicsRow& row, const PublishedGroup& g, const SystemFacts& f, const PooledEstimate& pooled) {
    double traversals = INFINITY, batches = 0;
    for (const CaseResult* r : g.cases)
        traversals = std::min(traversals, r->counter("psi6_traversals")), batches += r->counter("beta_pressure_batches");
    row.facts = {{"disks", double(f.disks)},
                 {"equilibration", mean_of(g.cases, "beta_pressure_equilibration")},
                 {"correlation_time", mean_of(g.cases, "beta_pressure_correlation_time")},
                 {"batches", batches},
                 {"relative_error", pooled.standard_error / std::abs(pooled.mean)},
                 {"psi6_traversals", std::isfinite(traversals) ? traversals : std::nan("")},
                 {"mixed", std::all_of(g.cases.begin(), g.cases.end(), [](const CaseResult* r) { return mixed(*r); }) ? 1.0 : 0.0},
                 {"replicate_chi2", pooled.chi2}};
}

// The verdict: fail when the scene is not the published system or a case lacks the counters;
// shown when psi6 has not mixed; else pass iff |z| <= 3 and the relative error <= the precision
// the suite asks of this backend (2e-4 unless [published_precision] says otherwise).
void judge(PhysicsRow& row, const std::string& mismatch, std::size_t without_counters, double relative_error_max) {
    std::ostringstream d;
    const double relative = row.facts.at("relative_error");
    if (!mismatch.empty()) {
        row.verdict = PhysicsVerdict::fail;
        d << "not the published system: " << mismatch;
    } else if (without_counters > 0) {
        row.verdict = PhysicsVerdict::fail;
        d << without_counters << " of " << row.replicates
          << " finished cases recorded no beta_pressure / beta_pressure_error: this backend does not measure the pressure; ";
    } else if (row.facts.at("mixed") == 0) {
        row.verdict = PhysicsVerdict::shown;
        d << "not mixed: the phase of psi6 crossed its full range " << row.facts.at("psi6_traversals")
          << " times in the sampled run (3 needed), so the run has not sampled the states the published value averages; ";
    } else {
        const bool close = row.score <= physics_z_max, precise = relative <= relative_error_max;
        row.verdict = close && precise ? PhysicsVerdict::pass : PhysicsVerdict::fail;
        if (!close) d << "|z| > " << physics_z_max << "; ";
        if (!precise) d << "relative error " << relative << " > " << relative_error_max << ": run longer; ";
    }
    d << "pooled over " << row.replicates << " replicates by inverse-variance weights (chi2 "
      << row.facts.at("replicate_chi2") << " on " << (row.replicates > 0 ? row.replicates - 1 : 0) << " d.o.f.)";
    row.detail = d.str();
}

// Strings made once (GCC 12 warns falsely, -Wrestrict, on assigning a short literal to a
// std::string member at -O3; physics_rows.cpp does the same).
const std::string& text(const char* which) {
    static const std::map<std::string, std::string> texts = {
        {"kind", "published_finite_n"}, {"z", "z"}, {"area fraction", "area fraction"},
        {"estimator", "collision virial in the rest frame, Z = 1 + ((N - 1)/N) W / K_int; batch means"}};
    return texts.at(which);
}

// How the cases measured the pressure, read from the counters they recorded (what a backend did,
// not its name): the lifts of event chains, the contact value of a gap histogram, or else the
// collision virial of dynamics.
std::string pressure_estimator(const CaseResult& r) {
    if (std::isfinite(r.counter("lifts")))
        return "lifts of straight event chains, Z = 1 + <sum x_ij> / l (Michel, Kapfer & Krauth 2014); batch means";
    if (std::isfinite(r.counter("contact_window"))) {
        std::ostringstream e;
        e << "contact value of the pair-gap histogram, a parabola over " << r.counter("contact_window")
          << " (length units) extrapolated to contact; batch means";
        return e.str();
    }
    return text("estimator");
}

PhysicsRow published_row(const PublishedGroup& g, const Scene& scene, const PublishedReference& ref,
                         const FiniteNPoint& point, double relative_error_max) {
    PhysicsRow row;
    row.row = text("kind");
    row.scene = g.scene, row.backend = g.backend, row.group = g.group;
    row.published = ref.key + ":" + point.id;
    row.box = point.box + " " + point.boundary;
    row.measured = "pressure beta P d^2 (d the diameter) at N = " + std::to_string(point.disks);
    row.estimator = pressure_estimator(*g.cases.front());
    row.reference_name = ref.name + (point.method.empty() ? "" : " " + point.method);
    row.citation = ref.citation;
    row.reference = point.beta_pressure_d2, row.reference_uncertainty = point.standard_error;
    row.statistic = text("z");
    std::vector<Estimate> estimates;
    std::size_t without_counters = 0;
    for (const CaseResult* r : g.cases) {
        const Estimate e{r->counter("beta_pressure"), r->counter("beta_pressure_error")};
        if (std::isfinite(e.value) && e.standard_error > 0) estimates.push_back(e);
        else ++without_counters;
    }
    const PooledEstimate pooled = pool_inverse_variance(estimates);
    row.replicates = g.cases.size();
    row.value = pooled.mean, row.standard_error = pooled.standard_error;
    row.score = std::abs(row.value - row.reference) / std::hypot(row.standard_error, row.reference_uncertainty);
    row.score_from = {row.estimator, row.value, row.standard_error, row.reference, row.reference_uncertainty, 0};
    const SystemFacts f = system_of(scene);
    row.parameter_name = text("area fraction"), row.parameter = f.eta;
    record_facts(row, g, f, pooled);
    row.facts["relative_error_max"] = relative_error_max;
    judge(row, system_mismatch(f, point), without_counters, relative_error_max);
    return row;
}

// --- Routes that must agree: every other backend's row against the reference backend's -------

bool same_point(const PhysicsRow& a, const PhysicsRow& b) {
    return a.scene == b.scene && a.published == b.published && a.parameter == b.parameter;
}

// The verdict of "reference vs other": fail where either row could not be judged for a reason
// of its own (not the published system, no counters), shown where either has not mixed, else
// pass iff |z| <= 3 on the difference. The precision of either row does not enter: a wide
// error bar makes the row weak, and the published rows say so.
void judge_routes(PhysicsRow& row, const PhysicsRow& reference, const PhysicsRow& other) {
    std::ostringstream d;
    const auto broken = [](const PhysicsRow& r) {
        return r.detail.rfind("not the published system", 0) == 0 || !std::isfinite(r.value);
    };
    if (broken(reference) || broken(other)) {
        row.verdict = PhysicsVerdict::fail;
        d << "a route could not be measured on the published system (see its own row); ";
    } else if (reference.facts.at("mixed") == 0 || other.facts.at("mixed") == 0) {
        row.verdict = PhysicsVerdict::shown;
        d << "not mixed: psi6 has not crossed its range in one of the two runs; ";
    } else {
        row.verdict = row.score <= physics_z_max ? PhysicsVerdict::pass : PhysicsVerdict::fail;
        if (row.verdict == PhysicsVerdict::fail) d << "|z| > " << physics_z_max << "; ";
    }
    d << other.backend << " " << other.value << " +- " << other.standard_error << " (" << other.replicates
      << " replicates) against " << reference.backend << " " << reference.value << " +- " << reference.standard_error
      << " (" << reference.replicates << "); published " << other.reference << " +- " << other.reference_uncertainty;
    row.detail = d.str();
}

PhysicsRow routes_row(const PhysicsRow& reference, const PhysicsRow& other) {
    PhysicsRow row = other;  // the point, the box, the backend and its estimate
    row.row = "routes_agree";
    row.measured = "pressure beta P d^2 by two routes: " + other.backend + " against " + reference.backend;
    row.estimator = other.estimator + " against " + reference.estimator;
    row.reference = reference.value, row.reference_uncertainty = reference.standard_error;
    row.reference_name = reference.backend + " (" + reference.estimator + ")";
    row.citation = "";
    row.statistic = "z";
    row.score = std::abs(row.value - row.reference) / std::hypot(row.standard_error, row.reference_uncertainty);
    row.score_from = {"difference of the two routes' pooled estimates", row.value, row.standard_error, row.reference,
                      row.reference_uncertainty, 0};
    row.facts["published"] = other.reference, row.facts["published_error"] = other.reference_uncertainty;
    judge_routes(row, reference, other);
    return row;
}

// One row per published row of a backend other than the reference, where the reference ran the
// same point: "event vs ecmc" (docs/monte-carlo.md, "How the routes are compared").
std::vector<PhysicsRow> routes_rows(const std::vector<PhysicsRow>& published, const std::string& reference_backend) {
    std::vector<PhysicsRow> rows;
    for (const PhysicsRow& reference : published) {
        if (reference.backend != reference_backend) continue;
        for (const PhysicsRow& other : published)
            if (other.backend != reference_backend && same_point(reference, other))
                rows.push_back(routes_row(reference, other));
    }
    return rows;
}

double relative_error_max_for(const Suite& suite, const std::string& backend) {
    const auto it = suite.published_precision.find(backend);
    return it == suite.published_precision.end() ? published_relative_error_max : it->second;
}

}  // namespace

std::vector<PhysicsRow> published_finite_n_rows(const Suite& suite, const std::vector<CaseResult>& results,
                                                const std::function<const Scene&(const CaseSpec&)>& scene_of) {
    std::vector<PhysicsRow> rows;
    std::map<std::string, PublishedReference> refs;
    for (const PublishedGroup& g : published_groups(suite, results)) {
        const std::string& name = suite.scenes[g.scene_index].published;
        const std::string key = name.substr(0, name.find(':')), id = name.substr(name.find(':') + 1);
        if (!refs.count(key)) refs.emplace(key, load_reference(suite.reference_dir, key));
        const PublishedReference& ref = refs.at(key);
        rows.push_back(published_row(g, scene_of(g.cases.front()->spec), ref, ref.finite_n_point(id),
                                     relative_error_max_for(suite, g.backend)));
    }
    std::vector<PhysicsRow> routes = routes_rows(rows, suite.reference);
    rows.insert(rows.end(), routes.begin(), routes.end());
    return rows;
}

}  // namespace collide::validation
