// A guard for code that streams particle arrays raw (the frame writers): every built-in array
// and every named field must hold exactly one value per particle.
#pragma once

#include <string>

#include "framework/particles/particles.h"

namespace upf {

// Throws std::logic_error naming `who` and the first array or field whose length is not
// particles.size(): a short array would be read past its end.
void check_array_sizes(const Particles& particles, const std::string& who);

}  // namespace upf
