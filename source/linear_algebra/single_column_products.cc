// SPDX-License-Identifier: LGPL-2.1-or-later
//
// The BLAS matrix products xGEMM of the process, with a single-column product sent to xGEMV.
//
// MUMPS' solve phase multiplies the blocks of its factors by the right-hand sides through xGEMM, also when there is
// one right-hand side (n = 1): the preconditioner of every GMRES iteration of scene full is such a solve. Debian 12's
// OpenBLAS (0.3.21) packs both operands of every xGEMM call into its blocked layout, and with n = 1 packing the factor
// block costs as much memory traffic as the product itself; xGEMV reads the block once. Measured on prm/prolate.prm
// (benchmarks/scaling, "Single-column products"): 394 248 of the 662 151 sgemm calls of the first time unit at
// refinement 3 have n = 1.
//
// The definitions below are found before the BLAS library's by every library of the process (the program's library
// is the first dependency of the executable and of the tests), and pass every product with n ≠ 1 to the BLAS
// library's own xGEMM. The result is the same product; its rounding may differ in the last bit.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace
{
  template <typename Number>
  using GemmFunction = void (*)(const char *, const char *, const int *, const int *, const int *, const Number *,
                                const Number *, const int *, const Number *, const int *, const Number *, Number *,
                                const int *);

  /// The next definition of @p name after this library's in the process' lookup order: the BLAS library's.
  template <typename Number>
  GemmFunction<Number>
  blas_gemm(const char *name)
  {
    void *symbol = dlsym(RTLD_NEXT, name);
    if (symbol == nullptr)
      {
        std::fprintf(stderr, "fluid_surface: the BLAS library's %s was not found (%s)\n", name, dlerror());
        std::abort();
      }
    return reinterpret_cast<GemmFunction<Number>>(symbol);
  }

  bool
  is_transposed(const char *operation)
  {
    return *operation != 'N' && *operation != 'n';
  }
} // namespace

extern "C"
{
  void
  sgemv_(const char *, const int *, const int *, const float *, const float *, const int *, const float *,
         const int *, const float *, float *, const int *);
  void
  dgemv_(const char *, const int *, const int *, const double *, const double *, const int *, const double *,
         const int *, const double *, double *, const int *);
}

namespace
{
  /// C = α op(A) op(B) + β C; for n = 1 as y = α op(A) x + β y with x the column (or row) op(B).
  template <typename Number, typename Gemv>
  void
  gemm(const GemmFunction<Number> blas,
       const Gemv                 gemv,
       const char                *transa,
       const char                *transb,
       const int                 *m,
       const int                 *n,
       const int                 *k,
       const Number              *alpha,
       const Number              *a,
       const int                 *lda,
       const Number              *b,
       const int                 *ldb,
       const Number              *beta,
       Number                    *c,
       const int                 *ldc)
  {
    // k = 0 must still scale C by β, which xGEMV skips when it has no columns.
    if (*n != 1 || *k <= 0 || *m <= 0)
      {
        blas(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
        return;
      }
    const int one      = 1;
    const int x_stride = is_transposed(transb) ? *ldb : 1;
    if (is_transposed(transa))
      gemv("T", k, m, alpha, a, lda, b, &x_stride, beta, c, &one);
    else
      gemv("N", m, k, alpha, a, lda, b, &x_stride, beta, c, &one);
  }
} // namespace

extern "C"
{
  void
  sgemm_(const char  *transa,
         const char  *transb,
         const int   *m,
         const int   *n,
         const int   *k,
         const float *alpha,
         const float *a,
         const int   *lda,
         const float *b,
         const int   *ldb,
         const float *beta,
         float       *c,
         const int   *ldc)
  {
    static const GemmFunction<float> blas = blas_gemm<float>("sgemm_");
    gemm(blas, sgemv_, transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  void
  dgemm_(const char   *transa,
         const char   *transb,
         const int    *m,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *b,
         const int    *ldb,
         const double *beta,
         double       *c,
         const int    *ldc)
  {
    static const GemmFunction<double> blas = blas_gemm<double>("dgemm_");
    gemm(blas, dgemv_, transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }
}
