#include "gui/ui_scale.h"

namespace ll::gui {
namespace {
float currentScale = 1.0f;  // one GUI per process, like ImGui's own context
}  // namespace

float uiScale() { return currentScale; }
void setUiScale(float scale) { currentScale = scale; }

}  // namespace ll::gui
