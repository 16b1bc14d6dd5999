// The density of a separation ("gap") just above contact, extrapolated to contact: the classic
// route from a sample of configurations to the hard-disk pressure (Allen & Tildesley, sec. 2.4
// and 5.5). Gaps in [0, window) are counted in `bins` equal bins; the counts per unit gap and
// per configuration are fitted by a straight line (least squares), whose value at gap 0 is the
// contact density. A least-squares fit is linear in the counts, so the mean of the contact
// values of many histograms is the contact value of their sum: a series of them can be
// averaged by batch means.
//
// The fit's bias is of the order of the curvature of the density over the window (the window
// is stated with every result: docs/monte-carlo.md, "Metropolis").
#pragma once

#include <cstddef>
#include <vector>

namespace collide {

class ContactHistogram {
public:
    ContactHistogram(double window, int bins) : window_(window), counts_(std::size_t(bins), 0.0) {}

    double window() const { return window_; }
    // Counts one gap (ignored outside [0, window)).
    void add(double gap) {
        if (gap < 0 || gap >= window_) return;
        counts_[std::size_t(gap / window_ * double(counts_.size()))] += 1;
    }
    void clear() { counts_.assign(counts_.size(), 0.0); }

    // The fitted density at gap 0, per unit gap, over `configurations` configurations counted.
    double contact_density(double configurations) const {
        const double width = window_ / double(counts_.size());
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t k = 0; k < counts_.size(); ++k) {
            const double x = (double(k) + 0.5) * width, y = counts_[k] / (width * configurations);
            n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        return (sy - slope * sx) / n;  // the intercept
    }

private:
    double window_;
    std::vector<double> counts_;
};

}  // namespace collide
