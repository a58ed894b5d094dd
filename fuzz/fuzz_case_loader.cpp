// libFuzzer target for the case loader (issue 6): the bytes of an input are
// the text of a case file, handed to parse_case_text exactly as load_case
// hands it the contents of a file.
//
// The contract under test (data/README.md, "Case file schema"): every text is
// either accepted, and then the Case holds values inside the documented
// ranges, or rejected with a CaseError whose message names the source. Any
// other exception, an empty or anonymous message, or an accepted value out
// of range is a bug of the loader: the target calls abort() so that libFuzzer
// records the input as a crash. ASan and UBSan (built in, see
// fuzz/CMakeLists.txt) turn memory errors and undefined behaviour into
// crashes as well. Nothing beyond the loader runs (no assembly).
//
// Run: fuzz/run-fuzz.sh SECONDS (see fuzz/README.md).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include <gsl/gsl_errno.h>

#include "blade_geometry.hpp"
#include "case_file.hpp"

namespace {

const std::string source = "fuzz.json";

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_case_loader: %s\n", what.c_str());
  std::abort();
}

void require(bool ok, const char* what) {
  if (!ok) fail(std::string("accepted case violates the schema: ") + what);
}

bool positive_finite(double x) {
  return std::isfinite(x) && x > 0.0;
}

/// The ranges of data/README.md that an accepted case must satisfy.
void check_accepted(const rsi::Case& c) {
  require(c.source == source, "source");
  require(positive_finite(c.material.young_modulus), "material.young_modulus > 0");
  require(positive_finite(c.material.density), "material.density > 0");
  const rsi::BladedDiskSpec& b = c.bladed_disk;
  require(b.n_blades >= 2 && b.n_blades <= 1000, "bladed_disk.n_blades in [2, 1000]");
  require(positive_finite(b.hub_radius), "bladed_disk.hub_radius > 0");
  require(std::isfinite(b.rim_radius) && b.rim_radius > b.hub_radius, "rim_radius > hub_radius");
  require(std::isfinite(b.tip_radius) && b.tip_radius > b.rim_radius, "tip_radius > rim_radius");
  require(b.n_blade_elements >= 1 && b.n_blade_elements <= 1000, "n_blade_elements in [1, 1000]");
  require(std::abs(b.kink_angle) <= 30.0 * M_PI / 180.0, "kink_angle in [-30, 30] degrees");
  for (const rsi::Section* s : {&b.blade, &b.disk, &b.rim_ring, &c.casing.section})
    require(positive_finite(s->width) && positive_finite(s->thickness), "section sizes > 0");
  require(std::isfinite(c.casing.radius) && c.casing.radius > b.tip_radius,
          "casing.radius > tip_radius");
  require(c.casing.n_elements >= 3 && c.casing.n_elements <= 100000, "casing.n_elements");
  require(c.casing.clamp_angle >= 0.0 && c.casing.clamp_angle < 2.0 * M_PI, "clamp_angle");
  require(c.operating_point.rotation_speed >= 0.0 && c.operating_point.rotation_speed <= 1e5,
          "rotation_speed in [0, 1e5]");
  require(c.operating_point.friction_coefficient >= 0.0 &&
              c.operating_point.friction_coefficient <= 2.0,
          "friction_coefficient in [0, 2]");
  require(std::isfinite(c.forcing.amplitude) && c.forcing.amplitude >= 0.0, "amplitude >= 0");
  require(c.forcing.nodal_diameter >= 0 && c.forcing.nodal_diameter <= c.casing.n_elements / 2,
          "nodal_diameter in [0, n_elements/2]");
  require(std::isfinite(c.forcing.duration) && c.forcing.duration >= 0.0, "forcing.duration");
  require(positive_finite(c.time.step), "time.step > 0");
  require(std::isfinite(c.time.duration) && c.time.duration >= c.time.step, "time.duration");
  require(c.time.output_every >= 1, "time.output_every >= 1");
  // The blade as a whole: its radius grows from the rim to the tip.
  const rsi::BladeGeometry g = rsi::blade_geometry(c.bladed_disk);
  for (std::size_t i = 2; i < g.nodes.size(); ++i)
    require(g.nodes[i].norm() > g.nodes[i - 1].norm(), "blade radius grows from rim to tip");
  for (const rsi::CampaignRun& run : c.campaign) {
    require(run.method == "cb" || run.method == "ccm" || run.method == "guyan", "campaign method");
    require(run.modes >= 0 && run.modes <= 100000, "campaign modes in [0, 100000]");
  }
}

} // namespace

// GSL's default handler aborts; the CLI turns it off once (cli/main.cpp) and
// checks every status, so the loader is fuzzed the same way.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gsl_set_error_handler_off();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    check_accepted(rsi::parse_case_text(text, source));
  } catch (const rsi::CaseError& e) {
    const std::string message = e.what();
    if (message.empty()) fail("CaseError with an empty message");
    if (message.compare(0, source.size() + 2, source + ": ") != 0)
      fail("CaseError message does not name the source: " + message);
  } catch (const std::exception& e) {
    fail(std::string("escaped the loader: ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fail("escaped the loader: an exception not derived from std::exception");
  }
  return 0;
}
