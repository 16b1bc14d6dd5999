// EventQueue: the calendar of the event-driven solver. Each particle owns exactly one slot,
// holding the time of its own earliest predicted event, and the queue is a binary min-heap
// over those N times with an index (particle -> heap position) so that a particle's time
// can be changed in O(log N) when it is re-predicted.
//
// One entry per particle (instead of one per predicted pair, as in a heap with lazy deletion)
// keeps the heap at N entries, so its memory and its depth do not grow with the density of
// predictions. A particle's entry can become stale when its partner changed course; the
// solver detects that with the partner's event counter when the entry reaches the top and
// re-predicts the particle (the idea of Marin, Risso and Cordero, J. Comput. Phys. 109 (1993)
// 306, with a heap instead of their tournament tree).
//
// Ties are broken by particle index, so the order of simultaneous events is deterministic.
#pragma once

#include <cstdint>
#include <vector>

namespace collide {

class EventQueue {
public:
    void reset(std::size_t n) {
        heap_.resize(n);
        position_.resize(n);
        for (std::size_t k = 0; k < n; ++k) heap_[k] = Entry{0.0, std::uint32_t(k)}, position_[k] = std::uint32_t(k);
    }

    bool empty() const { return heap_.empty(); }
    std::uint32_t top() const { return heap_[0].particle; }  // the particle with the earliest event
    double top_time() const { return heap_[0].time; }
    double time_of(std::uint32_t particle) const { return heap_[position_[particle]].time; }

    // Sets a particle's event time and restores the heap order (up or down as needed).
    void update(std::uint32_t particle, double t) {
        const std::size_t k = position_[particle];
        const double old = heap_[k].time;
        heap_[k].time = t;
        if (t < old) sift_up(k);
        else sift_down(k);
    }

private:
    // The time is stored in the heap next to the particle, so that comparing two children
    // reads one cache line instead of two random places (this dominates at N = 1e6).
    struct Entry {
        double time;
        std::uint32_t particle;
    };
    static bool earlier(const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.particle < b.particle);
    }
    void place(std::size_t k, const Entry& e) {
        heap_[k] = e;
        position_[e.particle] = std::uint32_t(k);
    }
    void sift_up(std::size_t k) {
        const Entry moving = heap_[k];
        while (k > 0) {
            const std::size_t parent = (k - 1) / 2;
            if (!earlier(moving, heap_[parent])) break;
            place(k, heap_[parent]);
            k = parent;
        }
        place(k, moving);
    }
    void sift_down(std::size_t k) {
        const Entry moving = heap_[k];
        const std::size_t n = heap_.size();
        for (;;) {
            std::size_t child = 2 * k + 1;
            if (child >= n) break;
            if (child + 1 < n && earlier(heap_[child + 1], heap_[child])) ++child;
            if (!earlier(heap_[child], moving)) break;
            place(k, heap_[child]);
            k = child;
        }
        place(k, moving);
    }

    std::vector<Entry> heap_;             // (time, particle) in heap order
    std::vector<std::uint32_t> position_; // heap position of each particle
};

}  // namespace collide
