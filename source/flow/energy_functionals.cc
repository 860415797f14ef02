#include <deal.II/fe/fe_values.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/geometry/surface_operators.h>

namespace FluidSurface
{
  namespace EnergyFunctionals
  {
    using namespace dealii;

    double
    kinetic_energy(const Mapping<2, 3>    &mapping,
                   const DoFHandler<2, 3> &dofs,
                   const VectorType       &state,
                   const Quadrature<2>    &quadrature,
                   const MPI_Comm          communicator)
    {
      FEValues<2, 3>                   fe_values(mapping, dofs.get_fe(), quadrature, update_values | update_JxW_values);
      const FEValuesExtractors::Vector velocity(0);
      std::vector<Tensor<1, 3>>        u(quadrature.size());
      double                           energy = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[velocity].get_function_values(state, u);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              energy += kinetic_energy_density(u[q]) * fe_values.JxW(q);
          }
      return Utilities::MPI::sum(energy, communicator);
    }

    double
    dissipation_rate(const Mapping<2, 3>    &mapping,
                     const DoFHandler<2, 3> &dofs,
                     const VectorType       &state,
                     const Quadrature<2>    &quadrature,
                     const double            Re,
                     const MPI_Comm          communicator)
    {
      FEValues<2, 3>                   fe_values(mapping,
                                 dofs.get_fe(),
                                 quadrature,
                                 update_gradients | update_normal_vectors | update_JxW_values);
      const FEValuesExtractors::Vector velocity(0);
      std::vector<Tensor<2, 3>>        gradient(quadrature.size());
      double                           rate = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[velocity].get_function_gradients(state, gradient);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const Tensor<2, 3> sigma = SurfaceOperators::strain_rate(gradient[q], fe_values.normal_vector(q));
                rate += scalar_product(sigma, sigma) * fe_values.JxW(q);
              }
          }
      return 2.0 / Re * Utilities::MPI::sum(rate, communicator);
    }
  } // namespace EnergyFunctionals
} // namespace FluidSurface
