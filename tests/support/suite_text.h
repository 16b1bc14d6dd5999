// A suite file written inline in a test: its text with one [[scene]] entry (head_on_equal)
// appended, parsed as "s.toml" in validation/suites, and the refusal such a text meets.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "validation/plan/suite.h"

namespace collide::test {

inline validation::Suite parse_suite_text(const std::string& text) {
    const std::string scene_entry = "\n[[scene]]\nname = \"head_on_equal\"\n";
    return validation::parse_suite(text + scene_entry, "s.toml", std::string(COLLIDE_SOURCE_DIR) + "/validation/suites");
}

// The message of the SuiteError that `text` is refused with; a test failure if it is accepted.
inline std::string suite_refusal(const std::string& text) {
    try {
        parse_suite_text(text);
    } catch (const validation::SuiteError& e) {
        return e.what();
    }
    ADD_FAILURE() << "accepted: " << text;
    return "";
}

}  // namespace collide::test
