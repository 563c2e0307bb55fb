#include "gui/pane_labels.h"

#include <algorithm>
#include <map>
#include <set>

#include "gui/app_actions.h"
#include "gui/viewport.h"

namespace ll::gui {

std::string shortParamName(const std::string& name) {
  static const std::map<std::string, std::string> kShort{
      {"max_depth", "depth"}, {"light_samples", "light samples"}, {"rr_depth", "roulette from"}};
  if (const auto it = kShort.find(name); it != kShort.end()) return it->second;
  std::string s = name;
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

namespace {

struct Item {
  std::string key;   // what is compared across panes ("technique", "t:max_depth", ...)
  std::string text;  // how this pane shows it
};

std::vector<Item> itemsOf(const PaneState& p) {
  std::vector<Item> items{{"technique", p.technique},
                          {"accelerator", p.accelerator == "none" ? std::string("brute force") : p.accelerator}};
  // Every pane has a view, the picture too: a picture beside a heatmap is the difference to name.
  items.push_back({"view", p.view == PaneView::Image              ? "picture"
                           : p.view == PaneView::NodesVisited     ? "nodes visited"
                           : p.view == PaneView::PrimitivesTested ? "primitives tested"
                                                                  : "light paths"});
  items.push_back({"spp", std::to_string(p.spp) + " spp"});
  const auto params = [&](const ParamSet& set, const std::string& prefix) {
    for (const ParamDecl& d : set.decls()) {
      const std::string& v = set.text(d.name);
      std::string text = shortParamName(d.name) + " " + v;
      if (d.type == ParamDecl::Type::Bool) text = (v == "true" ? "" : "no ") + shortParamName(d.name);
      items.push_back({prefix + d.name, text});
    }
  };
  params(p.techniqueParams, "t:" + p.technique + ":");
  params(p.accelParams, "a:" + p.accelerator + ":");
  return items;
}

}  // namespace

namespace {

// Per visible pane, the items that tell it apart from the others.
std::vector<std::vector<Item>> differingItems(const AppState& app) {
  const int n = std::clamp(app.paneCount, 1, kMaxPanes);
  std::vector<std::vector<Item>> items;
  for (int i = 0; i < n; ++i) items.push_back(itemsOf(app.panes[static_cast<size_t>(i)]));
  // Keys whose values differ between the panes that have them; a technique's (or
  // accelerator's) parameter compares only among the panes that run it.
  std::map<std::string, std::set<std::string>> values;
  std::map<std::string, int> holders;
  for (const auto& list : items)
    for (const Item& it : list) {
      values[it.key].insert(it.text);
      ++holders[it.key];
    }
  // The accelerator is named only where it tells apart panes of one technique: beside a rasterizer
  // ("none") a ray caster's "bvh" is noise that pushes the real difference off a projector's label.
  bool acceleratorMatters = false;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const PaneState &a = app.panes[static_cast<size_t>(i)], &b = app.panes[static_cast<size_t>(j)];
      acceleratorMatters = acceleratorMatters || (a.technique == b.technique && a.accelerator != b.accelerator);
    }
  std::vector<std::vector<Item>> out(items.size());
  for (size_t i = 0; i < items.size(); ++i)
    for (const Item& it : items[i]) {
      const bool param = it.key.rfind("t:", 0) == 0 || it.key.rfind("a:", 0) == 0;
      if (it.key == "accelerator" && !acceleratorMatters) continue;
      if (values[it.key].size() > 1 && !(param && holders[it.key] < 2) && !it.text.empty()) out[i].push_back(it);
    }
  return out;
}

}  // namespace

std::string paneSettings(const PaneState& pane) {
  std::string s = pane.technique + "|" + pane.accelerator + "|" + std::to_string(pane.spp) + "|" +
                  std::to_string(static_cast<int>(pane.view));
  for (const ParamSet* set : {&pane.techniqueParams, &pane.accelParams})
    for (const ParamDecl& d : set->decls()) s += "|" + d.name + "=" + set->text(d.name);
  return s;
}

std::vector<std::string> distinguishingLabels(const AppState& app) {
  const auto items = differingItems(app);
  std::vector<std::string> labels;
  for (size_t i = 0; i < items.size(); ++i) {
    std::string line(1, paneLetter(static_cast<int>(i)));
    const PaneState& pane = app.panes[i];
    if (!pane.label.empty() && paneSettings(pane) == pane.labelFor) {
      labels.push_back(line + "  " + pane.label);
      continue;
    }
    for (const Item& it : items[i]) line += "  " + it.text;
    if (items[i].empty()) line += "  " + app.panes[i].technique;
    labels.push_back(line);
  }
  return labels;
}

std::vector<std::string> parameterDifferences(const AppState& app) {
  const auto items = differingItems(app);
  std::vector<std::string> out;
  for (const auto& list : items) {
    std::string line;
    for (const Item& it : list)
      if (it.key != "technique" && it.key != "accelerator") line += (line.empty() ? "" : "  ") + it.text;
    out.push_back(line);
  }
  return out;
}

}  // namespace ll::gui
