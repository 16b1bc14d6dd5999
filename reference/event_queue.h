// EventQueue: the calendar of the event-driven solver. Each particle owns exactly one slot,
// holding the time of its own earliest predicted event; the queue hands out the particle with
// the earliest time and lets a particle's time be changed when it is re-predicted.
//
// One entry per particle (instead of one per predicted pair, as in a heap with lazy deletion)
// keeps the queue at N entries, so its memory does not grow with the density of predictions.
// A particle's entry can become stale when its partner changed course; the solver detects
// that with the partner's event counter when the entry reaches the top and re-predicts the
// particle (the idea of Marin, Risso and Cordero, J. Comput. Phys. 109 (1993) 306).
//
// The calendar (a bucket queue in the spirit of G. Paul, J. Comput. Phys. 221 (2007) 615):
// time from t0 on is cut into `bucket_count` buckets of width w. The bucket now being served
// is a small binary min-heap (the "front"); later buckets are unsorted lists, and times past
// the last bucket wait in an overflow list. A re-predicted particle nearly always lands in a
// later bucket, which costs O(1) (unlink, link) instead of the O(log N) sift of one big heap,
// and the front heap holds only the few entries of one bucket. When the front runs empty the
// next bucket is poured into it; when the buckets run out, they are rebuilt from the overflow
// (new t0 and w, sized so that a bucket holds about one entry).
//
// The order is exactly that of one heap over all entries: a bucket's index
// floor((t - t0) / w) never decreases with t, so every entry in the front is earlier than every
// entry in a later bucket, and inside the front ties are broken by a key per particle (its
// index unless the caller gives keys), so the order of simultaneous events is deterministic.
// The solver renumbers its particles now and then for memory locality and passes each
// particle's original index as the key, so the renumbering does not change the order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace collide {

class EventQueue {
public:
    // Empties the queue for n particles with keys 0..n-1 (or keys[p], distinct, if given); every
    // time is unset until update() sets it.
    void reset(std::size_t n, const std::uint32_t* keys = nullptr) {
        node_.assign(n, Node{});
        for (std::uint32_t p = 0; p < n; ++p) node_[p].key = keys ? keys[p] : p;
        heap_.clear();
        bucket_count_ = std::max<std::size_t>(16, n);
        head_.assign(bucket_count_ + 1, none);  // the last list is the overflow
        for (std::uint32_t p = 0; p < n; ++p) link(p, overflow());
        current_ = bucket_count_;  // no buckets yet: the first top() builds them from the times set by then
    }

    bool empty() const { return node_.empty(); }
    // The particle with the earliest event, and its time.
    std::uint32_t top() { return settle(), heap_[0].particle; }
    double top_time() { return settle(), heap_[0].time; }
    double time_of(std::uint32_t particle) const { return node_[particle].time; }

    // Sets a particle's event time and moves it to its bucket (or within the front heap).
    void update(std::uint32_t particle, double t) {
        Node& node = node_[particle];
        const double old = node.time;
        node.time = t;
        const std::size_t target = bucket_of(t);
        if (node.bucket == front) {
            if (target == front) {
                heap_[node.index].time = t;
                if (t < old) sift_up(node.index);
                else sift_down(node.index);
                return;
            }
            heap_remove(node.index);
        } else {
            if (target == node.bucket) return;  // same unsorted list
            unlink(particle);
        }
        if (target == front) heap_push(particle);
        else link(particle, target);
    }

private:
    static constexpr std::uint32_t none = 0xffffffffu;
    static constexpr std::size_t front = std::numeric_limits<std::size_t>::max();

    struct Node {
        double time = 0;
        std::size_t bucket = 0;        // front, a bucket number, or overflow()
        std::uint32_t index = none;    // position in the front heap (bucket == front)
        std::uint32_t next = none, prev = none;  // neighbours in the bucket's list
        std::uint32_t key = 0;         // breaks ties between equal times
    };
    // The time is stored in the heap next to the particle, so that comparing two children
    // reads one cache line instead of two random places.
    struct Entry {
        double time;
        std::uint32_t particle;
        std::uint32_t key;
    };

    std::size_t overflow() const { return bucket_count_; }

    // Where an entry with time t belongs: the front (its bucket is the current one or an
    // earlier one), a later bucket, or the overflow.
    std::size_t bucket_of(double t) const {
        if (current_ >= bucket_count_) return overflow();  // buckets not built yet
        if (!(t < std::numeric_limits<double>::infinity())) return overflow();
        const double k = std::floor((t - t0_) / width_);
        if (!(k > double(current_))) return front;  // (a NaN, which no prediction gives, too)
        if (k >= double(bucket_count_)) return overflow();
        return std::size_t(k);
    }

    // Makes the front heap non-empty (the queue is not empty).
    void settle() {
        while (heap_.empty()) {
            if (current_ + 1 < bucket_count_) {
                ++current_;
                pour(current_);
            } else if (!rebuild()) {
                return;
            }
        }
    }

    // Moves every entry of a bucket's list into the front heap.
    void pour(std::size_t bucket) {
        for (std::uint32_t p = head_[bucket], next; p != none; p = next) {
            next = node_[p].next;
            heap_push(p);
        }
        head_[bucket] = none;
    }

    // Starts new buckets at the earliest overflow time; returns false if the overflow is
    // empty. The width makes the buckets hold about one entry each up to the median time.
    // Degenerate cases fall back to one heap: if no time is finite (nothing will ever happen)
    // or all finite times are equal, every entry goes to the front.
    bool rebuild() {
        if (head_[overflow()] == none) return false;
        scratch_.clear();
        for (std::uint32_t p = head_[overflow()]; p != none; p = node_[p].next)
            if (std::isfinite(node_[p].time)) scratch_.push_back(node_[p].time);
        const double infinity = std::numeric_limits<double>::infinity();
        t0_ = infinity;
        width_ = infinity;  // every finite time falls into bucket 0, the front
        if (!scratch_.empty()) {
            const std::size_t half = scratch_.size() / 2;
            std::nth_element(scratch_.begin(), scratch_.begin() + std::ptrdiff_t(half), scratch_.end());
            t0_ = *std::min_element(scratch_.begin(), scratch_.begin() + std::ptrdiff_t(half) + 1);
            double spread = scratch_[half] - t0_, per = double(std::max<std::size_t>(1, half));
            if (!(spread > 0)) spread = *std::max_element(scratch_.begin(), scratch_.end()) - t0_, per = double(scratch_.size());
            if (spread / per > 0) width_ = spread / per;
        }
        current_ = 0;
        std::uint32_t p = head_[overflow()];
        head_[overflow()] = none;
        for (std::uint32_t next; p != none; p = next) {
            next = node_[p].next;
            const std::size_t target = std::isfinite(t0_) ? bucket_of(node_[p].time) : front;
            if (target == front) heap_push(p);
            else link(p, target);
        }
        return true;
    }

    void link(std::uint32_t p, std::size_t bucket) {
        Node& node = node_[p];
        node.bucket = bucket;
        node.prev = none;
        node.next = head_[bucket];
        if (node.next != none) node_[node.next].prev = p;
        head_[bucket] = p;
    }
    void unlink(std::uint32_t p) {
        const Node& node = node_[p];
        if (node.prev != none) node_[node.prev].next = node.next;
        else head_[node.bucket] = node.next;
        if (node.next != none) node_[node.next].prev = node.prev;
    }

    // The front: a binary min-heap ordered by (time, key).
    static bool earlier(const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.key < b.key);
    }
    void place(std::size_t k, const Entry& e) {
        heap_[k] = e;
        node_[e.particle].index = std::uint32_t(k);
    }
    void heap_push(std::uint32_t p) {
        node_[p].bucket = front;
        heap_.push_back(Entry{node_[p].time, p, node_[p].key});
        sift_up(heap_.size() - 1);
    }
    void heap_remove(std::size_t k) {
        const Entry last = heap_.back();
        heap_.pop_back();
        if (k == heap_.size()) return;
        const Entry removed = heap_[k];
        place(k, last);
        if (earlier(last, removed)) sift_up(k);
        else sift_down(k);
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

    std::vector<Node> node_;            // per particle: time and place in the calendar
    std::vector<Entry> heap_;           // the front: (time, particle) in heap order
    std::vector<std::uint32_t> head_;   // first particle of each bucket's list, then the overflow's
    std::vector<double> scratch_;       // times of the overflow, for sizing the buckets
    std::size_t bucket_count_ = 16;
    std::size_t current_ = 0;           // the bucket the front heap serves
    double t0_ = 0, width_ = 1;         // bucket k covers [t0 + k w, t0 + (k + 1) w)
};

}  // namespace collide
