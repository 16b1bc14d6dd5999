// Speed layer of the tuned `event` solver: the event calendar. EventQueue holds the solver's
// coming events. Each particle owns exactly one slot, holding the time of its own earliest
// predicted event; the queue hands out the particle with the earliest time and lets a
// particle's time be changed when it is re-predicted.
//
// One entry per particle (instead of one per predicted pair, as in a heap with lazy deletion)
// keeps the queue at N entries, so its memory does not grow with the density of predictions.
// A particle's entry can become stale when its partner changed course; the solver detects
// that with the partner's event counter when the entry reaches the top and re-predicts the
// particle (the idea of Marin, Risso and Cordero, J. Comput. Phys. 109 (1993) 306).
//
// The calendar (a bucket queue in the spirit of G. Paul, J. Comput. Phys. 221 (2007) 615, run
// as a ring like R. Brown's calendar queue, Commun. ACM 31 (1988) 1220): time is cut into
// buckets of width w, and the next `bucket_count` of them, counted from the one now being
// served, are kept as a ring of unsorted lists. The bucket being served is a small binary
// min-heap (the "front"). A re-predicted particle nearly always lands in a later bucket, which
// costs O(1) (unlink, link) instead of the O(log N) sift of one big heap. When the front runs
// empty the next bucket is poured into it, and the bucket it leaves behind becomes the ring's
// newest. Times beyond the ring wait in an overflow array, which is sorted into the ring every
// half turn; infinite times ("never") wait in an idle list that is never scanned. The width
// is chosen so that a bucket holds a few entries and the ring spans about four median event
// horizons, so only a few per cent of the predictions overflow. The calendar is rebuilt (new
// origin and width) only when it runs empty or its statistics say the width no longer fits
// (too many overflowing entries, or too many entries per bucket), not every turn.
//
// The order is exactly that of one heap over all entries: a bucket's absolute index
// floor((t - t0) / w) never decreases with t, the front holds the entries up to the current
// index, the ring those of the next bucket_count indices and the overflow later ones, and
// inside the front ties are broken by a key per particle (its index at reset), so the order of
// simultaneous events is deterministic. The solver renumbers its particles now and then for
// memory locality; the keys travel with the particles (renumber), so the renumbering does not
// change the order.
//
// Each particle's slot can carry a payload of the caller's (the solver keeps its prediction
// there): the slot is read and written at every event of the particle anyway, so what shares
// its cache line comes without a second memory access.
//
// What it buys, together with the compact records (event_records.h) and local clocks: 3.0x the
// collisions per second of `event-plain`, whose queue is a std::priority_queue of every
// prediction, with prefetching off (N = 1e5, area fraction 0.3, periodic, one core;
// `python3 bench/event_optimisations.py 100000`, median of three runs, before the batched pair
// tests of pair_batch.h, with which it is 3.8x; docs/course/5-making-it-fast.md). Two details of the calendar's own code (the front's
// emptiness tested inline, the short queue of link_soon kept as a ring) took 5 % of the
// instructions per collision off the whole solver (bench/journal.md, "event: the calendar
// without a call per look at the top").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "event_memory.h"
#include "core/numerics/prefetch.h"

namespace collide {

struct NoPayload {};

template <typename Payload = NoPayload>
class EventQueue {
public:
    static constexpr std::uint32_t none = 0xffffffffu;  // no particle (next_upcoming)

    // Empties the queue for n particles with keys 0..n-1; every time is unset until update()
    // sets it.
    void reset(std::size_t n) {
        if (n > max_particles) throw std::length_error("event queue: more than 2^32 - 16 particles");
        node_.assign(n, Node{});
        for (std::uint32_t p = 0; p < n; ++p) node_[p].key = p;
        heap_.clear();
        waiting_first_ = waiting_count_ = 0;
        bucket_count_ = std::uint32_t(std::max<std::size_t>(16, n));
        head_.assign(std::size_t(bucket_count_) + 2, none);  // the ring, then overflow and idle
        overflow_.clear();
        bucketed_ = overflowing_ = idle_ = 0;
        built_ = one_heap_ = false;  // the first top() builds the ring from the times set by then
        for (std::uint32_t p = 0; p < n; ++p) link(p, overflow());
    }

    bool empty() const { return node_.empty(); }
    // The particle with the earliest event, and its time.
    std::uint32_t top() { return settle(), heap_[0].particle; }
    double top_time() { return settle(), heap_[0].time; }
    double time_of(std::uint32_t particle) const { return node_[particle].time; }
    Payload& payload(std::uint32_t particle) { return node_[particle].payload; }
    const Payload& payload(std::uint32_t particle) const { return node_[particle].payload; }
    // How often the calendar was (re)built since reset: for tests and diagnostics.
    std::uint64_t builds() const { return builds_; }

    // Sets a particle's event time and moves it to its bucket (or within the front heap).
    void update(std::uint32_t particle, double t) {
        Node& node = node_[particle];
        const double old = node.time;
        node.time = t;
        const std::uint32_t target = bucket_of(t);
        if (node.bucket == front) {
            if (target == front) {
                heap_[node.index].time = t;
                if (t < old) sift_up(node.index);
                else sift_down(node.index);
                return;
            }
            heap_remove(node.index);
        } else if (node.bucket == waiting) {
            if (target == node.index) return;  // already waiting for that list
            forget_waiting(particle);
        } else {
            if (target == node.bucket) return;  // same unsorted list
            unlink(particle);
        }
        file(particle, target);
    }

    // Look-ahead for prefetching: each call walks one entry further through the lists of the
    // next few ring buckets (the events of the near future, in no particular order within a
    // bucket) and returns that particle, or `none` when the walk has reached its horizon. The
    // caller requests the memory of the particles it is given, so that their cache misses
    // overlap with the work of earlier events. The walk reads only the slots of particles it
    // returned on an earlier call (whose line the caller has requested by then) and the ring's
    // list heads. It is a hint and nothing more: when the entry it reached last has left its
    // list (re-filed, or poured into the front), the walk goes on with the next bucket instead
    // of following that entry's new links; entries filed behind the walk are missed (they were
    // just predicted, so their memory is in the cache anyway).
    std::uint32_t next_upcoming() {
        if (!built_ || one_heap_) return none;
        // Follow the list only while the entry reached last is still in it (not re-filed, and
        // its bucket not yet poured into the front).
        if (ahead_ != none && ahead_index_ > current_ && node_[ahead_].bucket == ring_slot(ahead_index_)) {
            ahead_ = node_[ahead_].next;
            if (ahead_ != none) return ahead_;
        }
        ahead_ = none;
        if (ahead_index_ < current_) ahead_index_ = current_;
        while (ahead_index_ < current_ + look_ahead_buckets) {
            ++ahead_index_;
            ahead_ = head_[ring_slot(ahead_index_)];
            if (ahead_ != none) return ahead_;
        }
        return none;
    }
    // The slot's memory address, for prefetching.
    const void* slot_address(std::uint32_t particle) const { return &node_[particle]; }

    // Renumbers the particles: particle k becomes what particle order[k] was (time, key,
    // payload and place in the calendar); new_of is the inverse of order. The calendar keeps
    // its buckets, so the order of events is unchanged and nothing is rebuilt.
    void renumber(const std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& new_of) {
        link_all_waiting();
        auto renamed = [&](std::uint32_t p) { return p == none ? none : new_of[p]; };
        node_scratch_.resize(node_.size());  // (kept between renumberings: no new pages to clear)
        for (std::size_t k = 0; k < order.size(); ++k) {
            Node node = node_[order[k]];
            node.next = renamed(node.next);
            node.prev = renamed(node.prev);
            node_scratch_[k] = node;
        }
        node_.swap(node_scratch_);
        for (std::uint32_t& h : head_) h = renamed(h);
        for (std::uint32_t& p : overflow_) p = new_of[p];
        for (Entry& e : heap_) e.particle = new_of[e.particle];
        ahead_ = renamed(ahead_);
    }

private:
    static constexpr std::uint32_t front = 0xfffffffeu;
    static constexpr std::uint32_t waiting = 0xfffffffdu;  // bucket of an entry not yet linked (link_soon)
    static constexpr std::uint32_t max_waiting = 4;  // (a power of 2: waiting_place)
    static constexpr std::size_t max_particles = 0xfffffff0u;

    // With a payload the slot is given a cache line of its own (the solver's fills one).
    struct alignas(std::is_empty_v<Payload> ? alignof(double) : 64) Node {
        double time = 0;
        std::uint32_t bucket = 0;      // front, waiting, a ring bucket, overflow() or idle()
        std::uint32_t index = none;    // position in the front heap (front) or in overflow_, or the list it waits for (waiting)
        std::uint32_t next = none, prev = none;  // neighbours in the bucket's list
        std::uint32_t key = 0;         // breaks ties between equal times
        [[no_unique_address]] Payload payload{};
    };

public:
    static constexpr std::size_t slot_bytes = sizeof(Node);

private:
    // The time is stored in the heap next to the particle, so that comparing two children
    // reads one cache line instead of two random places.
    struct Entry {
        double time;
        std::uint32_t particle;
        std::uint32_t key;
    };

    // How many ring buckets beyond the one being served next_upcoming() walks: about a dozen
    // entries. The walk moves one entry per call and the front serves entries at its own pace,
    // so the distance between them drifts; the further ahead the walk may go, the less often
    // the front overtakes it. Four named the most events in the solver (two fewer, six no
    // more; docs/event-driven.md, "Prefetching the coming events").
    static constexpr std::uint64_t look_ahead_buckets = 4;

    // The ring slot of absolute bucket index k (current_ <= k < current_ + bucket_count_).
    std::uint32_t ring_slot(std::uint64_t k) const {
        const std::uint64_t b = current_slot_ + (k - current_);
        return std::uint32_t(b >= bucket_count_ ? b - bucket_count_ : b);
    }

    std::uint32_t overflow() const { return bucket_count_; }
    std::uint32_t idle() const { return bucket_count_ + 1; }

    // Where an entry with time t belongs: the front (its absolute bucket index is the current
    // one or an earlier one), a ring bucket, the overflow, or the idle list (never).
    std::uint32_t bucket_of(double t) const {
        if (!(t < std::numeric_limits<double>::infinity())) return one_heap_ ? front : idle();  // (a NaN too)
        if (!built_) return overflow();
        // The absolute index is k = floor(q), q = (t - t0) / w. With whole numbers current and
        // bucket_count the tests k > current and k - current >= bucket_count read q >= current
        // + 1 and q >= current + bucket_count, and past them q >= 1, so the truncating
        // conversion is k: the same buckets as std::floor, which without SSE4.1 (the portable
        // x86-64 build) is a call of the C library, at every prediction.
        const double q = (t - t0_) / width_;
        if (!(q >= double(current_) + 1)) return front;
        if (q >= double(current_) + double(bucket_count_)) return overflow();
        return ring_slot(std::uint64_t(q));
    }

    // Puts a particle that is in no list into the front heap, the overflow array, or (soon)
    // the list `target`.
    void file(std::uint32_t p, std::uint32_t target) {
        if (target == front) heap_push(p);
        else if (target == overflow()) link(p, target);  // (an append: no list head to wait for)
        else link_soon(p, target);
    }

    // Deferred linking. Linking an entry into a list reads the list's head, which for a ring
    // of N buckets is a cache miss at a random place once N is large, and the processor would
    // wait for it. So an entry bound for a ring bucket or the idle list is linked a few
    // updates later: the head is requested from memory at once and read when the entry is
    // linked. Meanwhile the entry waits in a short queue, which is emptied before a rebuild or
    // a renumbering walks the lists (a refill walks only the overflow, for which no entry
    // waits); when the front runs empty, the waiting entries
    // bound for the bucket poured into it go into the front with that bucket (pour_waiting),
    // and the others keep waiting. A waiting entry's bucket lies beyond the one being served
    // when the update comes (the bucket index is taken then), and it enters the front when its
    // bucket does, so the front, and with it the order of events, is the same as without the
    // wait.
    //
    // The short queue is a ring of max_waiting places (waiting_first_ is the oldest), so that
    // taking the oldest moves nothing: shifting the array down, as it first did, cost a call
    // of the C library's memmove at about every event.
    void link_soon(std::uint32_t p, std::uint32_t target) {
        if (waiting_count_ == max_waiting) link_oldest_waiting();
        prefetch_line(&head_[target]);
        node_[p].bucket = waiting;
        node_[p].index = target;  // (index is free: it is used only in the front and the overflow)
        waiting_[waiting_place(waiting_count_++)] = p;
    }
    void link_oldest_waiting() {
        const std::uint32_t p = waiting_[waiting_first_];
        waiting_first_ = waiting_place(1);
        --waiting_count_;
        link(p, node_[p].index);
    }
    void link_all_waiting() {
        while (waiting_count_ > 0) link_oldest_waiting();
    }
    // Drops a waiting particle from the queue without linking it (it is being re-filed); the
    // younger ones move up one place, so the order stays oldest first.
    void forget_waiting(std::uint32_t p) {
        std::uint32_t k = 0;
        while (waiting_[waiting_place(k)] != p) ++k;
        for (; k + 1 < waiting_count_; ++k) waiting_[waiting_place(k)] = waiting_[waiting_place(k + 1)];
        --waiting_count_;
    }
    // The place in the ring of the k-th oldest waiting particle (max_waiting is a power of 2).
    std::uint32_t waiting_place(std::uint32_t k) const { return (waiting_first_ + k) & (max_waiting - 1); }

    // Makes the front heap non-empty (the queue is not empty). The solver asks for the top
    // about three times per event, and the front is nearly always non-empty: that test stays
    // inline at the caller, the work of refilling the front does not.
    void settle() {
        if (heap_.empty()) refill_front();
    }
    // The entries still waiting (link_soon) stay waiting across a pour, except those bound for
    // the bucket being poured, which go straight into the front: linking them all here would
    // read list heads requested a moment ago, and the processor would wait for each.
    void refill_front() {
        while (heap_.empty()) {
            if (bucketed_ == 0) link_all_waiting();  // (the ring may hold nothing but waiting entries)
            if (!built_ || rebuild_wanted_ || bucketed_ == 0) {
                if (!rebuild()) return;
                continue;
            }
            ++current_;
            if (++current_slot_ == bucket_count_) current_slot_ = 0;
            if (current_ >= refill_at_) refill();  // (no entry waits for the overflow: file() appends it)
            pour_waiting(current_slot_);
            pour(current_slot_);
        }
    }

    // Moves the waiting entries bound for a ring bucket into the front heap.
    void pour_waiting(std::uint32_t bucket) {
        for (std::uint32_t k = 0; k < waiting_count_;) {
            const std::uint32_t p = waiting_[waiting_place(k)];
            if (node_[p].index != bucket) {
                ++k;
                continue;
            }
            forget_waiting(p);
            heap_push(p);
            ++poured_;
        }
    }

    // Moves every entry of a ring bucket into the front heap.
    void pour(std::uint32_t bucket) {
        std::uint32_t count = 0;
        for (std::uint32_t p = head_[bucket], next; p != none; p = next, ++count) {
            next = node_[p].next;
            heap_push(p);
        }
        head_[bucket] = none;
        bucketed_ -= count;
        poured_ += count;
    }

    // Every half turn of the ring: sorts the overflow entries that the ring now reaches into
    // it. An entry that overflowed had a bucket index at least a whole turn ahead, so it is
    // still half a turn ahead at the next refill: no entry is ever passed by. Here the width
    // is also checked against what the last half turn saw.
    // The overflow is an array, not a list, so that the slots it names can be requested ahead
    // of the walk instead of each waiting for the one before it.
    void refill() {
        const std::uint64_t half_turn = bucket_count_ / 2;
        refill_at_ = current_ + half_turn;
        overflow_scratch_.swap(overflow_);
        overflow_.clear();
        overflowing_ = 0;
        constexpr std::size_t ahead = 8;
        const std::size_t m = overflow_scratch_.size();
        for (std::size_t k = 0; k < m; ++k) {
            if (k + ahead < m) prefetch_line(&node_[overflow_scratch_[k + ahead]]);
            const std::uint32_t p = overflow_scratch_[k];
            file(p, bucket_of(node_[p].time));
        }
        // Too narrow: over a quarter of the active entries lie beyond the ring. Too wide: more
        // than 16 entries per bucket on average, so the front heap grows.
        const std::uint32_t active = std::uint32_t(node_.size()) - idle_;
        if (std::uint64_t(overflowing_) * 4 > active || poured_ > 16 * half_turn) rebuild_wanted_ = true;
        poured_ = 0;
    }

    // Starts a new ring at the earliest time not in the front heap (which is empty when this
    // runs); returns false if the queue holds nothing at all. The width makes the ring span
    // four times the median time ahead, so a bucket holds a few entries. Degenerate cases fall
    // back to one heap: if no time is finite (nothing will ever happen) every entry goes to
    // the front and stays there, infinite times included, so that even their order is
    // that of one heap; if all finite times are equal, the width is infinite and the finite
    // ones go there.
    bool rebuild() {
        link_all_waiting();
        ++builds_;
        scratch_particles_.clear();
        auto take_list = [&](std::uint32_t bucket) {
            for (std::uint32_t p = head_[bucket]; p != none; p = node_[p].next) scratch_particles_.push_back(p);
            head_[bucket] = none;
        };
        if (bucketed_ > 0)
            for (std::uint32_t b = 0; b < bucket_count_; ++b) take_list(b);
        scratch_particles_.insert(scratch_particles_.end(), overflow_.begin(), overflow_.end());
        overflow_.clear();
        take_list(idle());
        bucketed_ = overflowing_ = idle_ = 0;
        if (scratch_particles_.empty()) return false;

        scratch_times_.clear();
        for (std::uint32_t p : scratch_particles_)
            if (std::isfinite(node_[p].time)) scratch_times_.push_back(node_[p].time);
        const double infinity = std::numeric_limits<double>::infinity();
        t0_ = -infinity;
        width_ = infinity;  // every finite time falls into bucket 0, the front
        one_heap_ = scratch_times_.empty();  // nothing will ever happen: all in the front
        if (!one_heap_) {
            const std::size_t half = scratch_times_.size() / 2;
            std::nth_element(scratch_times_.begin(), scratch_times_.begin() + std::ptrdiff_t(half), scratch_times_.end());
            t0_ = *std::min_element(scratch_times_.begin(), scratch_times_.begin() + std::ptrdiff_t(half) + 1);
            double span = scratch_times_[half] - t0_;
            if (!(span > 0)) span = *std::max_element(scratch_times_.begin(), scratch_times_.end()) - t0_;
            if (span > 0 && 4 * span / double(bucket_count_) > 0) width_ = 4 * span / double(bucket_count_);
        }
        built_ = true;
        rebuild_wanted_ = false;
        current_ = 0;
        current_slot_ = 0;
        ahead_ = none;
        ahead_index_ = 0;
        refill_at_ = bucket_count_ / 2;
        poured_ = 0;
        for (std::uint32_t p : scratch_particles_) file(p, bucket_of(node_[p].time));
        return true;
    }

    void link(std::uint32_t p, std::uint32_t bucket) {
        Node& node = node_[p];
        node.bucket = bucket;
        if (bucket == overflow()) {
            node.index = std::uint32_t(overflow_.size());
            overflow_.push_back(p);
            ++overflowing_;
            return;
        }
        node.prev = none;
        node.next = head_[bucket];
        if (node.next != none) node_[node.next].prev = p;
        head_[bucket] = p;
        count_of(bucket) += 1;
    }
    void unlink(std::uint32_t p) {
        const Node& node = node_[p];
        if (node.bucket == overflow()) {  // the last entry takes its place
            const std::uint32_t last = overflow_.back();
            overflow_[node.index] = last;
            node_[last].index = node.index;
            overflow_.pop_back();
            --overflowing_;
            return;
        }
        if (node.prev != none) node_[node.prev].next = node.next;
        else head_[node.bucket] = node.next;
        if (node.next != none) node_[node.next].prev = node.prev;
        count_of(node.bucket) -= 1;
    }
    // (The overflow counts its entries itself, in link and unlink.)
    std::uint32_t& count_of(std::uint32_t bucket) {
        return bucket < bucket_count_ ? bucketed_ : idle_;
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

    EventArray<Node> node_;         // per particle: time and place in the calendar
    EventArray<Node> node_scratch_;  // for renumber()
    std::vector<Entry> heap_;           // the front: (time, particle) in heap order
    EventArray<std::uint32_t> head_;  // first particle of each ring bucket, the overflow (always none: overflow_) and idle
    std::vector<std::uint32_t> overflow_, overflow_scratch_;  // the overflow's particles, in no order
    std::vector<std::uint32_t> scratch_particles_;  // for rebuild()
    std::vector<double> scratch_times_;
    std::uint32_t bucket_count_ = 16;   // buckets in the ring
    std::uint32_t bucketed_ = 0, overflowing_ = 0, idle_ = 0;  // entries in the ring, overflow, idle
    bool built_ = false;
    bool rebuild_wanted_ = false;
    bool one_heap_ = false;             // no finite time at the last build: every entry in the front
    std::uint64_t current_ = 0;         // absolute index of the bucket the front serves
    std::uint32_t current_slot_ = 0;    // its place in the ring
    std::uint64_t refill_at_ = 0;       // the absolute index at which the overflow is sorted in
    std::uint64_t poured_ = 0;          // entries poured since the last refill
    std::uint64_t builds_ = 0;
    std::uint32_t waiting_[max_waiting] = {};  // link_soon(): particles not yet linked, a ring
    std::uint32_t waiting_first_ = 0;          // whose oldest is here
    std::uint32_t waiting_count_ = 0;
    std::uint32_t ahead_ = none;        // next_upcoming(): the entry reached last
    std::uint64_t ahead_index_ = 0;     // and the absolute index of the bucket it was reached in
    double t0_ = 0, width_ = 1;         // absolute bucket k covers [t0 + k w, t0 + (k + 1) w)
};

}  // namespace collide
