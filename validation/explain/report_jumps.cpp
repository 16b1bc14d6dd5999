#include "validation/explain/report_jumps.h"

#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "validation/explain/explain_case.h"
#include "validation/run/case_result.h"

namespace collide::validation {
namespace {

struct DrawnCase {
    std::string id, scene, backend;
    double dt = 0;
    std::int64_t seed = 0;
};

// Scenes whose energy_drift check was judged somewhere (a pass or a fail, not left out).
std::set<std::string> scenes_judging_energy(const nlohmann::json& summary) {
    std::set<std::string> scenes;
    for (const auto& c : summary.at("checks"))
        if (c.at("check") == "energy_drift" && (c.at("status") == "pass" || c.at("status") == "fail"))
            scenes.insert(c.at("scene").get<std::string>());
    return scenes;
}

// Per (scene, backend): the completed case with the smallest dt, then the first seed.
std::vector<DrawnCase> drawn_cases(const nlohmann::json& summary) {
    const std::set<std::string> scenes = scenes_judging_energy(summary);
    const std::string reference = summary.at("reference").get<std::string>();
    std::map<std::pair<std::string, std::string>, DrawnCase> chosen;
    for (const auto& c : summary.at("cases")) {
        if (c.at("status") != "completed" || !c.contains("result_file") || c.at("result_file").is_null()) continue;
        DrawnCase d{c.at("id"), c.at("scene"), c.at("backend"), c.at("dt").is_number() ? c.at("dt").get<double>() : 0.0,
                    c.at("seed").get<std::int64_t>()};
        if (!scenes.count(d.scene) || d.backend == reference) continue;
        auto [it, fresh] = chosen.try_emplace({d.scene, d.backend}, d);
        if (!fresh && (d.dt < it->second.dt || (d.dt == it->second.dt && d.seed < it->second.seed))) it->second = d;
    }
    std::vector<DrawnCase> out;
    for (auto& [key, d] : chosen) out.push_back(d);
    return out;
}

nlohmann::json explain_one(const std::string& dir, const DrawnCase& d, const Suite* suite,
                           const std::string& suite_problem, const std::vector<BackendInfo>& backends,
                           std::mutex& opencl) {
    const CaseResult record = read_case_result(dir + "/cases/" + d.id + ".toml");
    const std::optional<IntervalJump> jump = largest_interval_jump(record.series);
    if (!jump) return nullptr;
    nlohmann::json out = {{"case", d.id}, {"scene", d.scene}, {"backend", d.backend}, {"t0", jump->t0},
                          {"t1", jump->t1}, {"change", jump->change}, {"median", jump->median},
                          {"scale", jump->scale}, {"explained", nullptr}, {"problem", ""}};
    if (!suite) {
        out["problem"] = suite_problem;
        return out;
    }
    try {
        std::unique_lock<std::mutex> one_device_at_a_time(opencl, std::defer_lock);
        if (d.backend.rfind("opencl", 0) == 0) one_device_at_a_time.lock();
        out["explained"] = explanation_json(explain_case(dir, *suite, d.id, backends, {}, jump->t0, jump->t1));
    } catch (const std::exception& e) {
        out["problem"] = e.what();
    }
    return out;
}

}  // namespace

nlohmann::json report_energy_jumps(const std::string& dir, const nlohmann::json& summary, const Suite* suite,
                                   const std::string& suite_problem, const std::vector<BackendInfo>& backends,
                                   int jobs) {
    const std::vector<DrawnCase> cases = drawn_cases(summary);
    std::vector<nlohmann::json> found(cases.size());
    std::atomic<std::size_t> next{0};
    std::mutex opencl;
    auto work = [&] {
        for (std::size_t k = next++; k < cases.size(); k = next++) {
            try {
                found[k] = explain_one(dir, cases[k], suite, suite_problem, backends, opencl);
            } catch (const std::exception& e) {  // its record unreadable: said, not dropped
                found[k] = {{"case", cases[k].id}, {"scene", cases[k].scene}, {"backend", cases[k].backend},
                            {"explained", nullptr}, {"problem", e.what()}};
            }
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < jobs; ++t) threads.emplace_back(work);
    work();
    for (auto& t : threads) t.join();
    nlohmann::json jumps = nlohmann::json::array();
    for (auto& j : found)
        if (!j.is_null()) jumps.push_back(std::move(j));
    return {{"jumps", jumps}};
}

}  // namespace collide::validation
