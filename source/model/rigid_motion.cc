// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/rigid_motion.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FluidSurface
{
  using namespace dealii;

  Tensor<1, 3>
  RigidMotion::value(const Point<3> &x) const
  {
    return translation + cross_product_3d(rotation, x - centre);
  }

  Tensor<2, 3>
  RigidMotion::rotation_over(const double tau) const
  {
    const double angle = tau * rotation.norm();
    Tensor<2, 3> Q     = unit_symmetric_tensor<3>();
    if (angle == 0)
      return Q;
    const Tensor<1, 3> axis = rotation / rotation.norm();
    Tensor<2, 3>       cross; // [axis]×
    cross[0][1] = -axis[2];
    cross[0][2] = axis[1];
    cross[1][0] = axis[2];
    cross[1][2] = -axis[0];
    cross[2][0] = -axis[1];
    cross[2][1] = axis[0];
    Q += std::sin(angle) * cross + (1.0 - std::cos(angle)) * (cross * cross);
    return Q;
  }

  Point<3>
  RigidMotion::carry(const Point<3> &x, const double tau) const
  {
    // The flow of R = U + Ω × (x − x_c) over τ: x_c + Q(x − x_c) + ∫₀^τ Q(s) ds U, with
    // ∫₀^τ Q(s) ds = τ[I + (1 − cos θ)/θ [ê]× + (1 − sin θ/θ)[ê]×²], θ = τ|Ω| (series for small θ).
    const double omega = rotation.norm();
    if (omega == 0)
      return x + tau * translation;
    const Tensor<1, 3> axis  = rotation / omega;
    const double       theta = tau * omega;
    const double       c1 = theta < 1e-6 ? theta / 2 : (1.0 - std::cos(theta)) / theta;
    const double       c2 = theta < 1e-6 ? theta * theta / 6 : 1.0 - std::sin(theta) / theta;
    const Tensor<1, 3> turned  = cross_product_3d(axis, translation);
    const Tensor<1, 3> shifted = tau * (translation + c1 * turned + c2 * cross_product_3d(axis, turned));
    return centre + rotation_over(tau) * (x - centre) + shifted;
  }


  namespace
  {
    /**
     * The coefficients c of the rigid motion of the shape from the sums of RigidMotion::fit() (the right-hand sides
     * ∫(u·ν)(r_j·ν) at [6..11], the Gram matrix at [12..47]), with the Tikhonov term or the spectral cutoff ε|S| =
     * @p cutoff.
     */
    Vector<double>
    fitted_coefficients(const std::array<double, 48> &sums, const double cutoff, const bool spectral_cutoff)
    {
      // The rigid motion of the shape: R minimizing ∫(u·ν − R·ν)² + ε|S| |c|², c the coefficients of R in the
      // scaled basis. ε cuts off the motions that hardly move the shape: the rotation of a body about its own
      // axis of symmetry (R·ν ≡ 0) moves no surface, and its mesh need not move.
      Vector<double> rhs(6), coefficients(6);
      for (unsigned int j = 0; j < 6; ++j)
        rhs(j) = sums[6 + j];
      if (spectral_cutoff)
        {
          // A spectral cutoff of the Gram matrix G instead: the motions with ∫(R·ν)² ≥ 2ε|S| per unit coefficient
          // are fitted exactly (a rigid velocity is followed to round-off), those below ε|S| not at all (the spin
          // of an axisymmetric body), with a smooth step between.
          LAPACKFullMatrix<double> gram(6, 6);
          for (unsigned int j = 0; j < 6; ++j)
            for (unsigned int l = 0; l < 6; ++l)
              gram(j, l) = sums[12 + 6 * j + l];
          FullMatrix<double> eigenvectors(6, 6); // the columns
          Vector<double>     eigenvalues(6);
          gram.compute_eigenvalues_symmetric(-1.0, std::numeric_limits<double>::max(), 0.0, eigenvalues, eigenvectors);
          for (unsigned int k = 0; k < eigenvalues.size(); ++k)
            {
              const double ratio  = std::min(1.0, std::max(0.0, eigenvalues(k) / cutoff - 1.0));
              const double filter = ratio * ratio * (3.0 - 2.0 * ratio);
              if (filter == 0)
                continue;
              double projection = 0;
              for (unsigned int j = 0; j < 6; ++j)
                projection += eigenvectors(j, k) * rhs(j);
              for (unsigned int j = 0; j < 6; ++j)
                coefficients(j) += filter * projection / eigenvalues(k) * eigenvectors(j, k);
            }
        }
      else
        {
          FullMatrix<double> normal_matrix(6, 6), inverse(6, 6);
          for (unsigned int j = 0; j < 6; ++j)
            for (unsigned int l = 0; l < 6; ++l)
              normal_matrix(j, l) = sums[12 + 6 * j + l] + (j == l ? cutoff : 0.0);
          inverse.invert(normal_matrix);
          inverse.vmult(coefficients, rhs);
        }
      return coefficients;
    }
  } // namespace

  RigidMotion
  RigidMotion::tisserand(const SurfaceGeometry &geometry, const DoFHandler<2, 3> &dofs, const VectorType &state)
  {
    const FiniteElement<2, 3>       &fe = dofs.get_fe();
    const QGauss<2>                  q(fe.degree + 1);
    FEValues<2, 3>                   fe_values(geometry.mapping(), fe, q,
                                               update_values | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector velocity(DofLayout::velocity_component);
    std::vector<Tensor<1, 3>>        u(q.size());
    // [0..5] (r_k, u) about the origin; [6] |S|; [7..9] ∫x; [10..18] ∫x ⊗ x.
    std::array<double, 19> sums{};
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[velocity].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const double        dA = fe_values.JxW(k);
              const Point<3>     &x  = fe_values.quadrature_point(k);
              const Tensor<1, 3>  L  = cross_product_3d(x, u[k]);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  sums[d] += u[k][d] * dA;
                  sums[3 + d] += L[d] * dA;
                  sums[7 + d] += x[d] * dA;
                  for (unsigned int e = 0; e < 3; ++e)
                    sums[10 + 3 * d + e] += x[d] * x[e] * dA;
                }
              sums[6] += dA;
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), geometry.get_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    RigidMotion motion;
    std::copy(sums.begin(), sums.begin() + 6, motion.momenta.begin());
    const double area = sums[6];
    Tensor<1, 3> P, L, c;
    Tensor<2, 3> second_moment;
    for (unsigned int d = 0; d < 3; ++d)
      {
        P[d] = sums[d];
        L[d] = sums[3 + d];
        c[d] = sums[7 + d] / area;
        for (unsigned int e = 0; e < 3; ++e)
          second_moment[d][e] = sums[10 + 3 * d + e] - area * c[d] * c[e];
      }
    // I = tr(M) 1 − M with M = ∫(x − x_c) ⊗ (x − x_c); L about x_c is L − x_c × P.
    const Tensor<2, 3> inertia = trace(second_moment) * unit_symmetric_tensor<3>() - second_moment;
    motion.centre              = Point<3>(c);
    motion.translation         = P / area;
    motion.rotation            = invert(inertia) * (L - cross_product_3d(c, P));
    return motion;
  }

  RigidMotion
  RigidMotion::fit(const SurfaceGeometry    &geometry,
                   const DoFHandler<2, 3>   &dofs,
                   const VectorType         &state,
                   const Function<3>        *prescribed_velocity,
                   const double              rigid_motion_cutoff,
                   const bool                spectral_cutoff)
  {
    const FiniteElement<2, 3>       &fe = dofs.get_fe();
    const QGauss<2>                  q(fe.degree + 1);
    FEValues<2, 3>                   fe_values(geometry.mapping(), fe, q,
                                               update_values | update_quadrature_points | update_normal_vectors |
                                                 update_JxW_values);
    const FEValuesExtractors::Vector velocity(DofLayout::velocity_component);
    std::vector<Tensor<1, 3>>        u(q.size());
    const SurfaceGeometry::Measures  m = geometry.measure();
    RigidMotion                      motion;
    motion.centre = Point<3>(m.centre_of_mass);
    // The radius of gyration makes the rotations r_{3+d} = e_d × (x − x_c)/R_g commensurate with the translations.
    double gyration = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int k = 0; k < q.size(); ++k)
            gyration += (fe_values.quadrature_point(k) - motion.centre).norm_square() * fe_values.JxW(k);
        }
    gyration = std::sqrt(Utilities::MPI::sum(gyration, geometry.get_communicator()) / m.area);

    // [0..5] (r_k, u) about the origin; [6..11] ∫(u·ν)(r_k·ν); [12..47] ∫(r_j·ν)(r_k·ν), r about x_c.
    std::array<double, 48> sums{};
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (prescribed_velocity != nullptr)
            for (unsigned int k = 0; k < q.size(); ++k)
              for (unsigned int d = 0; d < 3; ++d)
                u[k][d] = prescribed_velocity->value(fe_values.quadrature_point(k), d);
          else
            fe_values[velocity].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const double        dA = fe_values.JxW(k);
              const Point<3>     &x  = fe_values.quadrature_point(k);
              const Tensor<1, 3> &nu = fe_values.normal_vector(k);
              const Tensor<1, 3>  L  = cross_product_3d(x, u[k]);
              // r_k·ν: ν_d for the translations, (e_d × r)·ν = (r × ν)_d for the rotations.
              const Tensor<1, 3> moment = cross_product_3d(x - motion.centre, nu) / gyration;
              double             rn[6];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  rn[d]     = nu[d];
                  rn[3 + d] = moment[d];
                  sums[d] += u[k][d] * dA;
                  sums[3 + d] += L[d] * dA;
                }
              for (unsigned int j = 0; j < 6; ++j)
                {
                  sums[6 + j] += (u[k] * nu) * rn[j] * dA;
                  for (unsigned int l = 0; l < 6; ++l)
                    sums[12 + 6 * j + l] += rn[j] * rn[l] * dA;
                }
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), geometry.get_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    std::copy(sums.begin(), sums.begin() + 6, motion.momenta.begin());

    const Vector<double> coefficients = fitted_coefficients(sums, rigid_motion_cutoff * m.area, spectral_cutoff);
    for (unsigned int d = 0; d < 3; ++d)
      {
        motion.translation[d] = coefficients(d);
        motion.rotation[d]    = coefficients(3 + d) / gyration;
      }
    return motion;
  }
} // namespace FluidSurface
