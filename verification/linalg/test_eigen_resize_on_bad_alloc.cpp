// Eigen's resize under a failed allocation (issue 13, class 5). Eigen 3.4
// frees a dynamic matrix's block before allocating the new one; when the
// allocation throws std::bad_alloc its pointer was left at the freed block,
// and the destructor freed it again (glibc: "double free or corruption";
// AddressSanitizer: attempting double-free). With
// reference/linalg/eigen_resize_on_bad_alloc.hpp (included first in every
// file of the build) the matrix is left empty and destroyed once.
//
// The failing allocation needs no memory limit: 2^30 x 2^30 doubles
// (8 EiB) passes Eigen's overflow check of rows x cols (< 2^63) and no
// malloc can give it. The sizes are read at run time (the compiler would
// otherwise warn about the constant size it sees).

#include <cstdio>
#include <new>

#include <Eigen/Core>
#include <gtest/gtest.h>

/// AddressSanitizer's allocator refuses such a size with a report and
/// stops the process unless told to return null, as malloc does.
extern "C" const char* __asan_default_options() {
  return "allocator_may_return_null=1";
}

namespace {

volatile int huge_exponent = 30;
volatile int huge_vector_exponent = 62;
const Eigen::Index huge = Eigen::Index(1) << huge_exponent;
const Eigen::Index huge_vector = Eigen::Index(1) << huge_vector_exponent;

/// Resizes `m` (holding a block) to an impossible size: std::bad_alloc, and
/// `m` is left empty, usable, and destroyed once at the end of the scope.
template <class Matrix> void check_failed_resize(Matrix m, Eigen::Index rows, Eigen::Index cols) {
  ASSERT_GT(m.size(), 0);
  EXPECT_THROW(m.resize(rows, cols), std::bad_alloc);
  std::printf("after the failed resize: %ld x %ld, data %p\n", static_cast<long>(m.rows()),
              static_cast<long>(m.cols()), static_cast<const void*>(m.data()));
  // Source: the storage's invariant, data null exactly when the size is 0.
  EXPECT_EQ(m.size(), 0);
  EXPECT_EQ(m.data(), nullptr);
  m.resize(3, m.cols() == 1 ? 1 : 3); // usable again
  m.setZero();
  EXPECT_EQ(m.sum(), 0);
}

TEST(EigenResizeOnBadAlloc, MatrixXd) {
  check_failed_resize(Eigen::MatrixXd::Ones(40, 40).eval(), huge, huge);
}

TEST(EigenResizeOnBadAlloc, RowMajorMatrixXd) {
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  check_failed_resize(RowMajor::Ones(40, 40).eval(), huge, huge);
}

TEST(EigenResizeOnBadAlloc, VectorXd) {
  // 2^62 doubles: 2^65 bytes, more than any address space.
  check_failed_resize(Eigen::VectorXd::Ones(1000).eval(), huge_vector, 1);
}

TEST(EigenResizeOnBadAlloc, RowVectorXd) {
  Eigen::RowVectorXd v = Eigen::RowVectorXd::Ones(1000);
  EXPECT_THROW(v.resize(huge_vector), std::bad_alloc);
  EXPECT_EQ(v.size(), 0);
  EXPECT_EQ(v.data(), nullptr);
}

TEST(EigenResizeOnBadAlloc, VectorXi) {
  Eigen::VectorXi v = Eigen::VectorXi::Ones(1000);
  EXPECT_THROW(v.resize(huge_vector), std::bad_alloc);
  EXPECT_EQ(v.size(), 0);
  EXPECT_EQ(v.data(), nullptr);
}

TEST(EigenResizeOnBadAlloc, AssignmentOfAnotherSize) {
  // operator= resizes the destination first: the same path.
  Eigen::MatrixXd m = Eigen::MatrixXd::Ones(40, 40);
  EXPECT_THROW(m = Eigen::MatrixXd::Zero(huge, huge), std::bad_alloc);
  EXPECT_EQ(m.size(), 0);
}

} // namespace
