#include "slides/slide_figures.h"

#include <exception>

#include <stb/stb_image_write.h>

namespace ll {

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
      const PresetFigure figure = renderPresetFigure(slide.preset->preset, limits, [&](double fraction) {
        if (onProgress) onProgress(done + fraction);
      });
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
