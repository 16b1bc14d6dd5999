// Every process an outside program starts ends with the call that started it. A solver that
// daemonises (fork, setsid, fork again) leaves its own process group, so killing the group at
// the end of the call misses it, and the daemon would go on writing into the output directory
// after `collide validate` has exited. A child subreaper (prctl PR_SET_CHILD_SUBREAPER, Linux
// 3.4) adopts every orphaned descendant instead of init: the daemon becomes collide's own
// child, where end_children_except finds, kills and reaps it.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <set>

namespace collide {

// While it lives, this process is the reaper of its orphaned descendants; the previous setting
// comes back at its end, so that a program using collide (a Python interpreter) does not go on
// adopting the orphans of its other children.
class SubreaperScope {
public:
    SubreaperScope();
    ~SubreaperScope();
    SubreaperScope(const SubreaperScope&) = delete;
    SubreaperScope& operator=(const SubreaperScope&) = delete;

private:
    int previous_ = 0;
};

// The processes whose parent is this process now (any of its threads), zombies included:
// from /proc/self/task/*/children, else by a scan of /proc/*/stat.
std::set<pid_t> child_processes();

// Kills (SIGKILL) and reaps every child of this process that is not in `keep`, then the
// children those leave behind (adopted here as their subreaper), until none is left; returns
// how many it ended. Bounded: a program that forks faster than it is killed is cut off after
// 10,000 rounds.
std::size_t end_children_except(const std::set<pid_t>& keep);

}  // namespace collide
