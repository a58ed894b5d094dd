#pragma once
// How CalculiX (ccx 2.20) reads one line of an input deck and the numbers
// in it, so that rsi reads a deck as ccx does (src/readinput.c,
// splitline.f, nodes.f, noelsets.f):
//   - a line is read up to its first '\r'; at most 1319 characters
//     (fgets into 1320 bytes: a longer line is read as two lines);
//   - every blank and tab is removed ("1 2" is "12"); what is left empty
//     or starting "**" is skipped;
//   - the line is upper-cased, except a file name after FILE=, INPUT=,
//     OUTPUT=, FILENAME=, MASSFILE= or STIFFNESSFILE= (up to the next comma);
//   - fields are separated by commas, one trailing empty field dropped
//     ("1, 2," has two fields); at most 16 fields (more are an error
//     unless only commas follow);
//   - an integer is read with Fortran's I10 from the field's first 10
//     characters: an optional sign and digits, an empty field is 0;
//   - a real with F20.0 from the first 20 characters: sign, digits with
//     an optional point, an optional exponent (E, D or Q then an optional
//     sign and digits, or a sign and digits alone: "1.5+2" is 150); an
//     empty mantissa reads as 0 (".", "+", "e5"), as gfortran reads it.
// Each reading checked by running ccx 2.20 on a one-element deck holding
// it (verification/imports/test_calculix_deck.cpp lists them).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rsi {

/// The longest line ccx reads whole.
constexpr size_t kCalculixLineLength = 1319;
/// The most fields ccx reads from one line.
constexpr size_t kCalculixFields = 16;

/// A deck line as ccx sees it: up to the first '\r', blanks and tabs
/// removed; `upper` also upper-cased except file names.
struct CalculixLine {
  std::string squeezed; ///< blanks removed, case kept
  std::string upper;    ///< blanks removed, upper case except file names
  bool skipped() const { return upper.empty() || upper.rfind("**", 0) == 0; }
  bool keyword() const { return !skipped() && upper[0] == '*'; }
};

CalculixLine calculix_line(std::string_view raw);

/// The fields of a line (ccx's splitline); std::nullopt when ccx refuses
/// the line for holding more than 16 fields.
std::optional<std::vector<std::string>> calculix_fields(std::string_view line);

/// Fortran I10 of the field's first `width` characters (ccx: 10);
/// std::nullopt if they are not an integer or it lies outside
/// [-2147483648, 2147483647] (ccx refuses both). An empty field is 0.
std::optional<std::int64_t> fortran_integer(std::string_view field, size_t width = 10);

/// Fortran F20.0 of the field's first `width` characters (ccx: 20);
/// std::nullopt if they are not a number. May be infinite (an exponent
/// beyond double's range).
std::optional<double> fortran_real(std::string_view field, size_t width = 20);

} // namespace rsi
