// The typed reader of backend options (core/scene/option_reader.h): defaults, typed values, range
// checks, the caller's options over the scene's table, and unknown keys refused with where
// they were set (the scene file's line, --set) and the keys that are known.
#include "core/scene/option_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "core/scene/scene_loader.h"
#include "core/scene/scene_overrides.h"

namespace collide {
namespace {

const std::string kScene = R"(description = "options"
[world]
box = [0.0, 0.0, 10.0, 10.0]
[run]
duration = 1.0
output_interval = 0.5
dt = 0.01
[[particles]]
kind = "list"
disks = [{ x = 5.0, y = 5.0, vx = 0.0, vy = 0.0, radius = 0.5, mass = 1.0 }]
[backend.event]
tc = 0.001
renumber_interval = 5000
prefetch = "off"
)";

Scene scene_with(const std::string& extra_lines) { return parse_scene(kScene + extra_lines, "options.toml"); }

// The message of what f throws as BackendOptionError ("" if nothing).
template <typename F>
std::string refusal(F&& f) {
    try {
        f();
    } catch (const BackendOptionError& e) {
        return e.what();
    }
    return "";
}

TEST(OptionReader, TypedValuesAndDefaults) {
    const Scene scene = scene_with("");
    OptionReader r("event", &scene);
    EXPECT_EQ(r.get_double("tc", 7.0, 0, "a duration >= 0"), 0.001);
    EXPECT_EQ(r.get_int("renumber_interval", 1, 1, 1 << 20, "a whole number"), 5000);
    EXPECT_EQ(r.get_choice("prefetch", {"auto", "on", "off"}, "auto"), "off");
    EXPECT_EQ(r.get_double("absent", 2.5, 0, "a number"), 2.5) << "the default when the key is not set";
    EXPECT_FALSE(r.find_int("also_absent", 0, 10, "a number").has_value());
    EXPECT_NO_THROW(r.refuse_unknown());
}

TEST(OptionReader, UnknownKeyIsRefusedWithFileLineAndTheKnownKeys) {
    const Scene scene = scene_with("t_c = 1e-3\n");
    OptionReader r("event", &scene);
    r.get_double("tc", 0, 0, "a duration >= 0");
    r.get_int("renumber_interval", 1, 1, 1 << 20, "a whole number");
    r.get_choice("prefetch", {"auto", "on", "off"}, "auto");
    const std::string message = refusal([&] { r.refuse_unknown(); });
    EXPECT_NE(message.find("options.toml:15: event: scene 'options' [backend.event]"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown key 't_c' (known: tc, renumber_interval, prefetch)"), std::string::npos) << message;
}

TEST(OptionReader, KeySetOnTheCommandLineIsNamedSo) {
    const Scene scene = scene_with_overrides(scene_with(""), {parse_override("backend.event.tcc=1")});
    OptionReader r("event", &scene);
    r.get_double("tc", 0, 0, "a duration >= 0");
    r.get_int("renumber_interval", 1, 1, 1 << 20, "a whole number");
    r.get_choice("prefetch", {"auto", "on", "off"}, "auto");
    const std::string message = refusal([&] { r.refuse_unknown(); });
    EXPECT_EQ(message.rfind("--set backend.event.tcc: event: scene 'options' [backend.event]: unknown key 'tcc'", 0), 0u)
        << message;
}

TEST(OptionReader, WrongTypeIsRefusedWithTheValueAndWhatWasExpected) {
    const Scene scene = scene_with("flag = \"yes\"\ncount = 2.5\nspeed = \"fast\"\n");
    OptionReader r("event", &scene);
    EXPECT_NE(refusal([&] { r.get_bool("flag", false); }).find("options.toml:15: event: scene 'options' [backend.event] "
                                                               "flag = 'yes': expected true or false"),
              std::string::npos);
    EXPECT_NE(refusal([&] { r.get_int("count", 1, 1, 9, "a whole number >= 1"); })
                  .find("count = '2.5': expected a whole number >= 1"),
              std::string::npos);
    EXPECT_NE(refusal([&] { r.get_double("speed", 1, 0, "a speed >= 0"); }).find("speed = 'fast': expected a speed >= 0"),
              std::string::npos);
    EXPECT_NE(refusal([&] { r.get_choice("prefetch", {"auto", "on"}, "auto"); })
                  .find("prefetch = 'off': expected \"auto\" or \"on\""),
              std::string::npos);
}

TEST(OptionReader, OutOfRangeIsRefused) {
    const Scene scene = scene_with("low = -1\nzero = 0\nbig = 11\ninfinite = inf\n");
    OptionReader r("event", &scene);
    EXPECT_NE(refusal([&] { r.get_double("low", 1, 0, "a duration >= 0"); }).find("low = '-1'"), std::string::npos);
    EXPECT_EQ(r.get_double("zero", 1, 0, "a duration >= 0"), 0.0) << "min itself is in range";
    EXPECT_NE(refusal([&] { r.get_double("zero", 1, 0, "a scale > 0", true); }).find("expected a scale > 0"),
              std::string::npos);
    EXPECT_NE(refusal([&] { r.get_int("big", 1, 1, 10, "1..10"); }).find("big = '11': expected 1..10"), std::string::npos);
    EXPECT_EQ(r.get_int("big", 1, 1, 11, "1..11"), 11);
    EXPECT_FALSE(refusal([&] { r.get_double("infinite", 1, 0, "a finite number"); }).empty());
}

// The caller's options (BackendOptions::extra) win over the scene's table, are refused with
// "option" for the table, and an unknown one is refused too.
TEST(OptionReader, CallersOptionsWinAndAreChecked) {
    const Scene scene = scene_with("");
    OptionReader r("event", &scene, {{"tc", "0.5"}, {"bogus", "1"}});
    EXPECT_EQ(r.get_double("tc", 0, 0, "a duration >= 0"), 0.5);
    EXPECT_EQ(refusal([&] { r.refuse_unknown(); }), "event: option: unknown key 'bogus' (known: tc)");
    OptionReader bad("cpu", nullptr, {{"sort_interval", "-1"}});
    EXPECT_EQ(refusal([&] { bad.get_int("sort_interval", 1, 0, 9, "an integer >= 0"); }),
              "cpu: option sort_interval = '-1': expected an integer >= 0");
}

// A value set in code (or by a Python keyword) has no origin: the message starts with the backend.
TEST(OptionReader, ValueSetInCodeHasNoLocation) {
    Scene scene = scene_with("");
    scene.backend_options["event"]["tc"] = "-2";
    scene.backend_option_origins["event"].erase("tc");
    OptionReader r("event", &scene);
    EXPECT_EQ(refusal([&] { r.get_double("tc", 0, 0, "a duration >= 0"); }),
              "event: scene 'options' [backend.event] tc = '-2': expected a duration >= 0");
}

}  // namespace
}  // namespace collide
