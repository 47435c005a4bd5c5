#include "ecs/executor.h"

#include <oneapi/tbb/info.h>

namespace sylva::ecs {

executor::executor(int threads)
    : m_threads(threads > 0 ? threads : tbb::info::default_concurrency()),
      m_arena(std::make_unique<tbb::task_arena>(m_threads)) {
    m_arena->initialize();
}

}  // namespace sylva::ecs
