#include "part_definiteness.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "energy_resolution.hpp"

namespace rsi {
namespace {

/// Throws CaseError if `check` (of K or M of a part) found the matrix not
/// positive definite to working precision; `part` names the part ("the
/// bladed disk's"), `held_by` where its lowest mode moves, `keys` what to change.
void refuse_unless_definite(const DefinitenessCheck& check, const char* name, const Case& c,
                            const std::string& part, const std::string& held_by,
                            const std::string& keys) {
  if (check.positive_definite()) return;
  std::ostringstream what;
  what.precision(3);
  what << c.source << ": " << part << " " << name;
  if (!check.factorized) {
    // CHOLMOD's message starts with "not positive definite: " when a pivot is <= 0.
    const std::string prefix = "not positive definite: ";
    const bool pivot = check.why.rfind(prefix, 0) == 0;
    what << " is not positive definite (Cholesky factorization: "
         << (pivot ? check.why.substr(prefix.size()) : check.why) << ")";
  } else {
    const EnergyResolution& r = check.resolution;
    what << " is not positive definite to working precision: at its lowest mode (eigenvalue "
         << check.eigenvalue << held_by << ") the energy x^T A x = " << r.energy
         << " is below the rounding of its terms, gamma_p |x|^T |A| |x| = " << r.rounding
         << " (the energy's condition number |x|^T |A| |x| / x^T A x = " << r.condition()
         << ", double precision resolves up to 1/gamma_p = " << r.resolvable_condition()
         << ", p = " << r.row_terms << " entries a row)";
  }
  what << "; a beam bends with an energy (thickness / element length)^2 times its axial "
          "terms, and a smooth motion over many elements with (element length / wavelength)^4 "
          "times its own terms: too thin a section or too many elements lose it in their "
          "rounding; change "
       << keys;
  throw CaseError(what.str());
}

/// The share of the kinetic energy x^T M x of `x` on the dofs marked in `on`.
double share(const Eigen::SparseMatrix<double>& mass, const Eigen::VectorXd& x,
             const std::vector<bool>& on) {
  const Eigen::VectorXd mx = mass * x;
  double part = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (on[i]) part += x(i) * mx(i);
  return part / x.dot(mx);
}

std::string quoted_value(const std::string& key, double value, const char* unit) {
  std::ostringstream s;
  s.precision(6);
  s << "'" << key << "' (" << value << unit << ")";
  return s.str();
}

} // namespace

void check_bladed_disk_definite(const BladedDisk& bladed_disk, const Case& c) {
  const Eigen::SparseMatrix<double>& k = bladed_disk.stiffness;
  const Eigen::SparseMatrix<double>& m = bladed_disk.mass;
  const std::string part = "the bladed disk's";
  const DefinitenessCheck stiffness = check_positive_definite(k, m);
  std::string held_by;
  std::string keys =
      "keys " +
      quoted_value("bladed_disk.blade_section.thickness", c.bladed_disk.blade.thickness, " m") +
      ", 'bladed_disk.n_blade_elements', 'bladed_disk.disk_section', "
      "'bladed_disk.rim_ring_section'";
  if (stiffness.factorized && !stiffness.positive_definite()) {
    // Name the members the least-resolved mode moves: the blades (nodes 2..
    // of a sector) or the rim (node 1: the disk element and the ring).
    std::vector<bool> blade(k.rows());
    for (size_t i = 0; i < bladed_disk.dofs.size(); ++i)
      blade[i] = bladed_disk.dofs[i].node % bladed_disk.nodes_per_sector >= 2;
    const double in_blades = share(m, stiffness.motion, blade);
    std::ostringstream held;
    held.precision(3);
    held << ", " << 100.0 * in_blades << " % of its kinetic energy in the blades";
    held_by = held.str();
    keys = in_blades >= 0.5 ? "key " +
                                  quoted_value("bladed_disk.blade_section.thickness",
                                               c.bladed_disk.blade.thickness, " m") +
                                  " or 'bladed_disk.n_blade_elements' (" +
                                  std::to_string(c.bladed_disk.n_blade_elements) + ")"
                            : "keys " +
                                  quoted_value("bladed_disk.disk_section.thickness",
                                               c.bladed_disk.disk.thickness, " m") +
                                  " and " +
                                  quoted_value("bladed_disk.rim_ring_section.thickness",
                                               c.bladed_disk.rim_ring.thickness, " m");
  }
  refuse_unless_definite(stiffness, "stiffness K", c, part, held_by, keys);
  refuse_unless_definite(check_positive_definite(m, Eigen::SparseMatrix<double>()), "mass M", c,
                         part, "", keys);
}

void check_casing_definite(const Casing& casing, const Case& c) {
  const std::string keys =
      "key " + quoted_value("casing.section.thickness", c.casing.section.thickness, " m") +
      " or 'casing.n_elements' (" + std::to_string(c.casing.n_elements) + ")";
  refuse_unless_definite(check_positive_definite(casing.stiffness, casing.mass), "stiffness K", c,
                         "the casing's", "", keys);
  refuse_unless_definite(check_positive_definite(casing.mass, Eigen::SparseMatrix<double>()),
                         "mass M", c, "the casing's", "", keys);
}

} // namespace rsi
