#include "component_history_file.hpp"

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
  // The response after t; append_csv_number writes printf's "%.17g".
  m_rest.clear();
  append_history_csv_row(m_rest, row);
  const size_t comma = m_rest.find(',');
  m_line.append(m_rest, 0, comma);
  m_line += ',';
  append_csv_number(m_line, response);
  m_line.append(m_rest, comma, std::string::npos);
  m_file.append(m_line);
}

void ComponentHistoryFile::commit() {
  if (m_rows == 0) m_file.append(m_header);
  m_file.commit();
}

} // namespace rsi
