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
#include <vector>

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

  /// The file named in messages.
  const std::string& source() const { return m_source; }

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

/// The optional "damping" object of `document` (a case file's top level,
/// read by `top`): {"rayleigh": {"alpha": .., "beta": ..}, "modal_ratio": ..,
/// "note": ".."}; absent: all zero.
inline Damping read_damping(ObjectReader& top, const json& document) {
  Damping out;
  top.claim("damping");
  if (!document.contains("damping")) return out;
  ObjectReader damping = top.object("damping");
  damping.optional_note("note");
  damping.claim("rayleigh");
  if (document.at("damping").is_object() && document.at("damping").contains("rayleigh")) {
    ObjectReader rayleigh = damping.object("rayleigh");
    out.rayleigh.alpha = rayleigh.number("alpha", {0.0, inf, false, true, "1/s"});
    out.rayleigh.beta = rayleigh.number("beta", {0.0, inf, false, true, "s"});
    rayleigh.finish();
  }
  damping.claim("modal_ratio");
  if (document.at("damping").contains("modal_ratio"))
    out.modal_ratio = damping.number("modal_ratio", {0.0, 1.0, false, true, ""});
  damping.claim("projected_rayleigh");
  if (document.at("damping").contains("projected_rayleigh")) {
    const json& value = document.at("damping").at("projected_rayleigh");
    if (!value.is_boolean())
      damping.fail(damping.full("projected_rayleigh"), "must be true or false, got " + value.dump());
    out.projected_rayleigh = value.get<bool>();
    if (out.projected_rayleigh && out.modal_ratio != 0.0)
      damping.fail(damping.full("projected_rayleigh"),
                   "true gives the reduced bladed disk the projected Rayleigh damping; "
                   "modal_ratio would be a second one: drop one of them");
    if (out.projected_rayleigh && !out.rayleigh.any())
      damping.fail(damping.full("projected_rayleigh"),
                   "true projects damping.rayleigh, which is absent or zero: add it");
  }
  damping.finish();
  return out;
}

/// Deepest nesting of objects and arrays a case file may have (the schema
/// needs 4); deeper documents are refused before anything recurses on them.
inline constexpr int max_depth = 32;

/// The JSON document of `text`, refusing what a parser would silently
/// accept: a key repeated in one object (the last would win) and nesting
/// deeper than max_depth. CaseError names `source`, the key or the depth.
inline json parse_document(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keys; // one set per open object
  std::vector<bool> is_object;             // the open containers, innermost last
  std::string path_error;
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event,
                                            json& parsed) {
    using Event = json::parse_event_t;
    if (event == Event::object_start || event == Event::array_start) {
      if (depth >= max_depth)
        throw CaseError(source + ": JSON nested deeper than " + std::to_string(max_depth) +
                        " levels: not a case file");
      is_object.push_back(event == Event::object_start);
      if (event == Event::object_start) keys.emplace_back();
    } else if (event == Event::object_end || event == Event::array_end) {
      if (!is_object.empty()) {
        if (is_object.back()) keys.pop_back();
        is_object.pop_back();
      }
    } else if (event == Event::key && !keys.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!keys.back().insert(key).second)
        throw CaseError(source + ": key '" + key +
                        "' appears twice in one object (a JSON parser would keep the last "
                        "silently): keep one");
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::exception& e) {
    // Not only parse_error: a number beyond the range of a double (1e999)
    // raises out_of_range 406 (found by fuzz/fuzz_case_loader).
    throw CaseError(source + ": malformed JSON: " + e.what());
  }
}

} // namespace rsi::case_json
