// A lattice that fills a periodic box exactly: `columns` disks a row, `rows` rows, spacings
// width / columns and height / rows, and every row shifted against the one below by
// `row_shift` = (width / columns) * k / rows with k = floor(rows / 2). After `rows` rows the shift
// adds up to k whole spacings, so the top row meets the bottom one across the boundary as any
// two neighbouring rows meet: the lattice is periodic in the box whatever its shape.
// With an even number of rows the shift is half a spacing, and in a box of aspect ratio
// rows sqrt(3)/2 : columns this is the perfect hexagonal crystal (Li et al., J. Chem. Phys. 157,
// 234111 (2022): 9 x 8 disks in a 9 : 8 sqrt(3)/2 box); in other boxes (square, 1 : sqrt(3)/2) it
// is a sheared, stretched hexagonal lattice, a start without overlaps that a run melts.
// A square lattice has no shift. docs/scenes.md, `fill_box`.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace collide {

struct FilledLattice {
    std::int64_t columns = 1, rows = 1;
    double dx = 0, dy = 0, row_shift = 0;

    // The centre of disk k (row k / columns, column k % columns), relative to the box's corner.
    double x(std::int64_t k) const {
        const std::int64_t row = k / columns, column = k % columns;
        const double width = dx * double(columns);
        return std::fmod(dx * (double(column) + 0.25) + std::fmod(double(row) * row_shift, dx), width);
    }
    double y(std::int64_t k) const { return dy * (double(k / columns) + 0.5); }

    // The smallest distance between two centres, over the periodic images: the lattice is a
    // Bravais lattice, so the separations are (m dx + j row_shift, j dy) for whole m and j, and
    // the rows j apart are, across the boundary, rows - j apart the other way.
    double nearest_distance() const {
        double nearest = dx;  // within a row (and across the boundary: columns dx = width)
        if (rows == 1) return std::min(nearest, dy);
        for (std::int64_t j = 1; j < rows; ++j) {
            const double offset = std::fmod(double(j) * row_shift, dx);
            nearest = std::min(nearest, std::hypot(std::min(offset, dx - offset), double(std::min(j, rows - j)) * dy));
        }
        return nearest;
    }
};

inline FilledLattice filled_lattice(double width, double height, std::int64_t columns, std::int64_t rows, bool hexagonal) {
    FilledLattice l;
    l.columns = columns, l.rows = rows;
    l.dx = width / double(columns), l.dy = height / double(rows);
    l.row_shift = hexagonal ? l.dx * double(rows / 2) / double(rows) : 0.0;
    return l;
}

}  // namespace collide
