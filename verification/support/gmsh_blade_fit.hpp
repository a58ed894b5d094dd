#pragma once
// The gmsh blade's rotation fit (rotation_fit.hpp) at 200, 400, 800, 1200,
// 1600, 2000 rad/s, built once a test process: the fixture of
// test_rotation_fit and test_speed_subspace. ctest runs each case in its
// own process, so the ccx runs go to the build's shared cache
// (RSI_CCX_CACHE, the one the command-line tests use; entries are written
// by rename, so concurrent processes are safe): ccx runs once a build, in
// the first process that needs it, not six times in each. Without that
// definition, a cache of the process's own. Its tests skip (GTEST_SKIP,
// reason printed) when ccx or gmsh is not on PATH.

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "case_file.hpp"
#include "child_process.hpp"
#include "component_case.hpp"
#include "rotation_fit.hpp"

namespace rsi::testing {

/// The programs of `programs` not on PATH, comma-separated; empty if none.
inline std::string missing_programs(std::initializer_list<const char*> programs) {
  std::string why;
  for (const char* p : programs)
    if (!executable_on_path(p)) why += (why.empty() ? "" : ", ") + std::string(p);
  return why;
}

inline const std::vector<double>& blade_fit_speeds() {
  static const std::vector<double> speeds = {200.0, 400.0, 800.0, 1200.0, 1600.0, 2000.0};
  return speeds;
}

class GmshBladeFit : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    const std::string why = missing_programs({"ccx", "gmsh"});
    if (!why.empty()) {
      skip_reason = why + " not on PATH";
      return;
    }
    dir = std::filesystem::temp_directory_path() /
          ("rsi-blade-fit-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
#ifdef RSI_CCX_CACHE
    options.ccx_cache = RSI_CCX_CACHE;
#else
    options.ccx_cache = (dir / "cache").string();
#endif
    const std::string path = RSI_SOURCE_DIR "/data/cases/blade3d.json";
    c = parse_component_case(read_case_document(path), path);
    fit = fit_rotation(c, options, blade_fit_speeds(), 2);
  }
  static void TearDownTestSuite() {
    if (!dir.empty()) std::filesystem::remove_all(dir);
  }
  void SetUp() override {
    if (!skip_reason.empty()) {
      std::printf("skipped: %s\n", skip_reason.c_str());
      GTEST_SKIP() << skip_reason;
    }
  }
  static inline std::string skip_reason;
  static inline std::filesystem::path dir;
  static inline ComponentLoadOptions options;
  static inline ComponentCase c;
  static inline RotationFit fit;
};

} // namespace rsi::testing
