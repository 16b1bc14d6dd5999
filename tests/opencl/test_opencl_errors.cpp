// Bad options and device failures give clear errors (the CLI turns them into a message and a
// non-zero exit).
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/backend_registry.h"
#include "opencl/cl_programs.h"
#include "opencl_test_scenes.h"

namespace collide::test {
namespace {

// Runs `f` and returns the message of the std::exception it throws ("" if none).
template <typename F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

std::string load_error(const BackendOptions& options) {
    const auto c = opencl_cases(1).front();
    return error_of([&] { backend("opencl").create(options)->load(c.scene, c.initial); });
}

TEST(OpenclErrors, UnknownDeviceNameListsTheDevices) {
    BackendOptions options;
    options.device = "no-such-device-anywhere";
    const std::string message = load_error(options);
    EXPECT_NE(message.find("matches no device"), std::string::npos) << message;
    EXPECT_NE(message.find("0: "), std::string::npos) << "the message should list the devices: " << message;
}

TEST(OpenclErrors, DeviceIndexOutOfRange) {
    BackendOptions options;
    options.device = "99";
    EXPECT_NE(load_error(options).find("there are only"), std::string::npos);
}

TEST(OpenclErrors, UnknownGridMode) {
    BackendOptions options;
    options.extra["grid"] = "gpu";
    EXPECT_NE(load_error(options).find("expected \"host\", \"device\" or \"group\""), std::string::npos);
}

TEST(OpenclErrors, InvalidWorkGroupSize) {
    for (const char* size : {"0", "100000000", "many", "64abc"}) {
        BackendOptions options;
        options.extra["local_size"] = size;
        EXPECT_NE(load_error(options).find("invalid work-group size"), std::string::npos) << size;
    }
}

TEST(OpenclErrors, UnknownPrecision) {
    BackendOptions options;
    options.real = "half";
    EXPECT_NE(error_of([&] { backend("opencl").create(options); }).find("expected float or double"),
              std::string::npos);
}

TEST(OpenclErrors, BuildFailurePrintsTheBuildLog) {
    // Redefining the particle type breaks the kernels; the message must carry the log.
    const auto device = opencl::select_device("");
    const std::string message = error_of([&] { opencl::open_session(device, "-D Particle=int"); });
    EXPECT_NE(message.find("building the kernels failed"), std::string::npos) << message;
    EXPECT_NE(message.find("build log:"), std::string::npos) << message;
    EXPECT_NE(message.find("error"), std::string::npos) << "the compiler's own diagnostics: " << message;
}

// The error of loading a small scene whose [backend.opencl] table sets key = value.
std::string scene_option_error(const std::string& key, const std::string& value) {
    auto c = opencl_cases(1).front();
    c.scene.backend_options["opencl"][key] = value;
    return error_of([&] { backend("opencl").create({})->load(c.scene, c.initial); });
}

TEST(OpenclErrors, UnknownSceneKeyIsNamed) {
    const std::string message = scene_option_error("gird", "host");
    EXPECT_NE(message.find("unknown key 'gird'"), std::string::npos) << message;
}

TEST(OpenclErrors, SceneGridKeyIsValidated) {
    const std::string message = scene_option_error("grid", "sideways");
    EXPECT_NE(message.find("grid = 'sideways'"), std::string::npos) << message;
}

TEST(OpenclErrors, InvalidSortIntervalIsNamed) {
    for (const char* value : {"-1", "often", "1.5", "", "3x", "99999999999"}) {
        BackendOptions options;
        options.extra["sort_interval"] = value;
        const std::string message = load_error(options);
        EXPECT_NE(message.find("sort_interval = '" + std::string(value) + "'"), std::string::npos) << message;
        EXPECT_NE(message.find("expected an integer >= 0"), std::string::npos) << message;
    }
}

TEST(OpenclErrors, SceneSortIntervalIsValidated) {
    const std::string message = scene_option_error("sort_interval", "-2");
    EXPECT_NE(message.find("sort_interval = '-2'"), std::string::npos) << message;
}

TEST(OpenclErrors, ValidWorkGroupSizeRuns) {
    BackendOptions options;
    options.extra["local_size"] = "16";  // every OpenCL 1.2 device allows 16 work-items
    EXPECT_EQ(load_error(options), "");
}

}  // namespace
}  // namespace collide::test
