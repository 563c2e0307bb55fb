// lightlab radiosity SCENE [--json OUT.json] [--plot OUT.svg] [--set name=value ...]
// Meshes the scene into patches, computes the form factors and solves
// B = E + rho F B (the technique `radiosity`'s parameters choose how), then
// prints a summary: patches, times, form-factor diagnostics (row sums,
// reciprocity), the solver's iterations and residual, the energy balance.
// With progressive=true it runs progressive refinement and records its
// history (shots, unshot power, time) instead.
// --json writes every patch and the solver's history (and, up to 500
// patches, the form-factor matrix and the bounce terms K^n E until they fall
// below 1e-4 of E); --plot draws the residual history (log scale) as an SVG.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_setup.h"
#include "cli/task_lines.h"
#include "core/error.h"
#include "core/files.h"
#include "core/progress.h"
#include "radiosity_scene.h"

namespace ll::cli {

namespace {

struct RadiosityOptions {
  std::string scene, json, plot;
  std::vector<std::string> sets;
};

nlohmann::json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

// One patch as --json writes it: its corners, object, area, centre, normal, E, rho and radiosity B.
nlohmann::json patchJson(const Scene& scene, const a5::PatchMesh& mesh, uint32_t i, const Rgb& radiosity) {
  const a5::Patch& p = mesh.patches[i];
  nlohmann::json corners = nlohmann::json::array();
  for (int k = 0; k < p.corners(); ++k) corners.push_back(vec(mesh.positions[p.corner(k)]));
  return {{"id", i},
          {"corners", corners},
          {"object", scene.objects[p.object].name},
          {"object_id", p.object},
          {"area", p.area},
          {"centre", vec(p.centre)},
          {"normal", vec(p.normal)},
          {"emission", vec(p.emission)},
          {"reflectance", vec(p.reflectance)},
          {"radiosity", vec(radiosity)}};
}

// --json writes the form-factor matrix and the bounce terms up to this many patches.
constexpr size_t kMatrixMaxPatches = 500;
constexpr int kMaxBounceTerms = 64;

// The residual history as a small SVG plot: log10(residual) against iteration.
void writePlot(const a5::Solution& s, const std::string& title, const std::string& path) {
  createParentDirectory(path);
  std::ofstream out(path);
  if (!out) throwUserError(path + ": cannot write the plot");
  constexpr double w = 640, h = 400, left = 70, right = 20, top = 40, bottom = 50;
  double lo = 0.0, hi = 0.0;
  int last = 1;
  bool first = true;
  for (const a5::SolverStep& step : s.history) {
    if (!(step.residual > 0.0)) continue;
    const double l = std::log10(step.residual);
    lo = first ? l : std::min(lo, l);
    hi = first ? l : std::max(hi, l);
    first = false;
    last = std::max(last, step.iteration);
  }
  lo = std::floor(lo);
  hi = std::max(std::ceil(hi), lo + 1.0);
  const auto x = [&](double it) { return left + (w - left - right) * it / last; };
  const auto y = [&](double l) { return top + (h - top - bottom) * (hi - l) / (hi - lo); };
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<text x='" << left << "' y='24' font-size='14'>" << title << "</text>\n";
  for (double l = lo; l <= hi; l += 1.0)
    out << "<line x1='" << left << "' x2='" << w - right << "' y1='" << y(l) << "' y2='" << y(l)
        << "' stroke='#ddd'/><text x='" << left - 8 << "' y='" << y(l) + 4 << "' text-anchor='end'>1e" << l
        << "</text>\n";
  out << "<text x='" << (left + w - right) / 2 << "' y='" << h - 12 << "' text-anchor='middle'>iteration (of "
      << last << ")</text>\n<text x='16' y='" << (top + h - bottom) / 2 << "' transform='rotate(-90 16 "
      << (top + h - bottom) / 2 << ")' text-anchor='middle'>relative residual</text>\n<polyline fill='none' "
      << "stroke='#c0392b' stroke-width='2' points='";
  for (const a5::SolverStep& step : s.history)
    if (step.residual > 0.0) out << x(step.iteration) << "," << y(std::log10(step.residual)) << " ";
  out << "'/>\n</svg>\n";
}

// progressive=true: Cohen et al.'s progressive refinement, shot by shot
// (rows computed as patches shoot), recorded after 32, 64, 128, ... shots
// until the unshot power is below the tolerance or the cap (max_iterations
// x patches shots); --json writes that history and what it displays.
void runProgressive(const SceneSetup& s, const a5::RadiositySettings& settings, const RadiosityOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const a5::ProgressiveScene scene = a5::progressiveScene(s.scene, settings);
  const a5::PatchMesh& mesh = scene.patches->mesh;
  const size_t cap = static_cast<size_t>(std::max(settings.solver.maxIterations, 1)) * std::max<size_t>(mesh.patches.size(), 1);
  nlohmann::json history = nlohmann::json::array();
  std::vector<Rgb> shown;
  double unshot = 1.0;
  ProgressBar bar("progressive refinement (" + std::to_string(mesh.patches.size()) + " patches)", 1.0, settings.quiet);
  for (size_t shots = 32;; shots = std::min(2 * shots, cap)) {
    const size_t before = scene.state->shots();
    scene.state->advance(shots, settings.solver.tolerance);
    shown = scene.state->displayed(&unshot);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    history.push_back({{"shots", scene.state->shots()}, {"unshot_fraction", unshot}, {"seconds", seconds}});
    if (unshot > 0.0 && unshot < 1.0) bar.update(std::clamp(std::log(unshot) / std::log(settings.solver.tolerance), 0.0, 1.0));
    if (unshot <= settings.solver.tolerance || scene.state->shots() == before || shots >= cap) break;
  }
  bar.finish();
  const bool converged = unshot <= settings.solver.tolerance;
  std::printf("progressive refinement: %zu patches, %zu shots, unshot %.3g of the emitted power (%s), %.3f s\n",
              mesh.patches.size(), scene.state->shots(), unshot, converged ? "converged" : "NOT converged",
              history.back()["seconds"].get<double>());
  if (o.json.empty()) return;
  nlohmann::json patches = nlohmann::json::array();
  for (uint32_t i = 0; i < mesh.patches.size(); ++i) patches.push_back(patchJson(s.scene, mesh, i, shown[i]));
  const nlohmann::json out = {{"scene", o.scene},
                              {"parameters", s.techniqueParams.toJson()},
                              {"mesh", {{"patches", mesh.patches.size()}, {"seconds", scene.patches->meshSeconds}}},
                              {"progressive", {{"converged", converged}, {"shots", scene.state->shots()},
                                               {"unshot_fraction", unshot}, {"history", history}}},
                              {"patches", patches}};
  createParentDirectory(o.json);
  std::ofstream file(o.json);
  if (!file) throwUserError(o.json + ": cannot write");
  file << out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  std::printf("wrote %s\n", o.json.c_str());
}

}  // namespace

Command addRadiosityCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<RadiosityOptions>();
  CLI::App* cmd = app.add_subcommand("radiosity", "Solve a scene's radiosity: patches, form factors, B = E + rho F B");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj)")->required();
  cmd->add_option("--json", o->json, "Write every patch and the solver's history as JSON");
  cmd->add_option("--plot", o->plot, "Write the residual history as an SVG plot");
  cmd->add_option("--set", o->sets, "Parameter of the technique radiosity, name=value (repeatable)");
  return [o, &global]() {
    SceneSetup s = setUpScene(o->scene, "radiosity", "none", o->sets);
    a5::RadiositySettings settings = a5::radiositySettings(s.techniqueParams);
    settings.quiet = global.quiet;
    if (settings.progressive) {
      runProgressive(s, settings, *o);
      return;
    }
    const auto solved = a5::solveScene(s.scene, settings);
    printTaskLines(solved->missingTasks, {}, false);
    const a5::Solution& sol = solved->solution;
    const a5::FormFactorDiagnostics& d = solved->diagnostics();
    const double finalResidual = sol.history.empty() ? 0.0 : sol.history.back().residual;
    const int iterations = sol.history.empty() ? 0 : sol.history.back().iteration;
    if (solved->patches->refinement.size() > 1) {
      std::printf("adaptive refinement: patches");
      for (const size_t n : solved->patches->refinement) std::printf(" %zu", n);
      std::printf("\n");
    }
    const auto& hierarchy = solved->patches->hierarchy;
    if (hierarchy)
      std::printf("hierarchical radiosity (link_epsilon %g): %zu base patches, %zu elements, %zu leaves, %zu links, "
                  "%llu visibility rays, %d refinement rounds, %.3f s (refining %.3f s)\n",
                  settings.hierarchical.linkEpsilon, hierarchy->basePatches, hierarchy->elements,
                  solved->mesh().patches.size(), hierarchy->links,
                  static_cast<unsigned long long>(hierarchy->visibilityRays), hierarchy->rounds,
                  solved->patches->formFactorSeconds, hierarchy->refineSeconds);
    else
      std::printf("%zu patches (%.3f s), form factors %s: %zu non-zeros, %.3f s, row sums %.4f..%.4f (mean %.4f), "
                  "reciprocity error mean %.2g max %.2g\n",
                  solved->mesh().patches.size(), solved->patches->meshSeconds,
                  a5::methodName(settings.formFactors.method).c_str(), d.nonZeros, solved->patches->formFactorSeconds,
                  d.rowSumMin, d.rowSumMax, d.rowSumMean, d.reciprocityMeanError, d.reciprocityMaxError);
    std::printf("solver %s: %s after %d iterations, residual %.3g, %.3f s; power emitted %.4g, absorbed %.4g, "
                "escaped %.4g\n",
                a5::methodName(settings.solver.method).c_str(), sol.converged ? "converged" : "NOT converged",
                iterations, finalResidual, sol.seconds, solved->energy.emitted, solved->energy.absorbed,
                solved->energy.escaped);
    if (!o->plot.empty()) {
      writePlot(sol, "radiosity: " + a5::methodName(settings.solver.method) + ", " +
                         std::to_string(solved->mesh().patches.size()) + " patches", o->plot);
      std::printf("wrote %s\n", o->plot.c_str());
    }
    if (o->json.empty()) return;
    nlohmann::json patches = nlohmann::json::array();
    for (uint32_t i = 0; i < solved->mesh().patches.size(); ++i)
      patches.push_back(patchJson(s.scene, solved->mesh(), i, sol.radiosity[i]));
    nlohmann::json history = nlohmann::json::array();
    for (const a5::SolverStep& step : sol.history)
      history.push_back({{"iteration", step.iteration}, {"residual", step.residual}, {"seconds", step.seconds}});
    nlohmann::json out = {
        {"scene", o->scene},
        {"parameters", s.techniqueParams.toJson()},
        {"mesh",
         {{"patches", solved->mesh().patches.size()},
          {"seconds", solved->patches->meshSeconds},
          {"refinement", solved->patches->refinement}}},
        {"form_factors",
         {{"method", a5::methodName(settings.formFactors.method)},
          {"seconds", solved->patches->formFactorSeconds},
          {"non_zeros", d.nonZeros},
          {"visibility_rays", d.visibilityRays},
          {"row_sum", {{"min", d.rowSumMin}, {"mean", d.rowSumMean}, {"max", d.rowSumMax}}},
          {"reciprocity_error", {{"mean", d.reciprocityMeanError}, {"max", d.reciprocityMaxError}}}}},
        {"solver",
         {{"method", a5::methodName(settings.solver.method)},
          {"converged", sol.converged},
          {"failure", sol.failure},
          {"largest_row_sum_of_rho_f", sol.largestRowGain},
          {"iterations", iterations},
          {"residual", finalResidual},
          {"seconds", sol.seconds},
          {"history", history}}},
        {"energy",
         {{"emitted", solved->energy.emitted}, {"absorbed", solved->energy.absorbed}, {"escaped", solved->energy.escaped}}},
        {"missing_tasks", solved->missingTasks},
        {"patches", patches}};
    if (hierarchy)
      out["hierarchical"] = {{"link_epsilon", settings.hierarchical.linkEpsilon},
                             {"base_patches", hierarchy->basePatches},
                             {"elements", hierarchy->elements},
                             {"leaves", solved->mesh().patches.size()},
                             {"links", hierarchy->links},
                             {"visibility_rays", hierarchy->visibilityRays},
                             {"rounds", hierarchy->rounds},
                             {"seconds", solved->patches->formFactorSeconds},
                             {"refine_seconds", hierarchy->refineSeconds}};
    if (!hierarchy && solved->mesh().patches.size() <= kMatrixMaxPatches) {
      // What a user can check by hand on a small system: F itself (sparse rows), and the
      // Neumann series' terms K^n E that show=bounce displays, until they fade.
      const a5::FormFactors& f = solved->f();
      nlohmann::json rows = nlohmann::json::array();
      for (uint32_t i = 0; i < f.size(); ++i) {
        nlohmann::json row = nlohmann::json::array();
        for (uint32_t k = f.rowStart[i]; k < f.rowStart[i + 1]; ++k) row.push_back({f.column[k], f.value[k]});
        rows.push_back(row);
      }
      out["form_factors"]["matrix"] = {{"format", "row i: [[j, F_ij], ...] for F_ij > 0"}, {"rows", rows}};
      nlohmann::json bounces = nlohmann::json::array();
      std::vector<Rgb> term = a5::bounce(solved->system(), 0);
      float first = 0.0f;
      for (const Rgb& e : term) first = std::max(first, maxComponent(e));
      for (int k = 0; k <= kMaxBounceTerms; ++k) {
        if (k > 0) term = a5::bounce(solved->system(), k);
        float largest = 0.0f;
        nlohmann::json values = nlohmann::json::array();
        for (const Rgb& b : term) {
          values.push_back(vec(b));
          largest = std::max(largest, maxComponent(b));
        }
        bounces.push_back({{"bounce", k}, {"largest", largest}, {"radiosity", values}});
        if (!(largest > 1e-4f * first)) break;
      }
      out["bounces"] = bounces;
    }
    createParentDirectory(o->json);
    std::ofstream file(o->json);
    if (!file) throwUserError(o->json + ": cannot write");
    file << out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    std::printf("wrote %s\n", o->json.c_str());
  };
}

}  // namespace ll::cli
