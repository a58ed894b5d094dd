// GLIBC_TUNABLES as rsi sets it before executing itself again
// (cli/support/huge_page_heap.hpp); the execution itself is checked by
// verification/cli/huge_page_heap.sh under strace.

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "huge_page_heap.hpp"

namespace rsi {
namespace {

TEST(HugePageHeap, AddedWhenUnsetOrEmpty) {
  EXPECT_EQ(tunables_with_huge_pages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages(""), "glibc.malloc.hugetlb=1");
}

TEST(HugePageHeap, AppendedToOtherTunables) {
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=4"),
            "glibc.malloc.arena_max=4:glibc.malloc.hugetlb=1");
  // A longer name that starts with the key is another tunable.
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlbx=0"),
            "glibc.malloc.hugetlbx=0:glibc.malloc.hugetlb=1");
}

TEST(HugePageHeap, TheUsersSettingIsKept) {
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=0"), std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=1"), std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=4:glibc.malloc.hugetlb=0"),
            std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=0:glibc.malloc.arena_max=4"),
            std::nullopt);
}

// The second start: the marker the first one set gives GLIBC_TUNABLES back
// as the user had it (set or unset) and goes; nothing is executed.
TEST(HugePageHeap, TheSecondStartRestoresTheUsersTunables) {
  char name[] = "rsi";
  char* argv[] = {name, nullptr};
  setenv("RSI_USER_GLIBC_TUNABLES", "=glibc.malloc.arena_max=4", 1);
  setenv("GLIBC_TUNABLES", "glibc.malloc.arena_max=4:glibc.malloc.hugetlb=1", 1);
  run_on_huge_page_heap(argv);
  ASSERT_NE(std::getenv("GLIBC_TUNABLES"), nullptr);
  EXPECT_EQ(std::string(std::getenv("GLIBC_TUNABLES")), "glibc.malloc.arena_max=4");
  EXPECT_EQ(std::getenv("RSI_USER_GLIBC_TUNABLES"), nullptr);
  setenv("RSI_USER_GLIBC_TUNABLES", "-", 1);
  setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1);
  run_on_huge_page_heap(argv);
  EXPECT_EQ(std::getenv("GLIBC_TUNABLES"), nullptr);
  EXPECT_EQ(std::getenv("RSI_USER_GLIBC_TUNABLES"), nullptr);
}

} // namespace
} // namespace rsi
