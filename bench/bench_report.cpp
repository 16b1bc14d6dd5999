#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "bench_suite.h"
#include "core/io/output_file.h"
#include "core/io/progress_line.h"
#include "core/io/provenance.h"

namespace collide::bench {
namespace {

std::string to_text(const Value& v) {
    if (auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
    if (auto* d = std::get_if<double>(&v)) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", *d);
        return buf;
    }
    return std::get<std::string>(v);
}

nlohmann::ordered_json json_value(const Value& v) {
    return std::visit([](const auto& x) { return nlohmann::ordered_json(x); }, v);
}

}  // namespace

BenchReport::BenchReport(std::string suite) : suite_(std::move(suite)) {}
BenchReport::~BenchReport() = default;

void BenchReport::expect_work(double total) {
    work_total_ = total;
    work_done_ = 0;
}

void BenchReport::work_done(double amount, const std::string& what) {
    // In a log every step of a suite gets its line (a suite has tens of them, and the order of
    // the measurements is part of what a reader checks); on a terminal one line in place.
    if (!progress_) progress_ = std::make_unique<ProgressLine>(stderr, 0.0);
    work_done_ += amount;
    progress_->update(work_total_ > 0 ? work_done_ / work_total_ : 0.0, "[" + suite_ + "] " + what);
}

void BenchReport::add(const Row& row) {
    if (progress_) progress_->finish();  // the row replaces the progress line on a terminal
    rows_.push_back(row);
    std::string line = "[" + suite_ + "]";
    for (const auto& [k, v] : row) line += " " + k + "=" + to_text(v);
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

void BenchReport::note(const std::string& text) {
    notes_.push_back(text);
    std::printf("[%s] note: %s\n", suite_.c_str(), text.c_str());
}

void BenchReport::write(const std::string& prefix) const {
    std::set<std::string> columns;
    for (const auto& r : rows_)
        for (const auto& kv : r) columns.insert(kv.first);
    std::ostringstream csv;
    bool first = true;
    for (const auto& c : columns) csv << (first ? "" : ",") << c, first = false;
    csv << "\n";
    for (const auto& r : rows_) {
        first = true;
        for (const auto& c : columns) {
            auto it = r.find(c);
            csv << (first ? "" : ",") << (it == r.end() ? "" : to_text(it->second));
            first = false;
        }
        csv << "\n";
    }
    // Keys in the order suite, provenance, notes, rows; each row's keys sorted (Row is a map).
    nlohmann::ordered_json json;
    json["suite"] = suite_;
    auto prov = build_provenance();
    prov["command_line"] = command_line();
    json["provenance"] = nlohmann::ordered_json(prov);
    json["notes"] = notes_;
    json["rows"] = nlohmann::ordered_json::array();
    for (const auto& r : rows_) {
        nlohmann::ordered_json row = nlohmann::ordered_json::object();
        for (const auto& [k, v] : r) row[k] = json_value(v);
        json["rows"].push_back(row);
    }
    const std::string json_text = json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
    // The guard and rename of every output (core/io/output_file.h); both files are written before
    // either is renamed into place, so a failed .json leaves the old .csv untouched too.
    AtomicOutputFile csv_file(prefix + ".csv"), json_file(prefix + ".json");
    csv_file.write(csv.str());
    json_file.write(json_text);
    csv_file.commit();
    json_file.commit();
}

double time_seconds(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace collide::bench
