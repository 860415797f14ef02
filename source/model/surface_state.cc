// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/dofs/dof_tools.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/surface_state.h>

#include <string>

namespace FluidSurface
{
  using namespace dealii;

  void
  SurfaceState::reinit(const DoFHandler<2, 3> &flow_dofs, const SurfaceGeometry &geometry)
  {
    const MPI_Comm comm = geometry.get_communicator();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(flow_dofs, relevant);
    solution.reinit(flow_dofs.locally_owned_dofs(), relevant, comm);
    reference_position.reinit(flow_dofs.locally_owned_dofs(), relevant, comm);
    position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), comm);
    reference_surface.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), comm);
  }

  void
  SurfaceState::save(CheckpointData &data, const DoFHandler<2, 3> &flow_dofs, const SurfaceGeometry &geometry) const
  {
    data.set_fields("flow", flow_dofs, {&solution});
    // The second vector was X^{m−1}, which no step reads: X^m again keeps the block readable both ways.
    data.set_fields("geometry", geometry.dof_handler(), {&position, &position});
    data.set_fields("mesh reference", geometry.dof_handler(), {&reference_surface});
    data.set("model/target volume", target_volume);
    data.set("model/target area", target_area);
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      data.set("model/rigid target " + std::to_string(k), rigid_targets[k]);
  }

  void
  SurfaceState::load(const CheckpointData &data, const DoFHandler<2, 3> &flow_dofs, SurfaceGeometry &geometry)
  {
    VectorType fields, surface, unused;
    data.get_fields("flow", flow_dofs, {&fields});
    data.get_fields("geometry", geometry.dof_handler(), {&surface, &unused});
    reinit(flow_dofs, geometry);
    solution = fields;
    geometry.set_position(surface);
    position = geometry.position();
    curvature.reset();
    VectorType initial;
    data.get_fields("mesh reference", geometry.dof_handler(), {&initial});
    reference_surface = initial;
    target_volume     = data.get_double("model/target volume");
    target_area       = data.get_double("model/target area");
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      rigid_targets[k] = data.get_double("model/rigid target " + std::to_string(k));
  }
} // namespace FluidSurface
