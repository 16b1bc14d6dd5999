// Case records (validation/record/case_result.h): a record reads back as written; a record whose
// checksum line is missing or does not match, or that lacks a field or holds one of another
// type, is refused as damaged (so --resume runs its case again) instead of read as defaults.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>
#include <string>

#include "core/numerics/crc32.h"
#include "tests/support/scratch_directory.h"
#include "core/io/run_schema.h"
#include "validation/record/case_result.h"

namespace collide::validation {
namespace {

CaseResult sample() {
    CaseResult r;
    r.spec.id = "gas__step__seed1";
    r.spec.scene = "gas";
    r.spec.backend = "step";
    r.spec.dt = 1e-3;
    r.status = RunStatus::error;
    r.diagnostic = "NaN at t = 0.5";
    r.disks = 2;
    r.steps = 750;
    for (double t : {0.0, 0.5}) {
        Metrics m;
        m.time = t;
        m.kinetic_energy = m.momentum_x = m.momentum_y = 1;
        m.potential_energy = -0.25;
        m.overlapping_pairs = 3;
        m.max_wall_penetration = 0.125;
        r.series.push_back(m);
    }
    r.initial.x = {1, 2};
    r.provenance["rank"] = "0";
    return r;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Applies `edit` to the record's body; with `fresh_checksum` the checksum line is recomputed
// (as a careful hand edit would leave it), so only the field checks can find the fault.
void edit_record(const std::string& path, const std::regex& what, const std::string& by, bool fresh_checksum) {
    const std::string text = read_text(path);
    const auto newline = text.find('\n');
    const std::string body = std::regex_replace(text.substr(newline + 1), what, by);
    const std::string line = fresh_checksum ? "checksum = \"" + crc32_text(body) + "\"\n" : text.substr(0, newline + 1);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << line << body;
}

std::string refusal(const std::string& path) {
    try {
        read_case_result(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(CaseRecord, ReadsBackAsWritten) {
    test::ScratchDirectory dir;
    const std::string path = dir.file("r.toml");
    write_case_result(sample(), path);
    EXPECT_EQ(read_text(path).rfind("checksum = \"crc32:", 0), 0u);
    const CaseResult r = read_case_result(path);
    EXPECT_EQ(r.spec.id, "gas__step__seed1");
    EXPECT_EQ(r.spec.dt, 1e-3);
    EXPECT_EQ(r.status, RunStatus::error);
    EXPECT_EQ(r.diagnostic, "NaN at t = 0.5");
    EXPECT_EQ(r.steps, 750);
    ASSERT_EQ(r.series.size(), 2u);
    EXPECT_EQ(r.series[1].time, 0.5);
    // Every column of the run schema comes back under its own name.
    for (const MetricColumn& column : metric_columns)
        EXPECT_EQ(column.value(r.series[1]), column.value(sample().series[1])) << column.name;
    EXPECT_EQ(r.series[1].potential_energy, -0.25);
    EXPECT_EQ(r.series[1].overlapping_pairs, 3);
    EXPECT_EQ(r.series[1].max_wall_penetration, 0.125);
    EXPECT_EQ(r.provenance.at("rank"), "0");
}

TEST(CaseRecord, MissingStatusIsDamageNotAnError) {
    test::ScratchDirectory dir;
    const std::string path = dir.file("r.toml");
    write_case_result(sample(), path);
    edit_record(path, std::regex("\nstatus = [^\n]*\n"), "\n", true);
    EXPECT_NE(refusal(path).find(path + ": damaged case record: no field 'status'"), std::string::npos) << refusal(path);
}

TEST(CaseRecord, WronglyTypedFieldIsDamageNotZero) {
    test::ScratchDirectory dir;
    const std::string path = dir.file("r.toml");
    write_case_result(sample(), path);
    edit_record(path, std::regex("\nsteps = [^\n]*\n"), "\nsteps = \"many\"\n", true);
    EXPECT_NE(refusal(path).find("field 'steps' is not an integer"), std::string::npos) << refusal(path);
}

TEST(CaseRecord, ChangedOrUnsignedRecordsAreDamaged) {
    test::ScratchDirectory dir;
    const std::string path = dir.file("r.toml");
    write_case_result(sample(), path);
    edit_record(path, std::regex("steps = 750"), "steps = 751", false);
    EXPECT_NE(refusal(path).find("checksum does not match"), std::string::npos) << refusal(path);
    write_case_result(sample(), path);
    const std::string text = read_text(path);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text.substr(text.find('\n') + 1);
    EXPECT_NE(refusal(path).find("no checksum line"), std::string::npos) << refusal(path);
}

TEST(CaseRecord, ARecordOfAnotherBuildIsNamedAsSuchNotAsDamage) {
    // A build with a run-schema column more or less writes another format: its records have
    // fields this build does not read. The checksum holds, so the record is intact; the message
    // says which build wrote it, and --resume runs the case again.
    test::ScratchDirectory dir;
    const std::string path = dir.file("r.toml");
    write_case_result(sample(), path);
    const std::string format = std::regex_replace(read_text(path), std::regex("(?:.|\n)*\nrecord_format = ['\"]([^'\"]*)['\"](?:.|\n)*"), "$1");
    EXPECT_NE(format.find(':'), std::string::npos) << format;
    edit_record(path, std::regex("\nrecord_format = [^\n]*"), "\nrecord_format = \"1:crc32:00000000\"", true);
    const std::string other = refusal(path);
    EXPECT_NE(other.find("a case record of another build of collide (record format 1:crc32:00000000, this build's " + format),
              std::string::npos) << other;
    EXPECT_NE(other.find("--resume"), std::string::npos) << other;
    EXPECT_EQ(other.find("damaged"), std::string::npos) << other;
    // A record from before the format was stated reads the same way.
    write_case_result(sample(), path);
    edit_record(path, std::regex("\nrecord_format = [^\n]*\n"), "\n", true);
    EXPECT_NE(refusal(path).find("record format none"), std::string::npos) << refusal(path);
}

}  // namespace
}  // namespace collide::validation
