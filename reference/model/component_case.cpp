#include "component_case.hpp"
#include "interruption_flag.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

#include <unistd.h>
#include <filesystem>
#include <functional>
#include <initializer_list>

#include "calculix_deck.hpp"
#include "calculix_features.hpp"
#include "calculix_matrices.hpp"
#include "calculix_run.hpp"
#include "case_json.hpp"
#include "mass_lumping.hpp"
#include "matrix_market.hpp"
#include "sector_assembly.hpp"

namespace rsi {
namespace {

using namespace case_json;
using nlohmann::json;

std::string resolve(const std::string& path, const std::string& case_path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return path;
  return (std::filesystem::path(case_path).parent_path() / p).lexically_normal().string();
}

std::string string_value(ObjectReader& r, const json& object, const std::string& key) {
  r.claim(key);
  if (!object.contains(key)) r.fail(r.full(key), "missing (required)");
  const json& v = object.at(key);
  if (!v.is_string() || v.get<std::string>().empty())
    r.fail(r.full(key), "must be a non-empty string, got " + v.dump());
  return v.get<std::string>();
}

/// A deck's set or surface name as the case gives it, upper case (ccx's own
/// names are: *NSET, NSET=tip is TIP).
std::string deck_name(ObjectReader& r, const json& object, const std::string& key) {
  std::string name = string_value(r, object, key);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char ch) { return std::toupper(ch); });
  return name;
}

std::vector<int> integer_list(ObjectReader& r, const json& object, const std::string& key,
                              long low, long high) {
  r.claim(key);
  if (!object.contains(key)) r.fail(r.full(key), "missing (required)");
  const json& list = object.at(key);
  if (!list.is_array() || list.empty())
    r.fail(r.full(key), "must be a non-empty array of integers, got " + list.dump().substr(0, 80));
  std::vector<int> out;
  for (const json& v : list) {
    if (!v.is_number_integer() || v.get<long>() < low || v.get<long>() > high)
      r.fail(r.full(key), "must hold integers in [" + std::to_string(low) + ", " +
                              std::to_string(high) + "], got " + v.dump());
    out.push_back(v.get<int>());
  }
  return out;
}

/// A reduced run entry's "fixed_interface_modes": eta of a "cc" entry (the
/// fixed-interface modes under its characteristic constraint modes, which
/// are the counts varied), refused on any other method.
int fixed_interface_modes_of(ObjectReader& run, const json& entry, const std::string& method) {
  if (method == "cc") return run.integer("fixed_interface_modes", 0, 100000);
  if (entry.is_object() && entry.contains("fixed_interface_modes"))
    run.fail(run.full("fixed_interface_modes"),
             "only for \"method\": \"cc\" (the fixed-interface modes under its "
             "characteristic constraint modes); this run's method is \"" + method + "\"");
  return 0;
}

int node_id(int id) {
  return id;
}
int node_id(const ComponentNode& node) {
  return node.id;
}

/// Each of `fields` present in `object` read as a number (its range is the
/// spec check's), the others claimed.
void read_spec_numbers(ObjectReader& r, const json& object,
                       std::initializer_list<std::pair<const char*, double*>> fields) {
  for (const auto& [key, value] : fields)
    if (object.contains(key))
      *value = r.number(key, {-inf, inf, true, true, "(see data/README.md)"});
    else
      r.claim(key);
}

/// A spec check's "PREFIX.FIELD: what" failure at the case file's key
/// (twist and stagger are spelled with _deg there).
[[noreturn]] void fail_at_spec_key(ObjectReader& r, const std::invalid_argument& e,
                                   const std::string& prefix) {
  std::string what = e.what();
  if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
  const size_t colon = what.find(':');
  std::string field = what.substr(0, colon);
  if (field == "twist" || field == "stagger") field += "_deg";
  r.fail(r.full(field), colon == std::string::npos ? what : what.substr(colon + 2));
}

/// `check()` (a spec's range check), its failure reported at the case
/// file's key (fail_at_spec_key).
template <class Check>
void check_at_keys(ObjectReader& r, const Check& check, const std::string& prefix) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    fail_at_spec_key(r, e, prefix);
  }
}

/// The blade's parameters: every key optional, the coarse default otherwise
/// (gmsh_blade.hpp); ranges checked by check_gmsh_blade_spec.
GmshBladeSpec read_gmsh_blade(ObjectReader r, const json& object) {
  GmshBladeSpec spec;
  read_spec_numbers(r, object,
                    {{"span", &spec.span},
                     {"chord", &spec.chord},
                     {"thickness", &spec.thickness},
                     {"camber", &spec.camber},
                     {"twist_deg", &spec.twist},
                     {"stagger_deg", &spec.stagger},
                     {"root_length", &spec.root_length},
                     {"root_width", &spec.root_width},
                     {"root_height", &spec.root_height},
                     {"root_radius", &spec.root_radius},
                     {"element_size", &spec.element_size},
                     {"young_modulus", &spec.young_modulus},
                     {"poisson_ratio", &spec.poisson_ratio},
                     {"density", &spec.density}});
  r.finish();
  check_at_keys(r, [&] { check_gmsh_blade_spec(spec); }, "GmshBladeSpec.");
  return spec;
}

/// The bladed disk's parameters: every key optional, the default otherwise
/// (gmsh_bladed_disk.hpp); "blade" as gmsh_blade's object; ranges checked by
/// check_gmsh_bladed_disk_spec.
GmshBladedDiskSpec read_gmsh_bladed_disk(ObjectReader r, const json& object) {
  GmshBladedDiskSpec spec;
  r.claim("blade");
  if (object.contains("blade")) {
    if (!object.at("blade").is_object())
      r.fail(r.full("blade"), "must be an object of the blade's parameters");
    spec.blade = read_gmsh_blade(r.object("blade"), object.at("blade"));
  }
  if (object.contains("sectors"))
    spec.sectors = static_cast<int>(r.integer("sectors", 3, 200));
  else
    r.claim("sectors");
  read_spec_numbers(r, object,
                    {{"bore_radius", &spec.bore_radius},
                     {"rim_radius", &spec.rim_radius},
                     {"disk_width", &spec.disk_width}});
  r.finish();
  // The blade's own fields were checked by read_gmsh_blade.
  check_at_keys(r, [&] { check_gmsh_bladed_disk_spec(spec); }, "GmshBladedDiskSpec.");
  return spec;
}

/// The casing's parameters: every key optional, the default otherwise
/// (gmsh_casing.hpp); ranges checked by check_gmsh_casing_spec.
GmshCasingSpec read_gmsh_casing(ObjectReader r, const json& object) {
  GmshCasingSpec spec;
  if (object.contains("clamped_flanges"))
    spec.clamped_flanges = static_cast<int>(r.integer("clamped_flanges", 1, 2));
  else
    r.claim("clamped_flanges");
  read_spec_numbers(r, object,
                    {{"inner_radius", &spec.inner_radius},
                     {"thickness", &spec.thickness},
                     {"width", &spec.width},
                     {"element_size", &spec.element_size},
                     {"young_modulus", &spec.young_modulus},
                     {"poisson_ratio", &spec.poisson_ratio},
                     {"density", &spec.density}});
  r.finish();
  check_at_keys(r, [&] { check_gmsh_casing_spec(spec); }, "GmshCasingSpec.");
  return spec;
}

/// `text` with every occurrence of `from` replaced by `to`.
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

/// A tool's multi-line report as one line of a message: its lines trimmed,
/// the empty ones dropped, joined by " | ".
std::string one_line(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    const size_t a = line.find_first_not_of(" \t\r");
    if (a != std::string::npos) {
      const size_t b = line.find_last_not_of(" \t\r");
      out += (out.empty() ? "" : " | ") + line.substr(a, b - a + 1);
    }
    start = end + 1;
  }
  return out;
}

/// A deck that gmsh's mesh makes, in CACHE/NAME-<hash>/DECK, the hash of
/// everything the deck is made of (`key`: the script and the material), so
/// that a changed material never reads an older deck; `write(DIR)` writes
/// DIR/DECK. A gmsh failure keeps its folder as CACHE/NAME-<hash>.failed
/// (the script and gmsh.log the message names), as ccx's failures are kept;
/// `source` is the case file's key its message names.
std::string cached_gmsh_deck(const std::string& key, const std::string& name,
                             const std::string& deck,
                             const std::function<void(const std::string&)>& write,
                             const std::string& source, const std::string& cache_dir,
                             const std::string& case_path) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char ch : key) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  char hash[20];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(h));
  const std::filesystem::path entry = std::filesystem::path(cache_dir) / (name + "-" + hash);
  if (std::filesystem::exists(entry / deck)) return (entry / deck).string();
  std::filesystem::path work = entry;
  work += ".tmp" + std::to_string(::getpid());
  std::error_code ec;
  std::filesystem::remove_all(work, ec);
  try {
    write(work.string());
  } catch (const GmshError& e) {
    std::filesystem::path failed = entry;
    failed += ".failed";
    std::filesystem::remove_all(failed, ec);
    std::filesystem::rename(work, failed, ec);
    const std::string kept = ec ? work.string() : failed.string();
    std::string what = replace_all(e.what(), work.string(), kept);
    const std::string prefix = "write_gmsh_blade_deck: ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw ImportError(case_path + ": key '" + source + "': " + one_line(what));
  } catch (const Interrupted&) {
    // Stopped by a signal (forwarded to gmsh): no deck, no entry.
    std::filesystem::remove_all(work, ec);
    throw;
  } catch (const std::runtime_error& e) {
    std::filesystem::remove_all(work, ec);
    throw ImportError(e.what(), failed_input(FailedInput::ccx_cache));
  }
  std::filesystem::rename(work, entry, ec);
  if (ec && !std::filesystem::exists(entry / deck))
    throw ImportError("cannot rename " + work.string() + ": " + ec.message(),
                      failed_input(FailedInput::ccx_cache));
  std::filesystem::remove_all(work, ec);
  return (entry / deck).string();
}

/// The deck of the case's gmsh model (gmsh_blade, gmsh_bladed_disk or gmsh_casing).
std::string gmsh_deck(const ComponentCase& c, const std::string& cache_dir) {
  if (c.source == ComponentSource::gmsh_casing)
    return cached_gmsh_deck(
        gmsh_casing_cache_key(c.gmsh_casing), "gmsh-casing", "casing.inp",
        [&](const std::string& dir) { write_gmsh_casing_deck(c.gmsh_casing, dir); },
        "component.source.gmsh_casing", cache_dir, c.case_path);
  if (c.source == ComponentSource::gmsh_blade)
    return cached_gmsh_deck(
        gmsh_blade_cache_key(c.gmsh_blade), "gmsh-blade", "blade.inp",
        [&](const std::string& dir) { write_gmsh_blade_deck(c.gmsh_blade, dir); },
        "component.source.gmsh_blade", cache_dir, c.case_path);
  return cached_gmsh_deck(
      gmsh_bladed_disk_cache_key(c.gmsh_bladed_disk), "gmsh-bladed-disk", "disk.inp",
      [&](const std::string& dir) { write_gmsh_bladed_disk_decks(c.gmsh_bladed_disk, dir); },
      "component.source.gmsh_bladed_disk", cache_dir, c.case_path);
}

/// The "rubbing" object (component_case.hpp, data/README.md).
RubbingSetup read_rubbing(ObjectReader r, const json& object) {
  RubbingSetup out;
  r.claim("contact_nodes");
  if (object.contains("contact_nodes"))
    out.contact_nodes = integer_list(r, object, "contact_nodes", 1, 2147483647L);
  r.claim("gap");
  r.claim("casing");
  if (object.contains("casing")) {
    // The flexible casing: its geometry makes the gap.
    if (object.contains("gap"))
      r.fail(r.full("gap"), "must be absent with rubbing.casing (the flexible casing's surface "
                            "and the tips' positions make the gap)");
    const json& cj = object.at("casing");
    if (!cj.is_object() || !cj.contains("gmsh_casing") || !cj.at("gmsh_casing").is_object())
      r.fail(r.full("casing"), "must be {\"gmsh_casing\": {parameters}[, \"surface\": "
                               "\"NAME\"]}, got " + cj.dump().substr(0, 80));
    ObjectReader casing = r.object("casing");
    out.casing = read_gmsh_casing(casing.object("gmsh_casing"), cj.at("gmsh_casing"));
    casing.claim("forcing");
    if (cj.contains("forcing")) {
      const json& fj = cj.at("forcing");
      ObjectReader forcing = casing.object("forcing");
      RubbingSetup::CasingForcing f;
      f.pressure = forcing.number("pressure", {-inf, inf, true, true, "(force/length^2, nonzero)"});
      if (f.pressure == 0.0)
        forcing.fail(forcing.full("pressure"), "must be nonzero (absent forcing: no load), got 0");
      forcing.claim("nodal_diameters");
      if (fj.contains("nodal_diameters"))
        f.nodal_diameters = static_cast<int>(forcing.integer("nodal_diameters", 0, 1000));
      forcing.claim("duration");
      if (fj.contains("duration"))
        f.duration = forcing.number("duration", {0.0, inf, true, true, "s"});
      forcing.finish();
      out.casing_forcing = f;
    }
    casing.claim("modes");
    if (cj.contains("modes")) out.casing_modes = static_cast<int>(casing.integer("modes", 1, 100000));
    casing.claim("surface");
    if (cj.contains("surface")) {
      out.casing_surface = deck_name(casing, cj, "surface");
    }
    casing.finish();
  } else {
    const json& gj = object.contains("gap") ? object.at("gap") : json();
    const bool oval = gj.is_object() && gj.size() == 1 && gj.contains("oval");
    const bool constant = gj.is_object() && gj.size() == 1 && gj.contains("constant");
    if (!oval && !constant)
      r.fail(r.full("gap"), "must be {\"oval\": {\"g_m\": .., \"width\": ..}} or "
                            "{\"constant\": g0} (or rubbing.casing instead), got " +
                                gj.dump().substr(0, 80));
    ObjectReader gap = r.object("gap");
    out.oval_gap = oval;
    if (oval) {
      ObjectReader o = gap.object("oval");
      out.gap = o.number("g_m", {0.0, inf, true, true, "(length)"});
      out.gap_width = o.number("width", {0.0, 1.0, true, true, ""});
      o.finish();
    } else {
      out.gap = gap.number("constant", {-inf, inf, true, true, "(length)"});
    }
    gap.finish();
  }
  out.friction_coefficient = r.number("friction_coefficient", {0.0, 2.0, false, false, ""});
  out.rotation_speed = r.number("rotation_speed", {-1e5, 1e5, false, false, "rad/s"});
  if (out.rotation_speed == 0.0)
    r.fail(r.full("rotation_speed"), "must be nonzero, in [-100000, 100000] rad/s (its sign is "
                                     "the rotation direction about rotation_axis: > 0 "
                                     "counter-clockwise), got 0");
  r.claim("clearance_speed");
  if (object.contains("clearance_speed"))
    out.clearance_speed = r.number("clearance_speed", {0.0, 1e5, true, false, "rad/s"});
  r.claim("tip_sliding");
  if (object.contains("tip_sliding")) {
    const std::string sliding = string_value(r, object, "tip_sliding");
    if (sliding != "with_rotation" && sliding != "against_rotation")
      r.fail(r.full("tip_sliding"),
             "must be \"with_rotation\" or \"against_rotation\", got \"" + sliding + "\"");
    out.sliding_against_rotation = sliding == "against_rotation";
  }
  out.revolutions = r.number("revolutions", {0.0, 1e5, true, false, ""});
  out.steps_per_revolution = r.integer("steps_per_revolution", 1, 100000000);
  r.claim("output_every");
  if (object.contains("output_every")) out.output_every = r.integer("output_every", 1, 100000000);
  ObjectReader response = r.object("response");
  out.response_node = response.integer("node", 1, 2147483647L);
  out.response_direction = response.integer("direction", 1, 3);
  response.finish();
  r.claim("step_safety");
  if (object.contains("step_safety"))
    out.step_safety = r.number("step_safety", {0.0, 1.0, true, true, ""});
  r.claim("campaign");
  if (object.contains("campaign")) {
    const json& cj = object.at("campaign");
    ObjectReader campaign = r.object("campaign");
    campaign.claim("runs");
    const json& runs = cj.contains("runs") ? cj.at("runs") : json();
    if (!runs.is_array() || runs.empty())
      campaign.fail(campaign.full("runs"),
                    "must be a non-empty array of {\"method\": \"cb\"|\"ccm\"|\"macneal\", "
                    "\"modes\": [..]} or {\"method\": \"cc\", \"modes\": [..], "
                    "\"fixed_interface_modes\": N}");
    for (size_t i = 0; i < runs.size(); ++i) {
      ObjectReader run(runs[i], campaign.full("runs") + "[" + std::to_string(i) + "]", r.source());
      RubbingRuns item;
      item.method = string_value(run, runs[i], "method");
      if (item.method != "cb" && item.method != "ccm" && item.method != "macneal" &&
          item.method != "cc")
        run.fail(run.full("method"), "must be \"cb\", \"ccm\", \"macneal\" or \"cc\", got \"" +
                                         item.method + "\"");
      item.modes = integer_list(run, runs[i], "modes", 1, 100000);
      item.fixed_interface_modes = fixed_interface_modes_of(run, runs[i], item.method);
      run.finish();
      // cc runs are named cc-n_c (runs/cc-n_c): one n_c once in the campaign.
      if (item.method == "cc")
        for (const RubbingRuns& earlier : out.campaign)
          if (earlier.method == "cc")
            for (int n_c : item.modes)
              if (std::find(earlier.modes.begin(), earlier.modes.end(), n_c) != earlier.modes.end())
                run.fail(run.full("modes"), "n_c = " + std::to_string(n_c) +
                                                " is in an earlier cc entry already (each cc run "
                                                "is named cc-n_c: one n_c once)");
      out.campaign.push_back(item);
    }
    campaign.claim("full_revolutions");
    if (cj.contains("full_revolutions"))
      out.full_revolutions =
          campaign.number("full_revolutions", {0.0, out.revolutions, false, false, "(at most revolutions)"});
    campaign.finish();
  }
  r.claim("liner");
  if (object.contains("liner")) {
    const json& lj = object.at("liner");
    ObjectReader liner = r.object("liner");
    LinerSetup l;
    l.thickness = liner.number("thickness", {0.0, inf, true, true, "(length)"});
    l.young_modulus = liner.number("young_modulus", {0.0, inf, true, true, "(stress)"});
    l.yield_stress = liner.number("yield_stress", {0.0, inf, true, true, "(stress)"});
    l.hardening_modulus = liner.number("hardening_modulus", {0.0, inf, false, true, "(stress)"});
    l.cells_around = liner.integer("cells_around", 1, 10000000);
    liner.claim("rows");
    if (lj.contains("rows")) l.rows = liner.integer("rows", 1, 100000);
    liner.claim("z_min");
    liner.claim("z_max");
    if (lj.contains("z_min") != lj.contains("z_max"))
      liner.fail(liner.full(lj.contains("z_min") ? "z_max" : "z_min"),
                 "must be given with " + std::string(lj.contains("z_min") ? "z_min" : "z_max") +
                     " (the liner's axial extent, z_min < z_max), or neither");
    if (lj.contains("z_min")) {
      l.axial_extent = true;
      l.z_min = liner.number("z_min", {-inf, inf, true, true, "(length)"});
      l.z_max = liner.number("z_max", {-inf, inf, true, true, "(length)"});
      if (!(l.z_max > l.z_min))
        liner.fail(liner.full("z_max"), "must be greater than z_min = " +
                                            std::to_string(l.z_min) + ", got " +
                                            std::to_string(l.z_max));
    }
    liner.claim("tip_patch");
    if (lj.contains("tip_patch")) {
      ObjectReader patch = liner.object("tip_patch");
      l.patch_circumferential = patch.number("circumferential", {0.0, inf, true, true, "(length)"});
      l.patch_axial = patch.number("axial", {0.0, inf, true, true, "(length)"});
      patch.finish();
    }
    liner.finish();
    out.liner = l;
  }
  r.finish();
  if (out.casing && out.sliding_against_rotation)
    r.fail(r.full("tip_sliding"), "must be \"with_rotation\" against the flexible casing (the "
                                  "tips pass a casing at rest: the physical sliding)");
  if (out.casing && out.liner)
    r.fail(r.full("liner"), "lines the rigid casing only: remove it, or rubbing.casing");
  if (static_cast<double>(out.steps_per_revolution) * out.revolutions > 2147483647.0)
    r.fail(r.full("revolutions"), "revolutions x steps_per_revolution must be at most "
                                  "2147483647 (steps of one run), got " +
                                      std::to_string(out.revolutions * out.steps_per_revolution));
  return out;
}

/// The optional "sweep" object (component_case.hpp, data/README.md).
ComponentSweep read_component_sweep(ObjectReader& top, const json& value,
                                    const RubbingSetup& rubbing) {
  ComponentSweep out;
  ObjectReader sweep = top.object("sweep");
  sweep.optional_note("note");
  sweep.claim("speeds");
  if (!value.contains("speeds"))
    sweep.fail(sweep.full("speeds"), "missing: a list of speeds or {\"from\", \"to\", \"count\"}");
  // Signed as rubbing.rotation_speed (the sign is the direction): nonzero,
  // and one sign for the whole sweep (a map crosses no standstill).
  const Range speed{-1e5, 1e5, true, true, "rad/s, nonzero"};
  constexpr long max_speeds = 100000;
  const json& sj = value.at("speeds");
  if (sj.is_array()) {
    if (sj.empty() || static_cast<long>(sj.size()) > max_speeds)
      sweep.fail(sweep.full("speeds"), "must hold 1 to " + std::to_string(max_speeds) +
                                           " rotation speeds, got " + std::to_string(sj.size()));
    for (const json& v : sj) {
      if (!v.is_number() || !std::isfinite(v.get<double>()) || !speed.contains(v.get<double>()) ||
          v.get<double>() == 0.0)
        sweep.fail(sweep.full("speeds"), "must hold numbers in " + speed.text() + ", got " + v.dump());
      out.speeds.push_back(v.get<double>());
    }
  } else {
    ObjectReader range = sweep.object("speeds");
    const double from = range.number("from", speed);
    const double to = range.number("to", speed);
    const int count = range.integer("count", 1, max_speeds);
    range.finish();
    if (count > 1 && !(to > from))
      range.fail(range.full("to"), "must be above from = " + std::to_string(from) +
                                       " rad/s when count > 1");
    for (int i = 0; i < count; ++i)
      out.speeds.push_back(count == 1 ? from : from + (to - from) * i / (count - 1));
  }
  for (double w : out.speeds) {
    if (w == 0.0)
      sweep.fail(sweep.full("speeds"), "must not hold 0 rad/s (a rubbing run needs a rotation)");
    if ((w > 0.0) != (out.speeds.front() > 0.0))
      sweep.fail(sweep.full("speeds"), "must all have one sign (the rotation's direction), got " +
                                           std::to_string(out.speeds.front()) + " and " +
                                           std::to_string(w) + " rad/s");
  }
  out.revolutions = rubbing.revolutions;
  sweep.claim("revolutions");
  if (value.contains("revolutions"))
    out.revolutions = sweep.number("revolutions", {0.0, 1e5, true, false, ""});
  sweep.claim("transient_revolutions");
  if (value.contains("transient_revolutions"))
    out.transient_revolutions = sweep.number(
        "transient_revolutions",
        {0.0, out.revolutions, false, true, "(below sweep.revolutions, " +
                                                std::to_string(out.revolutions) + ")"});
  sweep.claim("rotation_fit_speeds");
  if (value.contains("rotation_fit_speeds")) {
    const json& fj = value.at("rotation_fit_speeds");
    if (!fj.is_array() || fj.size() != 6)
      sweep.fail(sweep.full("rotation_fit_speeds"),
                 "must be 6 ascending speeds in (0, 1e5) rad/s (2 deflection shapes: "
                 "m + m(m+1)/2 + 1 matrices), got " + fj.dump().substr(0, 80));
    for (const json& v : fj) {
      const bool ascending = out.rotation_fit_speeds.empty() ||
                             (v.is_number() && v.get<double>() > out.rotation_fit_speeds.back());
      if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0.0 ||
          v.get<double>() >= 1e5 || !ascending)
        sweep.fail(sweep.full("rotation_fit_speeds"),
                   "must be 6 ascending speeds in (0, 1e5) rad/s, got " + fj.dump().substr(0, 80));
      out.rotation_fit_speeds.push_back(v.get<double>());
    }
  }
  sweep.claim("runs");
  const json& runs = value.contains("runs") ? value.at("runs") : json();
  if (!runs.is_array() || runs.empty())
    sweep.fail(sweep.full("runs"), "must be a non-empty array of {\"method\": \"full\"}, "
                                   "{\"method\": \"cb\"|\"ccm\"|\"guyan\"|\"macneal\", "
                                   "\"modes\": [..]} or {\"method\": \"cc\", \"modes\": [..], "
                                   "\"fixed_interface_modes\": N}");
  for (size_t i = 0; i < runs.size(); ++i) {
    ObjectReader run(runs[i], sweep.full("runs") + "[" + std::to_string(i) + "]", top.source());
    const std::string method = string_value(run, runs[i], "method");
    if (method == "full") {
      run.finish(); // "modes" refused: the full model keeps every dof
      out.runs.push_back({method, 0, 0, static_cast<int>(i)});
      continue;
    }
    if (method != "cb" && method != "ccm" && method != "guyan" && method != "macneal" &&
        method != "cc")
      run.fail(run.full("method"), "must be \"full\", \"cb\", \"ccm\", \"guyan\", "
                                   "\"macneal\" or \"cc\", got \"" + method + "\"");
    const std::vector<int> counts =
        integer_list(run, runs[i], "modes", method == "guyan" ? 0 : 1, 100000);
    const int fixed_interface_modes = fixed_interface_modes_of(run, runs[i], method);
    run.finish();
    for (int m : counts) {
      // sweep.csv names a cc run cc-n_c: one n_c once in the sweep.
      if (method == "cc")
        for (const ComponentSweepRun& earlier : out.runs)
          if (earlier.method == "cc" && earlier.modes == m)
            run.fail(run.full("modes"), "n_c = " + std::to_string(m) +
                                            " is listed already (each cc run is named cc-n_c: "
                                            "one n_c once in sweep.runs)");
      out.runs.push_back({method, m, fixed_interface_modes, static_cast<int>(i)});
    }
  }
  sweep.finish();
  if (static_cast<double>(rubbing.steps_per_revolution) * out.revolutions > 2147483647.0)
    sweep.fail(sweep.full("revolutions"),
               "sweep.revolutions x rubbing.steps_per_revolution must be at most 2147483647 "
               "(steps of one run), got " +
                   std::to_string(out.revolutions * rubbing.steps_per_revolution));
  return out;
}

/// "key '...'" of the model's source, for messages about the model itself.
std::string source_key(const ComponentCase& c, const ComponentLoadOptions& options, bool material) {
  if (!options.source_override.empty())
    return "key 'component.source' (replaced by " + options.source_named() + " '" +
           options.source_override + "')";
  switch (c.source) {
  case ComponentSource::matrix_market:
    return "key 'component.source.matrix_market'";
  case ComponentSource::gmsh_blade:
    return material ? "keys 'component.source.gmsh_blade.young_modulus' and "
                      "'component.source.gmsh_blade.density'"
                    : "key 'component.source.gmsh_blade'";
  case ComponentSource::gmsh_bladed_disk:
    return material ? "keys 'component.source.gmsh_bladed_disk.blade.young_modulus' and "
                      "'component.source.gmsh_bladed_disk.blade.density'"
                    : "key 'component.source.gmsh_bladed_disk'";
  case ComponentSource::gmsh_casing:
    return material ? "keys 'component.source.gmsh_casing.young_modulus' and "
                      "'component.source.gmsh_casing.density'"
                    : "key 'component.source.gmsh_casing'";
  case ComponentSource::calculix_sector:
    return "key 'component.source.calculix_sector.deck'";
  case ComponentSource::calculix_deck:
    break;
  }
  return c.calculix_matrices.empty() ? "key 'component.source.calculix_deck'"
                                     : "key 'component.source.calculix_matrices'";
}

/// The model's stiffness against its mass. The diagonal ratios K_ii / M_ii
/// are the Rayleigh quotients of the unit vectors, so they lie between
/// omega_min^2 and omega_max^2 [rad^2 / time^2]: the scale of the
/// eigenvalues. Every eigensolver works on omega^2 or its inverse and
/// squares them (Lanczos, the tridiagonal eigenproblem): with every ratio
/// below 1e-100 or every ratio above 1e100 that over- or underflows a
/// double (about 1e+-308), and no structure has frequencies of 1e-50 or
/// 1e50 Hz.
/// A vanishing Young's modulus (1e-300 N/mm^2: K about 1e-299) is refused
/// here, naming the material's keys, where it reached the eigensolvers
/// and failed there with their internal names.
void check_frequency_scale(const Component& component, const ComponentCase& c,
                           const ComponentLoadOptions& options) {
  double largest = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < component.n_dofs(); ++i) {
    const double ratio = component.stiffness.coeff(i, i) / component.mass.coeff(i, i);
    largest = std::max(largest, ratio);
    smallest = std::min(smallest, ratio);
  }
  constexpr double low = 1e-100, high = 1e100;
  if (largest >= low && smallest <= high) return;
  std::ostringstream m;
  m.precision(3);
  m << c.case_path << ": " << source_key(c, options, true) << ": ";
  if (largest < low)
    m << "the stiffness vanishes against the mass: K_ii / M_ii, the scale of omega^2, is at "
         "most "
      << largest << " 1/time^2 on every one of the " << component.n_dofs() << " dofs";
  else
    m << "the mass vanishes against the stiffness: K_ii / M_ii, the scale of omega^2, is at "
         "least "
      << smallest << " 1/time^2 on every one of the " << component.n_dofs() << " dofs";
  m << " (allowed: in [1e-100, 1e100] on some dof, where the eigensolvers' squares of omega^2 "
       "and 1/omega^2 stay within double precision); check the Young's modulus, the density "
       "and their units";
  throw ImportError(m.str());
}

} // namespace

bool is_component_case(const json& document) {
  return document.is_object() && document.contains("component");
}

ComponentCase parse_component_case(const json& document, const std::string& path) {
  ObjectReader top(document, "", path);
  ComponentCase c;
  c.case_path = path;
  top.optional_note("description");
  const json& cj = document.contains("component") ? document.at("component") : json();
  ObjectReader comp = top.object("component");
  c.name = string_value(comp, cj, "name");
  // A name starting with '.' is a hidden folder, and rsi's own staging and
  // lock entries in --out start with '.rsi-'.
  if (c.name.find_first_of("/\\") != std::string::npos || c.name.front() == '.')
    comp.fail(comp.full("name"),
              "must be a plain folder name (no '/' or '\\', not starting with '.'), got '" +
                  c.name + "'");

  const json& sj = cj.contains("source") ? cj.at("source") : json();
  ObjectReader source = comp.object("source");
  const bool deck = sj.is_object() && sj.contains("calculix_deck") &&
                    (sj.size() == 1 || (sj.size() == 2 && sj.contains("calculix_matrices")));
  const bool folder = sj.is_object() && sj.size() == 1 && sj.contains("matrix_market");
  const bool blade = sj.is_object() && sj.size() == 1 && sj.contains("gmsh_blade");
  const bool disk = sj.is_object() && sj.size() == 1 && sj.contains("gmsh_bladed_disk");
  const bool casing = sj.is_object() && sj.size() == 1 && sj.contains("gmsh_casing");
  const bool sector = sj.is_object() && sj.size() == 1 && sj.contains("calculix_sector");
  if (!deck && !folder && !blade && !disk && !casing && !sector)
    comp.fail(comp.full("source"), "must be {\"calculix_deck\": file[, \"calculix_matrices\": "
                                   "\"dir/JOB\"]}, {\"matrix_market\": folder}, "
                                   "{\"gmsh_blade\": {parameters}}, "
                                   "{\"gmsh_bladed_disk\": {parameters}}, "
                                   "{\"gmsh_casing\": {parameters}} or "
                                   "{\"calculix_sector\": {\"deck\", \"sectors\", \"left\", "
                                   "\"right\"}}, got " +
                                       sj.dump().substr(0, 80));
  if (deck) {
    c.source = ComponentSource::calculix_deck;
    c.source_path = resolve(string_value(source, sj, "calculix_deck"), path);
    if (sj.contains("calculix_matrices"))
      c.calculix_matrices = resolve(string_value(source, sj, "calculix_matrices"), path);
  } else if (folder) {
    c.source = ComponentSource::matrix_market;
    c.source_path = resolve(string_value(source, sj, "matrix_market"), path);
  } else if (blade) {
    c.source = ComponentSource::gmsh_blade;
    c.gmsh_blade = read_gmsh_blade(source.object("gmsh_blade"), sj.at("gmsh_blade"));
  } else if (sector) {
    const json& xj = sj.at("calculix_sector");
    if (!xj.is_object())
      source.fail(source.full("calculix_sector"),
                  "must be {\"deck\": file, \"sectors\": N, \"left\": \"NSET\", \"right\": "
                  "\"NSET\"}");
    ObjectReader x = source.object("calculix_sector");
    c.source = ComponentSource::calculix_sector;
    c.source_path = resolve(string_value(x, xj, "deck"), path);
    c.sectors = static_cast<int>(x.integer("sectors", 3, 200));
    c.sector_left = deck_name(x, xj, "left");
    c.sector_right = deck_name(x, xj, "right");
    x.finish();
  } else if (casing) {
    if (!sj.at("gmsh_casing").is_object())
      source.fail(source.full("gmsh_casing"), "must be an object of the casing's parameters");
    c.source = ComponentSource::gmsh_casing;
    c.gmsh_casing = read_gmsh_casing(source.object("gmsh_casing"), sj.at("gmsh_casing"));
  } else {
    if (!sj.at("gmsh_bladed_disk").is_object())
      source.fail(source.full("gmsh_bladed_disk"), "must be an object of the disk's parameters");
    c.source = ComponentSource::gmsh_bladed_disk;
    c.gmsh_bladed_disk =
        read_gmsh_bladed_disk(source.object("gmsh_bladed_disk"), sj.at("gmsh_bladed_disk"));
  }
  source.finish();

  comp.claim("boundary");
  if (cj.contains("boundary")) {
    const json& bj = cj.at("boundary");
    ObjectReader boundary = comp.object("boundary");
    if (!bj.is_object() || bj.size() != 1 || !(bj.contains("nodes") || bj.contains("node_set")))
      boundary.fail(comp.full("boundary"),
                    "must be {\"nodes\": [ids]} or {\"node_set\": \"NAME\"} (an *NSET of the deck)");
    if (bj.contains("nodes")) {
      c.boundary_nodes = integer_list(boundary, bj, "nodes", 1, 2147483647L);
    } else {
      if (c.source == ComponentSource::matrix_market)
        boundary.fail(boundary.full("node_set"),
                      "needs a calculix_deck or gmsh_blade source (an *NSET of its deck)");
      c.boundary_node_set = deck_name(boundary, bj, "node_set");
    }
    boundary.finish();
  } else if (c.source == ComponentSource::matrix_market) {
    c.boundary_from_dofs = true;
  } else if (c.source == ComponentSource::gmsh_blade ||
             c.source == ComponentSource::gmsh_bladed_disk) {
    c.boundary_node_set = "TIP";
  } else if (c.source == ComponentSource::gmsh_casing) {
    c.boundary_node_set = "INNER";
  } else {
    comp.fail(comp.full("boundary"),
              std::string("missing (required for a ") +
                  (c.source == ComponentSource::calculix_sector ? "calculix_sector" : "calculix_deck") +
                  " source)");
  }

  comp.claim("mass");
  if (cj.contains("mass")) {
    const json& mass = cj.at("mass");
    if (mass != "consistent" && mass != "lumped")
      comp.fail(comp.full("mass"), "must be \"consistent\" or \"lumped\" (HRZ), got " +
                                       mass.dump().substr(0, 80));
    c.lumped_mass = mass == "lumped";
  }
  comp.claim("rotation_effects");
  if (cj.contains("rotation_effects")) {
    const json& effects = cj.at("rotation_effects");
    if (!effects.is_boolean())
      comp.fail(comp.full("rotation_effects"),
                "must be true or false, got " + effects.dump().substr(0, 80));
    c.rotation_effects = effects.get<bool>();
    if (c.rotation_effects && c.source == ComponentSource::matrix_market)
      comp.fail(comp.full("rotation_effects"),
                "needs a calculix_deck or gmsh_blade source (ccx runs the deck under the "
                "centrifugal load), the source is a Matrix Market folder");
    if (c.rotation_effects && c.source == ComponentSource::calculix_sector)
      comp.fail(comp.full("rotation_effects"),
                "not written yet for an assembled sector deck (calculix_sector): ccx would have "
                "to run the whole disk under the centrifugal load");
    if (c.rotation_effects && c.source == ComponentSource::gmsh_casing)
      comp.fail(comp.full("rotation_effects"),
                "the casing is the stator: it does not turn, and has no rotation effects");
    if (c.rotation_effects && !c.calculix_matrices.empty())
      comp.fail(comp.full("rotation_effects"),
                "needs ccx to run the deck under the centrifugal load, and "
                "source.calculix_matrices names matrices already written: drop one of them");
  }
  comp.claim("cyclic_bases");
  if (cj.contains("cyclic_bases")) {
    const json& cyclic = cj.at("cyclic_bases");
    if (!cyclic.is_boolean())
      comp.fail(comp.full("cyclic_bases"),
                "must be true or false, got " + cyclic.dump().substr(0, 80));
    c.cyclic_bases = cyclic.get<bool>();
    if (c.cyclic_bases && c.source != ComponentSource::gmsh_bladed_disk &&
        c.source != ComponentSource::calculix_sector)
      comp.fail(comp.full("cyclic_bases"),
                "needs a cyclic model, a gmsh_bladed_disk or calculix_sector source (its "
                "sector count says how the model turns onto itself)");
  }
  c.units = string_value(comp, cj, "units");
  comp.claim("rotation_axis");
  if (cj.contains("rotation_axis")) {
    const json& axis = cj.at("rotation_axis");
    bool ok = axis.is_array() && axis.size() == 3;
    for (size_t k = 0; ok && k < 3; ++k) {
      ok = axis[k].is_number() && std::isfinite(axis[k].get<double>());
      if (ok) c.rotation_axis(static_cast<int>(k)) = axis[k].get<double>();
    }
    if (!ok || !(c.rotation_axis.norm() > 0.0))
      comp.fail(comp.full("rotation_axis"),
                "must be three finite numbers, not all zero, got " + axis.dump().substr(0, 80));
    c.rotation_axis.normalize();
  }
  comp.finish();

  top.claim("modal_campaign");
  if (document.contains("modal_campaign")) {
    const json& mj = document.at("modal_campaign");
    ObjectReader mc = top.object("modal_campaign");
    ModalCampaign campaign;
    mc.claim("methods");
    const json& methods = mj.contains("methods") ? mj.at("methods") : json();
    if (!methods.is_array() || methods.empty())
      mc.fail(mc.full("methods"), "must be a non-empty array of \"cb\", \"ccm\", \"macneal\"");
    for (const json& m : methods) {
      if (!m.is_string() || (m != "cb" && m != "ccm" && m != "macneal"))
        mc.fail(mc.full("methods"), "must hold \"cb\", \"ccm\" or \"macneal\", got " + m.dump());
      campaign.methods.push_back(m.get<std::string>());
    }
    campaign.modes = integer_list(mc, mj, "modes", 1, 100000);
    std::sort(campaign.modes.begin(), campaign.modes.end());
    campaign.modes.erase(std::unique(campaign.modes.begin(), campaign.modes.end()),
                         campaign.modes.end());
    campaign.frequencies = mc.integer("frequencies", 1, 1000);
    mc.finish();
    c.modal_campaign = campaign;
  }
  top.claim("rubbing");
  if (document.contains("rubbing")) c.rubbing = read_rubbing(top.object("rubbing"), document.at("rubbing"));
  // The gmsh ring is built about z in mm (gmsh_casing.hpp): the rotor must
  // turn about z and be in the same units.
  if (c.rubbing && c.rubbing->casing && c.rotation_axis != Eigen::Vector3d::UnitZ())
    top.fail("component.rotation_axis", "must be [0, 0, 1] with rubbing.casing (the flexible "
                                        "ring is built about z)");
  if (c.rubbing && c.rubbing->casing && c.units != "N, mm, t, s")
    top.fail("component.units", "must be \"N, mm, t, s\" with rubbing.casing (the flexible "
                                "ring's units), got \"" + c.units + "\"");
  if (c.rubbing && c.rubbing->casing && c.rotation_effects)
    top.fail("rubbing.casing", "against the flexible casing the rotor runs without rotation "
                               "effects for now (component.rotation_effects: false)");
  if (c.rubbing && c.rubbing->clearance_speed != 0.0 && !c.rotation_effects)
    top.fail("rubbing.clearance_speed", "needs component.rotation_effects: true (without rotation "
                                        "effects the tip does not grow and the gap is the same "
                                        "at every speed), got " +
                                            std::to_string(c.rubbing->clearance_speed) + " rad/s");
  top.claim("sweep");
  if (document.contains("sweep")) {
    if (!c.rubbing)
      top.fail("sweep", "needs the case's \"rubbing\" object (a component's sweep runs its "
                        "rubbing set-up at each speed)");
    c.sweep = read_component_sweep(top, document.at("sweep"), *c.rubbing);
  }
  c.damping = read_damping(top, document);
  if (c.damping.projected_rayleigh)
    top.fail("damping.projected_rayleigh",
             "only for the paper's case (its reduced integrator); a component's reduced runs "
             "take damping.modal_ratio");
  top.finish();
  return c;
}

const std::string& ComponentLoadOptions::source_named() const {
  static const std::string unnamed = "the source override";
  return source_name.empty() ? unnamed : source_name;
}

const std::string& ComponentLoadOptions::ccx_cache_named() const {
  static const std::string unnamed = "the ccx cache";
  return ccx_cache_name.empty() ? unnamed : ccx_cache_name;
}

ComponentDeck component_deck(const ComponentCase& c, const ComponentLoadOptions& options) {
  if (c.source == ComponentSource::matrix_market)
    throw CaseError(c.case_path + ": key 'component.source.matrix_market': the component is "
                    "a Matrix Market folder, not a CalculiX deck");
  // The source override replaces the case's deck or folder, and nothing else: a case
  // whose model is more than that one path is refused, never half replaced.
  if (!options.source_override.empty() && !c.calculix_matrices.empty())
    throw CaseError(c.case_path +
                    ": key 'component.source.calculix_matrices': the case reads "
                    "the matrices " +
                    c.calculix_matrices + ".{sti,mas,dof} of a ccx run of " + c.source_path +
                    ", and " + options.source_named() + " names the deck " +
                    options.source_override +
                    ": rsi would mix that deck's nodes and sets with the other deck's matrices; "
                    "drop " +
                    options.source_named() + ", or run it on a case without calculix_matrices");
  const bool gmsh = c.source == ComponentSource::gmsh_blade ||
                    c.source == ComponentSource::gmsh_bladed_disk ||
                    c.source == ComponentSource::gmsh_casing;
  const char* model = c.source == ComponentSource::gmsh_blade    ? "blade"
                      : c.source == ComponentSource::gmsh_casing ? "casing"
                                                                 : "bladed-disk";
  if (!options.source_override.empty() && gmsh)
    throw CaseError(c.case_path + ": " + source_key(c, ComponentLoadOptions{}, false) +
                    ": the case builds its " + model +
                    " deck from these parameters, and " +
                    options.source_named() + " names " + options.source_override + ": " +
                    options.source_named() +
                    " replaces a calculix_deck or matrix_market source only; write a case whose "
                    "calculix_deck names that deck (with its boundary) instead");
  std::string source = options.source_override.empty() ? c.source_path : options.source_override;
  if (gmsh && options.source_override.empty()) source = gmsh_deck(c, options.ccx_cache);
  if (!std::filesystem::is_regular_file(source))
    throw ImportError(c.case_path + ": " + source_key(c, ComponentLoadOptions{}, false) + ": '" + source +
                      "' is not a file (the deck; " + options.source_named() + " overrides it)");
  const CalculixDeck deck = read_calculix_deck(source);
  check_calculix_features(deck);
  std::vector<int> boundary = c.boundary_nodes;
  if (!c.boundary_node_set.empty()) {
    const auto set = deck.nsets.find(c.boundary_node_set);
    if (set == deck.nsets.end())
      throw ImportError(c.case_path + ": key 'component.boundary.node_set': the deck " + source +
                        " has no *NSET named " + c.boundary_node_set);
    boundary = set->second;
    const auto dropped = deck.dropped_ids.find(c.boundary_node_set);
    if (dropped != deck.dropped_ids.end())
      throw ImportError(c.case_path + ": key 'component.boundary.node_set': the *NSET " +
                        c.boundary_node_set + " of " + source + " lists node " +
                        std::to_string(dropped->second.front()) +
                        ", above the deck's largest node id " +
                        std::to_string(deck.largest_node_id) +
                        ": ccx drops it (with a warning), so the set would lose it; define the "
                        "node or remove it from the set");
  }
  for (int id : boundary)
    if (!std::binary_search(deck.nodes.begin(), deck.nodes.end(), id,
                            [](const auto& a, const auto& b) { return node_id(a) < node_id(b); }))
      throw ImportError(c.case_path + ": key 'component.boundary': boundary node " +
                        std::to_string(id) + " is not a node of the deck " + source);
  return {source, deck, boundary};
}

/// The bladed disk of a calculix_sector source: the sector's component
/// turned and summed (sector_assembly.hpp). Faces pair within 1e-6 of the
/// sector's size (its largest node distance from the origin): a deck's
/// coordinates are often written to 6 or 7 digits, and two face nodes lie
/// an element apart.
Component assembled_sectors(const Component& sector, const ComponentCase& c,
                            const ComponentDeck& model) {
  const auto set = [&](const std::string& name, const char* key) {
    const auto found = model.deck.nsets.find(name);
    if (found == model.deck.nsets.end())
      throw ImportError(c.case_path + ": key 'component.source.calculix_sector." + key +
                        "': the deck " + model.source + " has no *NSET named " + name);
    return found->second;
  };
  SectorPattern p;
  p.sectors = c.sectors;
  p.axis = c.rotation_axis;
  p.left = set(c.sector_left, "left");
  p.right = set(c.sector_right, "right");
  p.boundary = model.boundary;
  p.stride = static_cast<int>(model.deck.largest_node_id) + 1;
  double size = 0.0;
  for (const ComponentNode& n : sector.nodes)
    if (!n.generated) size = std::max(size, n.x.norm());
  p.tolerance = 1e-6 * size;
  const std::string what =
      c.case_path + ": key 'component.source.calculix_sector' (" + model.source + ")";
  Component disk = assemble_sectors(sector, p, what);
  check_component(disk, what);
  return disk;
}

Component load_component(const ComponentCase& c, const ComponentLoadOptions& options) {
  Component component;
  if (c.source == ComponentSource::matrix_market) {
    const std::string source =
        options.source_override.empty() ? c.source_path : options.source_override;
    if (!std::filesystem::is_directory(source))
      throw ImportError(c.case_path + ": key 'component.source.matrix_market': '" + source +
                        "' is not a folder");
    component = read_matrix_market_component(
        source, c.name, c.boundary_from_dofs ? nullptr : &c.boundary_nodes);
  } else {
    const ComponentDeck model = component_deck(c, options);
    const CalculixDeck& deck = model.deck;
    const std::string& source = model.source;
    const std::vector<int>& boundary = model.boundary;
    const bool ran_ccx = c.calculix_matrices.empty();
    std::string job = c.calculix_matrices;
    if (ran_ccx) {
      try {
        job = calculix_matrices(deck, options.ccx_cache, options.ccx_cache_named());
      } catch (const ImportError& e) {
        // ccx refused the model (its *ERROR lines follow): the source's key.
        // A missing, unstartable or killed ccx, or an unusable cache, is not
        // the case's fault and keeps its own message.
        const std::string what = e.what();
        if (what.find(": ccx failed on the model") == std::string::npos) throw;
        throw ImportError(c.case_path + ": " + source_key(c, options, false) + ": " +
                          one_line(what));
      }
    }
    try {
      component = read_calculix_component(job, deck, boundary, c.name);
    } catch (const ImportError& e) {
      // A defect of the files rsi had ccx write (a zero mass on a dof ccx
      // made, say) is the deck's: say so before the cache file's name.
      if (!ran_ccx || std::string(e.what()).rfind(job, 0) != 0) throw;
      throw ImportError(source + ": the matrices ccx wrote for this deck (in " +
                        options.ccx_cache_named() + " " + options.ccx_cache +
                        ") are not a component: " + e.what());
    }
    if (c.source == ComponentSource::calculix_sector)
      component = assembled_sectors(component, c, model);
  }
  check_frequency_scale(component, c, options);
  component.units = c.units;
  component.rotation_axis = c.rotation_axis;
  if (c.cyclic_bases)
    component.cyclic_bases = c.source == ComponentSource::gmsh_bladed_disk
                                 ? c.gmsh_bladed_disk.sectors
                                 : c.sectors;
  if (c.lumped_mass) component.mass = hrz_lumped_mass(component);
  return component;
}

FlexibleCasing load_flexible_casing(const ComponentCase& c, const ComponentLoadOptions& options) {
  if (!c.rubbing || !c.rubbing->casing)
    throw std::invalid_argument("load_flexible_casing: the case has no rubbing.casing");
  const RubbingSetup& r = *c.rubbing;
  ComponentCase casing;
  casing.case_path = c.case_path;
  casing.name = c.name + "-casing";
  casing.source = ComponentSource::gmsh_casing;
  casing.gmsh_casing = *r.casing;
  casing.boundary_node_set = "INNER";
  casing.units = c.units;
  casing.lumped_mass = c.lumped_mass;
  ComponentLoadOptions own = options;
  own.source_override.clear();
  // The casing's own loader names its keys as a component's: here they are
  // rubbing.casing's.
  const auto renamed = [](std::string what) {
    what = replace_all(what, "component.source.gmsh_casing", "rubbing.casing.gmsh_casing");
    return replace_all(what, "component.boundary.node_set", "rubbing.casing (its node set INNER)");
  };
  try {
    const ComponentDeck deck = component_deck(casing, own);
    std::optional<CasingSurface> surface;
    try {
      surface.emplace(deck.deck, r.casing_surface);
    } catch (const ImportError& e) {
      throw CaseError(c.case_path + ": key 'rubbing.casing.surface': " + e.what());
    }
    return FlexibleCasing{load_component(casing, own), std::move(*surface)};
  } catch (const CaseError& e) {
    throw CaseError(renamed(e.what()), e.advice());
  } catch (const ImportError& e) {
    throw ImportError(renamed(e.what()), e.advice());
  }
}

} // namespace rsi
