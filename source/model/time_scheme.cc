// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/rigid_motion.h>
#include <fluid_surface/model/step_system.h>
#include <fluid_surface/model/time_scheme.h>

#include <cmath>
#include <stdexcept>

namespace FluidSurface
{
  using namespace dealii;

  std::unique_ptr<TimeScheme>
  TimeScheme::create(const std::string &name, const GeometryIteration::Predictor predictor)
  {
    if (name == "BDF2")
      return std::make_unique<VariableBDF2>(predictor);
    if (name == "SDIRK2")
      return std::make_unique<SDIRK2>(predictor);
    if (name == "backward Euler")
      return std::make_unique<BackwardEuler>();
    throw std::logic_error("no time scheme named '" + name + "'");
  }

  StepStart
  TimeScheme::next_stage(const unsigned int, const VectorType &, const StepSystem &, const StepFrame &, const double)
  {
    throw std::logic_error("A time scheme of one stage has no next stage.");
  }

  StepStart
  BackwardEuler::start(const VectorType &old_position,
                       const VectorType &old_fields,
                       const StepSystem &,
                       const StepFrame &,
                       const double tau)
  {
    StepStart start;
    start.tau       = tau;
    start.position  = &old_position;
    start.fields    = &old_fields;
    start.transport = &old_fields;
    return start;
  }

  StepStart
  VariableBDF2::start(const VectorType &old_position,
                      const VectorType &old_fields,
                      const StepSystem &system,
                      const StepFrame  &frame,
                      const double      tau)
  {
    if (backward_euler_step())
      return first_step.start(old_position, old_fields, system, frame, tau);
    const VectorType previous = previous_in_frame(system, frame);
    const double omega = tau / previous_step, alpha0 = (1 + 2 * omega) / (1 + omega);
    VectorType   start = system.owned_vector();
    start              = old_fields;
    start.sadd((1 + omega) / alpha0, -omega * omega / ((1 + omega) * alpha0), previous);
    const VectorType lagged = extrapolation(old_fields, previous, system, tau);
    StepStart        result = backward_euler_form(start, lagged, system, tau * (1 + omega) / (1 + 2 * omega));
    if (predictor != GeometryIteration::Predictor::old_surface)
      result.predicted = quadratic_predictor() && earlier_step > 0 ?
                           &quadratic_prediction(old_fields, previous, lagged, system, frame, tau) :
                           &lagged_fields;
    return result;
  }

  const VectorType &
  VariableBDF2::quadratic_prediction(const VectorType &old_fields,
                                     const VectorType &previous,
                                     const VectorType &linear,
                                     const StepSystem &system,
                                     const StepFrame  &frame,
                                     const double      tau)
  {
    // Lagrange's weights of t^m, t^{m−1}, t^{m−2} at t^{m+1}.
    const double tp = previous_step, tpp = earlier_step;
    VectorType   earlier = system.owned_vector(), quadratic = system.owned_vector();
    earlier = earlier_solution;
    if (frame.solved_in_frame())
      system.carry_fields(frame.motion, tp + tpp, earlier);
    quadratic = old_fields;
    quadratic.sadd((tau + tp) * (tau + tp + tpp) / (tp * (tp + tpp)), -tau * (tau + tp + tpp) / (tp * tpp), previous);
    quadratic.add(tau * (tau + tp) / ((tp + tpp) * tpp), earlier);
    // The shape (the normal part) to third order, the nodes' tangential places of the linear one: their rows take
    // the geometry at full weight, and the quadratic predictor's sevenfold amplification of unresolved tangential
    // motion broke the relaxing prolate's mesh (doc/scheme.md).
    quadratic -= linear;
    VectorType normal_part = system.owned_vector();
    normal_part            = linear;
    system.add_normal_part(quadratic, system.geometry().normal_field(), normal_part);
    quadratic = normal_part;
    quadratic_fields = system.ghosted_vector();
    quadratic_fields = quadratic;
    return quadratic_fields;
  }

  VectorType
  PreviousStateScheme::previous_in_frame(const StepSystem &system, const StepFrame &frame) const
  {
    VectorType previous = system.owned_vector();
    previous            = previous_solution;
    if (frame.solved_in_frame())
      system.carry_fields(frame.motion, previous_step, previous);
    return previous;
  }

  VectorType
  PreviousStateScheme::extrapolation(const VectorType &old_fields,
                                     const VectorType &previous,
                                     const StepSystem &system,
                                     const double      theta) const
  {
    const double omega  = theta / previous_step;
    VectorType   result = system.owned_vector();
    result              = old_fields;
    result.sadd(1 + omega, -omega, previous);
    return result;
  }

  StepStart
  PreviousStateScheme::backward_euler_form(const VectorType &start,
                                           const VectorType &lagged,
                                           const StepSystem &system,
                                           const double      tau_hat)
  {
    start_fields  = system.ghosted_vector();
    lagged_fields = system.ghosted_vector();
    start_fields  = start;
    lagged_fields = lagged;
    const SurfaceGeometry &geometry = system.geometry();
    start_position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), geometry.get_communicator());
    // From the ghosted copy (a geometry DoF this rank owns may sit on a flow DoF another rank owns), and through a
    // named vector: a move assignment would hand start_position the owned layout without its ghosts.
    const VectorType owned_start_position = system.new_position(start_fields);
    start_position                        = owned_start_position;
    StepStart result;
    result.tau                           = tau_hat;
    result.position                      = &start_position;
    result.fields                        = &start_fields;
    result.transport                     = &lagged_fields;
    result.frame_velocity_on_new_surface = true;
    return result;
  }

  void
  PreviousStateScheme::accept(const VectorType &old_fields, const StepSystem &system, const double tau)
  {
    previous_solution = system.ghosted_vector();
    previous_solution = old_fields;
    previous_step     = tau;
    if (backward_euler_steps > 0)
      --backward_euler_steps;
  }

  void
  PreviousStateScheme::save(CheckpointData &data, const StepSystem &system) const
  {
    if (backward_euler_steps > 0)
      data.set("model/backward Euler steps", static_cast<double>(backward_euler_steps));
    if (previous_step == 0)
      return;
    data.set("model/previous step", previous_step);
    data.set_fields("previous state", system.dof_handler(), {&previous_solution});
  }

  void
  PreviousStateScheme::load(const CheckpointData &data, const StepSystem &system)
  {
    previous_step = 0;
    backward_euler_steps =
      data.has("model/backward Euler steps") ? static_cast<unsigned int>(data.get_double("model/backward Euler steps")) : 0;
    if (!data.has("model/previous step"))
      return;
    previous_solution = system.read_field(data, "previous state");
    previous_step     = data.get_double("model/previous step");
  }

  void
  VariableBDF2::accept(const VectorType &old_fields, const StepSystem &system, const double tau)
  {
    if (previous_step > 0 && quadratic_predictor())
      {
        earlier_solution = previous_solution;
        earlier_step     = previous_step;
      }
    PreviousStateScheme::accept(old_fields, system, tau);
  }

  void
  VariableBDF2::save(CheckpointData &data, const StepSystem &system) const
  {
    PreviousStateScheme::save(data, system);
    if (previous_step == 0 || earlier_step == 0)
      return;
    data.set("model/earlier step", earlier_step);
    data.set_fields("earlier state", system.dof_handler(), {&earlier_solution});
  }

  void
  VariableBDF2::load(const CheckpointData &data, const StepSystem &system)
  {
    PreviousStateScheme::load(data, system);
    earlier_step = 0;
    if (previous_step == 0 || !quadratic_predictor() || !data.has("model/earlier step"))
      return;
    earlier_solution = system.read_field(data, "earlier state");
    earlier_step     = data.get_double("model/earlier step");
  }

  const double SDIRK2::gamma = 1 - 1 / std::sqrt(2.0);

  StepStart
  SDIRK2::start(const VectorType &old_position,
                const VectorType &old_fields,
                const StepSystem &system,
                const StepFrame  &frame,
                const double      tau)
  {
    stages = falling_back() ? 1 : 2;
    if (stages == 1)
      return first_step.start(old_position, old_fields, system, frame, tau);
    old_solution  = system.ghosted_vector();
    old_solution  = old_fields;
    lagged_fields = system.ghosted_vector();
    if (previous_step > 0)
      {
        previous                = previous_in_frame(system, frame);
        const VectorType lagged = extrapolation(old_fields, previous, system, gamma * tau);
        lagged_fields           = lagged;
      }
    else
      lagged_fields = old_fields;
    StepStart result;
    result.tau                           = gamma * tau;
    result.position                      = &old_position;
    result.fields                        = &old_solution;
    result.transport                     = &lagged_fields;
    result.frame_velocity_on_new_surface = true;
    if (predictor != GeometryIteration::Predictor::old_surface && previous_step > 0)
      result.predicted = &lagged_fields;
    return result;
  }

  StepStart
  SDIRK2::next_stage(const unsigned int stage,
                     const VectorType  &stage_fields,
                     const StepSystem  &system,
                     const StepFrame &,
                     const double tau)
  {
    Assert(stage == 1 && stages == 2, ExcInternalError());
    (void)stage;
    // x̂₂ = x^m + ((1−γ)/γ)(Y₁ − x^m): the backward-Euler form of x^{m+1} = x^m + τ((1−γ)f(Y₁) + γf(x^{m+1})).
    VectorType start = system.owned_vector();
    start            = old_solution;
    start.sadd(1 - (1 - gamma) / gamma, (1 - gamma) / gamma, stage_fields);
    VectorType lagged = system.owned_vector();
    if (previous_step > 0)
      lagged = extrapolation(old_solution, previous, system, tau);
    else
      lagged = stage_fields; // Y₁ at t^m + γτ
    StepStart result = backward_euler_form(start, lagged, system, gamma * tau);
    if (predictor != GeometryIteration::Predictor::old_surface)
      result.predicted = &lagged_fields;
    return result;
  }
} // namespace FluidSurface
