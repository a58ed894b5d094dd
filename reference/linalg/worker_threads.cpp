#include "worker_threads.hpp"

#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace rsi {

void run_on_threads(int count, const std::function<void()>& worker, std::atomic<bool>& failed) {
  std::mutex guard;
  std::exception_ptr first; ///< the first exception a worker let out
  auto guarded = [&]() noexcept {
    try {
      worker();
    } catch (...) {
      // `first` before `failed`: a worker that stops because it sees
      // `failed` (by an exception of its own) must not be taken for the cause.
      const std::lock_guard<std::mutex> lock(guard);
      if (!first) first = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> threads;
  try {
    threads.reserve(static_cast<size_t>(count));
    for (int t = 0; t < count; ++t)
      threads.emplace_back(guarded);
  } catch (const std::system_error&) { // a thread not started: the others share its work
  } catch (const std::bad_alloc&) {    // the vector itself: no thread started by this call
  }
  if (threads.empty()) guarded();
  for (std::thread& t : threads)
    t.join();
  if (first) std::rethrow_exception(first);
}

} // namespace rsi
