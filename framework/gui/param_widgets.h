// ImGui widgets generated from parameter declarations: a slider with the
// declared range for numbers (logarithmic when the range spans decades), a
// checkbox for booleans, a combo for choices; the help text and range are
// the tooltip. Nothing here knows any technique by name.
#pragma once

#include <functional>
#include <string>

#include "core/params.h"

namespace ll::gui {

// Draws one widget per declared parameter of `params`; returns true if any
// value changed (the new value is already stored, and always in range).
// `drawn`, if given, is called with each parameter's name right after its widget.
bool paramWidgets(ParamSet& params, const std::function<void(const std::string&)>& drawn = {});

}  // namespace ll::gui
