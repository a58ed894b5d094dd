#pragma once
// The full finite-element reference run (SPEC §2-3): the bladed disk and the
// casing, both full, integrated by central differences and coupled only
// through blade-tip contact with friction.

#include <functional>
#include <stdexcept>

#include "case_file.hpp"
#include <Eigen/Core>

#include "history.hpp"

namespace rsi {

/// Delta t at or above the stability limit 2/omega_max, not forced.
class StabilityError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

struct RunOptions {
  bool force = false; ///< integrate even above the stability limit
  /// Stop as a blow-up when the energy exceeds this multiple of the largest
  /// external work done so far (contact can feed energy in, SPEC §3, but a
  /// hundredfold gain is the sprag instability, not a physical response).
  double blowup_factor = 100.0;
  /// Called now and then with the fraction done (for progress display).
  std::function<void(double)> progress;
};

struct RunResult {
  History history;
  RunSummary summary;
  /// Casing radial and tangential displacement of every casing node (zeros
  /// at the clamp) at the first contact (empty without contact), for the
  /// figure of the casing deformation (paper Fig. 9).
  Eigen::VectorXd casing_u_at_first_contact;
  Eigen::VectorXd casing_v_at_first_contact;
};

/// Throws StabilityError (dt too large, not forced), IntegrationError or
/// ModalError (numerical failure). A blow-up is not an exception: the run
/// stops, summary.completed is false and summary.status says where.
RunResult run_reference(const Case& c, const RunOptions& options);

} // namespace rsi
