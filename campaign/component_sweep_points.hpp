#pragma once
// The sweep of a component case (a 3D blade rubbing on its rigid casing,
// rubbing_run.hpp): the rubbing run at each speed of its "sweep" object
// (or the caller's speeds), over sweep.revolutions, for each of its runs
// (full, or a reduced method and mode count: cb, ccm, guyan, macneal; cc
// with its n_c as the count, its eta a run's fixed_interface_modes);
// each history reduced to a row of indicators (sweep/rubbing_indicators.hpp).
//
// Beside sweep.csv, interaction_lines.csv: for each run, the blade's
// lowest natural frequencies f_k (its tip free, not spinning: the reduced
// model's, or the full model's) and, for engine orders EO = 1 .. 10, the
// speed Omega = 2 pi f_k / EO where the EO-th harmonic of the rotation
// meets f_k. The oval casing has two lobes (g0 has period pi in theta), so
// it forces at 2 Omega / 2 pi and its harmonics: EO = 2, 4, 6, 8, 10 are
// the casing's own lines (column `casing_harmonic` = 1); the odd orders are
// listed for the map's reading (a constant gap forces at none).
//
// A bladed disk against the flexible casing (rubbing.casing; issue 27 item
// 6): each speed's run is the system's (the casing in its modes plus static
// correction for the reduced runs, that basis built once), the indicators'
// column 8 is the response dof's largest |u| (the gap is the two bodies'),
// and beside sweep.csv are the campaign's nodal_diameters.csv and
// interaction_lines.csv (nodal_diameter_map.hpp: Omega_int = 2 pi (f_b +
// f_c) / n), the report make_system_sweep_report.py.

#include <memory>
#include <string>

#include "component_case.hpp"
#include "rotation_fit.hpp"
#include "rubbing_run.hpp"
#include "sweep_points.hpp"

namespace rsi {

/// The runs of `sweep` (its speeds, runs and revolutions set) on `model`:
/// builds each reduced run's basis once for every speed, and the natural
/// frequencies. A refused reduction throws ReductionError prefixed by
/// `where` (the key or option that lists the runs) and the run's name.
///
/// With rotation effects (`rotation`, fitted over the sweep's speeds) each
/// speed's run uses K(Omega), the mass at rest and the tip growth of the
/// parametric model (rotation_fit.hpp); a reduced run reduces inside one
/// speed subspace (speed_subspace.hpp), a full run builds K(Omega).
/// interaction_lines.csv then holds the crossings of the engine orders with
/// the rotating blade's lowest frequencies (campbell_crossings.hpp; on a
/// grid of speeds, written to campbell.csv: the first reduced run's
/// subspace model's, else the full parametric model's), each at its
/// crossing speed, for every run. `threads`: the threads a run's speed
/// subspace builds its bases on (the rows do not depend on it).
std::unique_ptr<SweepPoints> component_sweep_points(RubbingModel model, ComponentSweep sweep,
                                                    const std::string& where,
                                                    std::shared_ptr<const RotationFit> rotation = {},
                                                    int threads = 1);

/// The fit speeds of a sweep with rotation effects: sweep.rotation_fit_speeds,
/// or 0.1, 0.2, 0.4, 0.6, 0.8, 1 times its largest |Omega| or
/// rubbing.clearance_speed (the spacing measured in reports/rotation-fit).
/// Throws CaseError naming sweep.rotation_fit_speeds if a speed of the sweep
/// or the clearance speed is above the highest.
std::vector<double> sweep_rotation_fit_speeds(const ComponentCase& c, const ComponentSweep& sweep);

} // namespace rsi
