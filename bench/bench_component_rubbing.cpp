// A 3D component rubbing on the rigid oval casing (issue 12 items 4 and 6):
// the reduced component integrator (reduced/component_integrator.hpp) with
// CB, CCM (mass-carrying boundary, each at its own stable step) and MacNeal
// (massless boundary, at the case's steps per revolution), compared with
// each other. Not a test: prints a table (and optionally the histories).
//
// The set-up is the rotor37 README's rubbing case: the contact nodes are the
// component's boundary nodes (16 tip nodes for both data/cases/rotor37.json
// and data/cases/blade3d.json), oval gap g_m = 0.356 mm, mu = 0.15,
// Omega = 1344 rad/s, modal damping 0.5 %, zero initial conditions.
//
// Usage:
//   bench_component_rubbing CASE [--revolutions R] [--steps-per-revolution N]
//       [--methods macneal:10,cb:10,...] [--reference cb:20] [--response NODE.DIR]
//       [--ccx-cache DIR] [--safety 0.9] [--csv PREFIX] [--omega W] [--mu MU] [--zeta Z]
//       [--whole-w] [--sliding with|against]
// --sliding against: the tip slides against the rotation, NLstep's PLAUSIBLE
// set-up (data/cases/rotor37-rubbing.json's tip_sliding); default with.
// CB/CCM run at dt = T / (k N), k the smallest integer with dt <= safety x
// 2/omega_max (their own stable step), sampled every k steps so that every
// run is compared at the same N samples a revolution. e_2 = ||x - x_ref||_2 /
// ||x_ref||_2 and e_inf = max|x - x_ref| / max|x_ref| over the samples, for
// the response dof and for the sum of the normal multipliers.
// Integration wall time: the step loop alone (run_component), sampling every
// step; basis time: reduce().

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "component_case.hpp"
#include "component_integrator.hpp"
#include "component_run.hpp"
#include "modal_damping.hpp"
#include "reduction.hpp"
#include "rigid_casing.hpp"

using namespace rsi;

namespace {

struct Spec {
  std::string method;
  int modes = 0;
};

Spec parse_spec(const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("method spec '" + s + "': want name:modes");
  return {s.substr(0, colon), std::stoi(s.substr(colon + 1))};
}

struct Result {
  Spec spec;
  int r = 0;
  double dt = 0.0, critical_dt = 0.0, basis_s = 0.0;
  int steps = 0, every = 1;
  ComponentRunSummary summary;
  std::vector<double> response, normal_sum;
};

double e2(const std::vector<double>& x, const std::vector<double>& ref) {
  double num = 0.0, den = 0.0;
  const size_t n = std::min(x.size(), ref.size());
  for (size_t i = 0; i < n; ++i) {
    num += (x[i] - ref[i]) * (x[i] - ref[i]);
    den += ref[i] * ref[i];
  }
  return den > 0.0 ? std::sqrt(num / den) : NAN;
}

double einf(const std::vector<double>& x, const std::vector<double>& ref) {
  double num = 0.0, den = 0.0;
  const size_t n = std::min(x.size(), ref.size());
  for (size_t i = 0; i < n; ++i) {
    num = std::max(num, std::abs(x[i] - ref[i]));
    den = std::max(den, std::abs(ref[i]));
  }
  return den > 0.0 ? num / den : NAN;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s CASE [options] (see the source's header)\n", argv[0]);
    return 2;
  }
  std::string case_path = argv[1];
  double revolutions = 2.0;
  int steps_per_rev = 1000;
  std::string methods = "macneal:10,macneal:20,cb:10,cb:20,ccm:20";
  std::string reference = "cb:20";
  std::string response = "";
  std::string cache = "build/ccx-cache";
  std::string csv;
  bool whole_w = false; // --whole-w: Gauss-Seidel on the whole W every contact step
  bool against = false;  // --sliding against
  double safety = 0.9, omega = 1344.0, mu = 0.15, gm = 0.356, zeta = 0.005;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value");
      return argv[++i];
    };
    if (a == "--revolutions")
      revolutions = std::stod(next());
    else if (a == "--steps-per-revolution")
      steps_per_rev = std::stoi(next());
    else if (a == "--methods")
      methods = next();
    else if (a == "--reference")
      reference = next();
    else if (a == "--response")
      response = next();
    else if (a == "--ccx-cache")
      cache = next();
    else if (a == "--safety")
      safety = std::stod(next());
    else if (a == "--csv")
      csv = next();
    else if (a == "--omega")
      omega = std::stod(next());
    else if (a == "--mu")
      mu = std::stod(next());
    else if (a == "--zeta")
      zeta = std::stod(next());
    else if (a == "--whole-w")
      whole_w = true;
    else if (a == "--sliding") {
      const std::string v = next();
      if (v != "with" && v != "against") {
        std::fprintf(stderr, "--sliding: with or against, got %s\n", v.c_str());
        return 2;
      }
      against = v == "against";
    }
    else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  if (!(revolutions > 0) || steps_per_rev < 1 || !(safety > 0 && safety < 1)) {
    std::fprintf(stderr, "--revolutions > 0, --steps-per-revolution >= 1, --safety in (0, 1)\n");
    return 2;
  }

  std::ifstream in(case_path);
  if (!in) {
    std::fprintf(stderr, "%s: cannot open\n", case_path.c_str());
    return 2;
  }
  const auto t_load = std::chrono::steady_clock::now();
  const ComponentCase cc = parse_component_case(nlohmann::json::parse(in), case_path);
  const Component component = load_component(cc, {"", cache});
  const double load_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_load).count();
  // Contact nodes: the boundary's nodes, in boundary order.
  std::vector<int> nodes;
  for (int d : component.boundary)
    if (nodes.empty() || nodes.back() != component.dofs[d].node)
      nodes.push_back(component.dofs[d].node);
  const RigidCasing casing =
      rigid_casing_of(component, nodes, oval_casing_gap(gm), omega, against ? -omega : omega);
  // Response dof: NODE.DIR, default the first contact node's direction 2.
  int response_node = nodes.front(), response_dir = 2;
  if (!response.empty()) {
    const auto dot = response.find('.');
    response_node = std::stoi(response.substr(0, dot));
    response_dir = std::stoi(response.substr(dot + 1));
  }
  int response_dof = -1;
  for (int i = 0; i < component.n_dofs(); ++i)
    if (component.dofs[i].node == response_node &&
        component.dofs[i].kind == direction_kind(response_dir))
      response_dof = i;
  if (response_dof < 0) {
    std::fprintf(stderr, "--response %d.%d: no such dof\n", response_node, response_dir);
    return 2;
  }
  double r_min = 1e300, r_max = 0.0, phi_min = 1e300, phi_max = -1e300;
  for (int c = 0; c < casing.n_contacts(); ++c) {
    r_min = std::min(r_min, casing.radius(c));
    r_max = std::max(r_max, casing.radius(c));
    phi_min = std::min(phi_min, casing.polar_angle(c));
    phi_max = std::max(phi_max, casing.polar_angle(c));
  }
  const double period = 2.0 * M_PI / std::abs(omega);
  const int n_samples = static_cast<int>(std::lround(revolutions * steps_per_rev));
  std::printf("case %s: %d dofs, %zu boundary dofs, %zu contact nodes (r %.3f..%.3f, phi "
              "%.4f..%.4f rad), response dof %d (node %d dir %d); load %.2f s\n",
              case_path.c_str(), component.n_dofs(), component.boundary.size(), nodes.size(), r_min,
              r_max, phi_min, phi_max, response_dof, response_node, response_dir, load_s);
  std::printf("Omega %.1f rad/s (T %.4e s), g_m %.3f, mu %.2f, zeta %.4f, %.2f revolutions, %d "
              "samples a revolution\n",
              omega, period, gm, mu, zeta, revolutions, steps_per_rev);

  std::vector<Spec> specs;
  {
    std::stringstream ss(methods);
    std::string item;
    while (std::getline(ss, item, ','))
      specs.push_back(parse_spec(item));
  }
  std::vector<Result> results;
  for (const Spec& spec : specs) {
    Result res;
    res.spec = spec;
    const auto t0 = std::chrono::steady_clock::now();
    const ReducedBasis basis =
        reduce(component.stiffness, component.mass, component.boundary, spec.method, spec.modes);
    res.basis_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    res.r = basis.n_reduced();
    if (basis.massless_boundary) {
      // The caveat of component_integrator.hpp: the interior's largest
      // frequency when closed contacts hold the boundary. Condensed stiffness
      // K^_II - K^_IB S_h K^_BI (M^_II = I), S_h the boundary compliance with
      // the held directions constrained: S - S H^T (H S H^T)^-1 H S.
      std::vector<int> b = basis.boundary_position, in;
      std::vector<char> is_b(res.r, 0);
      for (int k : b)
        is_b[k] = 1;
      for (int k = 0; k < res.r; ++k)
        if (!is_b[k]) in.push_back(k);
      const auto blk = [&](const std::vector<int>& rr, const std::vector<int>& cc) {
        Eigen::MatrixXd out(rr.size(), cc.size());
        for (size_t i = 0; i < rr.size(); ++i)
          for (size_t j = 0; j < cc.size(); ++j)
            out(i, j) = basis.stiffness(rr[i], cc[j]);
        return out;
      };
      const Eigen::MatrixXd kbb = blk(b, b), kbi = blk(b, in), kii = blk(in, in);
      const Eigen::MatrixXd s_free = kbb.inverse();
      const auto omega_held = [&](const Eigen::MatrixXd& h) {
        Eigen::MatrixXd s = s_free;
        if (h.rows() > 0) {
          const Eigen::MatrixXd hs = h * s_free;
          s -= hs.transpose() * (hs * h.transpose()).ldlt().solve(hs);
        }
        const Eigen::MatrixXd k = kii - kbi.transpose() * s * kbi;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(0.5 * (k + k.transpose()),
                                                               Eigen::EigenvaluesOnly);
        return std::sqrt(std::max(e.eigenvalues().maxCoeff(), 0.0));
      };
      Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(casing.n_contacts(), b.size());
      for (int c = 0; c < casing.n_contacts(); ++c)
        for (int a = 0; a < 3; ++a)
          normals(c, casing.boundary_index(c)[a]) = casing.frame(c)(0, a);
      const double w_free = omega_held(Eigen::MatrixXd(0, b.size()));
      const double w_normal = omega_held(normals);
      const double w_all = omega_held(Eigen::MatrixXd::Identity(b.size(), b.size()));
      std::printf("%-8s %3d modes: interior omega_max, boundary free %.4e rad/s (2/omega %.3e s), "
                  "all 16 normals held %.4e (%.3e s), whole boundary held %.4e (%.3e s)\n",
                  spec.method.c_str(), spec.modes, w_free, 2 / w_free, w_normal, 2 / w_normal,
                  w_all, 2 / w_all);
    }
    ComponentIntegratorOptions o;
    o.mu = mu;
    o.damping = modal_damping(basis, zeta);
    o.closing_subset = !whole_w;
    // First at the sampling step, forced, only to read omega_max.
    o.dt = period / steps_per_rev;
    o.force_step = true;
    {
      ComponentIntegrator probe(basis, casing, o);
      res.critical_dt = probe.critical_dt();
    }
    res.every = std::max(1, static_cast<int>(std::ceil(o.dt / (safety * res.critical_dt))));
    o.dt = period / (static_cast<double>(steps_per_rev) * res.every);
    o.force_step = false;
    ComponentIntegrator integrator(basis, casing, o);
    res.dt = o.dt;
    ComponentRunOptions ro;
    ro.steps = static_cast<std::int64_t>(n_samples) * res.every;
    ro.output_every = res.every;
    ro.energy_every = 100 * res.every; // E costs 2 r^2: checked every 100 samples
    ComponentHistory h;
    res.summary = run_component(integrator, basis.transformation.row(response_dof), ro, h);
    res.steps = static_cast<int>(res.summary.steps);
    for (int k = 0; k < h.n_rows(); ++k) {
      res.response.push_back(h.response[k]);
      double s = 0.0;
      for (int c = 0; c < casing.n_contacts(); ++c)
        s += h.lambda[k](3 * c);
      res.normal_sum.push_back(s);
    }
    if (!csv.empty()) {
      std::ofstream out(csv + "_" + spec.method + std::to_string(spec.modes) + ".csv");
      out.precision(10);
      out << "t,response,lambda_n_sum,energy,contact_work,damping_work\n";
      for (int k = 0; k < h.n_rows(); ++k)
        out << h.time[k] << ',' << h.response[k] << ',' << res.normal_sum[k] << ',' << h.energy[k]
            << ',' << h.contact_work[k] << ',' << h.damping_work[k] << '\n';
    }
    std::printf(
        "%-8s %3d modes: r %3d, basis %.2f s, critical dt %.3e s, dt %.3e s (%d a "
        "revolution), %d steps, integration %.3f s wall, %.3f s CPU (%.2f us/step wall), %s\n",
        spec.method.c_str(), spec.modes, res.r, res.basis_s, res.critical_dt, res.dt,
        steps_per_rev * res.every, res.steps, res.summary.integration_seconds,
        res.summary.integration_cpu_seconds,
        1e6 * res.summary.integration_seconds / std::max(res.steps, 1), res.summary.status.c_str());
    std::printf("         certificate: penetration %.2e, cone %.2e, stick/slip residual %.2e, "
                "transitions %ld, stick %ld, slip %ld contact-steps, GS sweeps %ld; energy "
                "balance %.2e of scale %.3e, W_contact %.4e, W_damp %.4e\n",
                res.summary.max_penetration, res.summary.max_cone_violation,
                res.summary.max_stick_slip_residual, res.summary.stick_slip_transitions,
                res.summary.stick_contact_steps, res.summary.slip_contact_steps, res.summary.sweeps,
                res.summary.energy_balance_error, res.summary.energy_scale,
                res.summary.final_contact_work, res.summary.final_damping_work);
    std::fflush(stdout);
    results.push_back(std::move(res));
  }
  const Spec ref = parse_spec(reference);
  const Result* r_ref = nullptr;
  for (const Result& r : results)
    if (r.spec.method == ref.method && r.spec.modes == ref.modes) r_ref = &r;
  if (r_ref) {
    std::printf("\nagainst %s-%d over the common samples (response dof; sum of lambda_n):\n",
                ref.method.c_str(), ref.modes);
    std::printf("method   modes  e2_resp    einf_resp  e2_lamn    einf_lamn  steps    integ_s\n");
    for (const Result& r : results)
      std::printf("%-8s %5d  %.3e  %.3e  %.3e  %.3e  %7d  %.3f\n", r.spec.method.c_str(),
                  r.spec.modes, e2(r.response, r_ref->response), einf(r.response, r_ref->response),
                  e2(r.normal_sum, r_ref->normal_sum), einf(r.normal_sum, r_ref->normal_sum),
                  r.steps, r.summary.integration_seconds);
  }
  return 0;
}
