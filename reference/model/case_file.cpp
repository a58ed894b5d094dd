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
    throw CaseError(e.what(), in_context(e.advice(), source + ": "));
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

/// The entries of a run list ("campaign", "sweep.runs"): {"method",
/// "modes": [..]} with the optional axes, expanded to every (modes,
/// casing_modes, time_step) in that order; with `allow_full`, also
/// {"method": "full"} (no other key: the reference model has no axes).
std::vector<CampaignRun> read_run_entries(const ObjectReader& parent, const json& list,
                                          const std::string& key, bool allow_full) {
  if (!list.is_array())
    parent.fail(parent.full(key), "must be an array of {\"method\", \"modes\"} objects");
  std::vector<CampaignRun> runs;
  for (size_t i = 0; i < list.size(); ++i) {
    ObjectReader entry(list[i], parent.full(key) + "[" + std::to_string(i) + "]",
                       parent.source());
    entry.claim("method");
    const json& method = list[i].contains("method") ? list[i].at("method") : json();
    if (allow_full && method == "full") {
      CampaignRun full;
      full.method = "full";
      runs.push_back(full);
      entry.finish();
      continue;
    }
    if (!method.is_string() || (method != "cb" && method != "ccm" && method != "guyan"))
      entry.fail(entry.full("method"), std::string("must be ") +
                                           (allow_full ? "\"full\", " : "") +
                                           "\"cb\", \"ccm\" or \"guyan\", got " + method.dump());
    entry.claim("modes");
    const json& modes = list[i].contains("modes") ? list[i].at("modes") : json();
    if (!modes.is_array() || modes.empty())
      entry.fail(entry.full("modes"), "must be a non-empty array of mode counts, got " + modes.dump());
    for (const json& m : modes)
      if (!m.is_number_integer() || m.get<long>() < 0 || m.get<long>() > 100000)
        entry.fail(entry.full("modes"), "must hold integers in [0, 100000], got " + m.dump());
    const CampaignAxes axes = read_campaign_axes(entry, list[i]);
    for (const json& m : modes)
      for (const int casing_modes : axes.casing_modes)
        for (const StepRule& step : axes.steps)
          runs.push_back(
              {method.get<std::string>(), m.get<int>(), axes.selection, casing_modes, step});
    entry.finish();
  }
  return runs;
}

/// The rotation speeds of a sweep: a list [Omega, ...] or a range {"from",
/// "to", "count"} (count equally spaced speeds, both ends included).
std::vector<double> read_speeds(ObjectReader& sweep, const json& value) {
  const Range speed{0.0, 1e5, false, false, "rad/s"};
  constexpr long max_speeds = 100000;
  std::vector<double> speeds;
  if (value.is_array()) {
    if (value.empty() || static_cast<long>(value.size()) > max_speeds)
      sweep.fail(sweep.full("speeds"), "must hold 1 to " + std::to_string(max_speeds) +
                                           " rotation speeds, got " + std::to_string(value.size()));
    for (const json& v : value) {
      if (!v.is_number() || !std::isfinite(v.get<double>()) || !speed.contains(v.get<double>()))
        sweep.fail(sweep.full("speeds"), "must hold numbers in " + speed.text() + ", got " + v.dump());
      speeds.push_back(v.get<double>());
    }
    return speeds;
  }
  ObjectReader range = sweep.object("speeds");
  const double from = range.number("from", speed);
  const double to = range.number("to", speed);
  const int count = range.integer("count", 1, max_speeds);
  range.finish();
  if (count > 1 && !(to > from))
    range.fail(range.full("to"), "must be above from = " + std::to_string(from) +
                                     " rad/s when count > 1");
  for (int i = 0; i < count; ++i)
    speeds.push_back(count == 1 ? from : from + (to - from) * i / (count - 1));
  return speeds;
}

/// The optional "sweep" object (issue 15), checked against the case's time
/// stepping: each run must be countable and leave at least 16 history rows
/// after the transient for its spectrum.
SweepSpec read_sweep(ObjectReader& top, const json& value, const Case& c) {
  SweepSpec out;
  ObjectReader sweep = top.object("sweep");
  sweep.optional_note("note");
  sweep.claim("speeds");
  if (!value.contains("speeds"))
    sweep.fail(sweep.full("speeds"), "missing: a list of speeds or {\"from\", \"to\", \"count\"}");
  out.speeds = read_speeds(sweep, value.at("speeds"));
  out.duration = sweep.number("duration", positive("s"));
  out.transient = sweep.number("transient", {0.0, out.duration, false, true, "s (below duration)"});
  constexpr double max_steps = std::numeric_limits<int>::max();
  const double steps = std::round(out.duration / c.time.step);
  if (!(steps <= max_steps))
    sweep.fail(sweep.full("duration"), "over time.step gives more than " +
                                           std::to_string(static_cast<long long>(max_steps)) +
                                           " steps: shorten it");
  constexpr int min_rows = 16;
  const double interval = c.time.step * c.time.output_every;
  const double rows = std::floor((out.duration - out.transient) / interval + 1e-9);
  if (rows < min_rows)
    sweep.fail(sweep.full("transient"),
               "leaves " + std::to_string(static_cast<long long>(rows)) +
                   " history rows before duration (output interval " + std::to_string(interval) +
                   " s); the spectrum needs at least " + std::to_string(min_rows));
  out.damping = read_damping(sweep, value);
  sweep.claim("runs");
  if (!value.contains("runs")) sweep.fail(sweep.full("runs"), "missing: the runs of every speed");
  out.runs = read_run_entries(sweep, value.at("runs"), "runs", true);
  if (out.runs.empty()) sweep.fail(sweep.full("runs"), "must name at least one run");
  sweep.finish();
  return out;
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
    if (law == "sliding_sign")
      c.operating_point.friction_law = FrictionLaw::sliding_sign;
    else if (law != "coulomb")
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
  if (document.contains("campaign"))
    c.campaign = read_run_entries(top, document.at("campaign"), "campaign", false);

  top.claim("sweep");
  if (document.contains("sweep")) c.sweep = read_sweep(top, document.at("sweep"), c);
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
