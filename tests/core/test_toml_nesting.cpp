// The nesting guard that runs on a scene file's raw text before toml++ parses it (a file
// nested 10^5 deep overflows the parser's stack): it must pass every real scene and the TOML
// that only looks deep (dots in strings, numbers and comments), and refuse deep nesting with
// the right line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/scene/scene_loader.h"
#include "core/scene/scene_overrides.h"
#include "core/scene/toml_fields.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

std::string refusal(const std::string& text) {
    try {
        check_toml_nesting(text, "t.toml");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(TomlNesting, EveryLibrarySceneIsAccepted) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::scene_file("")))
        if (entry.path().extension() == ".toml") {
            EXPECT_EQ(refusal(test::read_text_file(entry.path().string())), "") << entry.path();
            ++scenes;
        }
    EXPECT_GE(scenes, 20);
}

TEST(TomlNesting, DotsInValuesStringsAndCommentsAreNotKeyParts) {
    const std::string text =
        "a = 1.5 # 1.2.3.4.5.6.7.8.9.10\n"
        "b = \"1.2.3.4.5.6.7.8.9.10 = [[[[[[[[[[\"\n"
        "c = '1.2.3.4.5.6.7.8.9.10'\n"
        "d = \"\"\"\n1.2.3.4.5.6.7.8.9.10 = 1\n[a.b.c.d.e.f.g.h.i.j]\n\"\"\"\n"
        "e = '''\n{{{{{{{{{{\n'''\n"
        "f = [ 1.5, 2.5,\n  3.5, { x.y = 1.25, z = {} }, [] ]\n"
        "\"quoted.key.with.many.dots.in.it.ok\" = 1\n"
        "[a.b.c.d.e.f.g.h]\n"
        "x = 1979-05-27T07:32:00.999Z\n";
    EXPECT_EQ(refusal(text), "");
}

TEST(TomlNesting, TooManyDottedPartsAreRefusedWithTheLine) {
    EXPECT_EQ(refusal("a = 1\n\n[a.b.c.d.e.f.g.h.i]\n").rfind("t.toml:3: a table header or key with more than 8", 0), 0u);
    EXPECT_EQ(refusal("[[a.b.c.d.e.f.g.h.i]]\n").rfind("t.toml:1: ", 0), 0u);
    EXPECT_EQ(refusal("x = \"\"\"\n\n\"\"\"\na.b.c.d.e.f.g.h.i = 1\n").rfind("t.toml:4: ", 0), 0u);
    EXPECT_EQ(refusal("x = [ 1,\n { y = 2, a.b.c.d.e.f.g.h.i = 1 } ]\n").rfind("t.toml:2: ", 0), 0u);
}

TEST(TomlNesting, DeepArraysAndInlineTablesAreRefused) {
    EXPECT_EQ(refusal("x = [[[[[[[[1]]]]]]]]\n"), "") << "8 levels are allowed";
    EXPECT_EQ(refusal("x = [[[[[[[[[1]]]]]]]]]\n").rfind("t.toml:1: arrays or inline tables nested more than 8 deep", 0), 0u);
    EXPECT_NE(refusal("x = {a={a={a={a={a={a={a={a={a=1}}}}}}}}}\n"), "");
}

TEST(TomlNesting, ParseSceneRunsTheGuardBeforeTheParser) {
    std::string deep = "[a";
    for (int k = 0; k < 200000; ++k) deep += ".a";
    try {
        parse_scene(deep + "]\n", "deep.toml");
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("deep.toml:1: a table header or key with more than 8 dotted parts", 0), 0u)
            << e.what();
    }
}

// The same bound for the dotted paths of `--set` and Scene.with_overrides: 150,000 parts
// added 150,000 nested tables, and toml++ destroyed them recursively (a stack overflow).
TEST(TomlNesting, KeyDepthIsBoundedForOverridePaths) {
    const Scene scene = load_scene(test::scene_file("head_on_equal.toml"));
    for (const int parts : {9, 150000}) {
        std::string path = "a";
        for (int k = 1; k < parts; ++k) path += ".a";
        try {
            scene_with_overrides(scene, {{path, "1"}});
            ADD_FAILURE() << "no SceneError for " << parts << " parts";
        } catch (const SceneError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(": --set a.a.a."), std::string::npos) << message;
            EXPECT_NE(message.find("a path with more than 8 dotted parts (it has " + std::to_string(parts) + ")"),
                      std::string::npos) << message;
            EXPECT_LT(message.size(), 400u);
        }
    }
    // 8 parts reach the loader, which names the unknown key.
    EXPECT_THROW(scene_with_overrides(scene, {{"a.a.a.a.a.a.a.a", "1"}}), SceneError);
}

// toml++ 3.3.0 reached a branch it marks unreachable (undefined behaviour) when it asked
// whether a character from U+00A1 to U+049A is whitespace; the scene-parser fuzzer found it
// under UndefinedBehaviorSanitizer (core/io/toml_library.cpp has the fix). Such a character
// where a key or a value belongs is a parse error naming the file and the line.
TEST(TomlNesting, ACharacterFromLatin1SupplementToCyrillicIsAParseErrorNotUndefinedBehaviour) {
    for (const char* character : {"\u00A1", "\u00E9", "\u0416", "\u049A"}) {
        const std::string text = std::string("description = \"x\"\n") + character + " = 1\n";
        try {
            parse_scene(text, "odd.toml");
            ADD_FAILURE() << "no SceneError for " << text;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("odd.toml"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace collide
