#include "stored_digits.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace rsi {

namespace {

/// Significant digits of the shortest representation of x that reads back to x.
int shortest_digits(double x) {
  char text[32];
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, x);
  int first = -1; // first nonzero digit of the mantissa
  int last = -1;  // last nonzero digit of the mantissa
  int position = 0;
  for (const char* c = text; c != r.ptr && *c != 'e'; ++c) {
    if (*c < '0' || *c > '9') continue; // sign, decimal point
    if (*c != '0') {
      if (first < 0) first = position;
      last = position;
    }
    ++position;
  }
  return first < 0 ? 0 : last - first + 1;
}

} // namespace

int stored_digits(const Eigen::SparseMatrix<double>& a) {
  int digits = 0;
  const double* values = a.valuePtr();
  const Eigen::Index n = a.outerSize();
  for (Eigen::Index j = 0; j < n && digits < 17; ++j) {
    const Eigen::Index end = a.isCompressed() ? a.outerIndexPtr()[j + 1]
                                              : a.outerIndexPtr()[j] + a.innerNonZeroPtr()[j];
    for (Eigen::Index k = a.outerIndexPtr()[j]; k < end; ++k)
      if (values[k] != 0.0) digits = std::max(digits, shortest_digits(values[k]));
  }
  return digits == 0 ? 17 : digits;
}

double digits_rounding(int digits) {
  const double unit_roundoff = 0.5 * std::numeric_limits<double>::epsilon();
  return std::max(0.5 * std::pow(10.0, 1 - digits), unit_roundoff);
}

} // namespace rsi
