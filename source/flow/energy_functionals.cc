// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/fe/fe_values.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/geometry/surface_operators.h>

namespace FluidSurface
{
  namespace EnergyFunctionals
  {
    using namespace dealii;

    namespace
    {
      /**
       * Σ over the locally owned cells and quadrature points, in this order, of add(fe_values, q, sum), which
       * adds the integrand times JxW to its running sum (one sum, so that the order of the additions is the
       * same for every functional); then the sum over the ranks.
       */
      template <typename AddIntegrand>
      double
      integrate(const Mapping<2, 3>    &mapping,
                const DoFHandler<2, 3> &dofs,
                const Quadrature<2>    &quadrature,
                const UpdateFlags       flags,
                const MPI_Comm          communicator,
                const AddIntegrand     &add)
      {
        FEValues<2, 3> fe_values(mapping, dofs.get_fe(), quadrature, flags | update_JxW_values);
        double         sum = 0;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              add(fe_values, sum);
            }
        return Utilities::MPI::sum(sum, communicator);
      }
    } // namespace

    double
    kinetic_energy(const Mapping<2, 3>    &mapping,
                   const DoFHandler<2, 3> &dofs,
                   const VectorType       &state,
                   const Quadrature<2>    &quadrature,
                   const MPI_Comm          communicator)
    {
      std::vector<Tensor<1, 3>> u(quadrature.size());
      return integrate(mapping, dofs, quadrature, update_values, communicator, [&](const FEValues<2, 3> &fe_values, double &sum) {
        fe_values[FEValuesExtractors::Vector(0)].get_function_values(state, u);
        for (unsigned int q = 0; q < u.size(); ++q)
          sum += kinetic_energy_density(u[q]) * fe_values.JxW(q);
      });
    }

    double
    dissipation_rate(const Mapping<2, 3>    &mapping,
                     const DoFHandler<2, 3> &dofs,
                     const VectorType       &state,
                     const Quadrature<2>    &quadrature,
                     const double            Re,
                     const MPI_Comm          communicator,
                     const double            grad_div,
                     const double            area_rate)
    {
      std::vector<Tensor<2, 3>> gradient(quadrature.size());
      double                    grad_div_sum = 0;
      const double              sum = integrate(
        mapping, dofs, quadrature, update_gradients | update_normal_vectors, communicator,
        [&](const FEValues<2, 3> &fe_values, double &sum) {
          fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(state, gradient);
          for (unsigned int q = 0; q < gradient.size(); ++q)
            {
              const Tensor<2, 3> sigma = SurfaceOperators::strain_rate(gradient[q], fe_values.normal_vector(q));
              sum += scalar_product(sigma, sigma) * fe_values.JxW(q);
              if (grad_div > 0)
                grad_div_sum += Utilities::fixed_power<2>(SurfaceOperators::surface_divergence(gradient[q]) - area_rate) * fe_values.JxW(q);
            }
        });
      if (grad_div > 0)
        grad_div_sum = Utilities::MPI::sum(grad_div_sum, communicator);
      return 2.0 / Re * sum + grad_div * grad_div_sum;
    }
  } // namespace EnergyFunctionals
} // namespace FluidSurface
