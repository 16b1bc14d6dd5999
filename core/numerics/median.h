// The sample median: the middle value of n samples, or the mean of the two middle values when
// n is even (0 for no samples). Used where one outlier must not move a summary: the benchmark's
// timing windows, the stability check's disk displacements.
#pragma once

#include <algorithm>
#include <vector>

namespace collide {

inline double median(std::vector<double> values) {
    const std::size_t n = values.size();
    if (n == 0) return 0;
    const auto middle = values.begin() + std::ptrdiff_t(n / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (n % 2) return *middle;
    // Even n: the other middle value is the largest of the lower half.
    return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

}  // namespace collide
