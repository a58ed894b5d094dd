#include "liner_patch_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "message_number.hpp"

namespace rsi {

namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("LinerPatchCells: " + what);
}

void width(double w, const char* name) {
  if (!(std::isfinite(w) && w >= 0.0))
    refuse(std::string(name) + " = " + message_number(w) + ", allowed finite and >= 0");
}

/// The integers i with centre (i + 1/2) h in [from, to] (closed): first and
/// last; last < first when there is none.
void centres_within(double from, double to, double h, double& first, double& last) {
  first = std::ceil(from / h - 0.5);
  last = std::floor(to / h - 0.5);
}

} // namespace

std::vector<int> patch_sectors(const AbradableCells& cells, double theta, double angle) {
  std::vector<int> sectors;
  patch_sectors(cells, theta, angle, sectors);
  return sectors;
}

void patch_sectors(const AbradableCells& cells, double theta, double angle,
                   std::vector<int>& sectors) {
  width(angle, "angular width");
  if (!std::isfinite(theta)) cells.sector(theta); // refuses it
  const double turn = 2.0 * M_PI;
  const double a = theta - turn * std::floor(theta / turn);
  double first = 0.0, last = 0.0;
  centres_within(a - 0.5 * angle, a + 0.5 * angle, cells.pitch(), first, last);
  const int n = cells.n_theta();
  sectors.clear();
  if (!(last >= first)) {
    sectors.push_back(cells.sector(theta));
  } else if (last - first + 1.0 >= n) {
    for (int i = 0; i < n; ++i)
      sectors.push_back(i);
  } else {
    // Fewer than n integers with a in [0, 2 pi): all within (-2 n, 2 n).
    for (long long i = static_cast<long long>(first); i <= static_cast<long long>(last); ++i)
      sectors.push_back(static_cast<int>(((i % n) + n) % n));
    std::sort(sectors.begin(), sectors.end());
  }
}

std::vector<int> patch_rows(const AbradableCells& cells, double z, double width_axial) {
  width(width_axial, "axial width");
  const int home = cells.row(z); // refuses z outside the liner
  const double z_min = cells.geometry().z_min;
  double first = 0.0, last = 0.0;
  centres_within(z - 0.5 * width_axial - z_min, z + 0.5 * width_axial - z_min, cells.row_height(),
                 first, last);
  first = std::max(first, 0.0);
  last = std::min(last, static_cast<double>(cells.n_axial() - 1));
  std::vector<int> rows;
  if (!(last >= first)) {
    rows.push_back(home);
  } else {
    for (int j = static_cast<int>(first); j <= static_cast<int>(last); ++j)
      rows.push_back(j);
  }
  return rows;
}

std::vector<int> patch_cells(const AbradableCells& cells, double theta, double z,
                             const TipPatch& patch) {
  width(patch.circumferential, "circumferential width");
  const std::vector<int> rows = patch_rows(cells, z, patch.axial);
  const std::vector<int> sectors =
      patch_sectors(cells, theta, patch.circumferential / cells.geometry().radius);
  std::vector<int> out;
  cells_of(rows, sectors, cells.n_theta(), out);
  return out;
}

void cells_of(const std::vector<int>& rows, const std::vector<int>& sectors, int n_theta,
              std::vector<int>& cells) {
  cells.clear();
  cells.reserve(rows.size() * sectors.size());
  for (int j : rows)
    for (int i : sectors)
      cells.push_back(j * n_theta + i);
}

double patch_compliant(const AbradableCells& cells, const std::vector<BarState>& from,
                       double depth_pred, double compliance, std::vector<BarResponse>& bars) {
  PatchCompliantSolve solve;
  return solve(cells, from, depth_pred, compliance, bars);
}

double PatchCompliantSolve::operator()(const AbradableCells& cells,
                                       const std::vector<BarState>& from, double depth_pred,
                                       double compliance, std::vector<BarResponse>& bars) {
  const double f = force(cells, from, depth_pred, compliance);
  bars.resize(from.size());
  for (size_t i = 0; i < from.size(); ++i)
    bars[i] = response(cells, from[i], depth_pred, compliance, f);
  return f;
}

void PatchCompliantSolve::place(const AbradableCells& cells, const std::vector<BarState>& from) {
  if (from.empty()) refuse("a patch over no cell");
  const double k = cells.stiffness();
  const auto same = [](const BarState& a, const BarState& b) {
    return a.wear == b.wear && a.yield_force == b.yield_force;
  };
  if (std::equal(from.begin(), from.end(), m_from.begin(), m_from.end(), same)) return;
  // The breakpoints of G (header), sorted.
  m_from = from;
  m_breaks.clear();
  for (const BarState& s : from) {
    m_breaks.push_back(s.wear);
    m_breaks.push_back(s.wear + s.yield_force / k);
  }
  std::sort(m_breaks.begin(), m_breaks.end());
  m_g.assign(m_breaks.size(), std::numeric_limits<double>::quiet_NaN());
}

LinearPiece PatchCompliantSolve::piece(const AbradableCells& cells,
                                       const std::vector<BarState>& from, double depth) {
  place(cells, from);
  const double k = cells.stiffness(), kh = cells.hardening_stiffness();
  const auto next = std::upper_bound(m_breaks.begin(), m_breaks.end(), depth);
  LinearPiece p;
  p.upper = next == m_breaks.end() ? std::numeric_limits<double>::infinity() : *next;
  if (next == m_breaks.begin()) {
    p.lower = -std::numeric_limits<double>::infinity();
    return p;
  }
  p.lower = *(next - 1);
  for (const BarState& s : from) {
    if (!(s.wear <= p.lower)) continue;
    if (s.wear + s.yield_force / k <= p.lower) {
      p.slope += k * kh / (k + kh);
      p.intercept += k * (s.yield_force - kh * s.wear) / (k + kh);
    } else {
      p.slope += k;
      p.intercept -= k * s.wear;
    }
  }
  return p;
}

double PatchCompliantSolve::force(const AbradableCells& cells, const std::vector<BarState>& from,
                                  double depth_pred, double compliance) {
  place(cells, from);
  if (!(compliance >= 0.0)) refuse("compliance = " + message_number(compliance) + ", allowed >= 0");
  const double k = cells.stiffness(), kh = cells.hardening_stiffness();
  const auto yield_depth = [k](const BarState& s) { return s.wear + s.yield_force / k; };
  // The piece holding the root starts at the largest b with
  // c G(b) <= d~ - b, G(b) from wear differences only (no d~).
  const auto at_or_past = [&](size_t j) {
    if (std::isnan(m_g[j])) {
      const double b = m_breaks[j];
      double g = 0.0;
      for (const BarState& s : from)
        g += cells.bar_force(s, b - s.wear);
      m_g[j] = g;
    }
    return compliance * m_g[j] <= depth_pred - m_breaks[j];
  };
  long lo = -1, hi = static_cast<long>(m_breaks.size());
  while (hi - lo > 1) {
    const long mid = lo + (hi - lo) / 2;
    (at_or_past(static_cast<size_t>(mid)) ? lo : hi) = mid;
  }
  double force = 0.0;
  if (lo >= 0) {
    const double start = m_breaks[static_cast<size_t>(lo)];
    double n_elastic = 0.0, n_plastic = 0.0, sum_elastic = 0.0, sum_plastic = 0.0;
    for (const BarState& s : from) {
      if (!(s.wear <= start)) continue; // not touching on this piece
      const double delta_pred = depth_pred - s.wear;
      if (yield_depth(s) <= start) {
        n_plastic += 1.0;
        sum_plastic += k * (kh * delta_pred + s.yield_force);
      } else {
        n_elastic += 1.0;
        sum_elastic += k * delta_pred;
      }
    }
    // The piece's closed form (header), term for term
    // AbradableCells::compliant's with one bar.
    if (n_plastic == 0.0)
      force = sum_elastic / (1.0 + compliance * (n_elastic * k));
    else
      force = ((k + kh) * sum_elastic + sum_plastic) /
              ((k + kh) * (1.0 + compliance * (n_elastic * k)) + compliance * k * kh * n_plastic);
  }
  return force;
}

} // namespace rsi
