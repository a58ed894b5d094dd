#include "huge_page_heap.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>

#include <unistd.h>

namespace rsi {
namespace {

/// Set for the second start only: "=" and the user's GLIBC_TUNABLES, or
/// "-" when it was unset. Its presence also stops a second execution.
constexpr const char* user_tunables_variable = "RSI_USER_GLIBC_TUNABLES";

/// GLIBC_TUNABLES as the user had it (`was`: the marker's value).
void restore_user_tunables(const char* was) {
  if (was[0] == '=')
    setenv("GLIBC_TUNABLES", was + 1, 1);
  else
    unsetenv("GLIBC_TUNABLES");
  unsetenv(user_tunables_variable);
}

} // namespace

std::optional<std::string> tunables_with_huge_pages(const char* current) {
  const std::string setting = "glibc.malloc.hugetlb=";
  if (current == nullptr || *current == '\0') return setting + "1";
  // GLIBC_TUNABLES is name=value pairs separated by ':'.
  const std::string tunables(current);
  std::size_t start = 0;
  while (start <= tunables.size()) {
    const std::size_t end = std::min(tunables.find(':', start), tunables.size());
    if (tunables.compare(start, std::min(setting.size(), end - start), setting) == 0)
      return std::nullopt;
    start = end + 1;
  }
  return tunables + ":" + setting + "1";
}

void run_on_huge_page_heap(char** argv) {
  if (const char* was = std::getenv(user_tunables_variable)) {
    restore_user_tunables(was);
    return;
  }
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::optional<std::string> tunables = tunables_with_huge_pages(current);
  if (!tunables) return;
  // The program's own path, not /proc/self/exe: the kernel names the
  // process after the path it executes (ps, pgrep and pkill find "rsi").
  char exe[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (length <= 0) return;
  exe[length] = '\0';
  const std::string was = current != nullptr ? std::string("=") + current : std::string("-");
  if (setenv(user_tunables_variable, was.c_str(), 1) == 0 &&
      setenv("GLIBC_TUNABLES", tunables->c_str(), 1) == 0)
    execv(exe, argv);
  restore_user_tunables(was.c_str());
}

} // namespace rsi
