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
        time_.assign(n, 0.0);
        heap_.resize(n);
        position_.resize(n);
        for (std::size_t k = 0; k < n; ++k) heap_[k] = std::uint32_t(k), position_[k] = std::uint32_t(k);
    }

    bool empty() const { return heap_.empty(); }
    std::uint32_t top() const { return heap_[0]; }  // the particle with the earliest event
    double top_time() const { return time_[heap_[0]]; }
    double time_of(std::uint32_t particle) const { return time_[particle]; }

    // Sets a particle's event time and restores the heap order (up or down as needed).
    void update(std::uint32_t particle, double t) {
        const double old = time_[particle];
        time_[particle] = t;
        const std::size_t k = position_[particle];
        if (t < old) sift_up(k);
        else sift_down(k);
    }

    // Builds the heap from the times set with set_initial (O(N), Floyd's method).
  
    void heapify() {
        for (std::size_t k = heap_.size() / 2; k-- > 0;) sift_down(k);
    }

private:
    bool earlier(std::uint32_t a, std::uint32_t b) const {
        return time_[a] < time_[b] || (time_[a] == time_[b] && a < b);
    }
    void place(std::size_t k, std::uint32_t particle) {
        heap_[k] = particle;
        position_[particle] = std::uint32_t(k);
    }
    void sift_up(std::size_t k) {
        const std::uint32_t moving = heap_[k];
        while (k > 0) {
            const std::size_t parent = (k - 1) / 2;
            if (!earlier(moving, heap_[parent])) break;
            place(k, heap_[parent]);
            k = parent;
        }
        place(k, moving);
    }
    void sift_down(std::size_t k) {
        const std::uint32_t moving = heap_[k];
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

    std::vector<double> time_;            // event time per particle
    std::vector<std::uint32_t> heap_;     // particles in heap order
    std::vector<std::uint32_t> position_; // heap position of each particle
};

}  // namespace collide
