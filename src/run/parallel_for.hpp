#pragma once
// The one worker pool: runs task(0), ..., task(count - 1) on `threads` threads (at most one
// per task) while the calling thread waits. Tasks are handed out in index order; once a task
// throws, no further task starts, and after every thread has finished the first exception is
// rethrown. `while_waiting`, when given, runs on the calling thread about every 250 ms until
// the tasks are done (a progress line, say).
#include <cstddef>
#include <functional>

namespace swarmagg {

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void()>& while_waiting = nullptr);

}  // namespace swarmagg
