// The scalar type and the host/device marker shared by every per-particle function.
#pragma once

#if defined(__CUDACC__)
#define UPF_HD __host__ __device__
#else
#define UPF_HD
#endif

// Inlined into its caller whatever the compiler's heuristics say, for the helpers of a particle
// stage's loop: left out of line, DEM's contact helper (apply) cost 22 % of the contact stage.
#if defined(__CUDACC__)
#define UPF_INLINE __forceinline__
#elif defined(__GNUC__)
#define UPF_INLINE __attribute__((always_inline)) inline
#else
#define UPF_INLINE inline
#endif

namespace upf {

#ifdef UPF_DOUBLE
using Real = double;
#else
using Real = float;
#endif

}  // namespace upf
