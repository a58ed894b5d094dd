#include "calculix_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "child_process.hpp"
#include "component.hpp"
#include "coordinate_entries.hpp"
#include "interruption_flag.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

namespace fs = std::filesystem;

/// The cache folder could not be created or written (the CLI names the
/// option that set it).
const FailureAdvice kCacheFailed = failed_input(FailedInput::ccx_cache);

std::uint64_t fnv1a(const std::string& text, std::uint64_t h = 14695981039346656037ull) {
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex(std::uint64_t h) {
  std::ostringstream s;
  s << std::hex << h;
  return stream_text(s);
}

/// Runs `ccx -i job` in `dir` with its output in dir/ccx.log; the exit
/// status. A ccx killed by a signal (Ctrl-C reaches the whole process group)
/// made no model, right or wrong: `dir` is removed and ImportError thrown,
/// never kept as a ".failed" entry.
int run_ccx(const std::string& ccx, const fs::path& dir) {
  const ChildResult r = run_child({ccx, "-i", "job"}, dir.string(), (dir / "ccx.log").string());
  if (!r.started) throw ImportError("ccx: cannot start " + ccx + ": " + r.error);
  if (r.signal != 0) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    throw ImportError("ccx was killed by signal " + std::to_string(r.signal) +
                      " before it wrote the matrices; run again");
  }
  return r.exit_status;
}

/// The lines of ccx's log that say what went wrong: each *ERROR line with
/// the indented lines that continue it (ccx cuts its messages over several
/// lines: "*ERROR reading *ELASTIC: the Young" / "modulus should exceed 0.0").
std::string error_lines(const fs::path& log) {
  std::ifstream in(log);
  std::string line;
  std::string out;
  int kept = 0;
  bool continuing = false;
  while (std::getline(in, line) && kept < 16) {
    const bool blank = line.find_first_not_of(" \t\r") == std::string::npos;
    if (line.find("ERROR") != std::string::npos) {
      out += "\n  " + line;
      ++kept;
      continuing = true;
    } else if (continuing && !blank && (line[0] == ' ' || line[0] == '\t')) {
      out += " " + line.substr(line.find_first_not_of(" \t"));
      ++kept;
    } else {
      continuing = false;
    }
  }
  return out.empty() ? " (no *ERROR line in " + log.string() + ")" : out;
}

/// The last line of `path` without its newline; empty when the file does
/// not end with a newline (cut short) or cannot be read.
std::string last_complete_line(const fs::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  const std::streamoff tail = std::min<std::streamoff>(size, 4096);
  std::string text(static_cast<size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(text.data(), tail);
  if (!in || text.empty() || text.back() != '\n') return "";
  text.pop_back();
  return text.substr(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
}

/// Why the matrices ccx wrote in `dir` are incomplete, or "" when they are
/// whole. ccx 2.20 exits 0 when a write fails (a full disk: its Fortran and
/// C writes are not checked), leaving a .sti, .mas or .dof cut short or
/// empty. A whole set: JOB.dof lists n dofs, and JOB.sti and JOB.mas (the
/// upper triangle column by column) end with a newline and the entry
/// "n n value", the last column's diagonal. (Their sizes may differ: a
/// value of three exponent digits, 1e-300, makes a longer line.)
std::string incomplete_matrices(const fs::path& dir) {
  long n = 0;
  {
    std::ifstream in(dir / "job.dof");
    std::string line;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos) ++n;
  }
  if (n == 0) return "job.dof lists no dof";
  for (const char* name : {"job.sti", "job.mas"}) {
    std::istringstream last(last_complete_line(dir / name));
    long row = 0, col = 0;
    double value = 0.0;
    if (!(last >> row >> col >> value) || row != n || col != n)
      return std::string(name) + " does not end with the diagonal entry of dof " +
             std::to_string(n) + " (job.dof's last), as a whole file does";
  }
  return "";
}

/// The cache entry for the model of `deck` followed by `step`: ccx run there
/// unless it already exists (and is whole: `incomplete`, when given, says
/// why an entry is not; such an entry, cut short after it was made, is run
/// again). Returns the entry folder. Messages name `cache_dir` after
/// `cache_name` (how the caller's user gave it).
fs::path cached_run(const CalculixDeck& deck, const std::string& step, const std::string& tag,
                    const std::vector<std::string>& outputs, const std::string& cache_dir,
                    std::string (*incomplete)(const fs::path&) = nullptr,
                    const std::string& cache_name = "the ccx cache") {
  const std::string text = deck.model_text + step;
  const fs::path entry = fs::path(cache_dir) / (fs::path(deck.path).stem().string() + "-" +
                                                hex(fnv1a(text)) + "-" + tag);
  if (fs::is_directory(entry)) {
    if (incomplete == nullptr || incomplete(entry).empty()) return entry;
    std::error_code ec;
    fs::remove_all(entry, ec);
  }
  const std::string ccx = find_ccx();
  std::error_code ec;
  fs::create_directories(cache_dir, ec);
  if (ec) throw ImportError("cannot create '" + cache_dir + "': " + ec.message(), kCacheFailed);
  fs::path work = entry;
  work += ".tmp" + std::to_string(getpid());
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec) throw ImportError("cannot create '" + work.string() + "': " + ec.message(), kCacheFailed);
  {
    std::ofstream out(work / "job.inp", std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      fs::remove_all(work, ec);
      throw ImportError("cannot write " + (work / "job.inp").string(), kCacheFailed);
    }
  }
  int status = 0;
  try {
    status = run_ccx(ccx, work);
  } catch (const Interrupted&) {
    // Stopped by a signal (forwarded to ccx): no model, no entry.
    fs::remove_all(work, ec);
    throw;
  }
  // ccx exits 0 after a failed write (a full disk) as after a whole run:
  // without an *ERROR line in its log, files cut short are the disk's doing.
  const bool ccx_error = error_lines(work / "ccx.log").rfind(" (no *ERROR line", 0) != 0;
  if (status == 0 && !ccx_error && incomplete != nullptr) {
    const std::string why = incomplete(work);
    if (!why.empty()) {
      // Not the model's fault, and no entry: the next run tries again.
      const fs::space_info space = fs::space(cache_dir, ec);
      fs::remove_all(work, ec);
      throw ImportError("ccx's output for " + deck.path + " is cut short (" + why +
                        ") though ccx reported success: a write failed, the disk holding " +
                        cache_name + " " + cache_dir + " may be full (" +
                        std::to_string(ec ? 0 : space.available / 1048576) +
                        " MB free now); nothing was cached: free space and run again");
    }
  }
  bool complete = status == 0;
  for (const std::string& name : outputs)
    complete = complete && fs::exists(work / name) && fs::file_size(work / name) > 0;
  if (!complete) {
    const std::string why = error_lines(work / "ccx.log");
    fs::path failed = entry;
    failed += ".failed";
    fs::remove_all(failed, ec);
    fs::rename(work, failed, ec);
    throw ImportError(deck.path + ": ccx failed on the model (exit status " +
                      std::to_string(status) + "; its files are in " + failed.string() + "):" +
                      why);
  }
  fs::rename(work, entry, ec);
  if (ec && !fs::is_directory(entry))
    throw ImportError("cannot rename " + work.string() + ": " + ec.message(), kCacheFailed);
  fs::remove_all(work, ec);
  return entry;
}

} // namespace

std::string find_ccx() {
  if (!executable_on_path("ccx"))
    throw ImportError("ccx (CalculiX) not found on PATH: install Debian's calculix-ccx "
                      "(./run-tests.sh does), or write the matrices yourself and name them "
                      "(calculix_matrices) or their Matrix Market folder as the source");
  return "ccx";
}

std::string calculix_matrices(const CalculixDeck& deck, const std::string& cache_dir,
                              const std::string& cache_name) {
  const std::string step = "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n";
  const fs::path entry = cached_run(deck, step, "matrices", {"job.sti", "job.mas", "job.dof"},
                                    cache_dir, incomplete_matrices, cache_name);
  return (entry / "job").string();
}

namespace {

/// The first `count` eigenvalues of the table in `dat`; ImportError when
/// ccx found fewer.
std::vector<double> first_eigenvalues(const fs::path& dat, int count) {
  std::vector<double> values = read_calculix_eigenvalues(dat.string());
  if (static_cast<int>(values.size()) < count)
    throw ImportError(dat.string() + ": ccx found " + std::to_string(values.size()) +
                      " eigenvalues, " + std::to_string(count) + " were asked");
  values.resize(count);
  return values;
}

/// The model-part set of every node (ids need not all be nodes: ccx takes
/// a GENERATE range as it is) and the nonlinear static step under the
/// centrifugal load, printing every node's displacement.
std::string prestress_steps(const CalculixDeck& deck, const CentrifugalLoad& load) {
  if (deck.section_elsets.empty())
    throw ImportError(deck.path + ": no *SOLID SECTION (or shell or beam section) names an "
                      "element set: nothing carries a centrifugal load");
  if (!std::isfinite(load.omega) || !load.point.allFinite() || !load.axis.allFinite() ||
      std::abs(load.axis.norm() - 1.0) > 1e-12)
    throw ImportError("calculix_prestressed: the speed, axis point and unit axis must be finite");
  char number[64];
  const auto g = [&number](double v) {
    std::snprintf(number, sizeof number, "%.17g", v);
    return std::string(number);
  };
  std::string text = "*NSET, NSET=RSI_ALL_NODES, GENERATE\n1, " +
                     std::to_string(std::max(deck.largest_node_id, 1)) +
                     "\n*STEP, NLGEOM\n*STATIC\n*DLOAD\n";
  for (const DeckKeyword& elset : deck.section_elsets)
    text += elset.name + ", CENTRIF, " + g(load.omega * load.omega) + ", " + g(load.point.x()) +
            ", " + g(load.point.y()) + ", " + g(load.point.z()) + ", " + g(load.axis.x()) + ", " +
            g(load.axis.y()) + ", " + g(load.axis.z()) + "\n";
  return text + "*NODE PRINT, NSET=RSI_ALL_NODES\nU\n*END STEP\n*STEP, PERTURBATION\n";
}

} // namespace

std::string calculix_prestressed_matrices(const CalculixDeck& deck, const CentrifugalLoad& load,
                                          const std::string& cache_dir,
                                          const std::string& cache_name) {
  const std::string step =
      prestress_steps(deck, load) + "*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n";
  const fs::path entry =
      cached_run(deck, step, "prestressed", {"job.sti", "job.mas", "job.dof", "job.dat"},
                 cache_dir, incomplete_matrices, cache_name);
  return (entry / "job").string();
}

std::vector<double> calculix_prestressed_eigenvalues(const CalculixDeck& deck,
                                                     const CentrifugalLoad& load, int count,
                                                     const std::string& cache_dir) {
  if (count < 1) throw ImportError("calculix_prestressed_eigenvalues: count must be >= 1");
  const std::string step =
      prestress_steps(deck, load) + "*FREQUENCY\n" + std::to_string(count) + "\n*END STEP\n";
  const fs::path entry = cached_run(deck, step, "prestressed-modes" + std::to_string(count),
                                    {"job.dat"}, cache_dir);
  return first_eigenvalues(entry / "job.dat", count);
}

std::map<int, Eigen::Vector3d> read_calculix_displacements(const std::string& dat_path) {
  std::ifstream in(dat_path);
  if (!in) throw ImportError(dat_path + ": cannot open");
  // ccx prints the table after every increment of the step: the last one is
  // the converged state at the step's end.
  std::vector<std::string> lines;
  size_t table = std::string::npos;
  for (std::string line; std::getline(in, line);) {
    if (line.find("displacements (vx,vy,vz)") != std::string::npos) table = lines.size();
    lines.push_back(line);
  }
  if (table == std::string::npos)
    throw ImportError(dat_path + ": no displacement table (*NODE PRINT, U)");
  std::map<int, Eigen::Vector3d> u;
  for (size_t k = table + 1; k < lines.size(); ++k) {
    std::istringstream fields(lines[k]);
    int node = 0;
    Eigen::Vector3d x;
    if (fields >> node >> x.x() >> x.y() >> x.z()) {
      if (!x.allFinite())
        throw ImportError(dat_path + ": displacement of node " + std::to_string(node) +
                          " is not finite (ccx's static step diverged)");
      u[node] = x;
    } else if (!u.empty() && lines[k].find_first_not_of(" \t\r") != std::string::npos) {
      break;
    }
  }
  if (u.empty()) throw ImportError(dat_path + ": the displacement table is empty");
  return u;
}

std::vector<double> calculix_eigenvalues(const CalculixDeck& deck, int count,
                                         const std::string& cache_dir) {
  if (count < 1) throw ImportError("calculix_eigenvalues: count must be >= 1");
  const std::string step = "*STEP, PERTURBATION\n*FREQUENCY\n" + std::to_string(count) +
                           "\n*NODE FILE\nU\n*END STEP\n";
  const fs::path entry = cached_run(deck, step, "modes" + std::to_string(count), {"job.dat"},
                                    cache_dir);
  return first_eigenvalues(entry / "job.dat", count);
}

std::vector<double> read_calculix_eigenvalues(const std::string& dat_path) {
  std::ifstream in(dat_path);
  if (!in) throw ImportError(dat_path + ": cannot open");
  std::string line;
  while (std::getline(in, line) && line.find("E I G E N V A L U E   O U T P U T") ==
                                       std::string::npos) {
  }
  std::vector<double> values;
  bool started = false;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    int mode = 0;
    double eigenvalue = 0.0;
    if (fields >> mode >> eigenvalue) {
      if (mode != static_cast<int>(values.size()) + 1)
        throw ImportError(dat_path + ": eigenvalue table out of order at mode " +
                          std::to_string(mode));
      values.push_back(eigenvalue);
      started = true;
    } else if (started) {
      const bool blank = line.find_first_not_of(" \t\r") == std::string::npos;
      if (!blank) break;
      if (!values.empty() && blank && started) break;
    }
  }
  if (values.empty()) throw ImportError(dat_path + ": no EIGENVALUE OUTPUT table");
  return values;
}

} // namespace rsi
