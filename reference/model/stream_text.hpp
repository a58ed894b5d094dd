#pragma once
// The text of a string stream, never a truncated one. A string stream fails
// only when its buffer cannot grow: libstdc++'s stringbuf catches the
// std::bad_alloc and returns eof, and the stream sets badbit instead of
// throwing, so a table, a deck or a cache key built under a memory limit
// came out cut short with no error (issue 13, class 5). Thrown here as
// std::bad_alloc, as operator new would.

#include <new>
#include <sstream>
#include <string>

namespace rsi {

inline std::string stream_text(const std::ostringstream& stream) {
  if (!stream) throw std::bad_alloc();
  return stream.str();
}

} // namespace rsi
