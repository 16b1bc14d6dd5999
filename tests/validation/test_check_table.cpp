// The check table (validation/record/check_table.h) is the one list of checks: the tolerance keys and
// the names leave_out accepts come from it, and docs/validation.md describes each check as it
// does.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "tests/support/markdown_table.h"
#include "validation/record/check_table.h"
#include "validation/judge/checks.h"
#include "validation/record/tolerances.h"

namespace collide::validation {
namespace {

TEST(CheckTable, DocsDescribeEveryCheckAsTheTableDoes) {
    const auto rows = test::markdown_table_after("docs/validation.md", "## The checks");
    ASSERT_EQ(rows.size(), check_count) << "docs/validation.md: one row per check of validation/record/check_table.h";
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const CheckDefinition& c = check_table[k];
        ASSERT_EQ(rows[k].size(), 6u) << c.name;
        EXPECT_EQ(rows[k][0], c.name) << "row " << k;
        EXPECT_EQ(rows[k][1], c.measures) << c.name;
        EXPECT_EQ(rows[k][2], c.passes_when) << c.name;
        EXPECT_EQ(rows[k][3], c.tolerance_key) << c.name;
        EXPECT_EQ(rows[k][4], c.applies) << c.name;
        EXPECT_EQ(rows[k][5], c.computed_by) << c.name;
    }
}

TEST(CheckTable, ToleranceKeysAreTheTablesAndSetTheirFields) {
    // The suite-file spellings stay as they were (suites written before the table still read).
    const std::vector<std::string> expected = {"momentum_drift", "energy_drift", "max_overlap", "mean_overlap",
                                               "overlapping_pairs_per_disk", "overlap_beyond_step", "wall_penetration", "trajectory_error",
                                               "statistics_z", "speed_ks_p_value"};
    EXPECT_EQ(tolerance_keys(), expected);
    for (const CheckDefinition& c : check_table) {
        EXPECT_EQ(c.tolerance == nullptr, std::string(c.tolerance_key).empty()) << c.name;
        if (!c.tolerance) continue;
        Tolerances t;
        tolerance_field(t, c.tolerance_key) = 123.5;
        EXPECT_EQ(t.*c.tolerance, 123.5) << c.name << ": " << c.tolerance_key;
        EXPECT_EQ(tolerance_value(t, c.tolerance_key), 123.5);
    }
    Tolerances t;
    EXPECT_THROW(tolerance_field(t, "pressure"), std::invalid_argument) << "a check name is no tolerance key";
}

TEST(CheckTable, CaseChecksComeInTheTablesOrder) {
    CaseResult r;
    r.spec.id = "x";
    r.status = RunStatus::left_out;
    r.diagnostic = "cannot";
    const auto checks = case_checks(r, SceneFeatures{}, Tolerances{}, BackendInfo{});
    const auto names = check_names(CheckKind::case_check);
    ASSERT_EQ(checks.size(), names.size());
    for (std::size_t k = 0; k < names.size(); ++k) EXPECT_EQ(checks[k].check, names[k]);
    EXPECT_EQ(check_names(CheckKind::trajectory), std::vector<std::string>{"trajectory_error"});
    EXPECT_EQ(check_names(CheckKind::statistics),
              (std::vector<std::string>{"pressure", "collision_rate", "speed_distribution"}));
    std::set<std::string> unique;
    for (const CheckDefinition& c : check_table) EXPECT_TRUE(unique.insert(c.name).second) << c.name;
}

}  // namespace
}  // namespace collide::validation
