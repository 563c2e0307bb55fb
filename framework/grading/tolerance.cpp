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

ZTestSettings zTestSettings(const nlohmann::json& entry) {
  ZTestSettings z;
  const nlohmann::json block = entry.value("ztest", nlohmann::json::object());
  z.alpha = block.value("alpha", z.alpha);
  z.absFloor = block.value("abs_floor", z.absFloor);
  z.relFloor = block.value("rel_floor", z.relFloor);
  z.maxRejected = block.value("max_rejected", z.maxRejected);
  return z;
}

}  // namespace ll::grading
