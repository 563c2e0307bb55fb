// Wrapping a pane caption's line to a width, between its fields. The
// captions separate fields with two spaces ("pass 3/16  47 %  1.20 s"), and
// a field is never split while it fits on a line of its own; only a field
// wider than the line breaks, at its single spaces. (ImGui's own wrapping
// also breaks after '.', which put "0." and "26 s" on separate lines.)
// Pure (no ImGui): the caller passes how wide a piece of text is drawn.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ll::gui {

// Drawn width of a piece of text, in the caller's units (pixels).
using TextWidth = std::function<float(std::string_view)>;

// `line` split into lines no wider than `width` where it can be: at field
// separators (two spaces) first, then at single spaces inside a field too
// wide for a line; a word wider than `width` stays whole. A separator field
// "|" or "/" starts the next line rather than ending this one. Lines carry
// no leading or trailing spaces; an empty `line` gives one empty line.
std::vector<std::string> wrapCaptionLine(const std::string& line, float width, const TextWidth& measure);

}  // namespace ll::gui
