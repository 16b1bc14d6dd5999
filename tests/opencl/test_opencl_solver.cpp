// The `opencl` backend against the double `step` reference on the same scenes: the double
// kernels must reproduce `step` to ~1e-12 (same rule, same operation order), the float
// kernels must stay within what float rounding explains over a short horizon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "core/backend_registry.h"
#include "core/run_driver.h"
#include "opencl/cl_devices.h"
#include "opencl_test_scenes.h"

namespace collide::test {
namespace {

// CI runs these on PoCL: a machine without any OpenCL device fails here, loudly, instead of
// skipping the backend's tests.
TEST(OpenclDevice, AtLeastOneDeviceIsAvailable) {
    try {
        const auto devices = opencl::list_devices();
        ASSERT_FALSE(devices.empty());
    } catch (const std::exception& e) {
        FAIL() << "no OpenCL device for the opencl tests (install PoCL: scripts/install-deps.sh): " << e.what();
    }
}

ParticleState<double> run_backend(const std::string& name, const OpenclCase& c, BackendOptions options = {}) {
    auto solver = backend(name).create(options);
    return run_scene(c.scene, *solver, c.initial).final_state;
}

struct Deviation {
    double position = 0, velocity = 0;
};

Deviation max_deviation(const ParticleState<double>& a, const ParticleState<double>& b) {
    Deviation d;
    for (std::size_t i = 0; i < a.size(); ++i) {
        d.position = std::max({d.position, std::fabs(a.x[i] - b.x[i]), std::fabs(a.y[i] - b.y[i])});
        d.velocity = std::max({d.velocity, std::fabs(a.vx[i] - b.vx[i]), std::fabs(a.vy[i] - b.vy[i])});
    }
    return d;
}

double max_speed(const ParticleState<double>& s) {
    double v = 0;
    for (std::size_t i = 0; i < s.size(); ++i) v = std::max(v, std::hypot(s.vx[i], s.vy[i]));
    return v;
}

constexpr int short_horizon = 40;  // steps

TEST(OpenclVsStep, DoubleKernelsMatchStepTo1e12) {
    BackendOptions options;
    options.real = "double";
    for (const auto& c : opencl_cases(short_horizon)) {
        SCOPED_TRACE(c.name);
        const auto reference = run_backend("step", c);
        const auto device = run_backend("opencl", c, options);
        const Deviation d = max_deviation(device, reference);
        // Same rule, same order of operations, IEEE double: only the order of library sqrt/floor
        // implementations could differ. 1e-12 of the box size / the largest speed.
        EXPECT_LE(d.position, 1e-12 * c.scene.world.width());
        EXPECT_LE(d.velocity, 1e-12 * std::max(1.0, max_speed(reference)));
    }
}

TEST(OpenclVsStep, FloatKernelsStayWithinFloatRounding) {
    for (const auto& c : opencl_cases(short_horizon)) {
        SCOPED_TRACE(c.name);
        const auto reference = run_backend("step", c);
        const auto device = run_backend("opencl", c);
        const Deviation d = max_deviation(device, reference);
        // Tolerance from float rounding (unit roundoff u = FLT_EPSILON/2, positions of size L):
        // each sub-step rounds a coordinate a few times (contact sum, x += v h, wall clamp),
        // at most 8 roundings of u L, so after S sub-steps the position error is at most
        // 8 S u L. A contact turns a position error dx into a velocity error of about
        // |v| dx / R (the normal rotates by dx / R, R = contact distance >= 0.5 here); allow
        // one such amplification per particle over the short horizon.
        const int substeps = c.scene.run.order == StepOrder::integrate_first ? c.scene.run.substeps : 1;
        const double u = FLT_EPSILON / 2;
        const double tol_position = 8.0 * short_horizon * substeps * u * c.scene.world.width();
        const double tol_velocity = std::max(1.0, max_speed(reference)) * tol_position / 0.5 +
                                    8.0 * short_horizon * substeps * u * std::max(1.0, max_speed(reference));
        EXPECT_LE(d.position, tol_position);
        EXPECT_LE(d.velocity, tol_velocity);
        RecordProperty(c.name + " position", std::to_string(d.position));
    }
}

TEST(OpenclGrid, HostAndDeviceBuiltGridsGiveBitwiseIdenticalRuns) {
    // Both grids hold every cell's disks in increasing index order, so the kernels visit the
    // same neighbours in the same order and every sum rounds the same way.
    for (const auto& c : opencl_cases(short_horizon)) {
        SCOPED_TRACE(c.name);
        BackendOptions host, device;
        host.extra["grid"] = "host";
        device.extra["grid"] = "device";
        const auto a = run_backend("opencl", c, host);
        const auto b = run_backend("opencl", c, device);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.vy, b.vy);
    }
}

TEST(OpenclGrid, RepeatedRunsAreBitwiseIdentical) {
    // The device grid's atomics scatter disks in timing-dependent order; the per-cell sort
    // must remove that order from the result.
    const auto c = opencl_cases(short_horizon).front();
    BackendOptions device;
    device.extra["grid"] = "device";
    const auto a = run_backend("opencl", c, device);
    const auto b = run_backend("opencl", c, device);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.vx, b.vx);
}

TEST(OpenclVsStep, ContactCountsMatchStep) {
    // A contact with a stone is counted by the moving disk whichever index is lower; with the
    // disks in the scene's order (sort_interval 0) and moved into cell order alike.
    for (const auto& c : opencl_cases(short_horizon)) {  // the last case has stones
        SCOPED_TRACE(c.name);
        auto reference = backend("step").create({});
        const auto r = run_scene(c.scene, *reference, c.initial);
        EXPECT_GT(r.stats.contacts, 0);
        for (const char* sort_interval : {"0", "1"}) {
            SCOPED_TRACE(std::string("sort_interval ") + sort_interval);
            BackendOptions options;
            options.real = "double";
            options.extra["sort_interval"] = sort_interval;
            auto device = backend("opencl").create(options);
            const auto d = run_scene(c.scene, *device, c.initial);
            EXPECT_EQ(d.stats.contacts, r.stats.contacts);
            EXPECT_EQ(d.stats.steps, r.stats.steps);
        }
    }
}

}  // namespace
}  // namespace collide::test
