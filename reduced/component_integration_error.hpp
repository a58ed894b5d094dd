#pragma once
// The numerical failure of a reduced component's integration
// (component_integrator.hpp and its parts): a failed factorization, a dt at
// or above the critical step (unless forced), a contact solve that does not
// converge or a non-finite state; the message names the step.

#include "failure_kinds.hpp"

namespace rsi {

class ComponentIntegrationError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

} // namespace rsi
