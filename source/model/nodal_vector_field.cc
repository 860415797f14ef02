// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/model/nodal_vector_field.h>
#include <fluid_surface/model/rigid_motion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <vector>

namespace FluidSurface
{
  using namespace dealii;

  NodalVectorField::NodalVectorField(const DoFHandler<2, 3> &dof_handler,
                                     const unsigned int      first_component,
                                     const Mapping<2, 3>    &mapping)
    : communicator(dof_handler.get_communicator())
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);
    const IndexSet                                                       owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, std::array<types::global_dof_index, 3>> nodes; // by the DoF of component 0
    const FiniteElement<2, 3>           &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          // The DoFs of one node share the index within the base element.
          std::map<unsigned int, std::array<types::global_dof_index, 3>> cell_nodes;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, index] = fe.system_to_component_index(i);
              if (component >= first_component && component < first_component + 3)
                cell_nodes[index][component - first_component] = dofs[i];
            }
          for (const auto &node : cell_nodes)
            if (owned.is_element(node.second[0]))
              nodes[node.second[0]] = node.second;
        }
    for (const auto &node : nodes)
      {
        triples.push_back(node.second);
        points.push_back(support_points.at(node.first));
      }
  }

  void
  NodalVectorField::rotated_difference(const VectorType     &a,
                                       const VectorType     &b,
                                       const double          factor,
                                       const Tensor<2, 3>   &Q,
                                       VectorType           &out) const
  {
    out = 0;
    for (const auto &dofs : triples)
      {
        Tensor<1, 3> d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = factor * (a[dofs[c]] - b[dofs[c]]);
        const Tensor<1, 3> r = Q * d;
        for (unsigned int c = 0; c < 3; ++c)
          out[dofs[c]] = r[c];
      }
    out.compress(VectorOperation::insert);
  }

  std::pair<Tensor<2, 3>, double>
  NodalVectorField::fit_rotation(const VectorType &from,
                                 const VectorType &to,
                                 const Point<3>   &centre,
                                 const VectorType &normal) const
  {
    const auto value = [&](const VectorType &v, const std::array<types::global_dof_index, 3> &dofs) {
      Tensor<1, 3> x;
      for (unsigned int c = 0; c < 3; ++c)
        x[c] = v[dofs[c]] - centre[c];
      return x;
    };
    // Kabsch: with H = Σ x₀ x₁ᵀ = U S Vᵀ, Q = V diag(1, 1, det(V Uᵀ)) Uᵀ maximizes Σ (Q x₀)·x₁.
    double H[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (const auto &dofs : triples)
      {
        const Tensor<1, 3> x0 = value(from, dofs), x1 = value(to, dofs);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            H[3 * i + j] += x0[i] * x1[j];
      }
    Utilities::MPI::sum(ArrayView<const double>(H, 9), communicator, ArrayView<double>(H, 9));
    LAPACKFullMatrix<double> svd(3, 3);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        svd(i, j) = H[3 * i + j];
    svd.compute_svd();
    const LAPACKFullMatrix<double> &U = svd.get_svd_u(), &Vt = svd.get_svd_vt();
    Tensor<2, 3>                    u, v;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          u[i][j] = U(i, j);
          v[i][j] = Vt(j, i);
        }
    Tensor<2, 3> d = unit_symmetric_tensor<3>();
    d[2][2]        = determinant(v * transpose(u)) < 0 ? -1 : 1;
    const Tensor<2, 3> Q = v * d * transpose(u);
    double             distance = 0;
    for (const auto &dofs : triples)
      {
        Tensor<1, 3> n;
        for (unsigned int c = 0; c < 3; ++c)
          n[c] = normal[dofs[c]];
        distance = std::max(distance, std::abs((value(from, dofs) - transpose(Q) * value(to, dofs)) * n));
      }
    return {Q, Utilities::MPI::max(distance, communicator)};
  }

  std::pair<double, double>
  NodalVectorField::fit_shape_rotation(const VectorType   &from,
                                       const VectorType   &to,
                                       const Point<3>     &centre,
                                       const VectorType   &normal,
                                       const Tensor<1, 3> &axis,
                                       const double        guess) const
  {
    // The normal distances at θ: their sum of squares and their largest value, over all ranks.
    const auto distances = [&](const double theta) {
      RigidMotion turn;
      turn.rotation           = -theta * axis;
      const Tensor<2, 3> back = turn.rotation_over(1.0);
      double             sum = 0, largest = 0;
      for (const auto &dofs : triples)
        {
          Tensor<1, 3> x, y, n;
          for (unsigned int c = 0; c < 3; ++c)
            {
              x[c] = from[dofs[c]] - centre[c];
              y[c] = to[dofs[c]] - centre[c];
              n[c] = normal[dofs[c]];
            }
          const double d = (x - back * y) * n;
          sum += d * d;
          largest = std::max(largest, std::abs(d));
        }
      return std::make_pair(Utilities::MPI::sum(sum, communicator), Utilities::MPI::max(largest, communicator));
    };
    // The turn is seen only through the normal part of the rotation field e × x: none on an axisymmetric surface,
    // whose turn is that of its nodes (@p guess).
    double sums[2] = {0, 0};
    for (const auto &dofs : triples)
      {
        Tensor<1, 3> x, n;
        for (unsigned int c = 0; c < 3; ++c)
          {
            x[c] = from[dofs[c]] - centre[c];
            n[c] = normal[dofs[c]];
          }
        const Tensor<1, 3> v = cross_product_3d(axis, x);
        sums[0] += (v * n) * (v * n);
        sums[1] += v * v;
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    double theta = guess;
    if (!(sums[0] > 1e-4 * sums[1]))
      return {theta, distances(theta).second};
    // A scan of ±0.5 rad about the nodes' turn (they may slide by that much behind the body), then parabolic steps
    // on shrinking brackets: the sum is smooth and nearly quadratic in θ near the turn.
    double best = distances(theta).first;
    for (int k = -50; k <= 50; ++k)
      {
        const double f = distances(guess + 0.01 * k).first;
        if (f < best)
          {
            best  = f;
            theta = guess + 0.01 * k;
          }
      }
    for (const double width : {0.005, 0.0005, 0.00005})
      {
        const double f0 = distances(theta - width).first, f1 = distances(theta).first,
                     f2 = distances(theta + width).first;
        const double curvature = f0 - 2 * f1 + f2;
        if (curvature > 0)
          theta += std::clamp(0.5 * width * (f0 - f2) / curvature, -width, width);
      }
    return {theta, distances(theta).second};
  }

  std::vector<std::array<double, 2>>
  NodalVectorField::azimuthal_content(const VectorType   &re,
                                      const VectorType   &im,
                                      const Tensor<1, 3> &axis,
                                      const Point<3>     &centre,
                                      const unsigned int  M) const
  {
    const std::array<Tensor<1, 3>, 2> frame = AzimuthalHarmonic::transverse_frame(axis);
    // sums[((k + M)·2 + parity)·3 + c] of a_c t_c e^{−ikφ}, real and imaginary parts interleaved.
    const unsigned int  n_wave = 2 * M + 1;
    std::vector<double> sums(2 * n_wave * 2 * 3, 0.0);
    double              n_nodes = 0;
    for (unsigned int n = 0; n < triples.size(); ++n)
      {
        const Tensor<1, 3> x   = points[n] - centre;
        const double       x1  = x * frame[0], x2 = x * frame[1], zeta = x * axis;
        const double       rho = std::hypot(x1, x2);
        if (rho < 1e-8 * x.norm())
          continue; // on the axis φ is undefined
        n_nodes += 1;
        const double       phi = std::atan2(x2, x1);
        const Tensor<1, 3> e_rho = (x1 * frame[0] + x2 * frame[1]) / rho;
        const Tensor<1, 3> e_phi = cross_product_3d(axis, e_rho);
        std::array<std::complex<double>, 3> a;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const std::complex<double> v(re[triples[n][c]], im[triples[n][c]]);
            a[0] += v * e_rho[c];
            a[1] += v * e_phi[c];
            a[2] += v * axis[c];
          }
        const double sign = zeta > 0 ? 1.0 : (zeta < 0 ? -1.0 : 0.0);
        for (unsigned int w = 0; w < n_wave; ++w)
          {
            const double               k = static_cast<double>(w) - M;
            const std::complex<double> phase(std::cos(k * phi), -std::sin(k * phi));
            for (unsigned int parity = 0; parity < 2; ++parity)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double               t = ((c == 2) == (parity == 0)) ? sign : 1.0;
                  const std::complex<double> term = a[c] * t * phase;
                  const unsigned int         i    = 2 * (((w * 2) + parity) * 3 + c);
                  sums[i] += term.real();
                  sums[i + 1] += term.imag();
                }
          }
      }
    Utilities::MPI::sum(sums, communicator, sums);
    n_nodes = Utilities::MPI::sum(n_nodes, communicator);
    std::vector<std::array<double, 2>> content(n_wave, {{0, 0}});
    for (unsigned int w = 0; w < n_wave; ++w)
      for (unsigned int parity = 0; parity < 2; ++parity)
        for (unsigned int c = 0; c < 3; ++c)
          {
            const unsigned int i = 2 * (((w * 2) + parity) * 3 + c);
            content[w][parity] += (sums[i] * sums[i] + sums[i + 1] * sums[i + 1]) / (n_nodes * n_nodes);
          }
    return content;
  }

  double
  NodalVectorField::normal_share(const VectorType &re, const VectorType &im, const VectorType &normal) const
  {
    double sums[2] = {0, 0};
    for (const auto &dofs : triples)
      {
        std::complex<double> normal_part;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const std::complex<double> z(re[dofs[c]], im[dofs[c]]);
            normal_part += z * normal[dofs[c]];
            sums[1] += std::norm(z);
          }
        sums[0] += std::norm(normal_part);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return sums[1] > 0 ? sums[0] / sums[1] : 0;
  }

  double
  NodalVectorField::symmetry_share(const VectorType   &re,
                                   const VectorType   &im,
                                   const VectorType   &normal,
                                   const Tensor<1, 3> &axis,
                                   const Point<3>     &centre) const
  {
    // sums: the Gram matrix G_kl = Σ s_k s_l (16), b_k = Σ s_k w (real and imaginary, 8), Σ|w|² (1).
    std::array<double, 25> sums{};
    for (unsigned int n = 0; n < triples.size(); ++n)
      {
        Tensor<1, 3>         nu;
        std::complex<double> w;
        for (unsigned int c = 0; c < 3; ++c)
          {
            nu[c] = normal[triples[n][c]];
            w += std::complex<double>(re[triples[n][c]], im[triples[n][c]]) * nu[c];
          }
        const std::array<double, 4> s = {{nu[0], nu[1], nu[2], cross_product_3d(axis, points[n] - centre) * nu}};
        for (unsigned int k = 0; k < 4; ++k)
          {
            for (unsigned int l = 0; l < 4; ++l)
              sums[4 * k + l] += s[k] * s[l];
            sums[16 + k] += s[k] * w.real();
            sums[20 + k] += s[k] * w.imag();
          }
        sums[24] += std::norm(w);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                        communicator,
                        ArrayView<double>(sums.data(), sums.size()));
    if (!(sums[24] > 0))
      return 0;
    // bᵀG⁺b by Gram–Schmidt in the inner product G: a generator with no normal part of its own drops out.
    const double                       floor = 1e-6 * std::max({sums[0], sums[5], sums[10], sums[15]});
    std::vector<std::array<double, 4>> basis;
    double                             projected = 0;
    for (unsigned int k = 0; k < 4; ++k)
      {
        std::array<double, 4> v{};
        v[k] = 1;
        for (const auto &q : basis)
          {
            double dot = 0;
            for (unsigned int l = 0; l < 4; ++l)
              dot += sums[4 * k + l] * q[l];
            for (unsigned int l = 0; l < 4; ++l)
              v[l] -= dot * q[l];
          }
        double norm2 = 0;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int l = 0; l < 4; ++l)
            norm2 += v[i] * sums[4 * i + l] * v[l];
        if (!(norm2 > floor))
          continue;
        for (double &c : v)
          c /= std::sqrt(norm2);
        double re_part = 0, im_part = 0;
        for (unsigned int l = 0; l < 4; ++l)
          {
            re_part += v[l] * sums[16 + l];
            im_part += v[l] * sums[20 + l];
          }
        projected += re_part * re_part + im_part * im_part;
        basis.push_back(v);
      }
    return projected / sums[24];
  }
} // namespace FluidSurface
