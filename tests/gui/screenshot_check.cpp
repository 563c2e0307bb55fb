// Checks a `lightlab gui --screenshot` picture against headless renders, using
// the sidecar JSON the GUI writes next to it (where each pane was drawn, and
// which boxes were drawn over the images). Exit 0 = pass, 1 = fail, with one
// line saying why.
//
//   screenshot_check SHOT.png pane I REF.pfm [U0 U1]   pane I shows REF (columns U0..U1 of it, for wipe)
//   screenshot_check SHOT.png diff A.pfm B.pfm          the compare view is the heatmap of A against B
//   screenshot_check SHOT.png differs OTHER.png         the two pictures differ visibly
//   screenshot_check SHOT.png magenta I                 prints the fraction of pane I's pixels (outside
//                                                       overlays) that are stub magenta (a task's stripes)
//
// Metric: the displayed region and the reference are both averaged over a
// grid of blocks in sRGB [0,1]; every block not touched by an overlay must
// agree within kBlockTolerance (the display resamples and quantises, so a
// per-pixel comparison would be unfair). A blank or uniform region fails.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "metrics/image_metrics.h"

namespace {

using ll::Image;
using ll::Rgb;
using Rect = std::array<double, 4>;  // x, y, w, h in screenshot pixels

constexpr int kGrid = 12;                 // blocks per side
constexpr double kBlockTolerance = 0.025;  // max |mean sRGB difference| per block and channel (8-bit: 0.004 a step)
constexpr double kMinSpread = 0.02;       // a region whose block means all lie within this is "uniform"

[[noreturn]] void fail(const std::string& why) {
  std::printf("FAIL: %s\n", why.c_str());
  std::exit(1);
}

Rgb toSrgb(Rgb linear) {
  Rgb c;
  for (int k = 0; k < 3; ++k) c[k] = ll::linearToSrgb(std::clamp(std::isfinite(linear[k]) ? linear[k] : 0.0f, 0.0f, 1.0f));
  return c;
}

// Mean sRGB colour of image pixels with centres inside [x0,x1) x [y0,y1).
Rgb blockMean(const Image& img, double x0, double y0, double x1, double y1) {
  Rgb sum(0.0f);
  int n = 0;
  for (int y = static_cast<int>(std::ceil(y0 - 0.5)); y + 0.5 < y1; ++y)
    for (int x = static_cast<int>(std::ceil(x0 - 0.5)); x + 0.5 < x1; ++x) {
      if (x < 0 || y < 0 || x >= img.width() || y >= img.height()) continue;
      sum += img.at(x, y);
      ++n;
    }
  return n > 0 ? sum / static_cast<float>(n) : Rgb(-1.0f);
}

bool overlaps(const Rect& a, const Rect& b) {
  return a[0] < b[0] + b[2] && b[0] < a[0] + a[2] && a[1] < b[1] + b[3] && b[1] < a[1] + a[3];
}

Image srgbOf(const Image& linear) {
  Image out(linear.width(), linear.height());
  for (int y = 0; y < linear.height(); ++y)
    for (int x = 0; x < linear.width(); ++x) out.at(x, y) = toSrgb(linear.at(x, y));
  return out;
}

// The reference as the GUI shows it over the screen pixels with centres inside [x0,x1) x [y0,y1) of
// `region`: each pixel centre mapped into columns [u0,u1) of `reference`, sampled as the texture is
// (GL_NEAREST when magnified, GL_LINEAR when minified), and averaged. Comparing block means of the
// two then does not depend on where block edges fall between the image's pixels.
Rgb shownMean(const Image& reference, double u0, double u1, const Rect& region, double x0, double y0, double x1,
              double y1) {
  const double rw = (u1 - u0) * reference.width(), rh = reference.height();
  const bool magnified = region[2] >= rw;
  const auto at = [&](int x, int y) {
    return reference.at(std::clamp(x, 0, reference.width() - 1), std::clamp(y, 0, reference.height() - 1));
  };
  Rgb sum(0.0f);
  int n = 0;
  for (int y = static_cast<int>(std::ceil(y0 - 0.5)); y + 0.5 < y1; ++y)
    for (int x = static_cast<int>(std::ceil(x0 - 0.5)); x + 0.5 < x1; ++x) {
      const double px = u0 * reference.width() + (x + 0.5 - region[0]) / region[2] * rw;  // reference pixels
      const double py = (y + 0.5 - region[1]) / region[3] * rh;
      if (magnified) {
        sum += at(static_cast<int>(std::floor(px)), static_cast<int>(std::floor(py)));
      } else {
        const double fx = px - 0.5, fy = py - 0.5;
        const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
        const float tx = static_cast<float>(fx - ix), ty = static_cast<float>(fy - iy);
        sum += (at(ix, iy) * (1 - tx) + at(ix + 1, iy) * tx) * (1 - ty) +
               (at(ix, iy + 1) * (1 - tx) + at(ix + 1, iy + 1) * tx) * ty;
      }
      ++n;
    }
  return n > 0 ? sum / static_cast<float>(n) : Rgb(-1.0f);
}

// Compares `region` of the screenshot with columns [u0,u1) of `reference` (both sRGB).
void compareRegion(const Image& shot, const Rect& region, const Image& reference, double u0, double u1,
                   const std::vector<Rect>& overlays, const std::string& what) {
  if (region[2] < kGrid || region[3] < kGrid) fail(what + ": region too small or not drawn");
  int compared = 0, bad = 0;
  double worst = 0.0, lo = 1e9, hi = -1e9;
  for (int by = 0; by < kGrid; ++by)
    for (int bx = 0; bx < kGrid; ++bx) {
      const double fx0 = static_cast<double>(bx) / kGrid, fx1 = static_cast<double>(bx + 1) / kGrid;
      const double fy0 = static_cast<double>(by) / kGrid, fy1 = static_cast<double>(by + 1) / kGrid;
      const Rect block{region[0] + fx0 * region[2], region[1] + fy0 * region[3], (fx1 - fx0) * region[2],
                       (fy1 - fy0) * region[3]};
      if (std::any_of(overlays.begin(), overlays.end(), [&](const Rect& o) { return overlaps(block, o); })) continue;
      const Rgb s = blockMean(shot, block[0], block[1], block[0] + block[2], block[1] + block[3]);
      const Rgb r = shownMean(reference, u0, u1, region, block[0], block[1], block[0] + block[2], block[1] + block[3]);
      if (s.r < 0 || r.r < 0) continue;
      ++compared;
      const double err = std::max({std::abs(s.r - r.r), std::abs(s.g - r.g), std::abs(s.b - r.b)});
      worst = std::max(worst, err);
      if (err > kBlockTolerance) ++bad;
      lo = std::min(lo, static_cast<double>(s.r + s.g + s.b) / 3);
      hi = std::max(hi, static_cast<double>(s.r + s.g + s.b) / 3);
    }
  if (compared < kGrid * kGrid / 2) fail(what + ": fewer than half the blocks are free of overlays");
  if (hi - lo < kMinSpread) fail(what + ": the region is uniform (nothing rendered?)");
  if (bad > 0)
    fail(what + ": " + std::to_string(bad) + " of " + std::to_string(compared) + " blocks differ by more than " +
         std::to_string(kBlockTolerance) + " (worst " + std::to_string(worst) + ")");
  std::printf("ok: %s matches (%d blocks, worst block difference %.4f)\n", what.c_str(), compared, worst);
}

Rect rectOf(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>(), j[3].get<double>()}; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) fail("usage: screenshot_check SHOT.png pane|diff|differs|magenta|legend ...");
  const std::string shotPath = argv[1], mode = argv[2];
  try {
    const Image shot = srgbOf(ll::loadImage(shotPath));
    if (mode == "differs") {
      const Image other = srgbOf(ll::loadImage(argv[3]));
      const double rmse = ll::compareImages(shot, other).rmse;
      if (rmse < 0.01) fail("the two screenshots look the same (RMSE " + std::to_string(rmse) + ")");
      std::printf("ok: screenshots differ (RMSE %.4f)\n", rmse);
      return 0;
    }
    std::string sidecarPath = shotPath.substr(0, shotPath.rfind('.')) + ".json";
    std::ifstream in(sidecarPath);
    if (!in) fail(sidecarPath + ": missing sidecar");
    const nlohmann::json side = nlohmann::json::parse(in);
    std::vector<Rect> overlays;
    for (const auto& o : side["overlays"]) overlays.push_back(rectOf(o));
    if (mode == "pane") {
      if (argc < 5) fail("pane needs an index and a reference");
      const int index = std::stoi(argv[3]);
      const nlohmann::json& pane = side["panes"].at(static_cast<size_t>(index));
      if (pane["phase"] != "done") fail("pane " + std::to_string(index) + " is not done: " + pane["phase"].get<std::string>());
      const double u0 = argc > 6 ? std::stod(argv[5]) : 0.0, u1 = argc > 6 ? std::stod(argv[6]) : 1.0;
      compareRegion(shot, rectOf(pane["rect"]), srgbOf(ll::loadImage(argv[4])), u0, u1, overlays,
                    "pane " + std::to_string(index) + " (" + pane["technique"].get<std::string>() + ")");
      return 0;
    }
    if (mode == "diff") {
      if (argc < 5) fail("diff needs two references");
      const float usedMax = side["compare"]["diff_max"].get<float>();
      const Image heat = ll::differenceHeatmap(ll::loadImage(argv[3]), ll::loadImage(argv[4]), ll::DiffMode::Absolute,
                                               usedMax);
      compareRegion(shot, rectOf(side["compare"]["rect"]), srgbOf(heat), 0.0, 1.0, overlays, "difference heatmap");
      return 0;
    }
    if (mode == "magenta") {
      const Rect r = rectOf(side["panes"].at(static_cast<size_t>(std::stoi(argv[3])))["rect"]);
      long magenta = 0, counted = 0;
      for (int y = static_cast<int>(r[1]); y < static_cast<int>(r[1] + r[3]) && y < shot.height(); ++y)
        for (int x = static_cast<int>(r[0]); x < static_cast<int>(r[0] + r[2]) && x < shot.width(); ++x) {
          bool covered = false;
          for (const Rect& o : overlays) covered = covered || (x >= o[0] && y >= o[1] && x < o[0] + o[2] && y < o[1] + o[3]);
          if (covered || x < 0 || y < 0) continue;
          const Rgb c = shot.at(x, y);
          ++counted;
          magenta += c.r > 0.6f && c.b > 0.6f && c.g < 0.35f;
        }
      if (counted == 0) fail("pane " + std::string(argv[3]) + " shows no pixels");
      std::printf("%.4f\n", static_cast<double>(magenta) / static_cast<double>(counted));
      return 0;
    }
    if (mode == "legend") {  // pane N's heatmap legend (the overlay strip along its bottom) shows no structure lines
      const Rect r = rectOf(side["panes"].at(static_cast<size_t>(std::stoi(argv[3])))["rect"]);
      const Rect* legend = nullptr;
      for (const Rect& o : overlays)
        if (std::abs(o[0] - r[0]) < 1 && std::abs(o[2] - r[2]) < 1 && std::abs(o[1] + o[3] - r[1] - r[3]) < 1) legend = &o;
      if (!legend) fail("pane " + std::string(argv[3]) + " has no legend strip");
      // The overlay's interior boxes are cyan (80, 220, 255); the legend's colours (inferno, white) never are.
      long cyan = 0;
      for (int y = static_cast<int>((*legend)[1]) + 1; y < static_cast<int>((*legend)[1] + (*legend)[3]) && y < shot.height(); ++y)
        for (int x = static_cast<int>((*legend)[0]); x < static_cast<int>((*legend)[0] + (*legend)[2]) && x < shot.width(); ++x) {
          const Rgb c = shot.at(x, y);
          cyan += c.g > c.r + 0.2f && c.b > c.r + 0.2f;
        }
      if (cyan > 0) fail("structure lines cross pane " + std::string(argv[3]) + "'s legend (" + std::to_string(cyan) + " cyan pixels)");
      std::printf("ok: pane %s's legend is clear of structure lines\n", argv[3]);
      return 0;
    }
    fail("unknown mode '" + mode + "' (allowed: pane, diff, differs, magenta, legend)");
  } catch (const std::exception& e) {
    fail(e.what());
  }
}
