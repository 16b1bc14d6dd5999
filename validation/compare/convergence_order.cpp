#include "validation/compare/convergence_order.h"

#include <algorithm>
#include <cmath>

#include "validation/judge/statistics.h"

namespace collide::validation {
namespace {

double local_order(const ErrorPoint& coarse, const ErrorPoint& fine) {
    return std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h);
}

// Whether the error stopped falling from `coarse` to the finer `fine` (see the header).
bool flat(const ErrorPoint& coarse, const ErrorPoint& fine) {
    if (coarse.h == fine.h) return true;
    if (local_order(coarse, fine) >= flat_local_order) return false;
    if (coarse.standard_error <= 0 || fine.standard_error <= 0) return true;
    const double shrink = std::pow(fine.h / coarse.h, flat_local_order);
    const double descent = coarse.error * shrink;
    return fine.error - descent > floor_standard_errors * std::hypot(fine.standard_error, coarse.standard_error * shrink);
}

// The number of points, from the coarsest, in the asymptotic range: everything up to the last
// point after which every step is flat.
std::size_t range_end(const std::vector<ErrorPoint>& p) {
    const std::size_t n = p.size();
    for (std::size_t k = 0; k + 1 < n; ++k) {
        bool rest_flat = true;
        for (std::size_t i = k + 1; i < n && rest_flat; ++i) rest_flat = flat(p[i - 1], p[i]);
        if (rest_flat) return k + 1;
    }
    return n;
}

// A step inside the range whose local order is below flat_local_order: the error stalled there
// and fell again later (noise, or a floor the coarser points still hide), so the fitted slope
// mixes the method with something else.
bool bends(const std::vector<ErrorPoint>& p, std::size_t end) {
    for (std::size_t i = 1; i < end; ++i)
        if (local_order(p[i - 1], p[i]) < flat_local_order) return true;
    return false;
}

}  // namespace

ConvergenceOrder asymptotic_order(std::vector<ErrorPoint> points) {
    points.erase(std::remove_if(points.begin(), points.end(),
                                [](const ErrorPoint& p) { return !(p.error > 0 && std::isfinite(p.error) && p.h > 0); }),
                 points.end());
    std::stable_sort(points.begin(), points.end(), [](const ErrorPoint& a, const ErrorPoint& b) { return a.h > b.h; });
    ConvergenceOrder out;
    out.points = points.size();
    if (points.empty()) {
        out.note = "no point with a non-zero error";
        return out;
    }
    const std::size_t end = range_end(points);
    out.used = end;
    out.h_coarse = points.front().h;
    out.h_fine = points[end - 1].h;
    if (end < points.size())
        out.floor = ErrorFloor{points[end - 1].h, points[end - 1].error, points.back().h, points.back().error,
                               points.size() - end};
    std::vector<double> h, e, se;
    for (std::size_t k = 0; k < end; ++k) {
        h.push_back(points[k].h);
        e.push_back(points[k].error);
        se.push_back(points[k].standard_error);
    }
    const auto fit = log_log_fit(h, e, order_min_points, se);
    if (!fit) {
        out.note = std::to_string(end) + " point(s) on the asymptotic range; an order needs " +
                   std::to_string(order_min_points) + " with distinct steps";
        return out;
    }
    out.order = fit->slope;
    out.standard_error = fit->slope_standard_error;
    out.bending = bends(points, end);
    return out;
}

}  // namespace collide::validation
