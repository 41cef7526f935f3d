// Decoding the pictures `upf render` and `upf view` write (stb_image), for the CLI tests: their
// size, how much their pixels vary (a blank picture has a luminance spread near 0), and how much
// of them is blue (water).
#pragma once

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace upf::cli_test {

struct Picture {
  int width = 0, height = 0;  // 0 when the file does not decode
  double luminance_std = 0;   // over every pixel, in 8-bit units (Rec. 709 luminance)
  double blue_fraction = 0;   // of the pixels whose blue exceeds red by more than 40 (of 255)
};

inline Picture decode_picture(const std::filesystem::path& file) {
  Picture p;
  int channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &p.width, &p.height, &channels, 3);
  if (!data) return p;
  double sum = 0, sum2 = 0;
  std::size_t blue = 0;
  const std::size_t n = std::size_t(p.width) * std::size_t(p.height);
  for (std::size_t i = 0; i < n; ++i) {
    const double y = 0.2126 * data[3 * i] + 0.7152 * data[3 * i + 1] + 0.0722 * data[3 * i + 2];
    sum += y;
    sum2 += y * y;
    blue += data[3 * i + 2] > data[3 * i] + 40;
  }
  p.blue_fraction = double(blue) / double(n);
  stbi_image_free(data);
  const double mean = sum / double(n);
  p.luminance_std = std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
  return p;
}

}  // namespace upf::cli_test
