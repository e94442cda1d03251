#include "core/thread_arena.h"

#include <algorithm>

namespace verity {

ThreadArena::ThreadArena(int threads) : arena_(threads > 0 ? threads : tbb::task_arena::automatic) {
  // The arena is initialised on its first execute(), after this.
  if (threads > 0)
    allowThreads_.emplace(
        tbb::global_control::max_allowed_parallelism,
        std::max<size_t>(threads, tbb::global_control::active_value(
                                      tbb::global_control::max_allowed_parallelism)));
}

}  // namespace verity
