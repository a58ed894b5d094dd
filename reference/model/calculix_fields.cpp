#include "calculix_fields.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

namespace rsi {
namespace {

/// Parameters whose value ccx keeps in its case (readinput.c).
constexpr std::string_view kFileParameters[] = {"FILE=",     "INPUT=",    "OUTPUT=",
                                                "FILENAME=", "MASSFILE=", "STIFFNESSFILE="};

bool ends_with_file_parameter(const std::string& upper) {
  for (std::string_view p : kFileParameters)
    if (upper.size() >= p.size() && upper.compare(upper.size() - p.size(), p.size(), p) == 0)
      return true;
  return false;
}

bool digit(char c) {
  return c >= '0' && c <= '9';
}

} // namespace

CalculixLine calculix_line(std::string_view raw) {
  const size_t cr = raw.find('\r');
  if (cr != std::string_view::npos) raw = raw.substr(0, cr);
  CalculixLine line;
  for (char c : raw)
    if (c != ' ' && c != '\t') line.squeezed.push_back(c);
  // Upper case, except from a file parameter's '=' to the next comma.
  bool file = false;
  for (char c : line.squeezed) {
    if (file && c == ',') file = false;
    line.upper.push_back(file ? c : static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    if (!file && ends_with_file_parameter(line.upper)) file = true;
  }
  return line;
}

std::optional<std::vector<std::string>> calculix_fields(std::string_view line) {
  std::vector<std::string> fields(1);
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] != ',') {
      fields.back().push_back(line[i]);
      continue;
    }
    if (fields.size() == kCalculixFields) {
      // ccx accepts a 17th field and beyond only if nothing but commas follow.
      for (size_t k = i + 1; k < line.size(); ++k)
        if (line[k] != ',') return std::nullopt;
      fields.emplace_back();
      break;
    }
    fields.emplace_back();
  }
  if (fields.back().empty()) fields.pop_back();
  return fields;
}

std::optional<std::int64_t> fortran_integer(std::string_view field, size_t width) {
  field = field.substr(0, std::min(width, field.size()));
  size_t i = 0;
  bool negative = false;
  if (i < field.size() && (field[i] == '+' || field[i] == '-')) negative = field[i++] == '-';
  std::int64_t value = 0;
  for (; i < field.size(); ++i) {
    if (!digit(field[i])) return std::nullopt;
    value = value * 10 + (field[i] - '0');
    if (value > std::int64_t{2147483648}) return std::nullopt;
  }
  if (negative) value = -value;
  if (value > std::numeric_limits<std::int32_t>::max() ||
      value < std::numeric_limits<std::int32_t>::min())
    return std::nullopt;
  return value;
}

std::optional<double> fortran_real(std::string_view field, size_t width) {
  field = field.substr(0, std::min(width, field.size()));
  size_t i = 0;
  std::string mantissa;
  if (i < field.size() && (field[i] == '+' || field[i] == '-')) {
    if (field[i] == '-') mantissa.push_back('-');
    ++i;
  }
  bool digits = false;
  bool point = false;
  for (; i < field.size(); ++i) {
    if (digit(field[i])) {
      digits = true;
      mantissa.push_back(field[i]);
    } else if (field[i] == '.' && !point) {
      point = true;
      mantissa.push_back('.');
    } else {
      break;
    }
  }
  std::string exponent;
  if (i < field.size()) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(field[i])));
    if (c == 'E' || c == 'D' || c == 'Q') ++i;
    else if (c != '+' && c != '-') return std::nullopt;
    if (i < field.size() && (field[i] == '+' || field[i] == '-')) exponent.push_back(field[i++]);
    bool exponent_digits = false;
    for (; i < field.size() && digit(field[i]); ++i) {
      exponent.push_back(field[i]);
      exponent_digits = true;
    }
    if (!exponent_digits || i != field.size()) return std::nullopt;
  }
  if (!digits) return 0.0; // gfortran reads ".", "+", "-" and "e5" as 0
  std::string text = mantissa;
  if (!exponent.empty()) text += "e" + exponent;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // Beyond double's range: 0 for an underflow, infinite for an overflow.
    const bool overflow = !exponent.empty() && exponent[0] != '-';
    const bool negative = mantissa[0] == '-';
    return overflow ? (negative ? -HUGE_VAL : HUGE_VAL) : (negative ? -0.0 : 0.0);
  }
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

} // namespace rsi
