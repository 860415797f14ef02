// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/geometry/surface_operators.h>

#include <array>

namespace FluidSurface
{
  using namespace dealii;
  namespace SO = SurfaceOperators;

  double
  SurfaceFlow::kinetic_energy() const
  {
    return EnergyFunctionals::kinetic_energy(geometry.mapping(), flow_dofs, current, geometry.quadrature(), communicator);
  }

  double
  SurfaceFlow::dissipation_rate() const
  {
    return EnergyFunctionals::dissipation_rate(
      geometry.mapping(), flow_dofs, current, geometry.quadrature(), parameters.fluid.Re, communicator);
  }

  namespace
  {
    /**
     * What the error norms leave out, the kernel of the stationary operator: the means p̄ and p̄_h of the
     * pressures, and the coefficients c_a of the L2 projections Σ_a c_a (a × x) of u and u_h onto the Killing
     * fields.
     */
    struct KernelComponents
    {
      double         mean_p   = 0; ///< p̄
      double         mean_p_h = 0; ///< p̄_h
      Vector<double> exact;        ///< c_a of u
      Vector<double> discrete;     ///< c_a of u_h
    };

    /// The KernelComponents of @p exact at @p time and of the solution @p solution, by quadrature with @p fv.
    KernelComponents
    kernel_components(FEValues<2, 3>                  &fv,
                      const DoFHandler<2, 3>          &dofs,
                      const VectorType                &solution,
                      const std::vector<Tensor<1, 3>> &killing,
                      const FlowField                 &exact,
                      const double                     time,
                      const MPI_Comm                   communicator)
    {
      const unsigned int        n_q = fv.n_quadrature_points;
      const unsigned int        n_k = killing.size();
      std::vector<Tensor<1, 3>> u(n_q);
      std::vector<double>       p(n_q);
      FullMatrix<double>        gram(n_k, n_k);
      std::vector<double>       sums(3 + 2 * n_k, 0.0); // area, ∫p, ∫p_h, (u, K_a), (u_h, K_a)
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            fv[FEValuesExtractors::Vector(0)].get_function_values(solution, u);
            fv[FEValuesExtractors::Scalar(3)].get_function_values(solution, p);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const Point<3> &x  = fv.quadrature_point(q);
                const double    dA = fv.JxW(q);
                sums[0] += dA;
                sums[1] += (exact.pressure ? exact.pressure(x, time) : 0.0) * dA;
                sums[2] += p[q] * dA;
                const Tensor<1, 3> u_exact = exact.velocity(x, time);
                for (unsigned int a = 0; a < n_k; ++a)
                  {
                    const Tensor<1, 3> K_a = cross_product_3d(killing[a], x);
                    sums[3 + a] += u_exact * K_a * dA;
                    sums[3 + n_k + a] += u[q] * K_a * dA;
                    for (unsigned int b = 0; b < n_k; ++b)
                      gram(a, b) += K_a * cross_product_3d(killing[b], x) * dA;
                  }
              }
          }
      Utilities::MPI::sum(sums, communicator, sums);
      for (unsigned int a = 0; a < n_k; ++a)
        for (unsigned int b = 0; b < n_k; ++b)
          gram(a, b) = Utilities::MPI::sum(gram(a, b), communicator);
      KernelComponents components;
      components.exact.reinit(n_k);
      components.discrete.reinit(n_k);
      if (n_k > 0)
        {
          Vector<double> r_exact(n_k), r_discrete(n_k);
          for (unsigned int a = 0; a < n_k; ++a)
            {
              r_exact(a)    = sums[3 + a];
              r_discrete(a) = sums[3 + n_k + a];
            }
          gram.gauss_jordan();
          gram.vmult(components.exact, r_exact);
          gram.vmult(components.discrete, r_discrete);
        }
      components.mean_p   = sums[1] / sums[0];
      components.mean_p_h = sums[2] / sums[0];
      return components;
    }

    /// [a]×, the Jacobian of the Killing field a × x.
    Tensor<2, 3>
    rotation_gradient(const Tensor<1, 3> &a)
    {
      Tensor<2, 3> rotation;
      rotation[0][1] = -a[2];
      rotation[0][2] = a[1];
      rotation[1][0] = a[2];
      rotation[1][2] = -a[0];
      rotation[2][0] = -a[1];
      rotation[2][1] = a[0];
      return rotation;
    }
  } // namespace

  SurfaceFlow::Errors
  SurfaceFlow::compute_errors(const FlowField &exact, const double time) const
  {
    const QGauss<2>           quadrature(geometry.degree() + 3);
    FEValues<2, 3>            fv(geometry.mapping(),
                      fe,
                      quadrature,
                      update_values | update_gradients | update_normal_vectors | update_JxW_values |
                        update_quadrature_points);
    const unsigned int        n_q = quadrature.size();
    std::vector<Tensor<1, 3>> u(n_q);
    std::vector<Tensor<2, 3>> G(n_q);
    std::vector<double>       p(n_q);
    const KernelComponents    kernel = kernel_components(fv, flow_dofs, current, killing, exact, time, communicator);

    std::array<double, 5> squares = {{0, 0, 0, 0, 0}};
    for (const auto &cell : flow_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv[FEValuesExtractors::Vector(0)].get_function_values(current, u);
          fv[FEValuesExtractors::Vector(0)].get_function_gradients(current, G);
          fv[FEValuesExtractors::Scalar(3)].get_function_values(current, p);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<3>     &x    = fv.quadrature_point(q);
              const double        dA   = fv.JxW(q);
              const Tensor<1, 3> &nu_h = fv.normal_vector(q);
              const Tensor<1, 3>  n    = exact_normal ? exact_normal(x) : nu_h;
              const Tensor<2, 3>  P    = SO::projection(n);
              const Tensor<2, 3>  P_h  = SO::projection(nu_h);
              Tensor<1, 3>        u_exact = exact.velocity(x, time);
              Tensor<2, 3>        J_exact = exact.velocity_gradient(x, time);
              Tensor<1, 3>        u_h     = u[q];
              Tensor<2, 3>        G_h     = G[q];
              for (unsigned int a = 0; a < killing.size(); ++a)
                {
                  const Tensor<2, 3> rotation = rotation_gradient(killing[a]);
                  const Tensor<1, 3> K_a      = cross_product_3d(killing[a], x);
                  u_exact -= kernel.exact(a) * K_a;
                  J_exact -= kernel.exact(a) * rotation;
                  u_h -= kernel.discrete(a) * K_a;
                  G_h -= kernel.discrete(a) * rotation * P_h;
                }
              const Tensor<1, 3> e = u_exact - u_h;
              squares[0] += e.norm_square() * dA;
              squares[1] += (P * e).norm_square() * dA;
              squares[2] += (P * J_exact * P - SO::projected_gradient(G_h, nu_h)).norm_square() * dA;
              const double p_exact = exact.pressure ? exact.pressure(x, time) - kernel.mean_p : 0.0;
              squares[3] += std::pow(p_exact - (p[q] - kernel.mean_p_h), 2) * dA;
              squares[4] += std::pow(SO::normal_component(u[q], n), 2) * dA;
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(squares.data(), 5), communicator, ArrayView<double>(squares.data(), 5));
    Errors errors;
    errors.velocity        = std::sqrt(squares[0]);
    errors.tangential      = std::sqrt(squares[1]);
    errors.gradient        = std::sqrt(squares[2]);
    errors.pressure        = std::sqrt(squares[3]);
    errors.normal_velocity = std::sqrt(squares[4]);
    return errors;
  }
} // namespace FluidSurface
