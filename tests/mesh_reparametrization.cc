// SPDX-License-Identifier: LGPL-2.1-or-later
// The safety valve (FluidDeformableSurface::reparametrize()) on the spheroid 1 : 1 : 2 (refinement 2) whose
// parametrization was sheared by a twist about its axis, x ↦ R_z(1.2 z) x, which maps the spheroid onto itself,
// rotating rigidly about its axis (ω = 2, momenta conserved); the mesh law's reference surface S₀ is the
// untwisted mesh. The valve must raise the mesh quality. In the Stokes limit without the conservation projection
// (the fields are only transferred) the new surface is as close to the spheroid as the old one and the rigid
// rotation, which lies in the velocity space, is carried over to rounding; with inertia and the projection
// (the default) A, V and L are kept to rounding, and the jump of F is printed (at this coarse refinement it is
// the re-interpolation of the twisted surface). The same on one and on two ranks (ghost cells in the point
// location).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include "parameter_overrides.h"

#include <cmath>
#include <cstdio>
#include <tuple>

using namespace FluidSurface;
using namespace dealii;

namespace
{
  const double omega = 2;

  /// F, A, V and L = ∫x × u (the geometry's quadrature) of the current state of @p model.
  std::tuple<double, double, double, Tensor<1, 3>>
  measures(SurfaceGeometry &geometry, const FluidDeformableSurface &model)
  {
    const double              F = model.kinetic_energy() + model.step().components().bending.energy(geometry.willmore_energy());
    const auto                m = geometry.measure();
    const Quadrature<2>       q = geometry.quadrature();
    FEValues<2, 3>            fe_values(geometry.mapping(), model.dof_handler().get_fe(), q,
                                        update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 3>> u(q.size());
    Tensor<1, 3>              L;
    for (const auto &cell : model.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(model.solution(), u);
          for (unsigned int k = 0; k < q.size(); ++k)
            L += cross_product_3d(fe_values.quadrature_point(k), u[k]) * fe_values.JxW(k);
        }
    return std::make_tuple(F, m.area, m.volume, Utilities::MPI::sum(L, geometry.get_communicator()));
  }

  /// The largest |x² + y² + z²/4 − 1| over a 9 × 9 grid of points of every cell (boundaries included).
  double
  distance_from_spheroid(const SurfaceGeometry &geometry)
  {
    const QIterated<2> points(QTrapezoid<1>(), 8);
    FEValues<2, 3>     fe_values(geometry.mapping(), geometry.fe(), points, update_quadrature_points);
    double             largest = 0;
    for (const auto &cell : geometry.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (const auto &p : fe_values.get_quadrature_points())
            largest = std::max(largest, std::abs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] / 4 - 1));
        }
    return Utilities::MPI::max(largest, geometry.get_communicator());
  }

  /// The largest |u − ω e_z × x| over the velocity nodes (x the new position Y at the same support point).
  double
  distance_from_rigid_rotation(const FluidDeformableSurface &model)
  {
    const auto                          &fe = model.dof_handler().get_fe();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    double                               largest = 0;
    for (const auto &cell : model.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first == FluidDeformableSurface::velocity_component)
              {
                const Point<2> xi = fe.unit_support_point(i);
                Point<3>       x;
                Tensor<1, 3>   u;
                for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                  if (fe.unit_support_point(j).distance(xi) < 1e-12)
                    {
                      const unsigned int c = fe.system_to_component_index(j).first;
                      if (c < 3)
                        u[c] = model.solution()[indices[j]];
                      else if (c >= FluidDeformableSurface::position_component &&
                               c < FluidDeformableSurface::position_component + 3)
                        x[c - FluidDeformableSurface::position_component] = model.solution()[indices[j]];
                    }
                largest = std::max(largest, (u - Tensor<1, 3>({-omega * x[1], omega * x[0], 0})).norm());
              }
        }
    return Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  for (const bool projection : {false, true}) // projection: inertia and conservation projection on
    {
      ParameterHandler prm;
      Simulation::declare_parameters(prm);
      set_overrides(prm,
                    {{"geometry/shape", "ellipsoid"},
                     {"geometry/semi-axes", "1, 1, 2"},
                     {"geometry/refinement", "2"},
                     {"initial state/angular velocity", std::to_string(omega)},
                     {"flow/conserve momenta", "true"},
                     {"flow/inertia", projection ? "true" : "false"},
                     {"conservation projection/enabled", projection ? "true" : "false"}});
      SurfaceGeometry geometry(MPI_COMM_WORLD);
      geometry.parse_parameters(prm);
      geometry.create();
      const VectorType untwisted = geometry.position();
      geometry.transform_nodes([](const Point<3> &x) {
        const double a = 1.2 * x[2];
        return Point<3>(std::cos(a) * x[0] - std::sin(a) * x[1], std::sin(a) * x[0] + std::cos(a) * x[1], x[2]);
      });
      TimeStepper time;
      time.parse_parameters(prm);
      FluidDeformableSurface model(geometry);
      model.parse_parameters(prm, time.maximum_step_size());
      model.setup();
      const double twisted_surface_error = distance_from_spheroid(geometry);
      const auto [F0, A0, V0, L0]        = measures(geometry, model);
      // F on the untwisted mesh (the same rigid rotation).
      double F_untwisted = 0;
      {
        SurfaceGeometry  plain(MPI_COMM_WORLD);
        plain.parse_parameters(prm);
        plain.create();
        FluidDeformableSurface plain_model(plain);
        plain_model.parse_parameters(prm, time.maximum_step_size());
        plain_model.setup();
        F_untwisted = std::get<0>(measures(plain, plain_model));
      }

      model.set_reference_surface(untwisted);
      const auto valve = model.reparametrize();
      if (!valve.done)
        {
          std::printf("re-parametrization failed: %s\n", valve.failure.c_str());
          return 1;
        }
      const double new_surface_error  = distance_from_spheroid(geometry);
      const double rotation_error     = distance_from_rigid_rotation(model);
      const auto [F1, A1, V1, L1]     = measures(geometry, model);
      if (!root)
        continue;
      std::printf(projection ? "inertia, conservation projection:\n" : "Stokes limit, no conservation projection:\n");
      std::printf("  mesh quality %.3f -> %.3f, raised by more than 50 %%: %s\n", valve.quality_before,
                  valve.quality_after, valve.quality_after > 1.5 * valve.quality_before ? "yes" : "no");
      if (!projection)
        {
          std::printf("  the new surface as far from the spheroid as the old one (|x^2 + y^2 + z^2/4 - 1| %.2e, "
                      "old %.2e, within 10 %%): %s\n",
                      new_surface_error, twisted_surface_error,
                      new_surface_error < 1.1 * twisted_surface_error ? "yes" : "no");
          std::printf("  the rigid rotation carried over (max |u - omega e_z x x| below 1e-10): %s\n",
                      rotation_error < 1e-10 ? "yes" : "no");
        }
      else
        {
          std::printf("  area %.10f -> %.10f, volume %.10f -> %.10f\n", A0, A1, V0, V1);
          std::printf("  jumps of A, V and L below 1e-12: %s\n",
                      std::abs(A1 - A0) < 1e-12 * A0 && std::abs(V1 - V0) < 1e-12 * V0 &&
                          (L1 - L0).norm() < 1e-12 * L0.norm() ?
                        "yes" :
                        "no");
          std::printf("  F %.2f -> %.2f (untwisted mesh %.2f), relative jump below 5e-2: %s\n", F0, F1, F_untwisted,
                      std::abs(F1 - F0) < 5e-2 * F0 ? "yes" : "no");
        }
    }
}
