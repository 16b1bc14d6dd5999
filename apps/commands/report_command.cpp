// `collide report DIR`: renders DIR/report/index.html (self-contained, figures embedded) and
// DIR/report/summary.md from the results of `collide validate`, with the Python renderer in
// validation/report/ run by the interpreter CMake found (Debian's matplotlib, numpy, jinja2).
// It reads and draws: every verdict, and the energy jumps' explanations, were decided by
// `collide validate` and are read from summary.json. No solver runs here, and nothing that
// summary.json names (its suite file, a solver beside it) is executed (docs/refusals.md,
// "What collide never does").

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/input_file.h"
#include "apps/python_script.h"
#include "apps/resource_path.h"
#include "apps/input_paths.h"
#include "commands.h"
#include "core/io/output_file.h"
#include "validation/record/case_result.h"
#include "validation/suite_runner.h"

namespace collide::cli {
namespace {

// DIR/summary.json. Only the fields read here are checked; the renderer checks the whole file
// (digest.load_summary).
nlohmann::json read_summary(const std::string& dir) {
    const std::string path = dir + "/summary.json";
    nlohmann::json summary;
    try {  // through the input guard (core/io/input_file.h): a FIFO or a device is refused
        summary = nlohmann::json::parse(read_input_file(path, max_text_input_bytes));
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
    }
    if (!summary.is_object() || !summary.contains("cases") || !summary["cases"].is_array())
        throw std::runtime_error(path + ": no list 'cases'; expected the summary of `collide validate`");
    return summary;
}

// The cases summary.json lists, by id (their records are cases/<id>.toml).
using ListedCases = std::map<std::string, const nlohmann::json*>;
ListedCases listed_cases(const nlohmann::json& summary) {
    ListedCases cases;
    for (const auto& c : summary["cases"])
        if (c.is_object() && c.contains("id") && c["id"].is_string()) cases.emplace(c["id"].get<std::string>(), &c);
    return cases;
}

// Files in cases/ that belong to no listed case (a case of an earlier suite, an editor's
// backup): not read, and named, so that nobody takes them for part of this report.
void warn_about_stray_files(const std::string& dir, const ListedCases& ids) {
    std::vector<std::string> stray;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir + "/cases", error)) {
        const std::string name = entry.path().filename().string();
        const auto dot = name.rfind('.');
        const std::string stem = name.substr(0, dot), extension = dot == std::string::npos ? "" : name.substr(dot);
        if (!((extension == ".toml" || extension == ".log") && ids.count(stem))) stray.push_back(name);
    }
    if (stray.empty()) return;
    std::sort(stray.begin(), stray.end());
    std::string names;
    for (std::size_t i = 0; i < stray.size() && i < 10; ++i) names += (i ? ", " : "") + stray[i];
    if (stray.size() > 10) names += ", and " + std::to_string(stray.size() - 10) + " more";
    std::fprintf(stderr, "report: warning: %s/cases holds %zu file(s) that summary.json does not list, not used: %s\n",
                 dir.c_str(), stray.size(), names.c_str());
}

// The run file a case's summary entry describes, or nothing when the entry predates the
// count of outputs (summary.json of an older collide: its record is parsed for the counts).
std::optional<validation::RunFileExpectation> expectation_from_summary(const nlohmann::json& entry) {
    if (!entry.contains("outputs") || !entry["outputs"].is_number_unsigned() || !entry.contains("disks") ||
        !entry["disks"].is_number_unsigned() || !entry.contains("hdf5_file") || !entry["hdf5_file"].is_string())
        return std::nullopt;
    validation::RunFileExpectation e;
    e.hdf5_file = entry["hdf5_file"].get<std::string>();
    e.outputs = entry["outputs"].get<std::size_t>();
    e.disks = entry["disks"].get<std::size_t>();
    const auto provenance = entry.find("provenance");
    if (provenance != entry.end() && provenance->is_object() && provenance->contains("hdf5_host") &&
        (*provenance)["hdf5_host"].is_string())
        e.hdf5_host = (*provenance)["hdf5_host"].get<std::string>();
    return e;
}

// One case's files, or "" when they can be trusted. Every record's bytes are checked against
// its checksum; a record the renderer reads (a drawn case's) is parsed in full, the others'
// run files are checked against the counts summary.json holds for them. Parsing every record
// took most of the report's own time (about 190 MB of TOML on the default suite).
std::string case_problem(const std::string& dir, const nlohmann::json& entry, std::mutex& hdf5) {
    const std::string id = entry["id"].get<std::string>();
    const std::string record = dir + "/cases/" + id + ".toml";
    if (!std::filesystem::exists(record)) return "";  // the renderer names it if it needs it
    try {
        const bool drawn = entry.value("drawn", false);
        std::optional<validation::RunFileExpectation> expected = drawn ? std::nullopt : expectation_from_summary(entry);
        if (expected) {
            validation::verify_case_record(record);
        } else {
            const validation::CaseResult result = validation::read_case_result(record);
            expected = validation::run_file_expectation(result);
        }
        const std::lock_guard<std::mutex> lock(hdf5);
        return validation::run_file_problem(*expected, dir, false);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
}

// Every listed case's record and HDF5 file must be intact (core/io/run_reader.h): a damaged or
// truncated one (a full disk, a copy cut short, a flipped bit) is named here rather than
// drawn from, or failing deep in Python. The frames are left to `collide render`, which checks
// those it draws. The records are read on every core at once; the HDF5 library is not
// thread-safe, so the run files are checked one at a time. The first problem by case id is named.
void check_case_files(const std::string& dir, const nlohmann::json& summary) {
    const ListedCases listed = listed_cases(summary);  // by id, so the first problem named is by id
    warn_about_stray_files(dir, listed);
    std::vector<const nlohmann::json*> cases;
    for (const auto& [id, entry] : listed) cases.push_back(entry);
    std::vector<std::string> problems(cases.size());
    std::atomic<std::size_t> next{0};
    std::mutex hdf5;
    auto work = [&] {
        for (std::size_t k = next++; k < cases.size(); k = next++) problems[k] = case_problem(dir, *cases[k], hdf5);
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < validation::default_jobs(); ++t) threads.emplace_back(work);
    work();
    for (auto& t : threads) t.join();
    for (const std::string& problem : problems)
        if (!problem.empty())
            throw std::runtime_error(problem + "; run `collide validate ... --resume` to run that case again");
}

// The files the renderer writes, checked before it starts (core/io/output_file.h; the renderer
// checks them again with python/collide/safe_output.py, its Python twin).
void check_report_outputs(const std::string& report_dir) {
    check_output_directory(report_dir);
    if (!std::filesystem::is_directory(report_dir)) return;  // created empty by the renderer
    for (const char* name : {"index.html", "checks.html", "checks.csv", "summary.md", "summary-full.md"})
        check_output_path(report_dir + "/" + name);
}

void execute(const std::string& dir) {
    if (!std::filesystem::exists(dir + "/summary.json"))
        throw std::runtime_error(dir + "/summary.json: not found; expected the output directory of `collide validate`");
    check_report_outputs(dir + "/report");  // first: refused at once, before reading every run file
    // A kill during the summary's rename leaves its temporary beside it: removed, and said.
    for (const std::string& name : remove_stale_temporaries(dir))
        std::fprintf(stderr, "report: removed %s/%s, a temporary file an interrupted run left\n", dir.c_str(), name.c_str());
    const nlohmann::json summary = read_summary(dir);
    check_case_files(dir, summary);  // every record's checksum, once: the renderer does not check them again
    const std::string script = resource_path("validation/report") + "/make_report.py";
    // The renderer calls this program back (`collide render` for motion strips):
    // run_python_script tells it which one.
    const int status = run_python_script(script, {dir});
    // Exit status 2: an input file is malformed; the renderer has named it and what is wrong.
    if (status == 2)
        throw std::runtime_error("no report written: " + dir + " holds a malformed input (named above)");
    // Exit status 3: an output path was refused (safe_output.py, the twin of the check above,
    // for what changed after it).
    if (status == 3)
        throw std::runtime_error("no report written: an output path was refused (named above)");
    if (status != 0)
        throw std::runtime_error(std::string("the report renderer failed (") + python_interpreter() + " " + script + ")");
}

}  // namespace

void add_report_command(CLI::App& app) {
    auto dir = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("report", "Render DIR/report/index.html and summary.md from `collide validate` results");
    cmd->add_option("dir", *dir, "Output directory of `collide validate`")->required()->check(readable_directory());
    cmd->callback([dir] { execute(*dir); });
}

}  // namespace collide::cli
