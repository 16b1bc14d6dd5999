// Neumaier's compensated summation (an improved Kahan sum): the rounding error of each
// addition is carried along, so a sum of N terms is accurate to about one rounding of the
// result instead of growing like N * eps. Metrics use it for momentum and energy totals,
// whose drift we want to measure at the 1e-12 level.
// Reference: A. Neumaier, ZAMM 54 (1974) 39-51.
#pragma once

#include <cmath>

namespace collide {

class CompensatedSum {
public:
    void add(double term) {
        const double t = sum_ + term;
        if (std::fabs(sum_) >= std::fabs(term))
            compensation_ += (sum_ - t) + term;
        else
            compensation_ += (term - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0.0;
    double compensation_ = 0.0;
};

}  // namespace collide
