// SPDX-License-Identifier: LGPL-2.1-or-later
// The program's xGEMM (source/linear_algebra/single_column_products.cc) is the one the process uses: sgemm_ and
// dgemm_ resolve to the program's library, not to the BLAS library, so MUMPS' solves take it. Its products equal a
// plain triple loop for every combination of transposes, for one column (sent to xGEMV), two columns (the BLAS
// library's xGEMM) and no inner dimension (C = βC), with strides larger than the matrices.
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

extern "C"
{
  void
  sgemm_(const char *, const char *, const int *, const int *, const int *, const float *, const float *,
         const int *, const float *, const int *, const float *, float *, const int *);
  void
  dgemm_(const char *, const char *, const int *, const int *, const int *, const double *, const double *,
         const int *, const double *, const int *, const double *, double *, const int *);
}

namespace
{
  /// The shared object that defines @p name in the process' lookup order.
  std::string
  defining_object(const char *name)
  {
    Dl_info info;
    void   *symbol = dlsym(RTLD_DEFAULT, name);
    if (symbol == nullptr || dladdr(symbol, &info) == 0 || info.dli_fname == nullptr)
      return "none";
    const std::string file = info.dli_fname;
    return file.find("libfluid_surface_library") != std::string::npos ? "the program's library" : "another object";
  }

  void
  gemm(const char *ta, const char *tb, const int *m, const int *n, const int *k, const float *alpha,
       const float *a, const int *lda, const float *b, const int *ldb, const float *beta, float *c, const int *ldc)
  {
    sgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  void
  gemm(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
       const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
       const int *ldc)
  {
    dgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  /// The largest difference, relative to the largest entry, between xGEMM and a triple loop in double precision.
  template <typename Number>
  double
  largest_error(const char transa, const char transb, const int m, const int n, const int k)
  {
    const bool ta = transa == 'T', tb = transb == 'T';
    // Column-major storage with leading dimensions two more than the rows stored.
    const int           a_rows = ta ? k : m, a_cols = ta ? m : k, b_rows = tb ? n : k, b_cols = tb ? k : n;
    const int           lda = a_rows + 2, ldb = b_rows + 2, ldc = m + 2;
    std::vector<Number> a(lda * a_cols), b(ldb * std::max(b_cols, 1)), c(ldc * n);
    for (std::size_t i = 0; i < a.size(); ++i)
      a[i] = static_cast<Number>(std::sin(1.0 + 0.7 * i));
    for (std::size_t i = 0; i < b.size(); ++i)
      b[i] = static_cast<Number>(std::cos(0.3 + 1.1 * i));
    for (std::size_t i = 0; i < c.size(); ++i)
      c[i] = static_cast<Number>(0.5 - 0.01 * i);
    const std::vector<Number> c0 = c;
    const Number              alpha = 1.5, beta = -0.25;
    gemm(&transa, &transb, &m, &n, &k, &alpha, a.data(), &lda, b.data(), &ldb, &beta, c.data(), &ldc);
    double error = 0, size = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < m; ++i)
        {
          double sum = 0;
          for (int l = 0; l < k; ++l)
            sum += double(ta ? a[l + i * lda] : a[i + l * lda]) * double(tb ? b[j + l * ldb] : b[l + j * ldb]);
          const double expected = alpha * sum + beta * double(c0[i + j * ldc]);
          error                 = std::max(error, std::abs(expected - double(c[i + j * ldc])));
          size                  = std::max(size, std::abs(expected));
        }
    // Entries of C outside its m rows are not touched.
    for (int j = 0; j < n; ++j)
      for (int i = m; i < ldc; ++i)
        error = std::max(error, std::abs(double(c[i + j * ldc] - c0[i + j * ldc])));
    return error / std::max(size, 1e-300);
  }
} // namespace

int
main()
{
  std::cout << "sgemm_ is defined by " << defining_object("sgemm_") << '\n';
  std::cout << "dgemm_ is defined by " << defining_object("dgemm_") << '\n';
  for (const char transa : {'N', 'T'})
    for (const char transb : {'N', 'T'})
      for (const int n : {1, 2})
        for (const int k : {7, 0})
          {
            const bool single = largest_error<float>(transa, transb, 5, n, k) < 1e-6;
            const bool dbl    = largest_error<double>(transa, transb, 5, n, k) < 1e-14;
            std::cout << "op(A) " << transa << ", op(B) " << transb << ", m = 5, n = " << n << ", k = " << k
                      << ": single precision " << (single ? "exact" : "WRONG") << ", double precision "
                      << (dbl ? "exact" : "WRONG") << '\n';
          }
}
