// Box2D 2.4's built-in profiler, switched off (box2d_profiler.cpp explains why and how).
#pragma once

namespace collide {

// True when this program's b2Timer replaces Box2D's own (b2World::GetProfile() then reads 0).
// Calling it also makes the linker keep box2d_profiler.cpp, whose definitions do the work.
bool box2d_profiler_off();

}  // namespace collide
