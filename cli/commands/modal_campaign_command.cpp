// rsi modal-campaign: the modal convergence of every reduction of a
// component without contact (issue 11): per method and mode count, the
// lowest reduced frequencies against the full ones.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "command_options.hpp"
#include "usage_error.hpp"
#include "component_input.hpp"
#include "critical_step.hpp"
#include "interruption.hpp"
#include "modal_analysis.hpp"
#include "output_files.hpp"
#include "partition.hpp"
#include "reduction.hpp"
#include "report_script.hpp"
#include "staged_output.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

struct ModalCampaignOptions {
  std::string case_path;
  std::string out = "out/modal-campaign";
  bool report = true; ///< run reports/make_modal_report.py at the end
  ComponentLoadOptions load;
};

class ModalCampaignCommand : public Command {
public:
  explicit ModalCampaignCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  ModalCampaignOptions m_options;
};

ModalCampaignCommand::ModalCampaignCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "modal-campaign",
          "Modal convergence of every reduction of a component (no contact): reduced against full "
          "frequencies -> DIR/{modal_convergence.csv,modal_errors.csv,modal_report.md}")) {
  ModalCampaignOptions& modal_campaign = m_options;
  m_command.add_option("case", modal_campaign.case_path, "component case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--out", modal_campaign.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  m_command.add_flag("!--no-report", modal_campaign.report,
                     "write the tables only, not modal_report.md and its figure");
  add_component_options(m_command, modal_campaign.load);
}


/// Largest mode count of every method on a component of n dofs, n_b on the
/// boundary: CB keeps at most the interior dofs, CCM and MacNeal at most the
/// dofs minus the boundary dofs (craig_bampton.hpp, craig_chang_martinez.hpp).
int largest_count(int n, int n_b) {
  return n - n_b;
}

double hz(double omega_squared) {
  return std::sqrt(std::max(omega_squared, 0.0)) / (2.0 * M_PI);
}

} // namespace

int ModalCampaignCommand::run(StagedOutput& output) {
  const ModalCampaignOptions& options = m_options;
  const ComponentInput input = load_component_input(options.case_path, "", options.load);
  if (!input.component_case || !input.component_case->modal_campaign)
    throw UsageError(input.case_source +
                     ": key 'modal_campaign': missing; a component case with "
                     "{\"methods\": [...], \"modes\": [...], \"frequencies\": N} is needed");
  const ModalCampaign& campaign = *input.component_case->modal_campaign;
  const Component& c = input.component;
  const int n = c.n_dofs();
  const int n_b = static_cast<int>(c.boundary.size());
  if (n_b == 0)
    throw UsageError(input.case_source + ": the component " + c.name +
                     " has no boundary dofs to keep; a reduction needs them");
  for (const std::string& method : campaign.methods)
    for (int modes : campaign.modes)
      if (modes > largest_count(n, n_b))
        throw UsageError(input.case_source + ": key 'modal_campaign.modes': " + method + " with " +
                         std::to_string(modes) + " modes: must be in [1, " +
                         std::to_string(largest_count(n, n_b)) + "] for " + c.name);
  const int count = std::min(campaign.frequencies, n - 1);

  const auto start = std::chrono::steady_clock::now();
  const Modes full = lowest_modes(c.stiffness, c.mass, count);
  const double full_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Relative residual |K phi - lambda M phi| / |K phi| of each full mode: to
  // first order the relative accuracy of its eigenvalue (for the tolerance
  // of the Rayleigh-Ritz comparison below).
  Eigen::VectorXd full_residual(count);
  {
    const Eigen::MatrixXd k_phi = c.stiffness * full.shapes;
    const Eigen::MatrixXd m_phi = c.mass * full.shapes;
    for (int i = 0; i < count; ++i)
      full_residual(i) =
          (k_phi.col(i) - full.omega_squared(i) * m_phi.col(i)).norm() / k_phi.col(i).norm();
  }
  std::printf("%s: %s, %d dofs, %d boundary dofs; full: %d modes in %.2f s (f1 %.6g Hz, f%d "
              "%.6g Hz)\n",
              input.case_source.c_str(), c.name.c_str(), n, n_b, count, full_seconds,
              full.frequency_hz(0), count, full.frequency_hz(count - 1));

  std::ostringstream table;
  table << "method,modes,reduced_dofs,compared,max_rel_error,rms_rel_error,min_rel_error,"
           "omega_max,critical_dt,build_s\n";
  std::ostringstream errors;
  errors.precision(12);
  errors << "method,modes,index,full_hz,reduced_hz,rel_error,tolerance\n";
  std::printf("%-8s %6s %8s %8s %12s %12s %12s %10s\n", "method", "modes", "dofs", "compared",
              "max err", "min err", "critical dt", "build s");
  for (const std::string& method : campaign.methods)
    for (int modes : campaign.modes) {
      throw_if_interrupted(); // between bases (each a few eigensolves)
      const ReducedBasis basis = reduce(c, method, modes, 0);
      const Eigen::VectorXd reduced = reduced_eigenvalues(basis);
      const int compared = std::min<int>(count, static_cast<int>(reduced.size()));
      double largest = 0.0, smallest = 0.0, squares = 0.0;
      const double lambda_max = reduced(reduced.size() - 1);
      for (int i = 0; i < compared; ++i) {
        // How far a correct reduced frequency may fall below the full one:
        // the dense reduced solve is backward stable, an absolute eigenvalue
        // error up to n_r eps lambda_max (Cholesky-reduced standard problem),
        // i.e. n_r eps lambda_max / lambda_i relative, halved for f; plus the
        // full mode's relative residual.
        const double tolerance = 0.5 * basis.n_reduced() * std::numeric_limits<double>::epsilon() *
                                     lambda_max / reduced(i) +
                                 full_residual(i);
        const double f_full = full.frequency_hz(i);
        const double f_reduced = hz(reduced(i));
        const double e = (f_reduced - f_full) / f_full;
        largest = i == 0 ? e : std::max(largest, e);
        smallest = i == 0 ? e : std::min(smallest, e);
        squares += e * e;
        errors << method << "," << modes << "," << i + 1 << "," << f_full << "," << f_reduced
               << "," << e << "," << tolerance << "\n";
      }
      const double omega_max = std::sqrt(reduced(reduced.size() - 1));
      char row[320];
      std::snprintf(row, sizeof row, "%s,%d,%d,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.4f\n",
                    method.c_str(), modes, basis.n_reduced(), compared, largest,
                    std::sqrt(squares / compared), smallest, omega_max, 2.0 / omega_max,
                    basis.build_seconds);
      table << row;
      std::printf("%-8s %6d %8d %8d %12.3e %12.3e %12.4e %10.3f\n", method.c_str(), modes,
                  basis.n_reduced(), compared, largest, smallest, 2.0 / omega_max,
                  basis.build_seconds);
    }

  nlohmann::ordered_json summary;
  summary["case"] = input.case_source;
  summary["component"] = c.name;
  summary["units"] = c.units;
  summary["full_dofs"] = n;
  summary["boundary_dofs"] = n_b;
  summary["frequencies"] = count;
  summary["full_modes_seconds"] = full_seconds;
  summary["peak_memory_bytes"] = peak_memory_bytes();
  std::vector<double> full_hz;
  for (int i = 0; i < count; ++i)
    full_hz.push_back(full.frequency_hz(i));
  summary["full_hz"] = full_hz;
  summary["full_max_relative_residual"] = full_residual.maxCoeff();

  const std::string stage = output.open(options.out, "--out", modal_campaign_output_set());
  write_text_file(stage + "/modal_convergence.csv", stream_text(table));
  write_text_file(stage + "/modal_errors.csv", stream_text(errors));
  write_text_file(stage + "/modal_summary.json", summary.dump(2) + "\n");
  output.announce("wrote " + options.out +
                  "/{modal_convergence.csv,modal_errors.csv,modal_summary.json}\n");
  if (options.report) {
    std::fflush(stdout);
    const int status = run_report_script("make_modal_report.py", stage);
    if (status != 0) {
      // Exit 1 publishes nothing (staged_output.hpp): --out stays as it was.
      std::fprintf(stderr,
                   "rsi: error: the report generator make_modal_report.py failed (status %d); "
                   "nothing was written to --out %s; use --no-report to skip it\n",
                   status, options.out.c_str());
      return 1;
    }
    output.announce("report: " + options.out + "/modal_report.md\n");
  }
  return 0;
}

std::unique_ptr<Command> add_modal_campaign_command(CLI::App& app) {
  return std::make_unique<ModalCampaignCommand>(app);
}

} // namespace rsi
