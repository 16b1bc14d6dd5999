#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "bench_suite.h"
#include "core/provenance.h"

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

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
        else out += c;
    }
    return out + "\"";
}

std::string json_value(const Value& v) {
    return std::holds_alternative<std::string>(v) ? json_string(std::get<std::string>(v)) : to_text(v);
}

}  // namespace

void BenchReport::add(const Row& row) {
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
    std::ostringstream json;
    json << "{\n  \"suite\": " << json_string(suite_) << ",\n  \"provenance\": {";
    first = true;
    auto prov = build_provenance();
    prov["command_line"] = command_line();
    for (const auto& [k, v] : prov) json << (first ? "\n    " : ",\n    ") << json_string(k) << ": " << json_string(v), first = false;
    json << "\n  },\n  \"notes\": [";
    first = true;
    for (const auto& n : notes_) json << (first ? "" : ", ") << json_string(n), first = false;
    json << "],\n  \"rows\": [";
    first = true;
    for (const auto& r : rows_) {
        json << (first ? "\n    {" : ",\n    {");
        bool f2 = true;
        for (const auto& [k, v] : r) json << (f2 ? "" : ", ") << json_string(k) << ": " << json_value(v), f2 = false;
        json << "}";
        first = false;
    }
    json << "\n  ]\n}\n";
    for (const auto& [ext, text] : {std::pair{".csv", csv.str()}, std::pair{".json", json.str()}}) {
        const std::string path = prefix + ext, tmp = path + ".tmp";
        std::ofstream f(tmp);
        f << text;
        f.close();
        if (!f || std::rename(tmp.c_str(), path.c_str()) != 0)
            throw std::runtime_error("cannot write benchmark results to " + path);
    }
}

double time_seconds(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace collide::bench
