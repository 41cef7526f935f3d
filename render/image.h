// An RGB picture in memory, what the overlays draw on it (filled rectangles and text), and its
// PNG encoding (stb_image_write, Debian's libstb). Text uses stb_easy_font's built-in bitmap-
// like font, scaled by whole pixels, so labels need no font files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/colour_map.h"

namespace upf::render {

class Image {
 public:
  Image(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  Colour& at(int x, int y) {
    return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
  }
  const Colour& at(int x, int y) const {
    return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
  }

  // Clipped to the image.
  void fill_rect(int x0, int y0, int x1, int y1, const Colour& c);
  // Text whose top-left corner is (x, y), `scale` pixels per font unit.
  void draw_text(int x, int y, const std::string& text, const Colour& c, int scale);
  static int text_width(const std::string& text, int scale);
  static int text_height(int scale);

  // 8-bit sRGB-free RGB (values are clamped to [0, 1] and scaled), row after row.
  std::vector<std::uint8_t> rgb8() const;

 private:
  int width_, height_;
  std::vector<Colour> pixels_;
};

// Writes `image` as a PNG at `path` atomically (see write_file_atomically); throws OutputError.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace upf::render
