#pragma once
// The two kinds of failure a computation reports, whatever raised it (the
// case loader, an import, a reduction, a modal solver, a time integrator):
// the CLI maps each kind to its exit status and message prefix in one place
// (SPEC §5: 2 for bad input, 3 for a numerical failure) instead of one
// clause per exception type.
//
//  - BadInput: what was asked cannot be computed as asked (a value out of
//    range, a model that cannot be read, modes or a step no solver here
//    resolves); the message says which input to change.
//  - NumericalFailure: the input was accepted, and the computation then
//    failed a check (a factorization, a modal check, an integrator's
//    monitor); the message carries what failed and its numbers.
//
// The specific types (CaseError, ModalError, ...) derive from one of the
// two, and keep the standard base their catchers rely on
// (std::invalid_argument, std::runtime_error).
//
// A kernel (reference/, reduced/) speaks of its own inputs only: what() is
// its text (what failed and its numbers), and FailureAdvice says, in the
// kernel's terms, which input failed and what would fix it. Which option or
// case key that input came from is the caller's business: the CLI words the
// advice (cli/support/failure_advice.hpp), so no kernel names a command
// line option.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rsi {

/// The input a failure is about, when the message names it first
/// ("INPUT: what failed").
enum class FailedInput {
  unnamed,             ///< the text names what failed itself
  mode_count,          ///< the number of modes a reduction keeps
  boundary_mode_count, ///< the characteristic constraint modes a reduction keeps
  method,              ///< the reduction method (full, cb, ccm, guyan, macneal)
  casing_mode_count,   ///< the number of casing modes of a reduced run
  time_step_value,     ///< the case's time step, the text starting with its value ("= dt s ...")
  ccx_cache,           ///< the folder ccx's and gmsh's outputs are cached in
};

/// What the user can change, appended to the kernel's text in this order.
enum class Remedy {
  fewer_jobs,                              ///< fewer runs at once
  full_method_no_dense_casing,             ///< the full-order method holds no dense casing matrix
  fewer_casing_modes,                      ///< a reduced casing's Rayleigh-Ritz step failed
  fewer_modes_or_another_method,           ///< a reduced model lost its definiteness
  fewer_modes_campaign_or_another_method,  ///< the same, where a campaign's run list sets modes
  massed_boundary_method,                  ///< a massless boundary whose condensation failed
  fewer_modes_or_coarser_model,            ///< an eigensolver did not converge on the count asked
  fewer_modes_or_report,                   ///< the modes failed their residual check
  smaller_step_or_force,                   ///< a step at or above the stability limit, not forced
  reduced_smaller_step,                    ///< a reduced run's contact solve failed at its step
  reduced_friction_or_smaller_step,        ///< a reduced run's contact problem has no solution
  lumped_mass_or_reduced_method,           ///< a full-order run's M is not positive definite
  component_lumped_mass_or_reduced_method, ///< the same, where the paper's case cannot reach it
  corrected_or_lumped_mass,                ///< the modes or omega_max need a (semi-)definite M
  lumped_mass_or_fewer_modes,              ///< a component's reduced mass is not positive definite
  smaller_step_unforced,                   ///< a full-order run's step did not settle or blew up
  friction_or_smaller_step,                ///< a full-order run's contact problem has no solution
  smaller_step_safety_unforced,            ///< a reduced component run blew up
  smaller_step_safety_or_friction,         ///< a reduced component run's contact solve failed
  thicker_liner_or_larger_clearance,       ///< a tip wore the abradable liner through
  more_boundary_modes, ///< a too coarse boundary of characteristic constraint modes
};

/// Which input failed and what to change, in the kernel's terms.
struct FailureAdvice {
  /// Text shown before the input's name (where it was read: a case file, a
  /// campaign run), verbatim; empty when the text says where itself.
  std::string context;
  FailedInput input = FailedInput::unnamed;
  std::vector<Remedy> remedies;
};

/// The failure of `input`, shown after `context`.
inline FailureAdvice failed_input(FailedInput input, std::string context = {}) {
  FailureAdvice a;
  a.context = std::move(context);
  a.input = input;
  return a;
}

/// A failure whose text names what failed, fixed by `remedies`.
inline FailureAdvice remedied_by(std::vector<Remedy> remedies) {
  FailureAdvice a;
  a.remedies = std::move(remedies);
  return a;
}

/// A failure whose text names what failed, shown after `context`.
inline FailureAdvice shown_after(std::string context) {
  FailureAdvice a;
  a.context = std::move(context);
  return a;
}

/// The same failure with `prefix` shown before it (a caller adding where).
inline FailureAdvice in_context(FailureAdvice advice, const std::string& prefix) {
  advice.context = prefix + advice.context;
  return advice;
}

class BadInput : public std::invalid_argument {
public:
  explicit BadInput(const std::string& what, FailureAdvice advice = {})
      : std::invalid_argument(what)
      , m_advice(std::move(advice)) {}
  explicit BadInput(const char* what)
      : std::invalid_argument(what) {}
  const FailureAdvice& advice() const { return m_advice; }

private:
  FailureAdvice m_advice;
};

class NumericalFailure : public std::runtime_error {
public:
  explicit NumericalFailure(const std::string& what, FailureAdvice advice = {})
      : std::runtime_error(what)
      , m_advice(std::move(advice)) {}
  explicit NumericalFailure(const char* what)
      : std::runtime_error(what) {}
  const FailureAdvice& advice() const { return m_advice; }

private:
  FailureAdvice m_advice;
};

/// The advice `e` carries (none for other exceptions).
inline FailureAdvice advice_of(const std::exception& e) {
  if (const auto* bad = dynamic_cast<const BadInput*>(&e)) return bad->advice();
  if (const auto* failed = dynamic_cast<const NumericalFailure*>(&e)) return failed->advice();
  return {};
}

} // namespace rsi
