#include "convergence_order.h"

#include <algorithm>
#include <cmath>

#include "statistics.h"

namespace collide::validation {
namespace {

double local_order(const ErrorPoint& coarse, const ErrorPoint& fine) {
    return std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h);
}

// The standard error of a local order from the two points' error bars (0 without them).
double local_order_error(const ErrorPoint& coarse, const ErrorPoint& fine) {
    return std::hypot(coarse.standard_error / coarse.error, fine.standard_error / fine.error) /
           std::fabs(std::log(coarse.h / fine.h));
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

bool bends(const std::vector<ErrorPoint>& p, std::size_t end) {
    if (end < 3) return false;
    const double first = local_order(p[0], p[1]), last = local_order(p[end - 2], p[end - 1]);
    const double se = std::hypot(local_order_error(p[0], p[1]), local_order_error(p[end - 2], p[end - 1]));
    return last < 0.5 * first && first - last > floor_standard_errors * se;
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
