#pragma once
// A series of doubles kept on disk, not in memory (issue 13, class 9: a
// campaign's memory must not grow with the length of its runs): appended
// in binary to an anonymous temporary file (std::tmpfile: the system
// removes it when it is closed or the process dies), read back in order.
// A campaign keeps each run's blade-1 gap this way until the reference has
// finished and the error norms can be formed (8 bytes a row a run, 16 MB a
// run at 2e6 rows, which stayed in memory before).

#include <cstdio>
#include <vector>

namespace rsi {

class ScratchSeries {
public:
  /// Throws OutputError when no temporary file can be made.
  ScratchSeries();
  ~ScratchSeries();
  ScratchSeries(const ScratchSeries&) = delete;
  ScratchSeries& operator=(const ScratchSeries&) = delete;

  /// Buffered; OutputError when a write fails (the temporary directory full).
  void append(double x);
  long size() const { return m_size; }
  /// Back to the first entry for read(); flushes what append() buffered.
  void rewind();
  /// Up to `count` next entries into `out`; returns how many (0 at the end).
  /// OutputError on a read error.
  std::size_t read(double* out, std::size_t count);

private:
  void flush();

  std::FILE* m_file = nullptr;
  std::vector<double> m_buffer;
  long m_size = 0;
};

} // namespace rsi
