// CellList: the neighbour structure of the event-driven solver. The box is cut into cells at
// least one contact distance wide (2 r_max), so a disk can only touch disks whose centres lie
// in its own cell or in one of the 8 around it. Unlike the stepping backends' UniformGrid,
// which is rebuilt every step, this list is kept up to date incrementally: a disk changes cell
// only at a "cell crossing" event, an O(1) unlink/link of an intrusive doubly linked list.
// That is what makes the cost per event independent of N (Rapaport, "The Art of Molecular
// Dynamics Simulation", 2nd ed., section 14.2).
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/scene.h"

namespace collide {

class CellList {
public:
    static constexpr std::uint32_t none = 0xffffffffu;

    // min_cell_size: the largest contact distance. The cell count is capped (a huge, nearly
    // empty box) by making cells larger, which stays correct and only costs speed.
    void configure(const World& world, double min_cell_size, std::size_t particles) {
        world_ = world;
        periodic_ = world.boundary == Boundary::periodic;
        cells_x_ = std::max<std::int64_t>(1, std::int64_t(world.width() / min_cell_size));
        cells_y_ = std::max<std::int64_t>(1, std::int64_t(world.height() / min_cell_size));
        const std::int64_t max_cells = std::max<std::int64_t>(std::int64_t(1) << 20, 4 * std::int64_t(particles));
        while (cells_x_ * cells_y_ > max_cells) {
            if (cells_x_ >= cells_y_) cells_x_ = std::max<std::int64_t>(1, cells_x_ / 2);
            else cells_y_ = std::max<std::int64_t>(1, cells_y_ / 2);
        }
        cell_w_ = world.width() / double(cells_x_);
        cell_h_ = world.height() / double(cells_y_);
        head_.assign(std::size_t(cells_x_ * cells_y_), none);
        next_.assign(particles, none);
        prev_.assign(particles, none);
        cell_.assign(particles, 0);
    }

    std::int64_t cells_x() const { return cells_x_; }
    std::int64_t cells_y() const { return cells_y_; }

    // The cell column/row containing coordinate x/y (clamped to the box).
    std::int64_t column_of(double x) const { return clamp(std::int64_t((x - world_.xmin) / cell_w_), cells_x_); }
    std::int64_t row_of(double y) const { return clamp(std::int64_t((y - world_.ymin) / cell_h_), cells_y_); }

    // Left/lower border of column/row c. The same expression is used for every crossing so
    // that a disk that crossed a border sits exactly on the border of its new cell.
    double border_x(std::int64_t c) const { return world_.xmin + double(c) * cell_w_; }
    double border_y(std::int64_t c) const { return world_.ymin + double(c) * cell_h_; }

    std::int64_t column(std::uint32_t i) const { return cell_[i] % cells_x_; }
    std::int64_t row(std::uint32_t i) const { return cell_[i] / cells_x_; }

    void insert(std::uint32_t i, std::int64_t column, std::int64_t row) {
        const std::uint32_t c = std::uint32_t(row * cells_x_ + column);
        cell_[i] = c;
        prev_[i] = none;
        next_[i] = head_[c];
        if (head_[c] != none) prev_[head_[c]] = i;
        head_[c] = i;
    }

    void remove(std::uint32_t i) {
        if (prev_[i] != none) next_[prev_[i]] = next_[i];
        else head_[cell_[i]] = next_[i];
        if (next_[i] != none) prev_[next_[i]] = prev_[i];
    }

    // Calls visit(j) for every disk j in the 3x3 neighbourhood of disk i's cell (i included).
    template <typename Visit>
    void for_each_neighbour(std::uint32_t i, Visit&& visit) const {
        const std::int64_t cx = column(i), cy = row(i);
        for (std::int64_t oy = -1; oy <= 1; ++oy) {
            std::int64_t ny = cy + oy;
            if (!wrap_or_skip(ny, cells_y_)) continue;
            for (std::int64_t ox = -1; ox <= 1; ++ox) {
                std::int64_t nx = cx + ox;
                if (!wrap_or_skip(nx, cells_x_)) continue;
                for (std::uint32_t j = head_[std::size_t(ny * cells_x_ + nx)]; j != none; j = next_[j]) visit(j);
            }
        }
    }

private:
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
    std::vector<std::uint32_t> head_;        // first disk of each cell
    std::vector<std::uint32_t> next_, prev_; // intrusive doubly linked list per cell
    std::vector<std::uint32_t> cell_;        // cell index of each disk
};

}  // namespace collide
