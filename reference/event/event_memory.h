// Speed layer of the tuned `event` solver: the allocation. The arrays that every event reads
// at random places (the disk records, the calendar slots, the cell list's heads) are
// allocated on 2 MiB huge pages (core/numerics/huge_page_allocator.h), so that a random access needs
// no page-table walk on top of its cache miss once the state outgrows what the TLB reaches
// with 4 KiB pages (about 8 MiB).
//
// What it buys: 0 to 8 % per collision at N = 1e6 (128 MB of records and slots; two rounds of
// `collide bench event --backend event --sizes 1000000` with the kernel's transparent huge
// pages on and off, bench/journal.md, "2026-11-29, fourth entry"), nothing below a few MiB. The
// plain solver (reference/plain_event_solver.cpp) uses ordinary vectors.
// Where the kernel does not follow the advice the memory is ordinary memory: no result depends
// on it.
#pragma once

#include "core/numerics/huge_page_allocator.h"

namespace collide {

// A per-disk array of the tuned event solver: a std::vector on huge pages once it reaches 2 MiB.
template <typename T>
using EventArray = HugePageVector<T>;

}  // namespace collide
