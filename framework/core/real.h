// The scalar type and the host/device marker shared by every per-particle function.
#pragma once

#if defined(__CUDACC__)
#define UPF_HD __host__ __device__
#else
#define UPF_HD
#endif

namespace upf {

#ifdef UPF_DOUBLE
using Real = double;
#else
using Real = float;
#endif

}  // namespace upf
