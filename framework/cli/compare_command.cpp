// lightlab compare A.img B.img [--metric NAME] [--diff OUT.png] [--relative] [--max V] [--json]
// B is the reference. Prints every metric (or the one asked for); --max makes
// the exit status 1 when the chosen metric is worse than V (for scripts).
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/error.h"
#include "metrics/image_metrics.h"

namespace ll::cli {

namespace {
struct CompareOptions {
  std::string a, b, metric, diff;
  bool relative = false, json = false;
  double max = std::numeric_limits<double>::quiet_NaN();
};
}  // namespace

Command addCompareCommand(CLI::App& app, const GlobalOptions&) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare an image with a reference: RMSE, relMSE, PSNR, SSIM, diff heatmap");
  cmd->add_option("image", o->a, "Image to judge (.png .jpg .hdr .pfm)")->required();
  cmd->add_option("reference", o->b, "Reference image")->required();
  cmd->add_option("--metric", o->metric, "Print only this metric: " + joinNames(metricNames(), "|"));
  cmd->add_option("--diff", o->diff, "Write a difference heatmap (inferno colour scale, legend strip below)");
  cmd->add_flag("--relative", o->relative, "Heatmap of relative instead of absolute difference");
  cmd->add_option("--max", o->max, "Exit with status 1 if --metric is worse than this (for ssim/psnr: lower)");
  cmd->add_flag("--json", o->json, "Print JSON");
  return [o]() {
    const Image a = loadImage(o->a);
    const Image b = loadImage(o->b);
    const ImageError e = compareImages(a, b);
    if (!o->metric.empty()) metricValue(e, o->metric);  // validates the name early
    if (!std::isnan(o->max) && o->metric.empty()) throwUserError("compare: --max needs --metric");
    nlohmann::json j = nlohmann::json::object();
    for (const std::string& name : metricNames()) j[name] = metricValue(e, name);
    j["mean"] = e.meanA;  // over pixels and channels: a brightness check (a furnace's 1 / (1 - albedo))
    j["reference_mean"] = e.meanB;
    if (!o->diff.empty()) {
      float used = 0.0f;
      const Image heat = differenceHeatmap(a, b, o->relative ? DiffMode::Relative : DiffMode::Absolute, 0.0f, &used);
      saveImage(withLegend(heat, used), o->diff);
      j["diff"] = o->diff;
      j["diff_scale_max"] = used;
    }
    if (o->json) {
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else if (!o->metric.empty()) {
      std::printf("%s %.6g\n", o->metric.c_str(), metricValue(e, o->metric));
    } else {
      for (const std::string& name : metricNames()) std::printf("%-7s %.6g\n", name.c_str(), metricValue(e, name));
      std::printf("mean    %.6g (reference %.6g)\n", e.meanA, e.meanB);
      if (!o->diff.empty())
        std::printf("diff    %s (black = 0, bright = %.4g)\n", o->diff.c_str(), j["diff_scale_max"].get<double>());
    }
    if (!std::isnan(o->max)) {
      const double v = metricValue(e, o->metric);
      const bool higherIsBetter = o->metric == "ssim" || o->metric == "psnr";
      if (higherIsBetter ? v < o->max : v > o->max) {
        std::fprintf(stderr, "lightlab: %s = %.6g fails the limit %.6g\n", o->metric.c_str(), v, o->max);
        throw CLI::RuntimeError(1);
      }
    }
  };
}

}  // namespace ll::cli
