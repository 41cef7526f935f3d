#include "framework/executors/cpu/cpu_executor.h"

#include <omp.h>

namespace upf {

CpuExecutor::CpuExecutor(int threads) : threads_(threads > 0 ? threads : omp_get_max_threads()) {}

int CpuExecutor::thread_index() { return omp_get_thread_num(); }

}  // namespace upf
