#include "case_file.hpp"
#include "blade_geometry.hpp"
#include "case_json.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace rsi {
namespace {

using namespace case_json;
using nlohmann::json;

constexpr double deg = M_PI / 180.0;

BladedDiskSpec read_bladed_disk(ObjectReader r) {
  BladedDiskSpec b;
  b.n_blades = r.integer("n_blades", 2, 1000);
  b.hub_radius = r.number("hub_radius", positive("m"));
  b.rim_radius = r.number("rim_radius", {b.hub_radius, inf, true, true, "m (above hub_radius)"});
  b.tip_radius = r.number("tip_radius", {b.rim_radius, inf, true, true, "m (above rim_radius)"});
  b.n_blade_elements = r.integer("n_blade_elements", 1, 1000);
  b.kink_angle = r.number("kink_angle_deg", {-30.0, 30.0, false, false, "degrees"}) * deg;
  b.blade = r.section("blade_section");
  b.disk = r.section("disk_section");
  b.rim_ring = r.section("rim_ring_section");
  r.finish();
  return b;
}

CasingSpec read_casing(ObjectReader r, double tip_radius) {
  CasingSpec c;
  c.radius =
      r.number("radius", {tip_radius, inf, true, true,
                          "m (above bladed_disk.tip_radius: the clearance must be positive)"});
  c.n_elements = r.integer("n_elements", 3, 100000);
  c.section = r.section("section");
  const double clamp_deg = r.number("clamp_angle_deg", {0.0, 360.0, false, true, "degrees"});
  const double pitch_deg = 360.0 / c.n_elements;
  if (std::abs(clamp_deg / pitch_deg - std::round(clamp_deg / pitch_deg)) > 1e-9)
    r.fail(r.full("clamp_angle_deg"),
           "must be the angle of a casing node, a multiple of 360/n_elements = " +
               std::to_string(pitch_deg) + " degrees");
  c.clamp_angle = clamp_deg * deg;
  r.finish();
  return c;
}

/// The optional axes of a campaign entry (issue 14): "selection" (a
/// name), "casing_modes" (integers, 0 = the full casing), "time_step"
/// ("case", "own" or steps in seconds) and "step_safety" (of "own").
struct CampaignAxes {
  std::string selection = "lowest";
  std::vector<int> casing_modes{0};
  std::vector<StepRule> steps{StepRule{}};
};

CampaignAxes read_campaign_axes(ObjectReader& entry, const json& object) {
  CampaignAxes axes;
  entry.claim("selection");
  if (object.contains("selection")) {
    const json& value = object.at("selection");
    static const std::set<std::string> names{"lowest", "families", "forced", "participation"};
    if (!value.is_string() || !names.count(value.get<std::string>()))
      entry.fail(entry.full("selection"),
                 "must be \"lowest\", \"families\", \"forced\" or \"participation\", got " +
                     value.dump());
    axes.selection = value.get<std::string>();
  }
  entry.claim("casing_modes");
  if (object.contains("casing_modes")) {
    const json& list = object.at("casing_modes");
    if (!list.is_array() || list.empty())
      entry.fail(entry.full("casing_modes"),
                 "must be a non-empty array of casing mode counts (0: the full casing), got " +
                     list.dump());
    axes.casing_modes.clear();
    for (const json& m : list) {
      if (!m.is_number_integer() || m.get<long>() < 0 || m.get<long>() > 400000)
        entry.fail(entry.full("casing_modes"),
                   "must hold integers in [0, 400000] (0: the full casing; at most the casing's "
                   "dofs, checked against the model), got " +
                       m.dump());
      axes.casing_modes.push_back(m.get<int>());
    }
  }
  double safety = 0.9;
  entry.claim("step_safety");
  if (object.contains("step_safety"))
    safety = entry.number("step_safety", {0.0, 1.0, true, true, "(fraction of 2/omega_max)"});
  entry.claim("time_step");
  if (object.contains("time_step")) {
    const json& list = object.at("time_step");
    if (!list.is_array() || list.empty())
      entry.fail(entry.full("time_step"),
                 "must be a non-empty array of \"case\", \"own\" or steps in seconds, got " +
                     list.dump());
    axes.steps.clear();
    for (const json& t : list) {
      StepRule rule;
      rule.safety = safety;
      if (t == "case") {
        rule.kind = StepRule::Kind::case_step;
      } else if (t == "own") {
        rule.kind = StepRule::Kind::own;
      } else if (t.is_number() && std::isfinite(t.get<double>()) && t.get<double>() > 0.0) {
        rule.kind = StepRule::Kind::given;
        rule.step = t.get<double>();
      } else {
        entry.fail(entry.full("time_step"),
                   "must hold \"case\", \"own\" or steps > 0 in seconds, got " + t.dump());
      }
      axes.steps.push_back(rule);
    }
  } else {
    axes.steps.front().safety = safety;
  }
  return axes;
}

/// The blade as a whole (issue 13, class 7): each key in range can still
/// make a blade that curls back (many elements at a kink: 1000 x 1 degree
/// turns it by 1000 degrees, the tip found on R_t after a spiral through
/// the casing and the neighbouring blades). A blade whose radius grows
/// strictly from the rim to the tip stays between rim and tip radius, so
/// inside the casing, and its rotated copies (the other sectors) never meet
/// it: each radius is crossed once per blade, at angles a pitch apart.
void check_blade_shape(const BladedDiskSpec& spec, const std::string& source) {
  BladeGeometry g;
  try {
    g = blade_geometry(spec);
  } catch (const CaseError& e) {
    // blade_geometry names the keys; the loader's messages start with the file.
    throw CaseError(source + ": " + e.what());
  }
  for (size_t i = 2; i < g.nodes.size(); ++i)
    if (!(g.nodes[i].norm() > g.nodes[i - 1].norm())) {
      std::ostringstream m;
      m.precision(6);
      m << source << ": keys 'bladed_disk.n_blade_elements' and 'bladed_disk.kink_angle_deg': the "
        << "blade curls back (node " << i - 1 << " of " << g.nodes.size() - 2
        << " lies at radius " << g.nodes[i].norm() << " m, not beyond the previous node's "
        << g.nodes[i - 1].norm() << " m; the kinks turn it by "
        << std::abs(spec.kink_angle) * spec.n_blade_elements / deg
        << " degrees in all); the radius must grow from rim to tip: use fewer elements or a "
           "smaller |kink angle|";
      throw CaseError(m.str());
    }
}

} // namespace

/// Counts derived from the time keys must fit what a run counts with (int
/// steps) and what a disk holds: the history, one row of about
/// 24 (1 + 2 n_blades + 4) bytes every output_every steps (%.17g numbers).
void check_run_size(const Case& c, const case_json::ObjectReader& time) {
  constexpr double max_steps = std::numeric_limits<int>::max();
  const double steps = std::round(c.time.duration / c.time.step);
  if (!(steps <= max_steps)) {
    std::ostringstream what;
    what << "over time.step gives " << steps << " steps, more than the "
         << static_cast<long long>(max_steps)
         << " a run can count: shorten time.duration or lengthen time.step";
    time.fail(time.full("duration"), what.str());
  }
  constexpr double max_history_bytes = 100e9;
  const double bytes =
      (steps / c.time.output_every + 1) * 24.0 * (1 + 2 * c.bladed_disk.n_blades + 4);
  if (bytes > max_history_bytes) {
    std::ostringstream what;
    what << "with time.duration / time.step = " << steps << " steps, history.csv would take about "
         << bytes / 1e9 << " GB (limit " << max_history_bytes / 1e9
         << " GB): raise time.output_every";
    time.fail(time.full("output_every"), what.str());
  }
}

Case parse_case(const json& document, const std::string& source) {
  ObjectReader top(document, "", source);
  Case c;
  c.source = source;
  top.optional_note("description");

  ObjectReader material = top.object("material");
  c.material.young_modulus = material.number("young_modulus", positive("Pa"));
  c.material.density = material.number("density", positive("kg/m^3"));
  material.finish();

  c.bladed_disk = read_bladed_disk(top.object("bladed_disk"));
  c.casing = read_casing(top.object("casing"), c.bladed_disk.tip_radius);
  check_blade_shape(c.bladed_disk, c.source);

  ObjectReader op = top.object("operating_point");
  c.operating_point.rotation_speed = op.number("rotation_speed", {0.0, 1e5, false, false, "rad/s"});
  c.operating_point.friction_coefficient =
      op.number("friction_coefficient", {0.0, 2.0, false, false, ""});
  op.claim("friction_law");
  if (document.at("operating_point").contains("friction_law")) {
    const json& law = document.at("operating_point").at("friction_law");
    if (law == "coulomb")
      c.operating_point.friction_law = FrictionLaw::coulomb;
    else if (law != "sliding_sign")
      op.fail("operating_point.friction_law",
              "must be \"sliding_sign\" or \"coulomb\", got " + law.dump());
  }
  op.finish();

  ObjectReader forcing = top.object("forcing");
  c.forcing.amplitude = forcing.number("amplitude", {0.0, inf, false, true, "N"});
  forcing.optional_note("amplitude_note");
  c.forcing.nodal_diameter = forcing.integer("nodal_diameter", 0, c.casing.n_elements / 2);
  c.forcing.duration = forcing.number("duration", {0.0, inf, false, true, "s"});
  forcing.finish();

  ObjectReader time = top.object("time");
  c.time.step = time.number("step", positive("s"));
  c.time.duration =
      time.number("duration", {c.time.step, inf, false, true, "s (at least one step)"});
  c.time.output_every = time.integer("output_every", 1, 100000000);
  time.finish();
  check_run_size(c, time);

  c.damping = read_damping(top, document);

  // Optional: "campaign": [{"method": "cb", "modes": [0, 10]}, ...].
  top.claim("campaign");
  if (document.contains("campaign")) {
    const json& list = document.at("campaign");
    if (!list.is_array())
      top.fail("campaign", "must be an array of {\"method\", \"modes\"} objects");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string path = "campaign[" + std::to_string(i) + "]";
      ObjectReader entry(list[i], path, source);
      entry.claim("method");
      entry.claim("modes");
      const json& method = list[i].contains("method") ? list[i].at("method") : json();
      if (!method.is_string() || (method != "cb" && method != "ccm" && method != "guyan"))
        entry.fail(entry.full("method"),
                   "must be \"cb\", \"ccm\" or \"guyan\", got " + method.dump());
      const json& modes = list[i].contains("modes") ? list[i].at("modes") : json();
      if (!modes.is_array() || modes.empty())
        entry.fail(entry.full("modes"),
                   "must be a non-empty array of mode counts, got " + modes.dump());
      for (const json& m : modes)
        if (!m.is_number_integer() || m.get<long>() < 0 || m.get<long>() > 100000)
          entry.fail(entry.full("modes"), "must hold integers in [0, 100000], got " + m.dump());
      const CampaignAxes axes = read_campaign_axes(entry, list[i]);
      // Every (modes, casing_modes, time_step) of the entry, in that order.
      for (const json& m : modes)
        for (const int casing_modes : axes.casing_modes)
          for (const StepRule& step : axes.steps)
            c.campaign.push_back(
                {method.get<std::string>(), m.get<int>(), axes.selection, casing_modes, step});
      entry.finish();
    }
  }
  top.finish();
  return c;
}

std::string CampaignRun::name() const {
  std::string out = method + "-" + std::to_string(modes);
  if (selection != "lowest") out += "-" + selection;
  if (casing_modes > 0) out += "-c" + std::to_string(casing_modes);
  if (step.kind != StepRule::Kind::case_step) out += "-dt-" + step.name();
  return out;
}

std::string StepRule::name() const {
  switch (kind) {
  case Kind::case_step: return "case";
  case Kind::own: return "own";
  case Kind::given: break;
  }
  std::ostringstream text;
  text.precision(6);
  text << step;
  return text.str();
}

Case parse_case_text(const std::string& text, const std::string& source) {
  return parse_case(case_json::parse_document(text, source), source);
}

nlohmann::json read_case_document(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open the case file (missing or unreadable)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError(path + ": cannot read the case file");
  return case_json::parse_document(text.str(), path);
}

Case load_case(const std::string& path) {
  return parse_case(read_case_document(path), path);
}

} // namespace rsi
