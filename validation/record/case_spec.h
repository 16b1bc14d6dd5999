// CaseSpec: one case of a suite, as the plan makes it and every later stage reads it (the runner,
// the case record, the checks, the comparisons, the summary). The plan that expands a suite
// into cases is plan/case_plan.h.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace collide::validation {

struct CaseSpec {
    std::string id;                 // e.g. "gas_small__step__dt0.001__sub1__seed2"; a variant
                                    // "box2d[shipped]" appears as "box2d-shipped" (file names)
    std::size_t scene_index = 0;    // into Suite::scenes
    std::string scene;              // scene name
    std::string backend;            // the name the report shows, e.g. "box2d[shipped]"
    bool reference = false;         // this is the suite's reference backend
    std::optional<double> dt;       // overrides of the scene for this sweep point
    std::optional<int> substeps;
    std::optional<int> iterations;
    std::vector<std::pair<std::string, double>> parameters;  // scene-key sweep point (path, value)
    std::uint64_t seed = 1;
    std::string left_out;           // non-empty: the backend refused the scene, with its reason
    // What defines the case, part by part (case_definition.h): filled by the runner before any
    // case runs, stored in the case record, compared by --resume.
    std::map<std::string, std::string> definition;
};

// The id of a case's sweep group: the case id without the "__seed<N>" suffix.
std::string group_id(const CaseSpec& spec);

// One hash over every part of a case's definition (names and hashes): what a record's
// definition_hash holds (the parts themselves: plan/case_definition.h).
std::string definition_hash(const std::map<std::string, std::string>& parts);

}  // namespace collide::validation
