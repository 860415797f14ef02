// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/local_error_estimate.h>
#include <fluid_surface/model/step_system.h>

#include <cmath>

namespace FluidSurface
{
  using namespace dealii;

  double
  LocalErrorEstimate::estimate(const StepSystem &system,
                               const VectorType &new_state,
                               const VectorType &old_position,
                               const VectorType &old_normal,
                               const double      tau,
                               const double      shape_radius)
  {
    if (candidate_normal_speed.size() != new_state.size())
      candidate_normal_speed = system.owned_vector();
    const auto &nodes         = system.new_position_nodes();
    const auto &geometry_dofs = system.new_position_geometry_dofs();
    double      largest_difference = 0;
    for (unsigned int n = 0; n < nodes.size(); ++n)
      {
        const auto  &node = nodes[n];
        Tensor<1, 3> move, normal;
        for (unsigned int d = 0; d < 3; ++d)
          {
            move[d]   = new_state[node[d]] - old_position[geometry_dofs[n][d]];
            normal[d] = old_normal[geometry_dofs[n][d]];
          }
        const double w                  = move * normal / tau;
        candidate_normal_speed[node[0]] = w;
        if (normal_speed_step > 0)
          largest_difference = std::max(largest_difference, std::abs(w - normal_speed[node[0]]));
      }
    candidate_normal_speed.compress(VectorOperation::insert);
    largest_difference = Utilities::MPI::max(largest_difference, system.geometry().get_communicator());
    if (normal_speed_step == 0)
      return -1;
    return tau * tau / (tau + normal_speed_step) * largest_difference / shape_radius;
  }

  void
  LocalErrorEstimate::accept(const StepSystem &system, const double tau)
  {
    if (!on_)
      return;
    normal_speed      = system.ghosted_vector();
    normal_speed      = candidate_normal_speed;
    normal_speed_step = tau;
  }

  void
  LocalErrorEstimate::save(CheckpointData &data, const StepSystem &system) const
  {
    if (!on_ || normal_speed_step == 0)
      return;
    data.set("model/normal speed step", normal_speed_step);
    data.set_fields("normal speed", system.dof_handler(), {&normal_speed});
  }

  void
  LocalErrorEstimate::load(const CheckpointData &data, const StepSystem &system)
  {
    normal_speed_step = 0;
    if (!on_ || !data.has("model/normal speed step"))
      return;
    normal_speed      = system.read_field(data, "normal speed");
    normal_speed_step = data.get_double("model/normal speed step");
  }
} // namespace FluidSurface
