#include "slides/slide_figures.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <stb/stb_image_write.h>

#include "scene/scene_loader.h"

namespace ll {

namespace {

constexpr int kResolutionScale = 2;  // render pixels per CSS pixel

}  // namespace

std::string pngBytes(const Image& image) {
  std::vector<uint8_t> bytes(image.pixelCount() * 3);
  for (size_t i = 0; i < image.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) bytes[3 * i + static_cast<size_t>(c)] = linearToSrgb8(image.pixels()[i][c]);
  std::string png;
  stbi_write_png_to_func(
      [](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), static_cast<size_t>(size)); },
      &png, image.width(), image.height(), 3, bytes.data(), 3 * image.width());
  return png;
}

std::vector<SlideFigure> renderDeckFigures(const Deck& deck, const FigureLimits& limits,
                                           const std::function<void(double)>& onProgress,
                                           std::vector<FigureReport>* reports) {
  std::vector<SlideFigure> figures(deck.slides.size());
  if (reports) reports->assign(deck.slides.size(), {});
  double done = 0.0;
  for (size_t i = 0; i < deck.slides.size(); ++i) {
    const Slide& slide = deck.slides[i];
    if (!slide.preset) continue;
    SlideFigure& f = figures[i];
    f.caption = slide.preset->preset.description;
    try {
      // The size shown in the page: the preset's, else its scene camera's; rendered at twice that.
      ViewPreset preset = slide.preset->preset;
      int w = preset.width, h = preset.height;
      if (w <= 0 || h <= 0) {
        const Scene scene = loadScene(preset.scene);
        w = scene.camera.width;
        h = scene.camera.height;
      }
      preset.width = w * kResolutionScale;
      preset.height = h * kResolutionScale;
      const PresetFigure figure = renderPresetFigure(preset, limits, [&](double fraction) {
        if (onProgress) onProgress(done + fraction);
      });
      const double css = static_cast<double>(w) / std::max(figure.paneWidth, 1);  // CSS pixels per PNG pixel
      f.width = static_cast<int>(std::lround(figure.image.width() * css));
      f.height = static_cast<int>(std::lround(figure.image.height() * css));
      for (const std::string& note : figure.notes) f.caption += (f.caption.empty() ? "" : " ") + note;
      f.png = pngBytes(figure.image);
      if (f.png.empty()) f.error = "PNG encoding failed";
      if (reports) (*reports)[i] = {figure.image.width(), figure.image.height(), figure.seconds, figure.missingTasks};
    } catch (const std::exception& e) {
      f.error = deck.path + ":" + std::to_string(slide.preset->line) + ": " + e.what();
    }
    done += 1.0;
    if (onProgress) onProgress(done);
  }
  return figures;
}

}  // namespace ll
