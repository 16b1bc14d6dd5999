// CellList: the neighbour structure of the event-driven solver. The box is cut into cells at
// least one contact distance wide (2 r_max), so a disk can only touch disks whose centres lie
// in its own cell or in one of the 8 around it. Unlike the stepping backends' UniformGrid,
// which is rebuilt every step, this list is kept up to date incrementally: a disk changes cell
// only at a "cell crossing" event, an O(1) unlink/link of an intrusive doubly linked list.
// That is what makes the cost per event independent of N (Rapaport, "The Art of Molecular
// Dynamics Simulation", 2nd ed., section 14.2).
//
// The list is intrusive: the links (`CellLinks`) live inside the caller's per-disk record,
// next to the disk's position and velocity. Walking a cell then reads one record per
// neighbour, and that record already holds everything a collision prediction needs, so a
// neighbour costs one cache line (event_records.h, `EventDisk`). The list itself only owns the
// first disk of every cell. Every method that follows links takes the records as `disks`,
// any indexable container whose elements have a member `links`.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "event_memory.h"
#include "core/numerics/prefetch.h"
#include "core/scene/scene.h"
#include "core/uniform_grid.h"

namespace collide {

// A disk's place in the cell list: its cell and its neighbours in that cell's list.
struct CellLinks {
    static constexpr std::uint32_t none = 0xffffffffu;
    std::uint32_t cell = 0;
    std::uint32_t next = none, prev = none;
};

class CellList {
public:
    static constexpr std::uint32_t none = CellLinks::none;

    // min_cell_size: the largest contact distance. The cell count is capped (a huge, nearly
    // empty box) by making cells larger, which stays correct and only costs speed.
    void configure(const World& world, double min_cell_size, std::size_t particles) {
        world_ = world;
        periodic_ = world.boundary == Boundary::periodic;
        cells_x_ = cells_along(world.width(), min_cell_size);  // (clamped: core/uniform_grid.h)
        cells_y_ = cells_along(world.height(), min_cell_size);
        const double max_cells = double(std::max<std::int64_t>(std::int64_t(1) << 20, 4 * std::int64_t(particles)));
        while (double(cells_x_) * double(cells_y_) > max_cells) {
            if (cells_x_ >= cells_y_) cells_x_ = std::max<std::int64_t>(1, cells_x_ / 2);
            else cells_y_ = std::max<std::int64_t>(1, cells_y_ / 2);
        }
        cell_w_ = world.width() / double(cells_x_);
        cell_h_ = world.height() / double(cells_y_);
        head_.assign(std::size_t(cells_x_ * cells_y_), none);
    }

    std::int64_t cells_x() const { return cells_x_; }
    std::int64_t cells_y() const { return cells_y_; }

    // The cell column/row containing coordinate x/y (clamped to the box).
    std::int64_t column_of(double x) const { return clamp(std::int64_t((x - world_.xmin) / cell_w_), cells_x_); }
    std::int64_t row_of(double y) const { return clamp(std::int64_t((y - world_.ymin) / cell_h_), cells_y_); }
    std::uint32_t cell_of(double x, double y) const { return std::uint32_t(row_of(y) * cells_x_ + column_of(x)); }

    // Left/lower border of column/row c. The same expression is used for every crossing so
    // that a disk that crossed a border sits exactly on the border of its new cell.
    double border_x(std::int64_t c) const { return world_.xmin + double(c) * cell_w_; }
    double border_y(std::int64_t c) const { return world_.ymin + double(c) * cell_h_; }

    std::int64_t column(const CellLinks& l) const { return l.cell % cells_x_; }
    std::int64_t row(const CellLinks& l) const { return l.cell / cells_x_; }

    template <typename Disks>
    void insert(Disks& disks, std::uint32_t i, std::int64_t column, std::int64_t row) {
        const std::uint32_t c = std::uint32_t(row * cells_x_ + column);
        CellLinks& l = disks[i].links;
        l.cell = c;
        l.prev = none;
        l.next = head_[c];
        if (head_[c] != none) disks[head_[c]].links.prev = i;
        head_[c] = i;
    }

    template <typename Disks>
    void remove(Disks& disks, std::uint32_t i) {
        const CellLinks& l = disks[i].links;
        if (l.prev != none) disks[l.prev].links.next = l.next;
        else head_[l.cell] = l.next;
        if (l.next != none) disks[l.next].links.prev = l.prev;
    }

    // Calls visit(j) for every disk j in the 3x3 neighbourhood of disk i's cell (i included).
    template <typename Disks, typename Visit>
    void for_each_neighbour(const Disks& disks, std::uint32_t i, Visit&& visit) const {
        const std::int64_t cx = column(disks[i].links), cy = row(disks[i].links);
        if (!interior(cx, cy)) {
            for_each_in_block(disks, cx - 1, cx + 1, cy - 1, cy + 1, visit);
            return;
        }
        // Away from the edges no cell wraps or falls outside. The nine list heads are read
        // first and their first records requested from memory together: walking a list one
        // record after another would wait for each cache miss in turn.
        std::uint32_t first[9];
        read_interior_heads(disks, cx, cy, first);
        for (std::uint32_t head : first)
            for (std::uint32_t j = head; j != none; j = disks[j].links.next) visit(j);
    }

    // Prefetching. Successive events of the solver fall at unrelated places in the box, so once
    // the disk records outgrow the cache, walking a block of cells means a chain of cache
    // misses: the list heads, then the records they name, then the records those name. The
    // solver knows the coming events a few events ahead and walks each chain one link per
    // event ahead of time (prefetch_pipeline.h), with the methods below. They only
    // request memory; nothing they do changes a result.

    // A rectangle of cells, columns x0..x1 and rows y0..y1; empty when any of its cells would
    // wrap around a periodic side or fall outside the grid (such blocks are not prefetched).
    struct Block {
        std::int64_t x0 = 0, x1 = -1, y0 = 0, y1 = -1;
    };
    // The 3x3 block around a disk's cell (what for_each_neighbour walks).
    Block neighbourhood_block(const CellLinks& l) const {
        const std::int64_t cx = column(l), cy = row(l);
        return inside({cx - 1, cx + 1, cy - 1, cy + 1});
    }
    // The cells a coming crossing of `border` by a disk in cell l reads, as one 2x3 (or 3x2)
    // block: the cell it enters (whose list it joins), the three beyond (which
    // for_each_entered walks), and the two cells beside the one it enters, which only a
    // crossing whose kept partner has changed course reads (it predicts afresh over the whole
    // 3x3 block). Requesting those two as well keeps the prefetch to one rectangle.
    Block crossing_block(const CellLinks& l, std::uint32_t border) const {
        return inside(beyond_border(column(l), row(l), border, 1, 2));
    }
    // Requests the list heads of a block (each row of at most three heads lies within at
    // most two cache lines).
    void prefetch_heads(const Block& b) const {
        for (std::int64_t y = b.y0; y <= b.y1; ++y) {
            prefetch_line(&head_[std::size_t(y * cells_x_ + b.x0)]);
            prefetch_line(&head_[std::size_t(y * cells_x_ + b.x1)]);
        }
    }
    // Requests the record at `depth` (0: the first, 1: the second) of each list of a block,
    // reading the heads (and for depth 1 the first records), which should have been requested
    // an event earlier.
    template <typename Disks>
    void prefetch_records(const Disks& disks, const Block& b, int depth) const {
        for (std::int64_t y = b.y0; y <= b.y1; ++y)
            for (std::int64_t x = b.x0; x <= b.x1; ++x) {
                std::uint32_t j = head_[std::size_t(y * cells_x_ + x)];
                for (int d = 0; d < depth && j != none; ++d) j = disks[j].links.next;
                prefetch_line(&disks[record_or_first(j)]);
            }
    }
    // Requests the first record of each list around disk i's cell.
    template <typename Disks>
    void prefetch_neighbourhood(const Disks& disks, std::uint32_t i) const {
        prefetch_records(disks, neighbourhood_block(disks[i].links), 0);
    }

    // Whether the disks a disk in this cell can touch need the minimum-image convention: only
    // in a periodic box, and there only in the cells along the edges (a neighbour in the 3x3
    // block of an interior cell lies less than 2 cells away, which is less than half the box
    // once the box has at least 4 cells per axis).
    bool needs_minimum_image(const CellLinks& l) const {
        return periodic_ && !(cells_x_ >= 4 && cells_y_ >= 4 && interior(column(l), row(l)));
    }

    // Calls visit(j) for every disk j in the cells that disk i's neighbourhood gained when i
    // crossed `border` into its current cell (0/1: it moved to lower/higher x, 2/3: lower/higher
    // y): the far column (or row) of three cells. The other six cells were neighbours before.
    template <typename Disks, typename Visit>
    void for_each_entered(const Disks& disks, std::uint32_t i, std::uint32_t border, Visit&& visit) const {
        const Block b = beyond_border(column(disks[i].links), row(disks[i].links), border, 1, 1);
        for_each_in_block(disks, b.x0, b.x1, b.y0, b.y1, visit);
    }

    // Renumbering for memory locality (cell_order_renumbering.h). cell_order lists the disks cell
    // by cell in the order of the cell index, each cell in the order of its list: order[k] is
    // the disk that becomes number k.
    template <typename Disks>
    void cell_order(const Disks& disks, std::vector<std::uint32_t>& order) const {
        order.clear();
        for (std::uint32_t head : head_)
            for (std::uint32_t j = head; j != none; j = disks[j].links.next) order.push_back(j);
    }
    // After the disks were renumbered in that order (their `cell` moved with them, the other
    // links are stale): relinks every cell as the run of consecutive disks it now holds, in
    // the same order as before, so that walking a cell visits the same disks in the same order.
    template <typename Disks>
    void relink_consecutive(Disks& disks, std::size_t n) {
        std::fill(head_.begin(), head_.end(), none);
        for (std::uint32_t i = 0; i < n; ++i) {
            CellLinks& l = disks[i].links;
            const bool first = i == 0 || disks[i - 1].links.cell != l.cell;
            const bool last = i + 1 == n || disks[i + 1].links.cell != l.cell;
            if (first) head_[l.cell] = i;
            l.prev = first ? none : i - 1;
            l.next = last ? none : i + 1;
        }
    }

private:
    // Visits the disks of the cells with columns x0..x1 and rows y0..y1 (wrapped in a periodic
    // box, skipped outside a reflecting one).
    template <typename Disks, typename Visit>
    void for_each_in_block(const Disks& disks, std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1,
                           Visit& visit) const {
        for (std::int64_t y = y0; y <= y1; ++y) {
            std::int64_t ny = y;
            if (!wrap_or_skip(ny, cells_y_)) continue;
            const std::uint32_t* row_heads = &head_[std::size_t(ny * cells_x_)];
            for (std::int64_t x = x0; x <= x1; ++x) {
                std::int64_t nx = x;
                if (!wrap_or_skip(nx, cells_x_)) continue;
                for (std::uint32_t j = row_heads[nx]; j != none; j = disks[j].links.next) visit(j);
            }
        }
    }

    // Reads the heads of the 3x3 block around interior cell (cx, cy) into first[] (row by row)
    // and asks the memory for each head's record without waiting for it.
    template <typename Disks>
    [[gnu::always_inline]] void read_interior_heads(const Disks& disks, std::int64_t cx, std::int64_t cy,
                                                    std::uint32_t first[9]) const {
        const std::uint32_t* corner = &head_[std::size_t((cy - 1) * cells_x_ + cx - 1)];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t j = corner[r * cells_x_ + c];
                first[3 * r + c] = j;
                prefetch_line(&disks[record_or_first(j)]);
            }
    }
    // The disk whose record a prefetch requests for list entry j: j itself, or disk 0 for an
    // empty list. Requesting disk 0's record (in the cache after the first time) costs less
    // than a test whether the list is empty, which the processor mispredicts about half the
    // time at area fraction 0.5; a prefetch changes no result. (A mask, not
    // `j != none ? j : 0`, which the compiler makes a branch again.)
    static std::uint32_t record_or_first(std::uint32_t j) { return j & (0u - std::uint32_t(j != none)); }
    // The columns (or rows) `near` to `far` cells away from cell (cx, cy) on the side of
    // `border`, three cells wide (unwrapped: it may reach past the grid). With near = far = 1,
    // the far column of the 3x3 block around the cell; with 1 and 2, the cell beyond the border,
    // the one after it, and those beside them.
    static Block beyond_border(std::int64_t cx, std::int64_t cy, std::uint32_t border, std::int64_t near,
                               std::int64_t far) {
        switch (border) {
        case 0: return {cx - far, cx - near, cy - 1, cy + 1};
        case 1: return {cx + near, cx + far, cy - 1, cy + 1};
        case 2: return {cx - 1, cx + 1, cy - far, cy - near};
        default: return {cx - 1, cx + 1, cy + near, cy + far};
        }
    }
    Block inside(const Block& b) const {
        return b.x0 >= 0 && b.y0 >= 0 && b.x1 < cells_x_ && b.y1 < cells_y_ ? b : Block{};
    }
    // A cell whose 3x3 block lies inside the grid.
    bool interior(std::int64_t cx, std::int64_t cy) const {
        return cx > 0 && cy > 0 && cx + 1 < cells_x_ && cy + 1 < cells_y_;
    }
    static std::int64_t clamp(std::int64_t c, std::int64_t cells) { return std::clamp<std::int64_t>(c, 0, cells - 1); }
    // Periodic boxes have at least 3 cells per axis (checked on load), so a wrapped
    // neighbourhood never visits a cell twice.
    bool wrap_or_skip(std::int64_t& c, std::int64_t cells) const {
        if (c >= 0 && c < cells) return true;
        if (!periodic_) return false;
        c = c < 0 ? c + cells : c - cells;
        return true;
    }

    World world_;
    bool periodic_ = false;
    std::int64_t cells_x_ = 1, cells_y_ = 1;
    double cell_w_ = 1, cell_h_ = 1;
    EventArray<std::uint32_t> head_;  // first disk of each cell (the links live in the disks)
};

}  // namespace collide
