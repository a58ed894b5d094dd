#pragma once
// Work shared by threads that are always joined (issue 13, class 5).
//
// A std::thread destroyed while joinable calls std::terminate, and so does
// an exception leaving a thread's function. Under a memory limit the
// campaign died both ways: a second thread that could not be started
// (std::system_error, no memory for its stack) while the first one ran,
// and std::bad_alloc thrown while a worker reported its run.
//
// run_on_threads starts `count` threads running `worker` and joins every
// one of them whatever happens. An exception a worker lets out sets
// `failed` (the other workers read it to stop taking jobs, or to abandon
// the job they are in by an exception of their own) and the first one is
// rethrown in the caller once all threads have joined: it is recorded
// before `failed` is set, so a worker that stopped because of `failed`
// is never taken for the cause. A thread
// that cannot be started is no error: the workers already running share
// the work (they take jobs in turn), and with none started the caller runs
// `worker` itself.

#include <atomic>
#include <functional>

namespace rsi {

void run_on_threads(int count, const std::function<void()>& worker, std::atomic<bool>& failed);

} // namespace rsi
