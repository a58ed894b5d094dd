// libFuzzer target for the component loader: a component case file and the
// files it reads, from one input. The bytes are cut at each line "@@@" into
// at most nine files, in this order, written to a folder of this process's
// own (emptied for each input):
//
//   case.json   the component case (parse_component_case)
//   mm/K.mtx, mm/M.mtx, mm/dofs.csv, mm/nodes.csv
//               a Matrix Market folder in `rsi export`'s layout
//   deck.inp    a CalculiX deck (read_calculix_deck, check_calculix_features)
//   job.sti, job.mas, job.dof
//               the matrices a ccx run of that deck would have written
//               (component.source.calculix_matrices)
//
// then read as `rsi modes case.json` reads it: read_case_document,
// is_component_case, parse_component_case, load_component. The seeds name
// "mm" or "deck.inp" with "calculix_matrices": "job". What would start an
// external program is not run: a gmsh_blade source, or a calculix_deck
// without calculix_matrices (ccx), is parsed and its deck read, not built.
// A case or deck naming a file outside the folder (an absolute path, "..",
// an *INCLUDE of /dev/zero) is skipped: the loader reads what the user
// names, and a device that never ends is not the loader's defect.
//
// The contract under test (data/README.md, component cases): every input
// is either loaded, and then the component passes check_component (K and M
// square of the dof map's size, finite, symmetric, M's diagonal positive)
// with its boundary dofs inside the model; or refused with CaseError or
// ImportError with a non-empty message (exit 2 in the CLI). Any other
// exception calls abort(), so libFuzzer records a crash; ASan and UBSan make
// memory errors and undefined behaviour crashes, libFuzzer's malloc limit
// an allocation beyond what the files hold.
//
// Run: fuzz/run-fuzz.sh SECONDS fuzz_component_loader (see fuzz/README.md).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <vector>

#include <gsl/gsl_errno.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "calculix_deck.hpp"
#include "calculix_features.hpp"
#include "case_file.hpp"
#include "component.hpp"
#include "component_case.hpp"

namespace fs = std::filesystem;

namespace {

const char* const file_names[] = {"case.json", "mm/K.mtx",  "mm/M.mtx", "mm/dofs.csv", "mm/nodes.csv",
                                  "deck.inp",  "job.sti",   "job.mas",  "job.dof"};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_component_loader: %s\n", what.c_str());
  std::abort();
}

/// True when `path` names something inside `folder` (after resolving "..").
bool inside(const fs::path& folder, const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec).lexically_normal();
  if (ec) return false;
  const std::string a = p.string();
  const std::string f = folder.string() + "/";
  return a.rfind(f, 0) == 0;
}

void check_loaded(const rsi::Component& c) {
  try {
    rsi::check_component(c, "fuzz");
  } catch (const rsi::ImportError& e) {
    fail(std::string("loaded component fails check_component: ") + e.what());
  }
  for (int b : c.boundary)
    if (b < 0 || b >= c.n_dofs()) fail("boundary dof outside the model");
}

void load(const fs::path& folder, const std::string& bytes) {
  const std::string case_path = (folder / "case.json").string();
  const nlohmann::json document = rsi::read_case_document(case_path);
  if (!rsi::is_component_case(document)) return;
  const rsi::ComponentCase c = rsi::parse_component_case(document, case_path);
  if (!inside(folder, c.source_path)) return;
  if (!c.calculix_matrices.empty() && !inside(folder, c.calculix_matrices)) return;
  if (c.source == rsi::ComponentSource::gmsh_blade ||
      c.source == rsi::ComponentSource::gmsh_bladed_disk ||
      c.source == rsi::ComponentSource::gmsh_casing)
    return;
  if (c.source == rsi::ComponentSource::calculix_deck ||
      c.source == rsi::ComponentSource::calculix_sector) {
    // *INCLUDE names files the harness cannot confine (relative to the
    // deck's folder, at any depth): only decks without one are read.
    std::string upper = bytes;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    if (upper.find("INCLUDE") != std::string::npos) return;
    if (c.calculix_matrices.empty()) {
      // rsi would run ccx on the deck: read it as load_component does first.
      if (!fs::is_regular_file(c.source_path)) return;
      rsi::check_calculix_features(rsi::read_calculix_deck(c.source_path));
      return;
    }
  }
  rsi::ComponentLoadOptions options;
  options.ccx_cache = (folder / "cache").string();
  check_loaded(rsi::load_component(c, options));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool gsl_quiet = (gsl_set_error_handler_off(), true);
  (void)gsl_quiet;
  static const fs::path folder =
      fs::weakly_canonical(fs::temp_directory_path()) /
      ("rsi-fuzz-component-" + std::to_string(getpid()));
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::error_code ec;
  fs::remove_all(folder, ec);
  fs::create_directories(folder / "mm");
  std::size_t start = 0;
  for (const char* name : file_names) {
    if (start > bytes.size()) break;
    std::size_t end = bytes.find("\n@@@\n", start);
    if (end == std::string::npos) end = bytes.size();
    std::ofstream out(folder / name, std::ios::binary);
    out.write(bytes.data() + start, static_cast<std::streamsize>(end - start));
    out.put('\n');
    start = end + 5;
  }
  try {
    load(folder, bytes);
  } catch (const rsi::CaseError& e) {
    if (std::string(e.what()).empty()) fail("CaseError with an empty message");
  } catch (const rsi::ImportError& e) {
    if (std::string(e.what()).empty()) fail("ImportError with an empty message");
  } catch (const std::exception& e) {
    fail(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
  }
  return 0;
}
