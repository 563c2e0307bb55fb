// The self-contained HTML grade report: inline CSS and JS, images embedded as
// base64 data URIs, so the one file can be handed back to the student.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "core/base64.h"
#include "core/error.h"
#include "core/markup.h"
#include "grading/grade_reports.h"
#include "grading/report_text.h"

namespace ll::grading {

namespace {

namespace fs = std::filesystem;

constexpr int kSmallImageWidth = 256;  // small renders are scaled up to about this width


std::string formatG(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}


// An id attribute (no whitespace allowed) for a task's section.
std::string anchor(const std::string& taskId) {
  std::string id = "task-" + taskId;
  std::replace_if(
      id.begin(), id.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n'; }, '-');
  return escapeMarkup(id, true);
}


std::string badge(Status s) {
  return std::string("<span class=\"badge ") + statusStyle(s).cssClass + "\">" + statusName(s) + "</span>";
}


// A PNG as embedded bytes, with its size from the IHDR chunk (0 if unreadable).
struct Png {
  std::string dataUri;
  int width = 0, height = 0;
};

std::optional<Png> loadPng(const fs::path& dir, const std::string& relative) {
  if (relative.empty()) return std::nullopt;
  std::ifstream in(dir / relative, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) return std::nullopt;
  Png png;
  png.dataUri = "data:image/png;base64," + base64(bytes);
  if (bytes.size() >= 24 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
      bytes.compare(12, 4, "IHDR") == 0) {
    auto be32 = [&bytes](size_t at) {
      uint32_t v = 0;
      for (size_t k = 0; k < 4; ++k) v = v << 8 | static_cast<unsigned char>(bytes[at + k]);
      return v;
    };
    const uint32_t w = be32(16), h = be32(20);
    if (w > 0 && h > 0 && w <= 1u << 16 && h <= 1u << 16) {
      png.width = static_cast<int>(w);
      png.height = static_cast<int>(h);
    }
  }
  return png;
}

// width/height attributes: small images scaled up by a whole factor to about 256 px.
std::string sizeAttributes(const Png& png) {
  if (png.width <= 0) return " style=\"width:" + std::to_string(kSmallImageWidth) + "px\"";
  const int scale = std::max(1, (kSmallImageWidth + png.width / 2) / png.width);
  return " width=\"" + std::to_string(png.width * scale) + "\" height=\"" +
         std::to_string(png.height * scale) + "\"";
}

std::string imgTag(const Png& png, const std::string& alt, const std::string& cls = "",
                   const std::string& attributes = "") {
  return "<img" + (cls.empty() ? std::string() : " class=\"" + cls + "\"") + " src=\"" +
         png.dataUri + "\" alt=\"" + escapeMarkup(alt, true) + "\"" +
         (attributes.empty() ? sizeAttributes(png) : attributes) + ">";
}

std::string figure(const std::optional<Png>& png, const std::string& caption) {
  std::string html = "<figure>";
  html += png ? imgTag(*png, caption) : "<div class=\"missing\">(image missing)</div>";
  return html + "<figcaption>" + escapeMarkup(caption, true) + "</figcaption></figure>\n";
}

std::string imageEvidence(const ImageEvidence& images, const fs::path& dir) {
  const std::optional<Png> student = loadPng(dir, images.student);
  const std::optional<Png> reference = loadPng(dir, images.reference);
  const std::optional<Png> diff = loadPng(dir, images.diff);

  std::string html = "<div class=\"images\">\n";
  html += figure(student, "student");
  html += figure(reference, "reference");

  // Wipe: the student's image over the reference, clipped to the slider's left part.
  html += "<figure class=\"wipe\">";
  if (student && reference) {
    html += "<div class=\"wipe-box\">" + imgTag(*reference, "reference");
    html += imgTag(*student, "student", "wipe-top", " style=\"clip-path:inset(0 50% 0 0)\"");
    html += "<div class=\"wipe-line\"></div></div>";
    html +=
        "<input type=\"range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"wipe position\">";
  } else {
    html += "<div class=\"missing\">(image missing)</div>";
  }
  html += "<figcaption>wipe: left = student, right = reference</figcaption></figure>\n";

  html += figure(diff, "difference, legend 0 .. " + formatG(images.diffScale));
  return html + "</div>\n";
}

std::string testHtml(const TaskResult& task, const TestResult& t, const fs::path& dir) {
  std::string html = "<div class=\"test " + std::string(statusStyle(t.status).cssClass) + "\">\n";
  html += "<div class=\"test-head\">" + badge(t.status) + " <span class=\"name\">" +
          escapeMarkup(t.name, true) + "</span> <span class=\"meta\">" + escapeMarkup(t.kind, true) +
          (t.kind.empty() ? "" : " &middot; ") + "weight " + formatNumber(t.weight, 3) +
          " &middot; " + formatNumber(t.seconds, 2) + " s</span></div>\n";
  if (!t.message.empty()) html += "<p class=\"message\">" + escapeMarkup(shownMessage(task, t), true) + "</p>\n";
  if (!t.details.empty()) html += "<pre>" + escapeMarkup(t.details, true) + "</pre>\n";
  if (t.images && t.status == Status::Passed)  // a passed test's pictures on request
    html += "<details><summary>images</summary>\n" + imageEvidence(*t.images, dir) + "</details>\n";
  else if (t.images)
    html += imageEvidence(*t.images, dir);
  return html + "</div>\n";
}

constexpr const char* kStyle = R"(
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; margin: 0;
       color: #222; background: #f6f6f4; }
header, section { max-width: 1100px; margin: 0 auto; padding: 16px 24px; }
header { border-bottom: 1px solid #ddd; }
h1 { margin: 8px 0 4px; font-size: 24px; }
h2 { font-size: 19px; margin: 24px 0 8px; }
.total { font-size: 20px; font-weight: 600; margin: 4px 0; }
.meta { color: #666; font-size: 13px; }
table { border-collapse: collapse; margin: 12px 0; background: #fff; }
th, td { text-align: left; padding: 4px 12px; border-bottom: 1px solid #e4e4e4; }
td.score { text-align: right; font-variant-numeric: tabular-nums; }
tfoot td { font-weight: 600; border-bottom: none; }
a { color: #2459a8; text-decoration: none; }
.badge { display: inline-block; padding: 1px 8px; border-radius: 10px; font-size: 12px;
         font-weight: 600; color: #fff; white-space: nowrap; }
.badge.passed { background: #2e8540; }
.badge.failed, .badge.error { background: #c0392b; }
.badge.notimpl { background: #d4a017; color: #222; }
.test { background: #fff; border: 1px solid #e0e0e0; border-left: 4px solid #c0392b;
        border-radius: 4px; padding: 8px 12px; margin: 8px 0; }
.test.passed { border-left-color: #2e8540; }
.test.notimpl { border-left-color: #d4a017; }
.test-head .name { font-weight: 600; }
.message { margin: 6px 0; }
.look { margin: 4px 0 8px; }
code { background: #ececea; padding: 0 4px; border-radius: 3px; }
pre { background: #f2f2f2; padding: 8px; font-size: 13px; margin: 6px 0;
      white-space: pre-wrap; overflow-wrap: anywhere; }  /* long commands wrap: printed, nothing is cut */
.images { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; margin-top: 8px; }
figure { margin: 0; }
figcaption { font-size: 13px; color: #555; text-align: center; }
img { image-rendering: pixelated; max-width: 100%; height: auto; display: block; background: #000; }
.missing { width: 256px; height: 96px; display: flex; align-items: center; justify-content: center;
           border: 1px dashed #aaa; color: #777; }
.wipe-box { position: relative; display: inline-block; line-height: 0; }
.wipe-top { position: absolute; top: 0; left: 0; width: 100%; height: 100%; }
.wipe-line { position: absolute; top: 0; bottom: 0; left: 50%; width: 1px; background: #fff;
             box-shadow: 0 0 2px #000; pointer-events: none; }
.wipe input { display: block; width: 100%; margin: 4px 0; }
)";

// Drives each wipe's clip from its slider.
constexpr const char* kScript = R"(
document.querySelectorAll('.wipe').forEach(function (w) {
  var range = w.querySelector('input'), upper = w.querySelector('.wipe-top');
  var line = w.querySelector('.wipe-line');
  if (!range || !upper) return;
  function update() {
    upper.style.clipPath = 'inset(0 ' + (100 - range.value) + '% 0 0)';
    if (line) line.style.left = range.value + '%';
  }
  range.addEventListener('input', update);
  update();
});
)";

}  // namespace

void writeHtmlReport(const GradeResult& result, const std::string& dir) {
  const fs::path dirPath(dir);
  const std::string path = (dirPath / "report.html").string();
  const std::string name =
      result.title.empty() ? result.assignment : result.assignment + " " + result.title;

  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += "<title>" + escapeMarkup(name, true) + " &ndash; grade report</title>\n";
  html += "<style>" + std::string(kStyle) + "</style>\n</head>\n<body>\n<header>\n";
  html += "<h1>" + escapeMarkup(name, true) + "</h1>\n";
  html += "<p class=\"total\">" + escapeMarkup(pointsSummary(result), true) + "</p>\n";
  html += "<p class=\"meta\">seed " + std::to_string(result.seed) + " &middot; " +
          (result.threads > 0 ? std::to_string(result.threads) + " threads" : "all cores") +
          " &middot; " + formatNumber(result.seconds, 1) + " s</p>\n";

  html +=
      "<table class=\"scores\">\n<thead><tr><th>Task</th><th>Title</th><th>Score</th>"
      "<th>Status</th></tr></thead>\n<tbody>\n";
  for (const TaskResult& task : result.tasks) {
    html += "<tr><td><a href=\"#" + anchor(task.id) + "\">" + escapeMarkup(task.id, true) +
            "</a></td><td>" + escapeMarkup(task.title, true) + "</td><td class=\"score\">" +
            formatNumber(task.score) + " / " + formatNumber(task.points) + "</td><td>" +
            badge(task.status) + "</td></tr>\n";
  }
  const OptionalPoints optional = optionalPoints(result);
  html += "</tbody>\n<tfoot><tr><td></td><td>Total</td><td class=\"score\">" +
          formatNumber(result.score - optional.score) + " / " + formatNumber(result.maxScore) + "</td><td></td></tr>\n";
  if (optional.points > 0.0)
    html += "<tr><td></td><td>Optional, on top</td><td class=\"score\">" + formatNumber(optional.score) + " / " +
            formatNumber(optional.points) + "</td><td></td></tr>\n";
  html += "</tfoot>\n</table>\n</header>\n";

  for (const TaskResult& task : result.tasks) {
    html += "<section id=\"" + anchor(task.id) + "\">\n<h2>" + badge(task.status) + " " +
            escapeMarkup(task.id, true) + " " + escapeMarkup(task.title, true) + " <span class=\"meta\">" +
            formatNumber(task.score) + " / " + formatNumber(task.points) + " points</span></h2>\n";
    if (!task.file.empty() && task.status != Status::Passed)
      html += "<p class=\"look\">look at: <code>" + escapeMarkup(task.file, true) + "</code> (" +
              escapeMarkup(task.functions, true) + ")</p>\n";
    if (task.tests.empty()) html += "<p class=\"meta\">(no tests)</p>\n";
    if (stillTheStub(task)) {  // one card, the checks listed on request
      html += "<div class=\"test notimpl\"><p class=\"message\">" + escapeMarkup(stubAdvice(task), true) +
              "</p>\n<details><summary>the checks</summary><ul>\n";
      for (const TestResult& t : task.tests) html += "<li>" + escapeMarkup(t.name, true) + "</li>\n";
      html += "</ul></details></div>\n</section>\n";
      continue;
    }
    // What needs looking at first: the tests that did not pass, then the rest (each in spec order).
    for (const bool passed : {false, true})
      for (const TestResult& t : task.tests)
        if ((t.status == Status::Passed) == passed) html += testHtml(task, t, dirPath);
    html += "</section>\n";
  }
  html += "<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";

  writeTextFile(path, html);
}

}  // namespace ll::grading
