#include "validation/record/case_result.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <sstream>
#include <string_view>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <toml++/toml.h>

#include "core/io/input_file.h"
#include "core/numerics/crc32.h"
#include "core/io/hdf5_handle.h"
#include "core/io/output_file.h"
#include "core/io/run_reader.h"
#include "core/io/run_schema.h"
#include "validation/record/case_spec.h"

namespace collide::validation {

const char* to_string(RunStatus s) {
    switch (s) {
        case RunStatus::completed: return "completed";
        case RunStatus::left_out: return "left_out";
        case RunStatus::error: return "error";
        case RunStatus::crashed: return "crashed";
        case RunStatus::timed_out: return "timed_out";
    }
    return "error";
}

RunStatus run_status_from_string(const std::string& s) {
    for (auto st : {RunStatus::completed, RunStatus::left_out, RunStatus::error, RunStatus::crashed,
                    RunStatus::timed_out})
        if (s == to_string(st)) return st;
    throw std::invalid_argument("unknown run status '" + s + "'");
}

namespace {

// TOML has nan and inf; toml++ writes and reads them, so columns round-trip as they are.
toml::array to_array(const std::vector<double>& v) {
    toml::array a;
    for (double x : v) a.push_back(x);
    return a;
}

toml::table to_table(const Snapshot& s) {
    return toml::table{{"x", to_array(s.x)}, {"y", to_array(s.y)}, {"vx", to_array(s.vx)},
                       {"vy", to_array(s.vy)}, {"radius", to_array(s.radius)}};
}

template <typename T>
toml::table to_table(const std::map<std::string, T>& m) {
    toml::table t;
    for (const auto& [k, v] : m) t.insert(k, v);
    return t;
}

// The record's first line holds the CRC-32 (core/numerics/crc32.h, Python's zlib.crc32) of every
// byte after it, so a record changed after it was written (a damaged disk, a hand edit, a
// copy cut short) is recognised as damaged instead of being judged.
constexpr std::string_view checksum_prefix = "checksum = \"crc32:";

std::string checksum_line(std::string_view body) { return "checksum = \"" + crc32_text(body) + "\"\n"; }

// The record's layout, as the record states it: the fields this build writes and reads (bump
// `layout` when one is added, removed or retyped) and the columns of [series], which follow the
// run schema (core/io/run_schema.h) by themselves. A record of another layout was written by
// another build of collide: refused as such, not as damage and not read field by field.
constexpr int layout = 1;

const std::string& record_format() {
    static const std::string format = [] {
        std::string columns;
        for (const MetricColumn& column : metric_columns) columns += std::string(column.name) + ",";
        return std::to_string(layout) + ":" + crc32_text(columns);
    }();
    return format;
}

// The record's [spec] table (left_out is not in it: a left-out case's record says why in its
// status and diagnostic).
toml::table spec_table(const CaseSpec& c) {
    toml::table spec{{"id", c.id}, {"scene", c.scene}, {"backend", c.backend},
                     {"reference", c.reference}, {"seed", std::int64_t(c.seed)},
                     {"scene_index", std::int64_t(c.scene_index)}};
    if (c.dt) spec.insert("dt", *c.dt);
    if (c.substeps) spec.insert("substeps", *c.substeps);
    if (c.iterations) spec.insert("iterations", *c.iterations);
    if (!c.parameters.empty()) {
        toml::array parameters;  // an array keeps the sweep order (a table would sort the paths)
        for (const auto& [path, value] : c.parameters) parameters.push_back(toml::table{{"path", path}, {"value", value}});
        spec.insert("parameters", parameters);
    }
    if (!c.definition.empty()) {
        spec.insert("definition_hash", definition_hash(c.definition));
        spec.insert("definition", to_table(c.definition));
    }
    return spec;
}

}  // namespace

void write_case_result(const CaseResult& r, const std::string& path) {
    const toml::table spec = spec_table(r.spec);
    toml::table series;
    for (const MetricColumn& column : metric_columns) {
        toml::array values;
        for (const Metrics& m : r.series) values.push_back(column.value(m));
        series.insert(column.name, values);
    }
    // Derived, not read back (total_energy() recomputes it): for the report's energy figures.
    toml::array total_energy;
    for (const Metrics& m : r.series) total_energy.push_back(m.total_energy());
    series.insert("total_energy", total_energy);
    toml::array trajectory;
    for (const auto& s : r.trajectory) trajectory.push_back(to_table(s));
    toml::table root{{"record_format", record_format()},
                     {"spec", spec},
                     {"status", to_string(r.status)},
                     {"diagnostic", r.diagnostic},
                     {"disks", std::int64_t(r.disks)},
                     {"total_mass", r.total_mass},
                     {"duration", r.duration},
                     {"dt", r.dt},
                     {"substeps", r.substeps},
                     {"wall_seconds", r.wall_seconds},
                     {"warmup_seconds", r.warmup_seconds},
                     {"steps", r.steps},
                     {"contacts", r.contacts},
                     {"phase_seconds", to_table(r.phase_seconds)},
                     {"counters", to_table(r.counters)},
                     {"provenance", to_table(r.provenance)},
                     {"series", series},
                     {"initial", to_table(r.initial)},
                     {"final", to_table(r.final_state)},
                     {"trajectory_time", to_array(r.trajectory_time)},
                     {"trajectory", trajectory},
                     {"twin_separation", to_array(r.twin_separation)},
                     {"overlap_depths", to_array(r.overlap_depths)},
                     {"compressibility", to_array(r.compressibility)},
                     {"hdf5_file", r.hdf5_file}};
    std::ostringstream text;
    text << root << "\n";
    write_file_atomically(path, checksum_line(text.str()) + text.str());  // the guard and rename of every output
}

namespace {

// A record is a few kilobytes; the bound keeps a mistaken file from being read whole.
constexpr std::size_t max_record_bytes = 64u << 20;

// The record's text after its checksum line, once the checksum matches it.
std::string verified_record_text(const std::string& path) {
    std::string text;
    try {  // the input guard (core/io/input_file.h): a FIFO or a device is refused, not waited on
        text = read_input_file(path, max_record_bytes);
    } catch (const InputFileError& e) {
        throw std::runtime_error(path + ": cannot read the case record (" + e.cause() + ")");
    }
    if (text.size() > max_record_bytes) throw std::runtime_error(path + ": more than 64 MiB: not a case record");
    const std::size_t newline = text.find('\n');
    if (text.rfind(checksum_prefix, 0) != 0 || newline == std::string::npos)
        throw std::runtime_error(path + ": damaged case record: no checksum line (cut short, edited, or written "
                                        "by an older collide)");
    const std::string_view body = std::string_view(text).substr(newline + 1);
    if (text.compare(0, newline + 1, checksum_line(body)) != 0)
        throw std::runtime_error(path + ": damaged case record: its checksum does not match its contents");
    text.erase(0, newline + 1);  // in place: a copy of the body was a second allocation the size of the record
    return text;
}

// Every field the writer writes is required, with its type. A record that lacks one, or holds
// one of another type, is damaged: no default stands in for a lost value (a default would read
// a record without its status as an error with an empty message, `steps = "many"` as 0 steps).
class RecordReader {
public:
    explicit RecordReader(const std::string& path) : path_(path) {}

    [[noreturn]] void damaged(const std::string& what) const {
        throw std::runtime_error(path_ + ": damaged case record: " + what);
    }
    const toml::node& node(const toml::table& t, const std::string& key, const std::string& where) const {
        const toml::node* n = t.get(key);
        if (!n) damaged("no field '" + where + key + "'");
        return *n;
    }
    std::string text(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const auto* v = node(t, key, where).as_string();
        if (!v) wrong_type(key, where, "text");
        return v->get();
    }
    std::int64_t integer(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const auto* v = node(t, key, where).as_integer();
        if (!v) wrong_type(key, where, "an integer");
        return v->get();
    }
    double number(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const toml::node& n = node(t, key, where);
        if (!n.is_number()) wrong_type(key, where, "a number");
        return *n.value<double>();
    }
    bool boolean(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const auto* v = node(t, key, where).as_boolean();
        if (!v) wrong_type(key, where, "true or false");
        return v->get();
    }
    const toml::table& table(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const auto* v = node(t, key, where).as_table();
        if (!v) wrong_type(key, where, "a table");
        return *v;
    }
    const toml::array& array(const toml::table& t, const std::string& key, const std::string& where = "") const {
        const auto* v = node(t, key, where).as_array();
        if (!v) wrong_type(key, where, "an array");
        return *v;
    }
    std::vector<double> numbers(const toml::table& t, const std::string& key, const std::string& where = "") const {
        std::vector<double> out;
        for (const toml::node& e : array(t, key, where)) {
            if (!e.is_number()) damaged("'" + where + key + "' holds a value that is not a number");
            out.push_back(*e.value<double>());
        }
        return out;
    }
    Snapshot snapshot(const toml::table& t, const std::string& where) const {
        return {numbers(t, "x", where), numbers(t, "y", where), numbers(t, "vx", where), numbers(t, "vy", where),
                numbers(t, "radius", where)};
    }
    std::map<std::string, double> number_map(const toml::table& t, const std::string& key) const {
        std::map<std::string, double> out;
        for (const auto& [k, v] : table(t, key)) out[std::string(k.str())] = number(table(t, key), std::string(k.str()), key + ".");
        return out;
    }
    std::map<std::string, std::string> text_map(const toml::table& t, const std::string& key) const {
        std::map<std::string, std::string> out;
        for (const auto& [k, v] : table(t, key)) out[std::string(k.str())] = text(table(t, key), std::string(k.str()), key + ".");
        return out;
    }

private:
    [[noreturn]] void wrong_type(const std::string& key, const std::string& where, const std::string& expected) const {
        damaged("field '" + where + key + "' is not " + expected);
    }
    std::string path_;
};

CaseSpec read_spec(const RecordReader& in, const toml::table& root) {
    const toml::table& t = in.table(root, "spec");
    const std::string w = "spec.";
    CaseSpec spec;
    spec.id = in.text(t, "id", w);
    spec.scene = in.text(t, "scene", w);
    spec.backend = in.text(t, "backend", w);
    spec.reference = in.boolean(t, "reference", w);
    spec.seed = std::uint64_t(in.integer(t, "seed", w));
    spec.scene_index = std::size_t(in.integer(t, "scene_index", w));
    // Written only when the case sets them; typed when present.
    if (t.contains("dt")) spec.dt = in.number(t, "dt", w);
    if (t.contains("substeps")) spec.substeps = int(in.integer(t, "substeps", w));
    if (t.contains("iterations")) spec.iterations = int(in.integer(t, "iterations", w));
    if (t.contains("parameters"))
        for (const toml::node& e : in.array(t, "parameters", w)) {
            const toml::table* p = e.as_table();
            if (!p) in.damaged("an entry of 'spec.parameters' is not a table");
            spec.parameters.emplace_back(in.text(*p, "path", w + "parameters."), in.number(*p, "value", w + "parameters."));
        }
    if (t.contains("left_out")) spec.left_out = in.text(t, "left_out", w);
    // A record written before definitions were stored has none: --resume then runs it again.
    if (t.contains("definition")) {
        spec.definition = in.text_map(t, "definition");
        if (in.text(t, "definition_hash", w) != definition_hash(spec.definition))
            in.damaged("'spec.definition_hash' does not match 'spec.definition'");
    }
    return spec;
}

// A record whose checksum holds but whose format is not this build's: written by another
// collide, before or after a change of the record's fields. --resume runs such a case again.
void refuse_another_format(const RecordReader& in, const toml::table& root, const std::string& path) {
    const toml::node* format = root.get("record_format");
    const std::string theirs = format && format->is_string() ? format->value<std::string>().value() : "none";
    if (theirs == "none" && format) in.damaged("field 'record_format' is not text");
    if (theirs != record_format())
        throw std::runtime_error(path + ": a case record of another build of collide (record format " + theirs +
                                 ", this build's " + record_format() +
                                 "): its fields differ from this build's; run the suite again, or run `collide validate "
                                 "... --resume` to run that case again");
}

MetricSeries read_series(const RecordReader& in, const toml::table& root) {
    const toml::table& s = in.table(root, "series");
    const std::string w = "series.";
    MetricSeries rows;
    for (const MetricColumn& column : metric_columns) {
        const std::vector<double> values = in.numbers(s, column.name, w);
        if (column.name == std::string_view("time")) rows.resize(values.size());
        if (values.size() != rows.size()) in.damaged("the columns of [series] differ in length");
        for (std::size_t k = 0; k < rows.size(); ++k) column.assign(rows[k], values[k]);
    }
    return rows;
}

}  // namespace

std::string case_spec_text(const CaseSpec& spec) {
    toml::table table = spec_table(spec);
    if (!spec.left_out.empty()) table.insert("left_out", spec.left_out);
    std::ostringstream text;
    text << toml::table{{"spec", table}};
    return text.str();
}

CaseSpec case_spec_from_text(const std::string& text) {
    const std::string source = "case request";
    try {
        return read_spec(RecordReader(source), toml::parse(text, source));
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(source + ": unreadable: " + std::string(e.description()));
    }
}

CaseResult read_case_result(const std::string& path) {
    const std::string body = verified_record_text(path);
    toml::table root;
    try {
        root = toml::parse(body, path);
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(path + ": unreadable case result: " + std::string(e.description()));
    }
    const RecordReader in(path);
    refuse_another_format(in, root, path);
    CaseResult r;
    r.spec = read_spec(in, root);
    try {
        r.status = run_status_from_string(in.text(root, "status"));
    } catch (const std::invalid_argument& e) {
        in.damaged(e.what());
    }
    r.diagnostic = in.text(root, "diagnostic");
    r.disks = std::size_t(in.integer(root, "disks"));
    r.total_mass = in.number(root, "total_mass");
    r.duration = in.number(root, "duration");
    r.dt = in.number(root, "dt");
    r.substeps = int(in.integer(root, "substeps"));
    r.wall_seconds = in.number(root, "wall_seconds");
    r.warmup_seconds = in.number(root, "warmup_seconds");
    r.steps = in.integer(root, "steps");
    r.contacts = in.integer(root, "contacts");
    r.phase_seconds = in.number_map(root, "phase_seconds");
    r.counters = in.number_map(root, "counters");
    r.provenance = in.text_map(root, "provenance");
    r.series = read_series(in, root);
    r.initial = in.snapshot(in.table(root, "initial"), "initial.");
    r.final_state = in.snapshot(in.table(root, "final"), "final.");
    r.trajectory_time = in.numbers(root, "trajectory_time");
    for (const toml::node& e : in.array(root, "trajectory")) {
        const toml::table* t = e.as_table();
        if (!t) in.damaged("an entry of 'trajectory' is not a table");
        r.trajectory.push_back(in.snapshot(*t, "trajectory[]."));
    }
    r.twin_separation = in.numbers(root, "twin_separation");
    r.overlap_depths = in.numbers(root, "overlap_depths");
    r.compressibility = in.numbers(root, "compressibility");
    r.hdf5_file = in.text(root, "hdf5_file");
    return r;
}

}  // namespace collide::validation

namespace collide::validation {

namespace {

// This machine's name as MPI reports it (Open MPI's MPI_Get_processor_name is the host name).
std::string this_host() {
    char name[256] = {};
    return ::gethostname(name, sizeof name - 1) == 0 ? std::string(name) : std::string();
}

}  // namespace

RunFileExpectation run_file_expectation(const CaseResult& result) {
    RunFileExpectation e;
    e.hdf5_file = result.hdf5_file;
    const auto host = result.provenance.find("hdf5_host");
    if (host != result.provenance.end()) e.hdf5_host = host->second;
    e.outputs = result.series.size();
    e.disks = result.disks;
    return e;
}

std::string run_file_problem(const RunFileExpectation& expected, const std::string& output_dir, bool frames) {
    if (expected.hdf5_file.empty()) return "";
    // A case run by an MPI rank on another node keeps its HDF5 file there (without
    // --gather-hdf5); the record says where, and only that node could check the file.
    if (!expected.hdf5_host.empty() && expected.hdf5_host != this_host()) return "";
    const std::string path = output_dir + "/" + expected.hdf5_file;
    if (!std::filesystem::is_regular_file(path)) return path + ": missing";
    try {
        // Every check of the run file (core/io/run_reader.h), then its agreement with the record.
        const RunFile run(path);
        if (run.output_count() != expected.outputs)
            return path + ": " + std::to_string(run.output_count()) + " outputs where the case record has " +
                   std::to_string(expected.outputs);
        if (expected.disks && run.disk_count() != expected.disks)
            return path + ": " + std::to_string(run.disk_count()) + " disks where the case record has " +
                   std::to_string(expected.disks);
        if (frames && run.has_frames()) run.verify_frames();
    } catch (const RunFileError& e) {
        return e.what();
    } catch (const Hdf5Error& e) {
        return e.what();
    }
    return "";
}

std::string case_files_problem(const CaseResult& result, const std::string& output_dir, bool frames) {
    return run_file_problem(run_file_expectation(result), output_dir, frames);
}

void verify_case_record(const std::string& path) { verified_record_text(path); }

}  // namespace collide::validation
