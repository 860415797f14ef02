// SPDX-License-Identifier: LGPL-2.1-or-later
// Scene stability: the Krylov side of Arnoldi, the Ritz values of the Hessenberg matrix with their classes and the
// thick (Krylov–Schur) restart (doc/stability.md, "Arnoldi").
#include <deal.II/lac/lapack_full_matrix.h>

#include <fluid_surface/scenes/stability_scene.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// A solution y of (H − μI) y ≈ 0 of unit norm: inverse iteration with the shift μ moved off the spectrum.
    std::vector<std::complex<double>>
    null_vector(const FullMatrix<double> &H, const unsigned int n, const std::complex<double> mu)
    {
      const std::complex<double>        shift = mu + std::max(1.0, std::abs(mu)) * 1e-10;
      std::vector<std::complex<double>> y(n, 1.0);
      for (unsigned int iteration = 0; iteration < 3; ++iteration)
        {
          // Gaussian elimination with partial pivoting of (H − shift I) y_new = y.
          std::vector<std::vector<std::complex<double>>> a(n, std::vector<std::complex<double>>(n + 1));
          for (unsigned int i = 0; i < n; ++i)
            {
              for (unsigned int j = 0; j < n; ++j)
                a[i][j] = H(i, j) - (i == j ? shift : 0.0);
              a[i][n] = y[i];
            }
          for (unsigned int c = 0; c < n; ++c)
            {
              unsigned int pivot = c;
              for (unsigned int r = c + 1; r < n; ++r)
                if (std::abs(a[r][c]) > std::abs(a[pivot][c]))
                  pivot = r;
              std::swap(a[c], a[pivot]);
              if (a[c][c] == 0.0)
                a[c][c] = 1e-300;
              for (unsigned int r = c + 1; r < n; ++r)
                {
                  const std::complex<double> f = a[r][c] / a[c][c];
                  for (unsigned int j = c; j <= n; ++j)
                    a[r][j] -= f * a[c][j];
                }
            }
          for (unsigned int i = n; i-- > 0;)
            {
              std::complex<double> s = a[i][n];
              for (unsigned int j = i + 1; j < n; ++j)
                s -= a[i][j] * y[j];
              y[i] = s / a[i][i];
            }
          double norm = 0;
          for (const auto &v : y)
            norm += std::norm(v);
          for (auto &v : y)
            v /= std::sqrt(norm);
        }
      return y;
    }
  } // namespace

  std::vector<StabilityScene::Mode>
  StabilityScene::ritz_modes(const FullMatrix<double>        &H,
                             const unsigned int               j,
                             const std::vector<Perturbation> &basis) const
  {
    LAPACKFullMatrix<double> block(j, j);
    for (unsigned int r = 0; r < j; ++r)
      for (unsigned int c = 0; c < j; ++c)
        block(r, c) = H(r, c);
    block.compute_eigenvalues();
    std::vector<Mode> modes;
    for (unsigned int i = 0; i < j; ++i)
      {
        const std::complex<double> mu = block.eigenvalue(i);
        if (mu.imag() < 0)
          continue;
        const std::vector<std::complex<double>> y = null_vector(H, j, mu);
        Mode                                    mode;
        mode.multiplier = mu;
        mode.residual   = std::abs(H(j, j - 1) * y[j - 1]) / std::max(std::abs(mu), 1e-300);
        mode.m          = 0;
        mode.odd        = false;
        mode.purity     = 0;
        mode.normal_share = 0;
        mode.symmetry_share = 0;
        mode.frequency  = std::arg(mu) / map_time;
          {
            Perturbation re = zero(), im = zero();
            for (unsigned int k = 0; k < j; ++k)
              {
                re.add(y[k].real(), basis[k]);
                im.add(y[k].imag(), basis[k]);
              }
            const unsigned int M       = 2 * *std::max_element(wavenumbers.begin(), wavenumbers.end()) + 4;
            auto               content = positions->azimuthal_content(re.position, im.position, axis, centre, M);
            const auto         flow    = velocities->azimuthal_content(re.velocity, im.velocity, axis, centre, M);
            double             total = 0, best = -1;
            int                best_k = 0;
            for (unsigned int w = 0; w < content.size(); ++w)
              for (unsigned int p = 0; p < 2; ++p)
                {
                  content[w][p] += flow[w][p];
                  total += content[w][p];
                  if (content[w][p] > best)
                    {
                      best     = content[w][p];
                      best_k   = static_cast<int>(w) - static_cast<int>(M);
                      mode.odd = p == 1;
                    }
                }
            mode.normal_share = positions->normal_share(re.position, im.position, base_normal);
            mode.symmetry_share = positions->symmetry_share(re.position, im.position, base_normal, axis, centre);
            mode.m            = std::abs(best_k);
            mode.purity = total > 0 ? best / total : 0;
            // z ∝ e^{imφ} with μ = e^{(σ + iΩ)T}: the real mode ∝ cos(mφ + Ωt), arg Q_m turns at −Ω in the frame
            // of the nodes, which turns at θ/T; the body turns at ω. Co-rotating: minus m(ω − θ/T), modulo 2π/T.
            if (best_k > 0)
              mode.frequency = -mode.frequency;
            const double period = 2 * numbers::PI / map_time;
            double       f      = mode.frequency - mode.m * (body_rotation_rate - node_rotation_rate);
            f -= period * std::round(f / period);
            mode.frequency = f;
          }
        modes.push_back(mode);
      }
    std::sort(modes.begin(), modes.end(), [](const Mode &a, const Mode &b) {
      return std::abs(a.multiplier) > std::abs(b.multiplier);
    });
    return modes;
  }

  unsigned int
  StabilityScene::restart(FullMatrix<double>        &H,
                          const unsigned int         j,
                          std::vector<Perturbation> &basis,
                          const std::vector<Mode>   &kept,
                          const Perturbation        &next) const
  {
    // Y: the real and imaginary parts of the leading Ritz vectors y (H_j y = μy), orthonormalized.
    std::vector<Vector<double>> Y;
    const auto                  add = [&](Vector<double> y) {
      for (unsigned int pass = 0; pass < 2; ++pass)
        for (const Vector<double> &q : Y)
          y.add(-(q * y), q);
      if (y.l2_norm() > 1e-8)
        {
          y /= y.l2_norm();
          Y.push_back(y);
        }
    };
    for (const Mode &mode : kept)
      {
        const bool complex = mode.multiplier.imag() > 1e-12 * std::abs(mode.multiplier);
        if (Y.size() + (complex ? 2 : 1) > j / 2)
          break;
        const std::vector<std::complex<double>> y = null_vector(H, j, mode.multiplier);
        Vector<double>                          re(j), im(j);
        for (unsigned int k = 0; k < j; ++k)
          {
            re[k] = y[k].real();
            im[k] = y[k].imag();
          }
        add(re);
        if (complex)
          add(im);
      }
    const unsigned int p = Y.size();
    FullMatrix<double> restarted(H.m(), H.n());
    for (unsigned int a = 0; a < p; ++a)
      {
        for (unsigned int b = 0; b < p; ++b)
          for (unsigned int r = 0; r < j; ++r)
            for (unsigned int c = 0; c < j; ++c)
              restarted(a, b) += Y[a][r] * H(r, c) * Y[b][c];
        restarted(p, a) = H(j, j - 1) * Y[a][j - 1];
      }
    H = restarted;
    std::vector<Perturbation> kept_basis(p, zero());
    for (unsigned int a = 0; a < p; ++a)
      for (unsigned int k = 0; k < j; ++k)
        kept_basis[a].add(Y[a][k], basis[k]);
    kept_basis.push_back(next);
    basis = std::move(kept_basis);
    return p;
  }
} // namespace FluidSurface
