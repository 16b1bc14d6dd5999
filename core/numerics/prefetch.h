// prefetch_line(p): asks the memory system for the cache line holding p and goes on without
// waiting for it. A hint only: it never faults and changes no result.
//
// Why not __builtin_prefetch alone: GCC 12 at -O2/-O3 deletes a __builtin_prefetch whose
// address comes out of a loop that follows links through a std::vector (CellList::
// prefetch_records, "for (d < depth) j = disks[j].links.next; prefetch(&disks[j])"): the
// whole loop compiled to nothing, silently, and the records it was meant to request were
// never requested (bench/journal.md, "Prefetching the coming events"). An asm statement
// marked volatile cannot be deleted, so on x86 (64- and 32-bit) and AArch64 the instruction
// is written out; elsewhere the builtin stays.
#pragma once

namespace collide {

inline void prefetch_line(const void* p) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#elif defined(__GNUC__) && defined(__aarch64__)
    asm volatile("prfm pldl1keep, %0" : : "Q"(*static_cast<const char*>(p)));
#else
    __builtin_prefetch(p);
#endif
}

}  // namespace collide
