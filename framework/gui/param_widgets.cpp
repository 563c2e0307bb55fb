#include "gui/param_widgets.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

namespace ll::gui {

namespace {

void tooltip(const ParamDecl& d) {
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n%s %s, default %s", d.help.c_str(), d.typeName().c_str(),
                      d.rangeText().c_str(), d.defaultValue.c_str());
}

// Sliders over several decades are easier to use on a log scale.
ImGuiSliderFlags sliderFlags(const ParamDecl& d) {
  ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
  if (d.min > 0.0 && d.max / d.min >= 100.0) flags |= ImGuiSliderFlags_Logarithmic;
  return flags;
}

}  // namespace

bool paramWidgets(ParamSet& params, const std::function<void(const std::string&)>& drawn) {
  bool changed = false;
  for (const ParamDecl& d : params.decls()) {
    ImGui::PushID(d.name.c_str());
    switch (d.type) {
      case ParamDecl::Type::Int: {
        int v = params.getInt(d.name);
        if (ImGui::SliderInt(d.name.c_str(), &v, static_cast<int>(d.min), static_cast<int>(d.max),
                             "%d", sliderFlags(d))) {
          params.set(d.name, std::to_string(
                                 std::clamp(v, static_cast<int>(d.min), static_cast<int>(d.max))));
          changed = true;
        }
        break;
      }
      case ParamDecl::Type::Float: {
        float v = static_cast<float>(params.getFloat(d.name));
        if (ImGui::SliderFloat(d.name.c_str(), &v, static_cast<float>(d.min),
                               static_cast<float>(d.max), "%.4g", sliderFlags(d))) {
          char text[64];
          std::snprintf(text, sizeof text, "%.9g",
                        std::clamp(static_cast<double>(v), d.min, d.max));
          params.set(d.name, text);
          changed = true;
        }
        break;
      }
      case ParamDecl::Type::Bool: {
        bool v = params.getBool(d.name);
        if (ImGui::Checkbox(d.name.c_str(), &v)) {
          params.set(d.name, v ? "true" : "false");
          changed = true;
        }
        break;
      }
      case ParamDecl::Type::Choice: {
        const std::string& current = params.getChoice(d.name);
        if (ImGui::BeginCombo(d.name.c_str(), current.c_str())) {
          for (const std::string& c : d.choices) {
            if (ImGui::Selectable(c.c_str(), c == current) && c != current) {
              params.set(d.name, c);
              changed = true;
            }
          }
          ImGui::EndCombo();
        }
        break;
      }
    }
    tooltip(d);
    if (drawn) drawn(d.name);
    ImGui::PopID();
  }
  return changed;
}

}  // namespace ll::gui
