#include "command_options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "usage_error.hpp"

namespace rsi {

const char* const modes_allowed =
    "an integer in [0, the method's maximum] (cb, ccm: the dofs minus the 44 boundary dofs, "
    "638 for the default case; macneal: the same, from 1; guyan: 0)";

CLI::Validator integer_in(long lo, long hi, const std::string& allowed) {
  return CLI::Validator(
      [lo, hi, allowed](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long value = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
          return "must be " + allowed + ", got '" + text + "'";
        return {};
      },
      "INT");
}

CLI::Validator number_above(double lo, const std::string& allowed) {
  return CLI::Validator(
      [lo, allowed](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > lo))
          return "must be " + allowed + ", got '" + text + "'";
        return {};
      },
      "NUMBER");
}

CLI::Validator number_between(double lo, double hi, const std::string& allowed) {
  return CLI::Validator(
      [lo, hi, allowed](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > lo) ||
            !(value < hi))
          return "must be " + allowed + ", got '" + text + "'";
        return {};
      },
      "NUMBER");
}

CLI::Validator one_of(const std::vector<std::string>& names) {
  std::string allowed;
  for (size_t i = 0; i < names.size(); ++i)
    allowed += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return CLI::Validator(
      [names, allowed](std::string& text) -> std::string {
        for (const std::string& name : names)
          if (text == name) return {};
        return "must be " + allowed + ", got '" + text + "'";
      },
      "NAME");
}

CLI::Validator nonempty_path() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        return path.empty() ? "must be a directory path that can be created and written, got ''"
                            : std::string();
      },
      "DIR");
}

CLI::Validator case_file() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code error;
        const auto status = std::filesystem::status(path, error);
        if (!std::filesystem::exists(status))
          return "'" + path + "': no such file; must be a JSON case file";
        if (std::filesystem::is_directory(status))
          return "'" + path + "' is a directory; must be a JSON case file";
        return {};
      },
      "CASE");
}

void add_component_options(CLI::App& command, ComponentLoadOptions& load) {
  // The loader's messages name the two inputs as the user gave them.
  load.source_name = "--source";
  load.ccx_cache_name = "--ccx-cache";
  command
      .add_option("--source", load.source_override,
                  "component case only: the deck or Matrix Market folder to read instead of "
                  "the case's component.source")
      ->check(nonempty_path());
  command
      .add_option("--ccx-cache", load.ccx_cache,
                  "folder of cached ccx runs (matrices of CalculiX decks)")
      ->capture_default_str()
      ->check(nonempty_path());
}

StepRule parse_step_option(const std::string& text, double safety) {
  StepRule rule;
  rule.safety = safety;
  if (text == "case") return rule;
  if (text == "own") {
    rule.kind = StepRule::Kind::own;
    return rule;
  }
  char* end = nullptr;
  errno = 0;
  const double step = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno != 0 || !std::isfinite(step) ||
      !(step > 0.0))
    throw UsageError("--time-step: must be case, own or a step in seconds > 0, got '" + text + "'");
  rule.kind = StepRule::Kind::given;
  rule.step = step;
  return rule;
}

} // namespace rsi
