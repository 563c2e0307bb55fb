#include "grading/tolerance.h"

namespace ll::grading {

std::vector<ToleranceCheck> checkTolerances(const ImageError& error, const nlohmann::json& tolerances) {
  std::vector<ToleranceCheck> out;
  for (const auto& tol : tolerances) {
    ToleranceCheck c;
    c.metric = tol.at("metric").get<std::string>();
    c.value = metricValue(error, c.metric);
    c.isMax = tol.contains("max");
    c.bound = c.isMax ? tol.at("max").get<double>() : tol.at("min").get<double>();
    c.passed = c.isMax ? c.value <= c.bound : c.value >= c.bound;
    out.push_back(c);
  }
  return out;
}

}  // namespace ll::grading
