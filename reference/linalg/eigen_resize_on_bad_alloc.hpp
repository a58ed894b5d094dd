#pragma once
// Eigen's resize of a dynamic matrix, made safe when the allocation fails
// (issue 13, class 5: "under a memory limit the campaign's unwinding from
// bad_alloc sometimes frees twice").
//
// Eigen 3.4 (and its master branch in 2025) resizes dynamic storage as
//     free(m_data); m_data = allocate(size);   // may throw std::bad_alloc
// so a failed allocation leaves m_data pointing at the freed block, and the
// matrix's destructor, run while the std::bad_alloc unwinds, frees it a
// second time: glibc aborts ("double free or corruption"), AddressSanitizer
// reports attempting double-free. Found under a heap limit in Eigen's
// SparseLU (its memory expansion catches the std::bad_alloc and resizes
// the same vector again), reproduced by a plain MatrixXd::resize
// (verification/linalg/test_eigen_resize_on_bad_alloc).
//
// This header is included first in every C++ file of the build (CMake:
// -include), before any use of these types, and gives the resize of each
// dynamic storage rsi's code and its header-only libraries (Eigen's own
// solvers, Spectra) instantiate an explicit specialization that empties
// the storage (null data, zero size) before allocating: a failed resize
// leaves an empty matrix that is destroyed once. Same arithmetic
// otherwise; Eigen's fixed-size and MaxRows/MaxCols storages never
// allocate. Scalars: double, int (index vectors, Eigen's SparseLU),
// long (Eigen::Index), bool; layouts: column-major and row-major.

#include <Eigen/Core>

#define RSI_EIGEN_SAFE_RESIZE_ROWS_COLS(T, Options)                                                \
  template <>                                                                                      \
  inline void                                                                                      \
  Eigen::DenseStorage<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::Dynamic, Options>::resize(         \
      Eigen::Index size, Eigen::Index rows, Eigen::Index cols) {                                   \
    if (size != m_rows * m_cols) {                                                                 \
      internal::conditional_aligned_delete_auto<T, (Options & DontAlign) == 0>(m_data,             \
                                                                               m_rows * m_cols);   \
      m_data = 0;                                                                                  \
      m_rows = 0;                                                                                  \
      m_cols = 0;                                                                                  \
      if (size > 0)                                                                                \
        m_data = internal::conditional_aligned_new_auto<T, (Options & DontAlign) == 0>(size);      \
    }                                                                                              \
    m_rows = rows;                                                                                 \
    m_cols = cols;                                                                                 \
  }

// A column vector (fixed 1 column, dynamic rows).
#define RSI_EIGEN_SAFE_RESIZE_ROWS(T, Options)                                                     \
  template <>                                                                                      \
  inline void Eigen::DenseStorage<T, Eigen::Dynamic, Eigen::Dynamic, 1, Options>::resize(          \
      Eigen::Index size, Eigen::Index rows, Eigen::Index) {                                        \
    if (size != m_rows) {                                                                          \
      internal::conditional_aligned_delete_auto<T, (Options & DontAlign) == 0>(m_data, m_rows);    \
      m_data = 0;                                                                                  \
      m_rows = 0;                                                                                  \
      if (size > 0)                                                                                \
        m_data = internal::conditional_aligned_new_auto<T, (Options & DontAlign) == 0>(size);      \
    }                                                                                              \
    m_rows = rows;                                                                                 \
  }

// A row vector (fixed 1 row, dynamic columns).
#define RSI_EIGEN_SAFE_RESIZE_COLS(T, Options)                                                     \
  template <>                                                                                      \
  inline void Eigen::DenseStorage<T, Eigen::Dynamic, 1, Eigen::Dynamic, Options>::resize(          \
      Eigen::Index size, Eigen::Index, Eigen::Index cols) {                                        \
    if (size != m_cols) {                                                                          \
      internal::conditional_aligned_delete_auto<T, (Options & DontAlign) == 0>(m_data, m_cols);    \
      m_data = 0;                                                                                  \
      m_cols = 0;                                                                                  \
      if (size > 0)                                                                                \
        m_data = internal::conditional_aligned_new_auto<T, (Options & DontAlign) == 0>(size);      \
    }                                                                                              \
    m_cols = cols;                                                                                 \
  }

#define RSI_EIGEN_SAFE_RESIZE(T)                                                                   \
  RSI_EIGEN_SAFE_RESIZE_ROWS_COLS(T, Eigen::ColMajor)                                              \
  RSI_EIGEN_SAFE_RESIZE_ROWS_COLS(T, Eigen::RowMajor)                                              \
  RSI_EIGEN_SAFE_RESIZE_ROWS(T, Eigen::ColMajor)                                                   \
  RSI_EIGEN_SAFE_RESIZE_COLS(T, Eigen::RowMajor)

RSI_EIGEN_SAFE_RESIZE(double)
RSI_EIGEN_SAFE_RESIZE(int)
RSI_EIGEN_SAFE_RESIZE(long)
RSI_EIGEN_SAFE_RESIZE(bool)

#undef RSI_EIGEN_SAFE_RESIZE
#undef RSI_EIGEN_SAFE_RESIZE_COLS
#undef RSI_EIGEN_SAFE_RESIZE_ROWS
#undef RSI_EIGEN_SAFE_RESIZE_ROWS_COLS
