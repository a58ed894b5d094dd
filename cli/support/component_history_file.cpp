#include "component_history_file.hpp"

#include <cstdio>

#include "run_outputs.hpp"

namespace rsi {

ComponentHistoryFile::ComponentHistoryFile(const std::string& path,
                                           const std::string& response_name, int n_contacts)
    : m_file(path)
    // t, the response dof, then the columns of the paper's case (3D: two tangents).
    , m_header("t," + response_name + history_csv_header(n_contacts, 2).substr(1)) {}

void ComponentHistoryFile::append(const HistoryRow& row, double response) {
  m_line.clear();
  if (m_rows++ == 0) {
    m_line = m_header;
    if (row.plastic_work) m_line.insert(m_line.size() - 1, ",W_plastic");
  }
  std::string rest;
  append_history_csv_row(rest, row);
  const size_t comma = rest.find(',');
  m_line += rest.substr(0, comma);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ",%.17g", response);
  m_line += buffer;
  m_line += rest.substr(comma);
  m_file.append(m_line);
}

void ComponentHistoryFile::commit() {
  if (m_rows == 0) m_file.append(m_header);
  m_file.commit();
}

} // namespace rsi
