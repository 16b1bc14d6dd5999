// The stepped rules' bias constants c_Z and c_nu (statistics_bias_model.h) fitted jointly over
// every statistical sweep point of one run and backend, beside the model's values: six checks
// that each pass can still lie all on one side of the prediction, and only the joint fit shows it.
//
// Each point i measures d_i = mean - reference with the combined standard error s_i and has the
// prediction c * k_i, where k_i = predicted_i / c_model is the model's shift per unit constant.
// Weighted least squares for one constant: c = sum(d k / s^2) / sum(k^2 / s^2), standard error
// 1 / sqrt(sum(k^2 / s^2)), chi^2 = sum((d - c k)^2 / s^2) on n - 1 degrees of freedom; the
// model's own constant gets chi^2_model = sum((d - c_model k)^2 / s^2) on n.
#pragma once

#include <string>
#include <vector>

#include "validation/record/comparisons.h"

namespace collide::validation {

struct BiasConstantFit {
    std::string backend, observable;  // observable: "pressure" (c_Z) or "collision_rate" (c_nu)
    double constant = 0, standard_error = 0;
    double model = 0, model_uncertainty = 0;
    double chi2 = 0, chi2_model = 0;
    std::size_t points = 0;
};

// One fit per backend and observable with at least two points that carry a prediction.
std::vector<BiasConstantFit> fit_bias_constants(const std::vector<WorkPrecisionLine>& lines);

}  // namespace collide::validation
