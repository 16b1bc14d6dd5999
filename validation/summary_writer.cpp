#include "summary_writer.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/output_file.h"
#include "core/provenance.h"
#include "check_table.h"

namespace collide::validation {
namespace {

// nlohmann::ordered_json keeps the keys in the order they are set, so the file lists them in
// the order below (id, scene, backend, ...), as a reader expects. NaN and infinities, which
// JSON lacks, are written as null (the report shows "n/a").
using Json = nlohmann::ordered_json;

// A JSON object built field by field (the chained calls below read like the file they write).
class Object {
public:
    Object& field(const std::string& key, Json value) {
        json_[key] = std::move(value);
        return *this;
    }
    Object& text(const std::string& key, const std::string& v) { return field(key, v); }
    Object& number(const std::string& key, double v) { return field(key, v); }
    Object& integer(const std::string& key, long long v) { return field(key, v); }
    Object& boolean(const std::string& key, bool v) { return field(key, v); }
    const Json& json() const { return json_; }

private:
    Json json_ = Json::object();
};

template <typename Range, typename ToJson>
Json array(const Range& items, ToJson&& to_json) {
    Json out = Json::array();
    for (const auto& item : items) out.push_back(to_json(item));
    return out;
}

Json string_map(const std::map<std::string, std::string>& m) {
    Object o;
    for (const auto& [k, v] : m) o.text(k, v);
    return o.json();
}

const char* to_string(CheckKind kind) {
    switch (kind) {
        case CheckKind::case_check: return "case";
        case CheckKind::trajectory: return "trajectory";
        case CheckKind::statistics: return "statistics";
        case CheckKind::stability: return "stability";
    }
    return "case";
}

// The check table (check_table.h), in its order: the report lays out its columns from it.
Json check_definitions_json() {
    return array(check_table, [](const CheckDefinition& c) {
        Object o;
        o.text("name", c.name).text("kind", to_string(c.kind)).text("measures", c.measures)
            .text("passes_when", c.passes_when).text("tolerance_key", c.tolerance_key).text("applies", c.applies)
            .text("computed_by", c.computed_by);
        return o.json();
    });
}

Json case_json(const CaseResult& r, const Classification* c) {
    Object o;
    o.text("id", r.spec.id).text("scene", r.spec.scene).text("backend", r.spec.backend)
        .boolean("reference", r.spec.reference).text("group", group_id(r.spec))
        .integer("seed", (long long)r.spec.seed).number("dt", r.dt).integer("substeps", r.substeps)
        .field("iterations", r.spec.iterations ? Json(*r.spec.iterations) : Json(nullptr))
        .text("status", to_string(r.status)).text("diagnostic", r.diagnostic)
        .integer("disks", (long long)r.disks).number("duration", r.duration)
        .number("wall_seconds", r.wall_seconds).number("warmup_seconds", r.warmup_seconds)
        .integer("steps", r.steps).integer("contacts", r.contacts)
        .text("result_file", "cases/" + r.spec.id + ".toml").text("hdf5_file", r.hdf5_file)
        .field("provenance", string_map(r.provenance));
    Object phases;
    for (const auto& [k, v] : r.phase_seconds) phases.number(k, v);
    o.field("phase_seconds", phases.json());
    Object parameters;  // path -> value of the scene-parameter sweep point
    for (const auto& [path, value] : r.spec.parameters) parameters.number(path, value);
    o.field("parameters", parameters.json());
    if (c) o.text("outcome", to_string(c->outcome)).text("outcome_reason", c->reason);
    return o.json();
}

Json check_json(const CheckResult& c) {
    Object o;
    o.text("subject", c.subject).text("scene", c.scene).text("backend", c.backend).text("check", c.check)
        .text("status", to_string(c.status)).number("value", c.value).number("tolerance", c.tolerance)
        .text("comparison", c.comparison).text("detail", c.detail);
    // a stepped backend's energy drift, pressure or collision rate: what the rule's model predicts
    // (energy_loss_model.h, statistics_bias_model.h)
    if (!std::isnan(c.predicted))
        o.number("predicted", c.predicted).number("predicted_uncertainty", c.predicted_uncertainty);
    return o.json();
}

Json line_json(const WorkPrecisionLine& line) {
    Object o;
    o.text("scene", line.scene).text("backend", line.backend).text("error_kind", line.error_kind)
        .number("order", line.order ? *line.order : std::nan(""))
        .number("order_standard_error", line.order_standard_error ? *line.order_standard_error : std::nan(""))
        .text("order_note", line.order_note);
    o.field("points", array(line.points, [](const WorkPrecisionPoint& p) {
        Object q;
        q.text("group", p.group).number("dt", p.dt).integer("substeps", p.substeps)
            .integer("iterations", p.iterations).number("seconds_per_time_unit", p.seconds_per_time_unit)
            .number("error", p.error).number("error_standard_error", p.error_standard_error)
            .integer("replicates", (long long)p.replicates);
        return q.json();
    }));
    return o.json();
}

Json physics_row_json(const PhysicsRow& r) {
    Object o;
    o.text("row", r.row).text("scene", r.scene).text("backend", r.backend).text("group", r.group)
        .text("parameter_name", r.parameter_name).number("parameter", r.parameter).text("measured", r.measured)
        .text("estimator", r.estimator).number("value", r.value).number("standard_error", r.standard_error)
        .integer("replicates", (long long)r.replicates).number("reference", r.reference)
        .number("reference_uncertainty", r.reference_uncertainty).text("reference_name", r.reference_name)
        .text("citation", r.citation).number("second_reference", r.second_reference)
        .text("second_reference_name", r.second_reference_name).text("statistic", r.statistic)
        .number("score", r.score).boolean("resolved", r.resolved).text("verdict", to_string(r.verdict))
        .text("detail", r.detail);
    return o.json();
}

Json physics_json(const PhysicsComparison& p) {
    Object o;
    o.field("rows", array(p.rows, physics_row_json));
    o.field("curves", array(p.curves, [](const ReferenceCurve& c) {
        Object q;
        q.text("name", c.name).text("citation", c.citation).field("eta", c.eta).field("z", c.z);
        return q.json();
    }));
    o.number("z_max", physics_z_max);
    return o.json();
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') ? ' ' : c;
        }
    }
    return out;
}

Json cases_json(const SuiteOutcome& outcome) {
    Json out = Json::array();
    for (std::size_t k = 0; k < outcome.cases.size(); ++k) {
        const Classification* c = k < outcome.classifications.size() ? &outcome.classifications[k] : nullptr;
        out.push_back(case_json(outcome.cases[k], c));
    }
    return out;
}

}  // namespace

void write_summary_json(const Suite& suite, const SuiteOutcome& outcome, const std::string& path) {
    Object counts;
    counts.integer("pass", (long long)outcome.count(CheckStatus::pass))
        .integer("fail", (long long)outcome.count(CheckStatus::fail))
        .integer("left_out", (long long)outcome.count(CheckStatus::left_out))
        .integer("physics_fail", (long long)outcome.physics_failures());
    std::map<std::string, std::string> seeds;
    for (const auto& s : suite.scenes) {
        std::string list;
        for (auto seed : s.seeds.empty() ? suite.seeds : s.seeds) {
            if (!list.empty()) list += ' ';
            list += std::to_string(seed);
        }
        seeds[s.name] = list;
    }
    std::map<std::string, std::string> scene_files;
    // Absolute paths: `collide report` and `collide explain` may run from another directory.
    auto absolute = [](const std::string& path) {
        return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
    };
    for (const auto& s : suite.scenes) scene_files[s.name] = absolute(s.path);
    Object root;
    root.text("suite", suite.name).boolean("stability", suite.stability).text("description", suite.description).text("suite_file", absolute(suite.source_path))
        .text("reference", suite.reference).boolean("passed", outcome.passed())
        .number("wall_seconds", outcome.wall_seconds).integer("cases_run", (long long)outcome.cases_run)
        .integer("cases_resumed", (long long)outcome.cases_resumed).field("counts", counts.json())
        .field("provenance", string_map(build_provenance())).text("command_line", command_line())
        .field("execution", string_map(outcome.execution))
        .field("seeds", string_map(seeds)).field("scene_files", string_map(scene_files))
        .field("cases", cases_json(outcome))
        .field("check_definitions", check_definitions_json())
        .field("checks", array(outcome.checks, check_json))
        .field("work_precision", array(outcome.work_precision, line_json))
        .field("physics", physics_json(outcome.physics));
    // Bytes that are not UTF-8 (in a path or a diagnostic) are replaced, not fatal: the summary
    // of a suite that ran for hours must still be written.
    write_file_atomically(path, root.json().dump(1, ' ', false, Json::error_handler_t::replace) + "\n");
}

void write_junit_xml(const Suite& suite, const SuiteOutcome& outcome, const std::string& path) {
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x << "<testsuites name=\"" << xml_escape(suite.name) << "\" tests=\"" << outcome.checks.size()
      << "\" failures=\"" << outcome.count(CheckStatus::fail) << "\" skipped=\""
      << outcome.count(CheckStatus::left_out) << "\" time=\"" << outcome.wall_seconds << "\">\n";
    x << "  <testsuite name=\"" << xml_escape(suite.name) << "\" tests=\"" << outcome.checks.size()
      << "\" failures=\"" << outcome.count(CheckStatus::fail) << "\" skipped=\""
      << outcome.count(CheckStatus::left_out) << "\">\n";
    for (const auto& c : outcome.checks) {
        x << "    <testcase classname=\"" << xml_escape(c.subject) << "\" name=\"" << xml_escape(c.check) << "\"";
        if (c.status == CheckStatus::pass) {
            x << "/>\n";
            continue;
        }
        x << ">\n      <" << (c.status == CheckStatus::fail ? "failure" : "skipped") << " message=\""
          << xml_escape(c.detail) << "\"/>\n    </testcase>\n";
    }
    x << "  </testsuite>\n</testsuites>\n";
    write_file_atomically(path, x.str());
}

}  // namespace collide::validation
