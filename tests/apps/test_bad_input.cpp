// Bad input, systematically. Each scene file in tests/data/bad_scenes/ is wrong in one way
// (a wrong type, a missing or unknown key, a NaN, a count beyond memory, a packing beyond the
// possible, ...) and states in its first lines the message it must produce:
//
//   # expect: 9: [physics].restitution = nan: expected a finite number
//   # expect: <further fragments, anywhere in the message>
//
// The first fragment must follow "FILE:" directly, so it pins the line number too. For every
// file, `collide run FILE --backend step --out EXISTING` must exit non-zero with that message
// on stderr, leave EXISTING byte for byte as it was, and leave no temporary file behind.
// Inputs that cannot carry a comment (an empty file, binary garbage) or are too big to keep in
// the repository (a huge string, nesting 10^5 deep, a 65 MiB file) are written by the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::contains;
using test::ScratchDirectory;

const std::string bad_scene_directory = std::string(COLLIDE_SOURCE_DIR) + "/tests/data/bad_scenes";
const std::string earlier_results = "an earlier run's results\n";

std::vector<std::string> bad_scene_files() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(bad_scene_directory))
        if (entry.path().extension() == ".toml") files.push_back(entry.path().filename().string());
    std::sort(files.begin(), files.end());
    return files;
}

// The "# expect: " lines at the top of a bad scene file.
std::vector<std::string> expected_fragments(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> fragments;
    const std::string marker = "# expect: ";
    for (std::string line; std::getline(in, line) && line.rfind(marker, 0) == 0;)
        fragments.push_back(line.substr(marker.size()));
    return fragments;
}

// Runs `collide run SCENE --backend step --out DIR/earlier.h5` over an existing output and
// checks everything a failing run promises; returns stderr for further checks.
std::string run_expecting_refusal(const std::string& scene, const std::vector<std::string>& fragments,
                                  const ScratchDirectory& dir) {
    const std::string out = dir.file("earlier.h5");
    test::write_text_file(out, earlier_results);
    const std::size_t entries_before = dir.entry_count();
    const auto result = test::run_program(COLLIDE_EXECUTABLE, {"run", scene, "--backend", "step", "--out", out}, dir);
    EXPECT_GT(result.exit_code, 0) << "a clean non-zero exit, not success or a crash";
    EXPECT_TRUE(contains(result.err, "collide: error: " + scene + ":")) << "names the file: " << result.err;
    if (!fragments.empty()) {
        EXPECT_TRUE(contains(result.err, scene + ":" + fragments.front()))
            << "expected\n  " << scene << ":" << fragments.front() << "\nin\n  " << result.err;
    }
    for (std::size_t k = 1; k < fragments.size(); ++k)
        EXPECT_TRUE(contains(result.err, fragments[k])) << "expected " << fragments[k] << " in " << result.err;
    EXPECT_LT(result.err.size(), 1000u) << "one readable message, not an echo of the input";
    EXPECT_EQ(test::read_text_file(out), earlier_results) << "the existing output is unchanged";
    EXPECT_EQ(dir.entry_count(), entries_before) << "no temporary file is left behind";
    return result.err;
}

TEST(BadInput, TheTableHoldsEveryCaseWithItsExpectedMessage) {
    const auto files = bad_scene_files();
    EXPECT_GE(files.size(), 50u) << "cases went missing from " << bad_scene_directory;
    for (const auto& file : files)
        EXPECT_FALSE(expected_fragments(bad_scene_directory + "/" + file).empty())
            << file << " lacks its '# expect: ' line";
}

class BadSceneFile : public testing::TestWithParam<std::string> {};

TEST_P(BadSceneFile, IsRefusedWithItsMessageAndWritesNothing) {
    const std::string scene = bad_scene_directory + "/" + GetParam();
    ScratchDirectory dir;
    run_expecting_refusal(scene, expected_fragments(scene), dir);
}

INSTANTIATE_TEST_SUITE_P(Table, BadSceneFile, testing::ValuesIn(bad_scene_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             return std::filesystem::path(info.param).stem().string();
                         });

// A hostile input written by the test: its text and the fragment that must follow "FILE:".
struct GeneratedInput {
    std::string name;
    std::string (*text)();
    std::string expected;
};

std::string repeated(const std::string& part, std::size_t times) {
    std::string text;
    text.reserve(part.size() * times);
    for (std::size_t k = 0; k < times; ++k) text += part;
    return text;
}

// Deterministic bytes (a linear congruential sequence), starting with a byte that is never
// valid UTF-8, so the parser fails on line 1 whatever follows.
std::string binary_garbage() {
    std::string bytes(4096, '\0');
    std::uint32_t state = 12345;
    for (char& b : bytes) b = char((state = state * 1103515245u + 12345u) >> 24);
    bytes[0] = char(0xff);
    return bytes;
}

const std::string valid_start = "description = \"x\"\n[world]\nbox = [0.0, 0.0, 10.0, 10.0]\n";

const GeneratedInput generated_inputs[] = {
    {"EmptyFile", [] { return std::string(); }, " no keys in the file: expected a scene"},
    {"OnlyComments", [] { return std::string("# a scene, some day\n\n"); }, " no keys in the file"},
    {"BinaryGarbage", binary_garbage, "1: malformed TOML"},
    {"HugeStringWhereANumberBelongs",
     [] { return valid_start + "[physics]\nrestitution = \"" + repeated("x", 20 << 20) + "\"\n"; },
     "5: [physics].restitution = \"xxxxxxxx"},
    {"HugeUnknownKey", [] { return std::string("\"").append(repeated("k", 1 << 20)).append("\" = 1\n"); }, "1: unknown key kkkkkkk"},
    {"TableHeaderNested100000Deep", [] { return "[a" + repeated(".a", 100000) + "]\n"; },
     "1: a table header or key with more than 8 dotted parts"},
    {"ArrayOfTablesNested100000Deep", [] { return "[[a" + repeated(".a", 100000) + "]]\n"; },
     "1: a table header or key with more than 8 dotted parts"},
    {"DottedKeyNested2000000Deep", [] { return valid_start + "a" + repeated(".a", 2000000) + " = 1\n"; },
     "4: a table header or key with more than 8 dotted parts"},
    {"InlineTableKeyNested2000000Deep", [] { return "x = { a" + repeated(".a", 2000000) + " = 1 }\n"; },
     "1: a table header or key with more than 8 dotted parts"},
    {"ArraysNested100000Deep", [] { return "x = " + repeated("[", 100000) + repeated("]", 100000) + "\n"; },
     "1: arrays or inline tables nested more than 8 deep"},
    {"InlineTablesNested100000Deep", [] { return "x = " + repeated("{ a = ", 100000) + "1" + repeated(" }", 100000) + "\n"; },
     "1: arrays or inline tables nested more than 8 deep"},
    {"FileOver64MiB", [] { return repeated(repeated("#", 1023) + "\n", 65 << 10) + valid_start; },
     " more than 64 MiB: expected a scene file of at most 64 MiB"},
};

// Shown by GoogleTest in place of the input's bytes.
void PrintTo(const GeneratedInput& input, std::ostream* out) { *out << input.name; }

class GeneratedBadInput : public testing::TestWithParam<GeneratedInput> {};

TEST_P(GeneratedBadInput, IsRefusedWithItsMessageAndWritesNothing) {
    ScratchDirectory dir;
    const std::string scene = dir.file("hostile.toml");
    test::write_text_file(scene, GetParam().text());
    run_expecting_refusal(scene, {GetParam().expected}, dir);
}

INSTANTIATE_TEST_SUITE_P(Written, GeneratedBadInput, testing::ValuesIn(generated_inputs),
                         [](const testing::TestParamInfo<GeneratedInput>& info) { return info.param.name; });

// Bad command lines over a good scene.
const std::string good_scene = test::scene_file("head_on_equal.toml");

TEST(BadInput, UnknownBackendIsRefusedNamingItAndTheChoices) {
    ScratchDirectory dir;
    const std::string out = dir.file("earlier.h5");
    test::write_text_file(out, earlier_results);
    const auto result =
        test::run_program(COLLIDE_EXECUTABLE, {"run", good_scene, "--backend", "no_such_backend", "--out", out}, dir);
    EXPECT_GT(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "'no_such_backend'")) << result.err;
    EXPECT_TRUE(contains(result.err, "step")) << "lists the backends that exist: " << result.err;
    EXPECT_EQ(test::read_text_file(out), earlier_results);
    EXPECT_EQ(dir.entry_count(), 1u) << "no temporary file is left behind";
}

// A path below a regular file cannot be created by anyone, root included (unlike a directory
// without write permission), so this test means the same on every machine.
TEST(BadInput, OutputBelowARegularFileIsRefusedBeforeTheRun) {
    ScratchDirectory dir;
    const std::string blocker = dir.file("existing_file");
    test::write_text_file(blocker, earlier_results);
    const std::string out = blocker + "/x.h5";
    const auto result = test::run_program(COLLIDE_EXECUTABLE, {"run", good_scene, "--backend", "step", "--out", out}, dir);
    EXPECT_GT(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "cannot write '" + out + "'")) << result.err;
    EXPECT_TRUE(contains(result.err, "is not a directory")) << result.err;
    EXPECT_FALSE(contains(result.out, "scene ")) << "refused before the simulation: " << result.out;
    EXPECT_EQ(test::read_text_file(blocker), earlier_results);
    EXPECT_EQ(dir.entry_count(), 1u) << "no temporary file is left behind";
}

TEST(BadInput, OutputThatIsADirectoryIsRefused) {
    ScratchDirectory dir;
    std::filesystem::create_directory(dir.file("results.h5"));
    const auto result =
        test::run_program(COLLIDE_EXECUTABLE, {"run", good_scene, "--backend", "step", "--out", dir.file("results.h5")}, dir);
    EXPECT_GT(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "a directory of that name exists")) << result.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir.file("results.h5")));
    EXPECT_EQ(dir.entry_count(), 1u) << "no temporary file is left behind";
}

}  // namespace
}  // namespace collide
