#include "failure_advice.hpp"

namespace rsi {
namespace {

/// The option or key a command reads the input from.
const char* input_name(FailedInput input) {
  switch (input) {
  case FailedInput::unnamed:
    return "";
  case FailedInput::mode_count:
    return "--modes";
  case FailedInput::method:
    return "--method";
  case FailedInput::casing_mode_count:
    return "casing_modes";
  }
  return "";
}

/// What to change, in the options and keys of the commands that reach it.
const char* remedy_words(Remedy remedy) {
  switch (remedy) {
  case Remedy::fewer_jobs:
    return " or fewer --jobs";
  case Remedy::full_method_no_dense_casing:
    return " (simulate --method full keeps no dense casing matrix)";
  case Remedy::fewer_casing_modes:
    return "; keep fewer casing modes (--casing-modes, casing_modes)";
  case Remedy::fewer_modes_or_another_method:
    return "; keep fewer modes (--modes) or use another --method";
  case Remedy::fewer_modes_campaign_or_another_method:
    return "keep fewer modes (--modes, or the campaign's modes) or use another --method";
  case Remedy::massed_boundary_method:
    return "; use a method with a massed boundary (--method cb or ccm)";
  case Remedy::fewer_modes_or_coarser_model:
    return "; ask for fewer modes (--count, --modes) or make the model coarser (fewer elements)";
  case Remedy::fewer_modes_or_report:
    return "; ask for fewer modes (--count, --modes), or report the model";
  }
  return "";
}

} // namespace

std::string with_advice(const std::string& what, const FailureAdvice& advice) {
  std::string out = advice.context;
  if (advice.input != FailedInput::unnamed) out += std::string(input_name(advice.input)) + ": ";
  out += what;
  for (const Remedy r : advice.remedies)
    out += remedy_words(r);
  return out;
}

std::string failure_message(const std::exception& e) {
  return with_advice(e.what(), advice_of(e));
}

} // namespace rsi
