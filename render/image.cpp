#include "render/image.h"

#include <stb_easy_font.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"

namespace upf::render {

Image::Image(int width, int height)
    : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height)) {}

void Image::fill_rect(int x0, int y0, int x1, int y1, const Colour& c) {
  for (int y = std::max(0, y0); y < std::min(height_, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(width_, x1); ++x) at(x, y) = c;
}

void Image::draw_text(int x, int y, const std::string& text, const Colour& c, int scale) {
  // stb_easy_font emits quads of 4 vertices (x, y, z, colour: 16 bytes each) in font units.
  std::vector<char> buffer(text.size() * 300 + 1024);
  std::string copy = text;
  const int quads =
      stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
  for (int q = 0; q < quads; ++q) {
    const float* v = reinterpret_cast<const float*>(buffer.data() + std::size_t(q) * 64);
    const float* w = reinterpret_cast<const float*>(buffer.data() + std::size_t(q) * 64 + 32);
    fill_rect(x + int(std::lround(v[0] * float(scale))), y + int(std::lround(v[1] * float(scale))),
              x + int(std::lround(w[0] * float(scale))), y + int(std::lround(w[1] * float(scale))),
              c);
  }
}

int Image::text_width(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

int Image::text_height(int scale) {
  return 7 * scale;
}

std::vector<std::uint8_t> Image::rgb8() const {
  std::vector<std::uint8_t> out(pixels_.size() * 3);
  for (std::size_t i = 0; i < pixels_.size(); ++i)
    for (int c = 0; c < 3; ++c)
      out[3 * i + std::size_t(c)] =
          std::uint8_t(std::lround(std::clamp(pixels_[i][c], 0.f, 1.f) * 255.f));
  return out;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  const std::vector<std::uint8_t> rgb = image.rgb8();
  std::string encoded;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(append, &encoded, image.width(), image.height(), 3, rgb.data(),
                              image.width() * 3))
    throw OutputError(path.string() + ": the PNG encoder failed");
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(encoded.data(), std::streamsize(encoded.size())); });
}

}  // namespace upf::render
