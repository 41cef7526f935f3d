#include "render/colour_map.h"

#include "framework/output/type_palette.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace upf::render {

namespace {
Colour hex(std::uint32_t rgb) {
  return Colour(float((rgb >> 16) & 0xff), float((rgb >> 8) & 0xff), float(rgb & 0xff)) / 255.f;
}
}  // namespace

Colour type_colour(ParticleType type) {
  // The palette every output shares (the PLY point clouds too), so a liquid is the same blue.
  const Rgb8 c = upf::type_colour(type);
  return Colour(float(c.r), float(c.g), float(c.b)) / 255.f;
}

Colour material_colour(std::uint32_t material) {
  // Okabe & Ito's colour-blind-safe set (2008), then repeating.
  static const std::array<std::uint32_t, 8> kPalette = {0x0072b2, 0xe69f00, 0x009e73, 0xcc79a7,
                                                        0x56b4e9, 0xd55e00, 0xf0e442, 0x999999};
  return hex(kPalette[material % kPalette.size()]);
}

Colour viridis(double s) {
  // matplotlib's viridis sampled at s = 0, 1/8, ..., 1; linear in between.
  static const std::array<std::uint32_t, 9> kSamples = {
      0x440154, 0x472c7a, 0x3b518b, 0x2c718e, 0x21908d, 0x27ad81, 0x5cc863, 0xaadc32, 0xfde725};
  if (std::isnan(s)) return hex(0xff00ff);
  const double x = std::clamp(s, 0.0, 1.0) * double(kSamples.size() - 1);
  const std::size_t i = std::min<std::size_t>(std::size_t(x), kSamples.size() - 2);
  const float f = float(x - double(i));
  return (1 - f) * hex(kSamples[i]) + f * hex(kSamples[i + 1]);
}

}  // namespace upf::render
