// SPDX-License-Identifier: LGPL-2.1-or-later
// NodalVectorField::symmetry_share, the column of scene stability's spectrum.csv that tells the neutral modes of a
// rigidly rotating state (the translations, the turn about the rotation axis) from shape modes. On the triaxial
// ellipsoid [1, 0.8, 0.6] (refinement 2, Q2): the turn e_z × x, a translation, and the two with a tangential slide
// added have share 1; the radial m = 2 and m = 3 displacements about e_z, which change the shape, have a share
// near 0; a mixed complex field its part. On the spheroid [0.8, 0.8, 1.2] the turn about its axis moves no node
// normally and drops out: a translation still has share 1, the m = 2 displacement near 0.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/nodal_vector_field.h>
#include <fluid_surface/scenes/simulation.h>

#include <cstdio>
#include <functional>
#include <map>
#include <string>

using namespace FluidSurface;
using dealii::Point;
using dealii::Tensor;

namespace
{
  /// The nodal field f(x) on the position DoFs (owned).
  VectorType
  nodal(const SurfaceGeometry &geometry, const std::function<Tensor<1, 3>(const Point<3> &)> &f)
  {
    std::map<dealii::types::global_dof_index, Point<3>> points;
    dealii::DoFTools::map_dofs_to_support_points(geometry.mapping(), geometry.dof_handler(), points);
    VectorType out(geometry.locally_owned_dofs(), MPI_COMM_WORLD);
    const auto &fe = geometry.dof_handler().get_fe();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : geometry.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (geometry.locally_owned_dofs().is_element(dofs[i]))
              out[dofs[i]] = f(points.at(dofs[i]))[fe.system_to_component_index(i).first];
        }
    out.compress(dealii::VectorOperation::insert);
    return out;
  }

  void
  report(const SurfaceGeometry &geometry, const char *what, const VectorType &re, const VectorType &im)
  {
    const NodalVectorField positions(geometry.dof_handler(), 0, geometry.mapping());
    const Point<3>         centre(geometry.measure().centre_of_mass);
    const double share = positions.symmetry_share(re, im, geometry.normal_field(), Tensor<1, 3>({0, 0, 1}), centre);
    std::printf("  %-34s %.3f\n", what, share);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const char *axes : {"1, 0.8, 0.6", "0.8, 0.8, 1.2"})
    {
      dealii::ParameterHandler prm;
      Simulation::declare_parameters(prm);
      prm.enter_subsection("geometry");
      prm.set("semi-axes", axes);
      prm.set("refinement", "2");
      prm.set("position degree", "2");
      prm.leave_subsection();
      SurfaceGeometry geometry(MPI_COMM_WORLD);
      geometry.parse_parameters(prm);
      geometry.create();
      std::printf("ellipsoid [%s]\n", axes);
      const Tensor<1, 3>     e_z({0, 0, 1});
      const AzimuthalHarmonic m2(e_z, 2, false), m3(e_z, 3, false);
      const VectorType        zero = nodal(geometry, [](const Point<3> &) { return Tensor<1, 3>(); });
      const VectorType turn = nodal(geometry, [&](const Point<3> &x) { return cross_product_3d(e_z, x); });
      const VectorType shift = nodal(geometry, [](const Point<3> &) { return Tensor<1, 3>({0.3, -0.2, 0.5}); });
      // A slide along the surface (the tangential part of a field that is not a rigid motion) changes no share.
      const VectorType slid = nodal(geometry, [&](const Point<3> &x) {
        const Tensor<1, 3> n    = Tensor<1, 3>({x[0] / 1.0, x[1] / 0.64, x[2] / 0.36}) /
                               Tensor<1, 3>({x[0] / 1.0, x[1] / 0.64, x[2] / 0.36}).norm();
        const Tensor<1, 3> kick({x[1] * x[2], 1.0, x[0]});
        return cross_product_3d(e_z, x) + 0.5 * (kick - (kick * n) * n);
      });
      const auto radial = [](const AzimuthalHarmonic &h) {
        return [&h](const Point<3> &x) { return h.normalized_real_part(x) * x / x.norm(); };
      };
      const bool triaxial = std::string(axes) == "1, 0.8, 0.6";
      if (triaxial)
        {
          report(geometry, "turn about e_z", turn, zero);
          report(geometry, "turn with a tangential slide", slid, zero);
        }
      report(geometry, "translation", shift, zero);
      report(geometry, "radial m = 2", nodal(geometry, radial(m2)), zero);
      report(geometry, "radial m = 3", nodal(geometry, radial(m3)), zero);
      report(geometry, "translation + i radial m = 3", shift, nodal(geometry, radial(m3)));
    }
}
