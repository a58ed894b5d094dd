#pragma once
// The heap on transparent huge pages. A basis of the default 3D disk holds
// dense n x r blocks (107,976 x 1,076 doubles: 930 MB each) and makes
// several temporaries of that size. glibc's malloc maps each anew, and the
// kernel faults every 4 KiB page of it in at its first touch: on this
// machine (a virtual machine, transparent huge pages "madvise") perf put
// 18 % of a CB-20 basis' samples in exc_page_fault and 30 % in the kernel,
// and the basis took 64-75 s. With glibc's tunable glibc.malloc.hugetlb=1
// malloc asks for huge pages (madvise MADV_HUGEPAGE, 2 MiB) and the same
// basis takes 31-34 s, the run's history.csv cmp-identical (the same
// arithmetic on the same values; bench/RESULTS.md, session 40). glibc reads
// its tunables only when a program starts, so rsi sets the tunable and
// executes itself again, once, before anything else.

#include <optional>
#include <string>

namespace rsi {

/// GLIBC_TUNABLES with glibc.malloc.hugetlb=1 added to `current` (the
/// variable's value, or nullptr when unset); nullopt when `current` already
/// sets glibc.malloc.hugetlb (the user's choice, 0 included: the way to
/// turn this off).
std::optional<std::string> tunables_with_huge_pages(const char* current);

/// Executes the running program again (its path read from /proc/self/exe)
/// with argv and GLIBC_TUNABLES set by tunables_with_huge_pages, unless that
/// gives nullopt. The second start finds RSI_USER_GLIBC_TUNABLES, which the
/// first one set, puts GLIBC_TUNABLES back as the user had it (so that
/// ccx, gmsh and the report scripts run on their default heap), removes
/// the marker and returns: one execution at most. Returns too when it does
/// not execute (nothing to add, or execv failed: the environment as it was,
/// and the program goes on with glibc's default heap).
void run_on_huge_page_heap(char** argv);

} // namespace rsi
