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

#include <stdexcept>

namespace rsi {

class BadInput : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

class NumericalFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace rsi
