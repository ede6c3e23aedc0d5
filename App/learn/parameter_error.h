// The parameter error of uvtran.md Sec. 5.3: the mean L2 distance between the (u, v) a
// parameterizer gives the boundary points and the ground truth, on the synthetic test split.
// UVTran's parameters live in the target's own domain and are compared as they are. NP and MVC
// produce parameters in a plane or N-gon of their own, so they are first moved by the
// least-squares similarity (rotation, reflection, uniform scale, translation; Umeyama 1991)
// onto the truth: the most favourable placement, which only flatters them.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "fill/parameterizer.h"
#include "learn/uvtran_data.h"

namespace holefill::learn {

double parameterError(const std::vector<Eigen::Vector2d>& uv, const std::vector<Eigen::Vector2d>& truth);
double alignedParameterError(const std::vector<Eigen::Vector2d>& uv, const std::vector<Eigen::Vector2d>& truth);

// A classical parameterizer (np or mvc) run on a synthetic sample's boundary, with the sample's
// corners as the hole's corners (what MVC maps to its N-gon).
std::vector<Eigen::Vector2d> classicalParameters(const UvtranSample& sample, ParamMethod method);

}  // namespace holefill::learn
