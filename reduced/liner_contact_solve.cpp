#include "liner_contact_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "component_integration_error.hpp"
#include "message_number.hpp"

namespace rsi {

namespace {

const std::string kWhere = "ComponentIntegrator (abradable liner): ";
// Sweeps in a row whose change stays at or below the round-off floor
// relative_change x S before the step is taken as converged (header).
constexpr int kStagnationSweeps = 100;

struct DiskSolution {
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  bool rim = false; ///< |x| = R (slip)
  bool ok = true;
};

/// argmin 1/2 x^T A x + b^T x over |x| <= R (header): stick inside, else
/// x = -(A + nu I)^-1 b on the rim, nu by Newton's method on
/// 1/|x(nu)| - 1/R safeguarded by bisection on [0, |b| / R] (at nu = |b|/R,
/// |x| <= |b| / (a_min + nu) <= R).
DiskSolution disk_minimum(const Eigen::Matrix2d& a, const Eigen::Vector2d& b, double radius) {
  DiskSolution d;
  const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  if (!(a(0, 0) > 0.0 && det > 0.0)) {
    d.ok = radius <= 0.0;
    d.rim = true;
    return d;
  }
  if (radius <= 0.0) {
    d.rim = true;
    return d;
  }
  const auto at = [&](double nu, Eigen::Matrix2d& inverse) {
    Eigen::Matrix2d m = a;
    m(0, 0) += nu;
    m(1, 1) += nu;
    const double dm = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    inverse << m(1, 1) / dm, -m(0, 1) / dm, -m(1, 0) / dm, m(0, 0) / dm;
    return Eigen::Vector2d(-(inverse * b));
  };
  Eigen::Matrix2d inverse;
  Eigen::Vector2d x = at(0.0, inverse);
  if (x.norm() <= radius) {
    d.x = x;
    return d;
  }
  const double eps = std::numeric_limits<double>::epsilon();
  double lo = 0.0, hi = b.norm() / radius, nu = 0.0;
  for (int it = 0; it < 200; ++it) {
    const double n = x.norm();
    if (std::abs(n - radius) <= 4.0 * eps * radius || hi - lo <= 4.0 * eps * hi) {
      d.x = x * (radius / n);
      d.rim = true;
      return d;
    }
    (n > radius ? lo : hi) = nu;
    const double q = x.dot(inverse * x);
    double next = nu + (n - radius) / radius * n * n / q;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    nu = next;
    x = at(nu, inverse);
  }
  d.ok = false;
  return d;
}

/// Whether two ascending lists share an element.
bool sorted_lists_meet(const std::vector<int>& a, const std::vector<int>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    (*i < *j) ? ++i : ++j;
  }
  return false;
}

} // namespace

LinerContactSolve::LinerContactSolve(int n_contacts, double dt, double mu,
                                     const AbradableCells& cells, const LinerContactLayout& layout,
                                     const LinerContactSolveOptions& options)
    : m_nc(n_contacts)
    , m_dt(dt)
    , m_mu(mu)
    , m_cells(cells)
    , m_options(options)
    , m_phi(layout.polar_angle)
    , m_omega(layout.omega)
    , m_patch(layout.patch)
    , m_patched(layout.patch.present())
    , m_axial(layout.axial) {
  if (static_cast<int>(layout.polar_angle.size()) != n_contacts ||
      static_cast<int>(layout.axial.size()) != n_contacts)
    throw std::invalid_argument(kWhere + "the layout has " +
                                std::to_string(layout.polar_angle.size()) + " angles and " +
                                std::to_string(layout.axial.size()) + " axial coordinates, allowed " +
                                std::to_string(n_contacts) + " each");
  if (!(std::isfinite(mu) && mu >= 0.0))
    throw std::invalid_argument(kWhere + "mu = " + message_number(mu) + ", allowed finite >= 0");
  if (!std::isfinite(layout.omega))
    throw std::invalid_argument(kWhere + "omega = " + message_number(layout.omega) +
                                ", allowed finite");
  if (!(std::isfinite(layout.patch.circumferential) && layout.patch.circumferential >= 0.0 &&
        std::isfinite(layout.patch.axial) && layout.patch.axial >= 0.0))
    throw std::invalid_argument(
        kWhere + "tip patch " + message_number(layout.patch.circumferential) + " x " +
        message_number(layout.patch.axial) + ", allowed finite widths >= 0");
  if (options.max_sweeps < 1 || !(options.relative_change >= 0.0 && options.relative_change < 1.0) ||
      !(options.law_tolerance > 0.0 && options.law_tolerance < 1.0))
    throw std::invalid_argument(kWhere + "options: max_sweeps >= 1, relative_change in [0, 1), "
                                         "law_tolerance in (0, 1)");
  for (int c = 0; c < n_contacts; ++c) {
    try {
      m_row.push_back(m_cells.row(layout.axial[static_cast<size_t>(c)]));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(kWhere + "contact node " + std::to_string(c) + ": " + e.what());
    }
  }
  m_lambda.setZero(3 * m_nc);
  m_y.setZero(3 * m_nc);
  m_state.assign(m_nc, ReducedContactState::open);
  m_cell.assign(m_nc, 0);
  m_active.assign(m_nc, 0);
  m_response.assign(m_nc, BarResponse{});
  if (m_patched) {
    if (m_mu > 0.0) m_slip_set.emplace(m_mu);
    m_patch_angle = m_patch.circumferential / m_cells.geometry().radius;
    for (int c = 0; c < m_nc; ++c) m_patch_rows.push_back(patch_rows(m_cells, m_axial[c], m_patch.axial));
    m_patch_cells.assign(m_nc, {});
    m_read.assign(m_nc, {});
    m_previous.assign(m_nc, {});
    m_patch_response.assign(m_nc, {});
    m_patch_solve.assign(m_nc, PatchCompliantSolve{});
    m_patch_sectors.assign(m_nc, {});
    for (int c = 0; c < m_nc; ++c)
      for (int e = 0; e < m_nc; ++e)
        m_rows_meet.push_back(sorted_lists_meet(m_patch_rows[c], m_patch_rows[e]));
  }
}

void LinerContactSolve::set_contact_matrix(const Eigen::MatrixXd& w) {
  m_w = 0.5 * (w + w.transpose()).eval();
  m_wtt.resize(m_nc);
  for (int c = 0; c < m_nc; ++c) m_wtt[c] = m_w.block<2, 2>(3 * c + 1, 3 * c + 1);
  m_w_row_abs.resize(m_nc);
  for (int c = 0; c < m_nc; ++c)
    m_w_row_abs(c) = m_w.row(3 * c).cwiseAbs().sum() / m_w(3 * c, 3 * c);
  start();
}

void LinerContactSolve::start() {
  m_lambda.setZero(3 * m_nc);
  m_state.assign(m_nc, ReducedContactState::open);
  m_contact_work = m_normal_work = m_elastic_energy = 0.0;
  m_max_law_residual = 0.0;
  m_sweeps = 0;
  m_direct_starts = 0;
}

int LinerContactSolve::cell(int c, double t) const {
  return m_row[c] * m_cells.n_theta() + m_cells.sector(m_omega * t + m_phi[c]);
}

std::vector<int> LinerContactSolve::cells_under(int c, double t) const {
  if (!m_patched) return {cell(c, t)};
  return patch_cells(m_cells, m_omega * t + m_phi[c], m_axial[c], m_patch);
}

void LinerContactSolve::place_patches(double t) {
  const int n_theta = m_cells.n_theta();
  m_chained = false;
  for (int c = 0; c < m_nc; ++c) {
    // patch_cells (liner_patch_cells.hpp) without its allocations: the rows
    // are fixed, the sectors move with the casing-frame angle.
    std::vector<int>& sectors = m_patch_sectors[c];
    patch_sectors(m_cells, m_omega * t + m_phi[c], m_patch_angle, sectors);
    std::vector<int>& cells = m_patch_cells[c];
    cells_of(m_patch_rows[c], sectors, n_theta, cells);
    const size_t n = cells.size();
    m_previous[c].assign(n, PatchLink{});
    m_read[c].assign(n, 0);
    m_patch_response[c].resize(n);
    // Each cell's latest earlier contact over it: only patches that share a
    // row and a sector can share a cell, and both lists are ascending.
    size_t unlinked = n;
    for (int e = c - 1; e >= 0 && unlinked > 0; --e) {
      if (!m_rows_meet[static_cast<size_t>(c * m_nc + e)] ||
          !sorted_lists_meet(sectors, m_patch_sectors[e]))
        continue;
      const std::vector<int>& earlier = m_patch_cells[e];
      for (size_t i = 0; i < n; ++i) {
        if (m_previous[c][i].contact >= 0) continue;
        const auto at = std::lower_bound(earlier.begin(), earlier.end(), cells[i]);
        if (at == earlier.end() || *at != cells[i]) continue;
        const int position = static_cast<int>(at - earlier.begin());
        m_previous[c][i] = PatchLink{e, position};
        m_chained = true;
        --unlinked;
        if (!m_read[e][position]) {
          // Read by a chain before its first evaluation, a response holds
          // the cell's committed state (the grow test of a contact that
          // joins in the same pass as e).
          m_read[e][position] = 1;
          m_patch_response[e][position] = BarResponse{};
          m_patch_response[e][position].state = m_cells.state(cells[i]);
        }
      }
    }
  }
}

bool LinerContactSolve::direct_start(const Eigen::VectorXd& predicted) {
  // Unchained, each patch's bars start from their committed states.
  const auto piece_at = [&](int c, double depth) {
    const std::vector<int>& cells = m_patch_cells[c];
    m_from.resize(cells.size());
    double least = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < cells.size(); ++i) {
      m_from[i] = m_cells.state(cells[i]);
      least = std::min(least, m_from[i].wear);
    }
    // Short of every bar: PatchCompliantSolve::piece's answer without its
    // sorted breakpoints (the least one is the least wear, F_Y > 0).
    if (depth < least)
      return LinearPiece{0.0, 0.0, -std::numeric_limits<double>::infinity(), least};
    return m_patch_solve[c].piece(m_cells, m_from, depth);
  };
  m_start = m_lambda;
  if (!m_slip_set->solve(m_w, predicted, piece_at, m_start)) return false;
  m_lambda = m_start;
  for (int c = 0; c < m_nc; ++c)
    if (m_lambda(3 * c) > 0.0) m_active[c] = 1;
  return true;
}

BarState LinerContactSolve::patch_start_state(int c, int position) const {
  // The latest earlier ACTIVE contact over the same cell left its state.
  PatchLink link = m_previous[c][position];
  while (link.contact >= 0 && !m_active[link.contact])
    link = m_previous[link.contact][link.position];
  if (link.contact >= 0) return m_patch_response[link.contact][link.position].state;
  return m_cells.state(m_patch_cells[c][position]);
}

double LinerContactSolve::patch_solve(int c, double depth_pred, double compliance, bool all) {
  const int n = static_cast<int>(m_patch_cells[c].size());
  m_from.resize(n);
  for (int i = 0; i < n; ++i) m_from[i] = patch_start_state(c, i);
  const double force = m_patch_solve[c].force(m_cells, m_from, depth_pred, compliance);
  // A response no chain reads is needed only at the certificate (header).
  for (int i = 0; i < n; ++i)
    if (all || m_read[c][i])
      m_patch_response[c][i] =
          PatchCompliantSolve::response(m_cells, m_from[i], depth_pred, compliance, force);
  return force;
}

void LinerContactSolve::add_contact_work(const Eigen::VectorXd& lambda_n,
                                         const Eigen::MatrixXd& rows,
                                         const Eigen::VectorXd& increment) {
  const Eigen::VectorXd moved = rows * increment;
  m_contact_work += 0.5 * lambda_n.dot(moved);
  for (int c = 0; c < m_nc; ++c) m_normal_work += 0.5 * lambda_n(3 * c) * moved(3 * c);
}

BarState LinerContactSolve::start_state(int c) const {
  // Contacts over one cell in one step push its bar in turn (node order).
  for (int e = c - 1; e >= 0; --e)
    if (m_active[e] && m_cell[e] == m_cell[c]) return m_response[e].state;
  return m_cells.state(m_cell[c]);
}

double LinerContactSolve::least_wear(int c, bool chained) const {
  if (!m_patched) return chained ? start_state(c).wear : m_cells.state(m_cell[c]).wear;
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < m_patch_cells[c].size(); ++i)
    least = std::min(least, chained ? patch_start_state(c, static_cast<int>(i)).wear
                                    : m_cells.state(m_patch_cells[c][i]).wear);
  return least;
}

double LinerContactSolve::sweep(const Eigen::VectorXd& predicted) {
  m_y = predicted;
  for (int c = 0; c < m_nc; ++c)
    if (m_active[c] && m_lambda.segment<3>(3 * c).any())
      m_y.noalias() += m_w.middleCols<3>(3 * c) * m_lambda.segment<3>(3 * c);
  double change = 0.0;
  for (int c = 0; c < m_nc; ++c) {
    if (!m_active[c]) continue;
    const double wnn = m_w(3 * c, 3 * c);
    double force = 0.0;
    if (m_patched) {
      force = patch_solve(c, -(m_y(3 * c) - wnn * m_lambda(3 * c)), wnn, false);
    } else {
      const BarState from = start_state(c);
      const double delta = -(m_y(3 * c) - wnn * m_lambda(3 * c)) - from.wear;
      m_response[c] = m_cells.compliant(from, delta, wnn);
      force = m_response[c].force;
    }
    const double dn = force - m_lambda(3 * c);
    if (dn != 0.0) {
      m_y.noalias() += m_w.col(3 * c) * dn;
      m_lambda(3 * c) = force;
    }
    const Eigen::Vector2d lt = m_lambda.segment<2>(3 * c + 1);
    const Eigen::Vector2d b = m_y.segment<2>(3 * c + 1) - m_wtt[c] * lt;
    const DiskSolution disk = disk_minimum(m_wtt[c], b, m_mu * m_lambda(3 * c));
    if (!disk.ok) {
      m_state[c] = ReducedContactState::open; // marks the failure for solve()
      return std::numeric_limits<double>::quiet_NaN();
    }
    const Eigen::Vector2d dt = disk.x - lt;
    if (dt.any()) {
      m_y.noalias() += m_w.middleCols<2>(3 * c + 1) * dt;
      m_lambda.segment<2>(3 * c + 1) = disk.x;
    }
    m_state[c] = m_lambda(3 * c) > 0.0
                     ? (disk.rim ? ReducedContactState::slip : ReducedContactState::stick)
                     : ReducedContactState::open;
    change = std::max({change, std::abs(dn), dt.cwiseAbs().maxCoeff()});
  }
  return change;
}

double LinerContactSolve::rounding_scale_bound(const Eigen::VectorXd& predicted,
                                               double size) const {
  double bound = 0.0;
  for (int c = 0; c < m_nc; ++c)
    if (m_active[c])
      bound = std::max(bound, std::abs(predicted(3 * c)) / m_w(3 * c, 3 * c) + m_w_row_abs(c) * size);
  return bound * (1.0 + 1e-12); // its own rounding: never below S as computed
}

double LinerContactSolve::rounding_scale(const Eigen::VectorXd& predicted) const {
  double scale = 0.0;
  for (int c = 0; c < m_nc; ++c) {
    if (!m_active[c]) continue;
    double terms = std::abs(predicted(3 * c));
    for (int j = 0; j < 3 * m_nc; ++j) terms += std::abs(m_w(3 * c, j) * m_lambda(j));
    scale = std::max(scale, terms / m_w(3 * c, 3 * c));
  }
  return scale;
}

void LinerContactSolve::fail(int step, const std::string& what) const {
  throw ComponentIntegrationError(kWhere + "step " + std::to_string(step) + " (t = " +
                                      message_number(step * m_dt) + " s): " + what,
                                  remedied_by({Remedy::smaller_step_safety_or_friction}));
}

void LinerContactSolve::solve(const Eigen::VectorXd& predicted, int step, StepReport& report) {
  const std::vector<ReducedContactState> before = m_state;
  const double t = step * m_dt;
  for (int c = 0; c < m_nc; ++c) {
    if (!m_patched) m_cell[c] = cell(c, t); // a patch's cells are placed below
    m_active[c] = 0;
  }
  if (m_patched) place_patches(t);
  // Active: positive predicted indentation into the cell's worn surface, or
  // a force at the last step (chained wear only grows the indentation's
  // threshold, so the unchained state is the generous test).
  bool any = false;
  for (int c = 0; c < m_nc; ++c) {
    // Wear is >= 0: a tip short of the unworn surface reads no cell.
    m_active[c] = (-predicted(3 * c) > 0.0 && -predicted(3 * c) - least_wear(c, false) > 0.0) ||
                  m_lambda(3 * c) > 0.0;
    any = any || m_active[c];
  }
  for (int c = 0; c < m_nc; ++c)
    if (!m_active[c]) {
      m_lambda.segment<3>(3 * c).setZero();
      m_state[c] = ReducedContactState::open;
    }
  if (any) {
    if (m_slip_set && !m_chained && direct_start(predicted)) ++m_direct_starts;
    for (;;) {
      int sweeps = 0, at_floor = 0;
      for (;;) {
        const double change = sweep(predicted);
        ++sweeps;
        if (std::isnan(change)) fail(step, "a tangential block of W is not positive definite or its disk solve did not converge");
        const double size = m_lambda.cwiseAbs().maxCoeff();
        if (change <= m_options.relative_change * size) break;
        // S itself only near the floor (its bound is O(n_c), S O(n_c^2)).
        const bool below_floor =
            change <= m_options.relative_change * rounding_scale_bound(predicted, size) &&
            change <= m_options.relative_change * rounding_scale(predicted);
        if (below_floor && change <= 100.0 * m_options.relative_change * size) break;
        at_floor = below_floor ? at_floor + 1 : 0;
        if (at_floor >= kStagnationSweeps) break;
        if (sweeps >= m_options.max_sweeps)
          fail(step, "the Gauss-Seidel sweeps did not converge in " +
                         std::to_string(m_options.max_sweeps) + " (last change " +
                         message_number(change) + " of multipliers up to " + message_number(size) +
                         ", round-off scale " + message_number(rounding_scale(predicted)) + ")");
      }
      m_sweeps += sweeps;
      // Grow: a contact the others' forces push into its bar joins.
      m_y = predicted;
      for (int c = 0; c < m_nc; ++c)
        if (m_active[c]) m_y.noalias() += m_w.middleCols<3>(3 * c) * m_lambda.segment<3>(3 * c);
      bool grown = false;
      for (int c = 0; c < m_nc; ++c)
        if (!m_active[c] && -m_y(3 * c) > 0.0 && -m_y(3 * c) - least_wear(c, true) > 0.0) {
          m_active[c] = 1;
          grown = true;
        }
      if (!grown) break;
    }
  } else {
    m_y = predicted;
  }

  // Certificate on every contact at the final lambda (header), and the
  // responses to commit.
  double largest = 0.0, cone = 0.0, stick = 0.0, slip = 0.0, slip_scale = 0.0, force_scale = 0.0;
  for (int c = 0; c < m_nc; ++c) largest = std::max(largest, m_lambda(3 * c));
  double residual = 0.0;
  m_elastic_energy = 0.0;
  report.max_penetration = 0.0;
  report.min_lambda = std::numeric_limits<double>::infinity();
  report.max_complementarity = 0.0;
  for (int c = 0; c < m_nc; ++c) {
    // An inactive contact's evaluation only checks that it stays out of its bar.
    const double g = m_y(3 * c);
    const double wnn = m_w(3 * c, 3 * c);
    if (m_patched) {
      const double depth = -(g - wnn * m_lambda(3 * c));
      if (!m_active[c] && (depth < 0.0 || depth < least_wear(c, true))) {
        // Short of every bar (lambda_n,c = 0): the solve's force and every
        // bar's is exactly 0, its residual |lambda_n,c|, its energy 0.
        residual = std::max(residual, std::abs(m_lambda(3 * c)));
      } else {
        // An inactive contact's responses are kept too: no chain reads them.
        const double f = patch_solve(c, depth, wnn, true);
        residual = std::max(residual, std::abs(m_lambda(3 * c) - f));
        for (const BarResponse& r : m_patch_response[c])
          m_elastic_energy += r.force * r.force / (2.0 * m_cells.stiffness());
      }
    } else {
      const BarState from = start_state(c);
      const BarResponse r = m_cells.compliant(from, -(g - wnn * m_lambda(3 * c)) - from.wear, wnn);
      residual = std::max(residual, std::abs(m_lambda(3 * c) - r.force));
      if (m_active[c]) m_response[c] = r;
      m_elastic_energy += r.force * r.force / (2.0 * m_cells.stiffness());
    }
    const double ln = m_lambda(3 * c);
    const Eigen::Vector2d lt = m_lambda.segment<2>(3 * c + 1);
    const Eigen::Vector2d s = m_y.segment<2>(3 * c + 1);
    report.max_penetration = std::max(report.max_penetration, -g);
    report.min_lambda = std::min(report.min_lambda, ln);
    report.max_complementarity = std::max(report.max_complementarity, std::abs(ln * g));
    cone = std::max(cone, lt.norm() - m_mu * ln);
    slip_scale = std::max(slip_scale, predicted.segment<2>(3 * c + 1).norm());
    force_scale = std::max(force_scale, m_mu * ln);
    if (m_state[c] == ReducedContactState::stick) stick = std::max(stick, s.norm());
    if (m_state[c] == ReducedContactState::slip && m_mu * ln > 0.0)
      slip = std::max(slip, s.norm() > 0.0 ? (lt + m_mu * ln * s / s.norm()).norm()
                                           : std::abs(lt.norm() - m_mu * ln));
  }
  const double law = largest > 0.0 ? residual / largest : residual;
  m_max_law_residual = std::max(m_max_law_residual, law);
  if (!(law <= m_options.law_tolerance))
    fail(step, "the bars' law holds only to " + message_number(law) + " of the largest force (allowed " +
                   message_number(m_options.law_tolerance) + ")");
  int worn_through = -1;
  const auto keep = [&](int cell, const BarResponse& response) {
    m_cells.commit(cell, response);
    if (worn_through < 0 && m_cells.state(cell).wear >= m_cells.geometry().thickness)
      worn_through = cell;
  };
  for (int c = 0; c < m_nc; ++c) {
    if (!m_active[c]) continue;
    if (!m_patched) {
      keep(m_cell[c], m_response[c]);
      continue;
    }
    for (size_t i = 0; i < m_patch_cells[c].size(); ++i)
      keep(m_patch_cells[c][i], m_patch_response[c][i]);
  }
  if (worn_through >= 0)
    throw ComponentIntegrationError(
        kWhere + "step " + std::to_string(step) + " (t = " + message_number(step * m_dt) +
            " s): the abradable liner is worn through at sector " +
            std::to_string(worn_through % m_cells.n_theta()) + ", row " +
            std::to_string(worn_through / m_cells.n_theta()) + ": wear " +
            message_number(m_cells.state(worn_through).wear) + " >= its thickness " +
            message_number(m_cells.geometry().thickness),
        remedied_by({Remedy::thicker_liner_or_larger_clearance}));
  report.max_cone_violation = std::max(cone, 0.0);
  report.max_stick_slip_residual = std::max(slip_scale > 0.0 ? stick / slip_scale : 0.0,
                                            force_scale > 0.0 ? slip / force_scale : 0.0);
  report.n_stick = report.n_slip = 0;
  for (int c = 0; c < m_nc; ++c) {
    if (m_state[c] == ReducedContactState::stick) ++report.n_stick;
    if (m_state[c] == ReducedContactState::slip) ++report.n_slip;
    if (m_state[c] != before[c]) ++report.stick_slip_transitions;
  }
  report.n_active = report.n_stick + report.n_slip;
}

} // namespace rsi
