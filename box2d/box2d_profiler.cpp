// Box2D 2.4 times itself: b2World::Step, b2World::Solve and b2Island::Solve each read the wall
// clock through b2Timer (gettimeofday) to fill b2World::GetProfile(), about six readings per
// island per step, and in a dilute gas every free disk is an island of its own. On a virtual
// machine whose clock costs 59 ns a reading, that was 55 % of the processor time of a Box2D
// step of `box_gas_1000` (1000 disks, perf; docs/box2d-baseline.md, "What a step costs"), none of
// it physics, and a share that depends on the machine's clock, not on the engine. Nothing in
// collide reads the profile (its own clock times advance_to), and Box2D 2.4 has no switch for it.
//
// The two member functions are defined here with no clock. libbox2d calls them through its
// procedure linkage table, and a definition in the program comes before the library's in the
// dynamic linker's search (ELF symbol interposition, as a program's own operator new replaces
// the C++ library's), so Box2D's solver runs unchanged and only the stopwatch stops.
// Test: Box2dSolver.TheBuiltInProfilerReadsNoClock.
#include "box2d/box2d_profiler.h"

#include <box2d/b2_timer.h>

void b2Timer::Reset() {}
float b2Timer::GetMilliseconds() const { return 0; }

namespace collide {

bool box2d_profiler_off() { return true; }

}  // namespace collide
