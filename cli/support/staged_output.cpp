#include "staged_output.hpp"

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <vector>

#include <fnmatch.h>
#include <unistd.h>

namespace rsi {
namespace {

namespace fs = std::filesystem;

const std::string staging_prefix = ".rsi-stage-";
const std::string old_prefix = ".rsi-old-";

std::vector<std::string> components(const std::string& entry) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t slash; (slash = entry.find('/', start)) != std::string::npos; start = slash + 1)
    parts.push_back(entry.substr(start, slash - start));
  parts.push_back(entry.substr(start));
  return parts;
}

bool present(const fs::path& p) {
  std::error_code error;
  return fs::exists(fs::symlink_status(p, error));
}

/// Appends to `found` the paths (relative to `root`) below `prefix` that
/// parts[i..] name.
void expand(const fs::path& root, const std::vector<std::string>& parts, size_t i,
            const fs::path& prefix, std::vector<fs::path>& found) {
  if (i == parts.size()) {
    found.push_back(prefix);
    return;
  }
  const bool last = i + 1 == parts.size();
  std::error_code error;
  if (parts[i].find_first_of("*?[") == std::string::npos) {
    const fs::path p = root / prefix / parts[i];
    if (present(p) && (last || fs::is_directory(p, error)))
      expand(root, parts, i + 1, prefix / parts[i], found);
    return;
  }
  std::vector<fs::path> names;
  for (const fs::directory_entry& d : fs::directory_iterator(root / prefix, error))
    names.push_back(d.path().filename());
  std::sort(names.begin(), names.end());
  for (const fs::path& name : names)
    // FNM_PERIOD: `*` never matches the hidden staging, old-set and lock files.
    if (::fnmatch(parts[i].c_str(), name.c_str(), FNM_PERIOD) == 0 &&
        (last || fs::is_directory(root / prefix / name, error)))
      expand(root, parts, i + 1, prefix / name, found);
}

/// The paths under `root` that each entry of `set` names, entry by entry.
std::vector<std::vector<fs::path>> matches(const fs::path& root, const OutputSet& set) {
  std::vector<std::vector<fs::path>> found(set.size());
  for (size_t i = 0; i < set.size(); ++i)
    expand(root, components(set[i]), 0, fs::path(), found[i]);
  return found;
}

/// Throws std::logic_error if a file under `staging` lies under none of
/// `named`: the command wrote outside its set, and publishing would drop it.
void check_covered(const fs::path& staging, const std::vector<std::vector<fs::path>>& named) {
  std::set<fs::path> covered;
  for (const std::vector<fs::path>& paths : named)
    covered.insert(paths.begin(), paths.end());
  std::error_code error;
  for (const fs::directory_entry& d : fs::recursive_directory_iterator(staging, error)) {
    if (d.is_directory(error)) continue;
    bool inside = false;
    for (fs::path p = d.path().lexically_relative(staging); !inside && !p.empty();
         p = p.parent_path())
      inside = covered.count(p) > 0;
    if (!inside)
      throw std::logic_error("StagedOutput::publish: " + d.path().string() +
                             " is in no entry of the command's output set (cli/output_sets.cpp)");
  }
}

/// Removes the empty folders under `root`, deepest first: a folder made for
/// a run that produced nothing (a refused mode count) is no output.
void remove_empty_folders(const fs::path& root) {
  std::vector<fs::path> folders;
  std::error_code error;
  for (const fs::directory_entry& d : fs::recursive_directory_iterator(root, error))
    if (d.is_directory(error) && !d.is_symlink(error)) folders.push_back(d.path());
  for (auto p = folders.rbegin(); p != folders.rend(); ++p)
    if (fs::is_empty(*p, error)) fs::remove(*p, error);
}

} // namespace

StagedOutput::AbandonOnThrow::AbandonOnThrow(StagedOutput& output)
    : m_output(output), m_exceptions(std::uncaught_exceptions()) {}

StagedOutput::AbandonOnThrow::~AbandonOnThrow() {
  if (std::uncaught_exceptions() > m_exceptions) m_output.abandon();
}

StagedOutput::~StagedOutput() {
  abandon();
}

std::string StagedOutput::open(const std::string& out, const std::string& option,
                               const OutputSet& set) {
  assert(m_staging.empty() && !m_lock && "StagedOutput::open twice");
  m_directories.make(out, option);
  m_lock.emplace(out, option);
  m_out = out;
  m_option = option;
  m_set = set;
  // Holding the lock, no other run is writing here: a staging or old-set
  // folder is what a killed run left.
  std::error_code error;
  for (const fs::directory_entry& d : fs::directory_iterator(out, error)) {
    const std::string name = d.path().filename().string();
    if (name.rfind(staging_prefix, 0) == 0 || name.rfind(old_prefix, 0) == 0)
      fs::remove_all(d.path(), error);
  }
  const std::string staging = out + "/" + staging_prefix + std::to_string(::getpid());
  if (!fs::create_directory(staging, error) || error)
    throw OutputError(option + " " + out + ": cannot create the staging folder " + staging + " (" +
                      error.message() + ")");
  m_staging = staging;
  return m_staging;
}

void StagedOutput::make(const std::string& path) {
  assert(!m_staging.empty() && "StagedOutput::make before open");
  std::error_code error;
  fs::create_directories(path, error);
  if (error || !fs::is_directory(path))
    throw OutputError(m_option + " " + m_out + ": cannot create the folder " + path + " (" +
                      (error ? error.message() : "not a directory") + ")");
}

void StagedOutput::publish() {
  if (m_staging.empty()) return;
  const fs::path out(m_out);
  const fs::path staging(m_staging);
  remove_empty_folders(staging);
  const std::vector<std::vector<fs::path>> fresh = matches(staging, m_set);
  const std::vector<std::vector<fs::path>> old = matches(out, m_set);
  check_covered(staging, fresh);
  const fs::path trash = out / (old_prefix + std::to_string(::getpid()));
  auto move = [&](const fs::path& from, const fs::path& to) {
    std::error_code error;
    fs::create_directories(to.parent_path(), error);
    if (!error) fs::rename(from, to, error);
    if (error)
      throw OutputError(m_option + " " + m_out + ": cannot replace " +
                        to.lexically_relative(out).string() + " (" + error.message() + ")");
  };
  std::set<fs::path> moved;
  // Old set out, descriptions first (reverse order)...
  for (size_t i = old.size(); i-- > 0;)
    for (const fs::path& p : old[i])
      if (moved.insert(p).second) move(out / p, trash / p);
  // ... new set in, data first.
  for (const std::vector<fs::path>& paths : fresh)
    for (const fs::path& p : paths)
      move(staging / p, out / p);
  std::error_code error;
  fs::remove_all(trash, error);
  fs::remove_all(staging, error);
  m_staging.clear();
  // A folder that held only old entries (export's component folders) goes too.
  for (const fs::path& p : moved)
    for (fs::path parent = p.parent_path(); !parent.empty(); parent = parent.parent_path())
      if (fs::is_empty(out / parent, error)) fs::remove(out / parent, error);
  m_lock.reset();
  m_directories.remove_empty();
  for (const std::string& line : m_announced)
    std::fputs(line.c_str(), stdout);
  m_announced.clear();
  std::fflush(stdout);
}

void StagedOutput::announce(const std::string& line) {
  if (m_staging.empty()) {
    std::fputs(line.c_str(), stdout);
    return;
  }
  m_announced.push_back(line);
}

void StagedOutput::abandon() noexcept {
  // Runs in the destructor, also while an exception unwinds (out of
  // memory included): it must not throw. remove_all and the checks of
  // remove_empty build paths, which allocate; by now the command's own
  // memory is released, but if an allocation still fails, what is left is
  // hidden (.rsi-stage-PID, removed by the next run on --out) and the lock
  // is released all the same.
  if (!m_staging.empty()) {
    try {
      std::error_code error;
      fs::remove_all(m_staging, error);
      m_abandoned = m_staging;
    } catch (...) {
    }
    m_staging.clear();
  }
  m_announced.clear();
  m_lock.reset();
  m_directories.remove_empty();
}

std::string StagedOutput::shown(const std::string& message) const {
  const std::string& staging = m_staging.empty() ? m_abandoned : m_staging;
  if (staging.empty()) return message;
  std::string text = message;
  for (size_t at = 0; (at = text.find(staging, at)) != std::string::npos; at += m_out.size())
    text.replace(at, staging.size(), m_out);
  return text;
}

} // namespace rsi
