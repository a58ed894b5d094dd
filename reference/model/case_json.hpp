#pragma once
// Reading one JSON object of a case file key by key, with the checks every
// case file shares: numbers in a stated range, integers, optional notes, and
// unknown keys rejected by finish(). Every failure raises CaseError naming
// the file, the dotted key and the allowed range.

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "case_file.hpp"

namespace rsi::case_json {

using nlohmann::json;

inline constexpr double inf = std::numeric_limits<double>::infinity();

/// Allowed interval of a number; `open_low` excludes the lower bound.
struct Range {
  double low;
  double high;
  bool open_low;
  bool open_high;
  std::string unit;

  bool contains(double x) const {
    return (open_low ? x > low : x >= low) && (open_high ? x < high : x <= high);
  }
  std::string text() const {
    std::ostringstream s;
    s << (open_low ? "(" : "[") << low << ", " << high << (open_high ? ")" : "]");
    if (!unit.empty()) s << " " << unit;
    return s.str();
  }
};

inline Range positive(const std::string& unit) {
  return {0.0, inf, true, true, unit};
}

/// One JSON object of the case file, read key by key; `finish()` rejects
/// the keys that were never asked for (unknown keys).
class ObjectReader {
public:
  ObjectReader(const json& object, std::string path, const std::string& source)
      : m_object(object)
      , m_path(std::move(path))
      , m_source(source) {
    if (!m_object.is_object())
      fail(m_path.empty() ? "(top level)" : m_path, "must be a JSON object");
  }

  double number(const std::string& key, const Range& range) {
    const json& value = get(key);
    if (!value.is_number())
      fail(full(key), "must be a number in " + range.text() + ", got " + value.dump());
    const double x = value.get<double>();
    if (!std::isfinite(x) || !range.contains(x))
      fail(full(key), "must be in " + range.text() + ", got " + value.dump());
    return x;
  }

  int integer(const std::string& key, long low, long high) {
    const json& value = get(key);
    const std::string allowed =
        "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]";
    if (!value.is_number_integer()) fail(full(key), "must be " + allowed + ", got " + value.dump());
    const long x = value.get<long>();
    if (x < low || x > high) fail(full(key), "must be " + allowed + ", got " + value.dump());
    return static_cast<int>(x);
  }

  /// An optional free-text note (how a calibrated value was found).
  void optional_note(const std::string& key) {
    claim(key);
    if (m_object.contains(key) && !m_object.at(key).is_string())
      fail(full(key), "must be a string (a note), got " + m_object.at(key).dump());
  }

  /// Marks a key as known; the caller reads and checks it itself.
  void claim(const std::string& key) { m_seen.insert(key); }

  ObjectReader object(const std::string& key) {
    return ObjectReader(get(key), full(key), m_source);
  }

  Section section(const std::string& key) {
    ObjectReader s = object(key);
    Section result;
    result.width = s.number("width", positive("m"));
    result.thickness = s.number("thickness", positive("m"));
    s.optional_note("thickness_note");
    s.finish();
    return result;
  }

  void finish() const {
    for (const auto& item : m_object.items())
      if (!m_seen.count(item.key())) fail(full(item.key()), "unknown key");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw CaseError(m_source + ": key '" + key + "': " + what);
  }

  std::string full(const std::string& key) const {
    return m_path.empty() ? key : m_path + "." + key;
  }

private:
  const json& get(const std::string& key) {
    m_seen.insert(key);
    if (!m_object.contains(key)) fail(full(key), "missing (required)");
    return m_object.at(key);
  }

  const json& m_object;
  std::string m_path;
  const std::string& m_source;
  std::set<std::string> m_seen;
};

} // namespace rsi::case_json
