#include "validation/explain/report_jumps.h"

#include <atomic>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "core/io/run_schema.h"
#include "validation/explain/explain_case.h"
#include "validation/record/case_result.h"
#include "validation/summary/drawn_cases.h"

namespace collide::validation {
namespace {

// Whether the case's backend (a variant: its base's) uses its device one process at a time
// (BackendInfo::one_device).
bool uses_one_device(const std::vector<BackendInfo>& backends, const std::string& name) {
    const std::string base = name.substr(0, name.find('['));
    for (const BackendInfo& b : backends)
        if (b.name == name || b.name == base) return b.one_device;
    return false;
}

// FNV-1a over the bits of a record's numbers: every metric of its series (the run schema's
// columns) and its final state. Equal records hash equally; equal hashes are confirmed by
// same_numbers before a case is taken for another's twin.
std::uint64_t numbers_hash(const CaseResult& r) {
    std::uint64_t h = 14695981039346656037ull;
    auto mix = [&h](double v) {
        unsigned char bytes[sizeof v];
        std::memcpy(bytes, &v, sizeof v);
        for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    };
    for (const Metrics& m : r.series)
        for (const MetricColumn& column : metric_columns) mix(column.value(m));
    for (const auto* a : {&r.final_state.x, &r.final_state.y, &r.final_state.vx, &r.final_state.vy, &r.final_state.radius})
        for (double v : *a) mix(v);
    return h;
}

// Whether two records hold the same numbers, bit for bit (NaN equals NaN, -0 differs from 0).
bool same_numbers(const CaseResult& a, const CaseResult& b) {
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    if (a.series.size() != b.series.size()) return false;
    for (std::size_t k = 0; k < a.series.size(); ++k)
        for (const MetricColumn& column : metric_columns)
            if (!same(column.value(a.series[k]), column.value(b.series[k]))) return false;
    const Snapshot &x = a.final_state, &y = b.final_state;
    for (auto [p, q] : {std::pair{&x.x, &y.x}, {&x.y, &y.y}, {&x.vx, &y.vx}, {&x.vy, &y.vy}, {&x.radius, &y.radius}}) {
        if (p->size() != q->size()) return false;
        for (std::size_t i = 0; i < p->size(); ++i)
            if (!same((*p)[i], (*q)[i])) return false;
    }
    return true;
}

CaseResult record_of(const std::string& dir, const DrawnCase& d) {
    return read_case_result(dir + "/cases/" + d.id + ".toml");
}

// What the first pass finds in a drawn case's record: its jump, if any, and its numbers' hash;
// or why the record could not be read.
struct Found {
    std::optional<IntervalJump> jump;
    std::uint64_t hash = 0;
    std::string unreadable;
};

nlohmann::json jump_json(const DrawnCase& d, const IntervalJump& jump) {
    return {{"case", d.id}, {"scene", d.scene}, {"backend", d.backend}, {"t0", jump.t0}, {"t1", jump.t1},
            {"change", jump.change}, {"median", jump.median}, {"scale", jump.scale}, {"explained", nullptr},
            {"problem", ""}};
}

// Runs work(k) for k = 0 .. n-1 on up to `jobs` threads.
template <typename Work>
void for_each_index(std::size_t n, int jobs, Work work) {
    std::atomic<std::size_t> next{0};
    auto run = [&] {
        for (std::size_t k = next++; k < n; k = next++) work(k);
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < jobs; ++t) threads.emplace_back(run);
    run();
    for (auto& t : threads) t.join();
}

}  // namespace

std::vector<DrawnCase> cases_to_explain(const std::vector<CaseResult>& cases, const std::vector<CheckResult>& checks,
                                        const std::map<std::string, bool>& exact) {
    std::set<std::string> judging_energy;  // scenes whose energy_drift was judged (not left out)
    for (const CheckResult& c : checks)
        if (c.check == "energy_drift" && (c.status == CheckStatus::pass || c.status == CheckStatus::fail))
            judging_energy.insert(c.scene);
    const std::vector<bool> drawn = drawn_cases(cases);
    std::vector<DrawnCase> out;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const CaseSpec& spec = cases[k].spec;
        const auto claim = exact.find(spec.backend);
        if (drawn[k] && judging_energy.count(spec.scene) && !(claim != exact.end() && claim->second))
            out.push_back({spec.id, spec.scene, spec.backend});
    }
    return out;
}

nlohmann::json report_energy_jumps(const std::string& dir, const std::vector<DrawnCase>& cases, const Suite* suite,
                                   const std::string& suite_problem, const std::vector<BackendInfo>& backends,
                                   int jobs) {
    std::vector<Found> found(cases.size());
    for_each_index(cases.size(), jobs, [&](std::size_t k) {
        try {
            const CaseResult record = record_of(dir, cases[k]);
            found[k].jump = largest_interval_jump(record.series);
            found[k].hash = numbers_hash(record);
        } catch (const std::exception& e) {  // its record unreadable: said, not dropped
            found[k].unreadable = e.what();
        }
    });
    // A case with a jump whose numbers equal an earlier one's on the same scene is its twin.
    std::vector<std::optional<std::size_t>> twin(cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k)
        for (std::size_t j = 0; j < k && found[k].jump; ++j)
            if (found[j].jump && !twin[j] && cases[j].scene == cases[k].scene && found[j].hash == found[k].hash &&
                same_numbers(record_of(dir, cases[j]), record_of(dir, cases[k]))) {
                twin[k] = j;
                break;
            }
    std::vector<nlohmann::json> jumps(cases.size());
    std::mutex device;
    for_each_index(cases.size(), jobs, [&](std::size_t k) {
        const DrawnCase& d = cases[k];
        if (!found[k].unreadable.empty()) {
            jumps[k] = {{"case", d.id}, {"scene", d.scene}, {"backend", d.backend}, {"explained", nullptr},
                        {"problem", found[k].unreadable}};
            return;
        }
        if (!found[k].jump || twin[k]) return;
        jumps[k] = jump_json(d, *found[k].jump);
        if (!suite) {
            jumps[k]["problem"] = suite_problem;
            return;
        }
        try {
            std::unique_lock<std::mutex> one_device_at_a_time(device, std::defer_lock);
            if (uses_one_device(backends, d.backend)) one_device_at_a_time.lock();
            jumps[k]["explained"] = explanation_json(
                explain_case(dir, *suite, d.id, backends, {}, found[k].jump->t0, found[k].jump->t1));
        } catch (const std::exception& e) {
            jumps[k]["problem"] = e.what();
        }
    });
    for (std::size_t k = 0; k < cases.size(); ++k)
        if (twin[k]) {
            jumps[k] = jump_json(cases[k], *found[k].jump);
            jumps[k]["explained"] = jumps[*twin[k]]["explained"];
            jumps[k]["problem"] = jumps[*twin[k]]["problem"];
            jumps[k]["same_as"] = cases[*twin[k]].id;
        }
    nlohmann::json out = nlohmann::json::array();
    for (auto& j : jumps)
        if (!j.is_null()) out.push_back(std::move(j));
    return {{"jumps", out}};
}

}  // namespace collide::validation
