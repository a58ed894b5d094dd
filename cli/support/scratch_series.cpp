#include "scratch_series.hpp"

#include "output_files.hpp"

namespace rsi {
namespace {

constexpr std::size_t buffer_entries = 8192; // 64 KB

} // namespace

ScratchSeries::ScratchSeries() : m_file(std::tmpfile()) {
  if (!m_file)
    throw OutputError("cannot create a temporary file for the campaign's gap series "
                      "(the temporary directory, TMPDIR or /tmp, not writable)");
  m_buffer.reserve(buffer_entries);
}

ScratchSeries::~ScratchSeries() {
  if (m_file) std::fclose(m_file);
}

void ScratchSeries::append(double x) {
  m_buffer.push_back(x);
  ++m_size;
  if (m_buffer.size() == buffer_entries) flush();
}

void ScratchSeries::flush() {
  if (m_buffer.empty()) return;
  if (std::fwrite(m_buffer.data(), sizeof(double), m_buffer.size(), m_file) != m_buffer.size())
    throw OutputError("cannot write the campaign's gap series to its temporary file (the "
                      "temporary directory, TMPDIR or /tmp, full)");
  m_buffer.clear();
}

void ScratchSeries::rewind() {
  flush();
  if (std::fflush(m_file) != 0 || std::fseek(m_file, 0, SEEK_SET) != 0)
    throw OutputError("cannot write the campaign's gap series to its temporary file (the "
                      "temporary directory, TMPDIR or /tmp, full)");
}

std::size_t ScratchSeries::read(double* out, std::size_t count) {
  const std::size_t got = std::fread(out, sizeof(double), count, m_file);
  if (got < count && std::ferror(m_file))
    throw OutputError("cannot read back the campaign's gap series from its temporary file");
  return got;
}

} // namespace rsi
