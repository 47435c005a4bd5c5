#include "ecs/executor.h"

#include <algorithm>
#include <oneapi/tbb/info.h>

namespace sylva::ecs {

executor::executor(int threads)
    : m_threads(threads > 0 ? threads : tbb::info::default_concurrency()),
      m_worker_limit(std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism,
          std::size_t(std::max(m_threads, tbb::info::default_concurrency())))),
      m_arena(std::make_unique<tbb::task_arena>(m_threads)) {
    m_arena->initialize();
}

}  // namespace sylva::ecs
