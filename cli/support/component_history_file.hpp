#pragma once
// history.csv of a component's rubbing run, streamed row by row
// (StreamedTextFile: temporary file, renamed by commit()): t, the response
// dof u_NODE_DIR, then the columns of the paper's case with two tangents per
// contact (run_outputs.hpp). Written by rsi simulate and rsi campaign alike.

#include <cstdint>
#include <string>

#include "history.hpp"
#include "output_files.hpp"

namespace rsi {

class ComponentHistoryFile {
public:
  ComponentHistoryFile(const std::string& path, const std::string& response_name, int n_contacts);
  /// Appends one row (the header first, with the first row).
  void append(const HistoryRow& row, double response);
  /// Writes the header if no row came, then renames the file into place.
  void commit();

private:
  StreamedTextFile m_file;
  std::string m_header;
  std::string m_line;
  std::string m_rest; ///< the row without the response, reused
  std::int64_t m_rows = 0;
};

} // namespace rsi
