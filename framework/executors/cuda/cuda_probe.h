// The CUDA executor's entry points available so far: whether a device is present.
#pragma once

#include <string>

namespace upf::cuda {

// Number of CUDA devices; 0 when there is no device or no driver (never throws).
int device_count();
// A one-line description of device 0, or why there is none.
std::string describe_device();

}  // namespace upf::cuda
