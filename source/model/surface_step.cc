// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/step_assembly.h>
#include <fluid_surface/model/surface_step.h>

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// A TimerOutput section for the lifetime of the object (nothing without a timer).
    class TimerSection
    {
    public:
      TimerSection(TimerOutput *timer, const std::string &name)
        : timer(timer)
        , name(name)
      {
        if (timer)
          timer->enter_subsection(name);
      }
      ~TimerSection()
      {
        if (timer)
          timer->leave_subsection(name);
      }
      TimerSection(const TimerSection &) = delete;
      TimerSection &
      operator=(const TimerSection &) = delete;

    private:
      TimerOutput *timer;
      std::string  name;
    };
  } // namespace

  struct SurfaceStep::GlobalConstraints
  {
    std::vector<const VectorType *> columns, rows;
    std::vector<double>             values;
    bool                            volume_row = false, rigid_rows = false;
    /// The momentum targets in the frame of the step, without the constant parts of the linearized rows.
    std::array<double, 6> targets = {{0, 0, 0, 0, 0, 0}};
    unsigned int
    first_rigid() const
    {
      return volume_row ? 1 : 0;
    }
  };

  struct SurfaceStep::StepUnderWay
  {
    /// A stage of the step as @p request asks, in @p frame, whose terms are those of @p components.
    StepUnderWay(const StepRequest &request, const StepFrame &frame, const StepComponents &components, StepSystem &system)
      : request(request)
      , frame(frame)
      , assembly(components, request, system)
    {}
    const StepRequest &request;
    const StepFrame   &frame;    ///< the frame it is solved in
    const StepAssembly assembly; ///< its terms
    double             tau   = 0;       ///< the step (the stage's time, SDIRK2)
    const StepStart   *start = nullptr; ///< its backward-Euler form
    SurfaceGeometry::Measures         old_measures;            ///< of S^m
    const SurfaceGeometry::Curvature *old_curvature = nullptr; ///< of S^m
    double                            membrane_weight = 0;
    GlobalConstraints                 constraints;
    /// The curvature of the last surface the step evaluated (S^m, or the last iterate of the geometry): the
    /// modes of the area and volume projection.
    SurfaceGeometry::Curvature evaluated_curvature;
  };

  SurfaceStep::SurfaceStep(SurfaceGeometry &geometry, const SurfaceState &state)
    : geometry(geometry)
    , state(state)
    , system(geometry)
    , time_scheme(std::make_unique<BackwardEuler>())
  {}

  SurfaceStep::~SurfaceStep() = default;

  void
  SurfaceStep::declare_parameters(ParameterHandler &prm)
  {
    StepComponents::declare_parameters(prm);
  }

  void
  SurfaceStep::parse_parameters(ParameterHandler &prm, const double maximum_time_step)
  {
    parts.parse_parameters(prm, maximum_time_step);
    bordered_solver.parse_parameters(prm); // the entries shared with scene fixed surface
  }

  void
  SurfaceStep::set_time_scheme(const std::string &name, const FlowStepFrame frame)
  {
    time_scheme = TimeScheme::create(name, parts.geometry_iteration.predictor);
    flow_step_frame = frame;
  }

  void
  SurfaceStep::setup_system()
  {
    system.setup_system();
    bordered_solver.release_factorization();
  }

  StepFrame
  SurfaceStep::frame_of(const StepRequest &request) const
  {
    const MeshRedistribution &redistribution = parts.redistribution;
    const bool                reference      = request.law == MeshRedistribution::Law::reference;
    StepFrame                 frame;
    // The co-rotating flow steps are solved in the Tisserand frame of u^m, and the mesh turns with it.
    if (flow_step_frame == FlowStepFrame::tisserand && request.velocity == StepRequest::Velocity::flow &&
        request.global_constraints)
      {
        frame.kind    = StepFrame::Kind::co_rotating;
        frame.motion  = RigidMotion::tisserand(geometry, system.dof_handler(), state.solution);
        frame.carried = frame.motion;
        return frame;
      }
    // The mesh moves along with the rigid motion R of the shape (fit of u^m·ν): law bgn relaxes towards X^m + τR,
    // law reference carries the nodes by the rotation itself and solves the step in the frame they are carried in.
    const bool follow = redistribution.follow_rigid_motion && (reference || redistribution.relaxation_time > 0);
    // The momenta of u^m, once per step: the constant parts of the momentum constraints.
    if (follow || (parts.momentum_constraints.active() && parts.flow.inertia))
      frame.motion = rigid_motion(request, state.solution);
    if (reference && redistribution.follow_rigid_motion)
      frame.kind = StepFrame::Kind::carried;
    if (follow)
      frame.carried = frame.motion;
    return frame;
  }

  RigidMotion
  SurfaceStep::rigid_motion(const StepRequest &request, const VectorType &flow_vector) const
  {
    return RigidMotion::fit(geometry,
                            system.dof_handler(),
                            flow_vector,
                            request.prescribed_velocity(),
                            parts.redistribution.rigid_motion_cutoff,
                            request.law == MeshRedistribution::Law::reference);
  }

  void
  SurfaceStep::accept_history(const StepCandidate &candidate)
  {
    corrected_steps.accept();
    membrane_pull.accept(candidate.tau);
    time_scheme->accept(state.solution, system, candidate.tau);
    error_estimate.accept(system, candidate.tau);
    bordered_solver.turn_kept_factors(candidate.mesh_rotation);
  }

  void
  SurfaceStep::save_history(CheckpointData &data) const
  {
    corrected_steps.save(data);
    membrane_pull.save(data);
    time_scheme->save(data, system);
    error_estimate.save(data, system);
  }

  void
  SurfaceStep::load_history(const CheckpointData &data)
  {
    corrected_steps.load(data);
    membrane_pull.load(data);
    time_scheme->load(data, system);
    error_estimate.load(data, system);
  }

  void
  SurfaceStep::restore_old_geometry()
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = state.position;
    geometry.set_position(position);
  }

  StepAssemblyData
  SurfaceStep::assembly_data(const StepUnderWay &step, const VectorType &normal) const
  {
    StepAssemblyData data;
    data.tau                           = step.start->tau;
    data.old_position                  = step.start->position;
    data.old_fields                    = step.start->fields;
    data.transport_fields              = step.start->transport;
    data.frame_velocity_on_new_surface = step.start->frame_velocity_on_new_surface;
    data.normal                        = &normal;
    data.reference_position            = &state.reference_position;
    data.frame                         = &step.frame;
    data.area_rate       = area_rate(step);
    data.area_scale      = state.target_area / geometry.measure().area;
    data.membrane_weight = step.membrane_weight;
    return data;
  }

  void
  SurfaceStep::set_up_global_constraints(const StepUnderWay &step, GlobalConstraints &constraints) const
  {
    const StepRequest &request = step.request;
    // The mesh relaxation of the valve moves no surface: none of the global constraints.
    constraints.volume_row = parts.volume_constraint.enabled && request.global_constraints;
    constraints.rigid_rows = parts.momentum_constraints.active() && request.global_constraints;
    if (constraints.volume_row)
      {
        constraints.columns.push_back(&system.volume_column());
        constraints.rows.push_back(&system.volume_column());
        constraints.values.push_back(-(step.old_measures.volume - state.target_volume) / drift_time(step.start->tau));
      }
    if (!constraints.rigid_rows)
      return;
    // The constant parts of the linearized momenta on S^{m+1} move to the right: with δ = Y − X^m and
    // div_S X^m = 2 they are −2∫u^m and −3∫x × u^m (set_constraint_values()). A drift P^m − P₀ is returned by
    // the fraction τ/τ_c per step, like the area and volume drifts, so that a retry with a smaller τ asks for
    // a smaller change of u.
    const bool                  inertia     = parts.flow.inertia;
    const std::array<double, 6> old_momenta = inertia ? step.frame.motion.momenta : std::array<double, 6>{{0, 0, 0, 0, 0, 0}};
    const double                fraction    = inertia ? std::min(1.0, step.tau / drift_time(step.tau)) : 1.0;
    for (unsigned int k = 0; k < 6; ++k)
      constraints.targets[k] = old_momenta[k] + fraction * (state.rigid_targets[k] - old_momenta[k]);
    if (step.frame.solved_in_frame())
      {
        // In the carried frame (Y = QỸ + c, u = Qũ): P̃ = QᵀP, L̃ = Qᵀ(L − c × P).
        const Tensor<2, 3> Q = step.frame.motion.rotation_over(step.tau);
        const Tensor<1, 3> c = step.frame.motion.carry(Point<3>(), step.tau);
        Tensor<1, 3>       P, L;
        for (unsigned int d = 0; d < 3; ++d)
          {
            P[d] = constraints.targets[d];
            L[d] = constraints.targets[3 + d];
          }
        const Tensor<1, 3> P_frame = transpose(Q) * P, L_frame = transpose(Q) * (L - cross_product_3d(c, P));
        for (unsigned int d = 0; d < 3; ++d)
          {
            constraints.targets[d]     = P_frame[d];
            constraints.targets[3 + d] = L_frame[d];
          }
      }
    for (unsigned int k = 0; k < 6; ++k)
      {
        constraints.columns.push_back(&system.rigid_columns()[k]);
        constraints.rows.push_back(&system.rigid_rows()[k]);
      }
  }

  void
  SurfaceStep::set_constraint_values(StepUnderWay &step, const bool on_old_surface) const
  {
    GlobalConstraints &constraints = step.constraints;
    constraints.values.resize(constraints.first_rigid());
    if (!constraints.rigid_rows)
      return;
    // The rows' Y entries take û of the start (MomentumConstraints::assemble_new_surface_rows()); the constant
    // parts must take the same û, or the linearization is off by 3∫x × (û − u^m) = O(τ) in every BDF2 step,
    // which the multipliers then enforce against the dynamics (a torque ∝ Ω × L in a tumbling body; the work it
    // does broke the energy law, doc/scheme.md, "The discrete energy law").
    std::array<double, 6> momenta = {{0, 0, 0, 0, 0, 0}};
    if (parts.flow.inertia)
      momenta = on_old_surface && step.start->fields == &state.solution ?
                  step.frame.motion.momenta :
                  rigid_motion(step.request, *step.start->fields).momenta;
    for (unsigned int k = 0; k < 6; ++k)
      constraints.values.push_back(constraints.targets[k] + (k < 3 ? 2.0 : 3.0) * momenta[k]);
  }

  bool
  SurfaceStep::solve(StepUnderWay &step, BorderedSystem::BlockVector &solution, Result &result, const bool same_step)
  {
    const GlobalConstraints &constraints = step.constraints;
    const BorderedSystem     bordered(system.matrix(), constraints.columns, constraints.rows);
    const BorderedSolver::Outcome outcome = bordered_solver.solve(
      bordered, system, step.start->tau, constraints.values, step.request.solver, solution, same_step);
    result.linear_iterations += outcome.iterations;
    result.factorized = result.factorized || outcome.factorized;
    if (outcome.failure != StepFailure::none)
      {
        result.failure         = outcome.failure;
        result.message         = outcome.message;
        result.failure_details = outcome.details;
        return false;
      }
    if (constraints.volume_row)
      result.gamma = outcome.multipliers[0];
    double rigid = 0;
    for (unsigned int k = constraints.first_rigid(); k < outcome.multipliers.size(); ++k)
      rigid += outcome.multipliers[k] * outcome.multipliers[k];
    result.rigid_force = std::sqrt(rigid);
    if (record_energy_budget)
      {
        // The multipliers enter the rows of u as +Σ μ_k c_k: their force on the fluid is −Σ μ_k c_k.
        double power = 0;
        for (unsigned int k = 0; k < outcome.multipliers.size(); ++k)
          power -= outcome.multipliers[k] * ((*constraints.columns[k]) * solution.block(0));
        result.energy_budget.multiplier_power = power;
      }
    return true;
  }

  bool
  SurfaceStep::iterate_geometry(StepUnderWay &step, BorderedSystem::BlockVector &solution, Result &result)
  {
    const GeometryIteration &iteration = parts.geometry_iteration;
    const double             node_spacing =
      std::sqrt(step.old_measures.area / geometry.triangulation().n_global_active_cells()) / geometry.degree();
    bool       converged = false;
    // The surface Ỹ_k the step is assembled on; the next one from Ỹ_k and G(Ỹ_k), the solve's new position.
    VectorType             surface = solution.block(0);
    VectorType             iterate = system.ghosted_vector();
    FixedPointAcceleration acceleration([this](const VectorType &a, const VectorType &b) { return system.position_dot(a, b); });
    for (unsigned int k = 1; k <= iteration.max_iterations && !converged; ++k)
      {
        iterate = surface;
        system.copy_new_position_to_geometry(iterate);
        {
          TimerSection section(step_timer, "assembly");
          step.evaluated_curvature = geometry.curvature();
          step.assembly.assemble(assembly_data(step, geometry.normal_field()));
          if (step.constraints.rigid_rows && parts.flow.inertia)
            set_constraint_values(step, false);
        }
        if (!solve(step, solution, result, true))
          return false;
        result.geometry_iterations = k;
        result.geometry_change     = system.largest_node_move(solution.block(0), surface) / node_spacing;
        converged                  = iteration.converged(k, result.geometry_change);
        if (!converged)
          acceleration.advance(surface, solution.block(0));
      }
    if (converged)
      return true;
    std::ostringstream why;
    why << "the geometry iteration did not converge: after " << iteration.max_iterations
        << " re-assemblies the nodes still moved by " << std::setprecision(3) << result.geometry_change
        << " h (tolerance 'geometry iteration/tolerance' = " << iteration.tolerance << ")";
    result.failure = StepFailure::geometry_iteration;
    result.message = why.str();
    return false;
  }

  void
  SurfaceStep::finish(StepUnderWay &step, VectorType &x, Result &result, StepCandidate &candidate)
  {
    const StepRequest &request = step.request;
    const bool         budget  = record_energy_budget && request.velocity == StepRequest::Velocity::flow;
    if (budget)
      result.energy_budget.bending_power = bending_power(x);
    if (error_estimate.enabled() && request.velocity == StepRequest::Velocity::flow)
      result.error_estimate = error_estimate.estimate(system,
                                                      x,
                                                      state.position,
                                                      step.old_curvature->normal,
                                                      step.tau,
                                                      std::sqrt(step.old_measures.area / (4 * numbers::PI)));
    candidate.solution = system.ghosted_vector();
    candidate.solution = x;
    {
      TimerSection section(step_timer, "diagnostics");
      result.dissipation_rate = dissipation_rate(candidate.solution, area_rate(step)); // of ũ on S^m, that of u on the carried surface
    }
    if (step.frame.solved_in_frame())
      {
        system.carry_fields(step.frame.motion, step.tau, x); // out of the carried frame: u = Qũ, Y = carry(Ỹ)
        candidate.solution = x;
      }
    system.copy_new_position_to_geometry(candidate.solution);
    const auto kinetic = [&](const VectorType &flow_vector) {
      return parts.flow.inertia ? kinetic_energy(flow_vector) : 0.0;
    };
    if (budget)
      {
        result.energy_budget.bending_solved    = parts.bending.energy(geometry.willmore_energy());
        result.energy_budget.kinetic_solved    = kinetic(candidate.solution);
        result.energy_budget.kinetic_projected = result.energy_budget.kinetic_solved;
      }
    const ConservationProjection &conservation = parts.conservation;
    if (conservation.enabled && request.prescribed_velocity() == nullptr)
      {
        // The co-rotating step takes the modes of the new surface itself: its last evaluated surface is in the
        // frame, turned by τΩ against the lab.
        const SurfaceGeometry::Curvature modes = step.frame.co_rotating() ? geometry.curvature() : step.evaluated_curvature;
        result.node_correction                 = conservation.project_area_and_volume(
          geometry, modes, state.target_area, state.target_volume, parts.volume_constraint.enabled);
        if (budget)
          result.energy_budget.kinetic_projected = kinetic(candidate.solution);
        VectorType projected = system.owned_vector();
        projected            = candidate.solution;
        system.copy_position_into(geometry.position(), projected);
        if (parts.flow.conserve_momenta && parts.flow.inertia)
          result.momentum_correction =
            conservation.project_momenta(geometry, system.dof_handler(), state.rigid_targets, projected);
        candidate.solution = projected;
      }
    {
      TimerSection section(step_timer, "curvature and energy");
      candidate.position       = geometry.position();
      candidate.curvature      = geometry.curvature();
      candidate.kinetic_energy = kinetic(candidate.solution);
    }
    candidate.tau           = step.tau;
    candidate.mesh_rotation = step.frame.mesh_rotation(step.tau);
    result.solved           = true;
  }

  SurfaceStep::Result
  SurfaceStep::advance(const StepRequest &request, const double tau, StepCandidate &candidate)
  {
    Result                    result;
    const MeshRedistribution &redistribution = parts.redistribution;
    const bool                flow_step      = request.velocity == StepRequest::Velocity::flow;
    const StepFrame           frame          = frame_of(request);
    // X^m: the accepted state's surface; the valve's solves move the geometry itself between them.
    TimeScheme &scheme = flow_step && request.global_constraints ? *time_scheme : backward_euler;
    std::optional<StepStart> start;
    start.emplace(scheme.start(flow_step ? state.position : geometry.position(), state.solution, system, frame, tau));
    const SurfaceGeometry::Measures old_measures = geometry.measure();
    const SurfaceGeometry::Curvature old_curvature = geometry.curvature(); // of S^m (the geometry may be iterated)
    if (record_energy_budget && flow_step)
      {
        result.energy_budget.bending_start = parts.bending.energy(old_curvature.willmore_energy);
        result.energy_budget.kinetic_start = parts.flow.inertia ? kinetic_energy(state.solution) : 0.0;
      }
    // The valve's relaxation solves (velocity at rest) always pull with full weight.
    const double membrane_weight =
      flow_step ? membrane_pull.flow_step_weight(redistribution, old_measures.mesh_quality) : 1.0;
    const bool iterating = corrected_steps.iterating(parts.geometry_iteration) &&
                           request.prescribed_velocity() == nullptr && request.global_constraints;
    // The stages of the step (one but for SDIRK2), each a backward-Euler solve in the frame of the step.
    for (unsigned int stage = 0;; ++stage)
      {
        StepUnderWay step(request, frame, parts, system);
        step.tau                 = scheme.stage_time(stage, tau);
        step.start               = &*start;
        step.old_measures        = old_measures;
        step.old_curvature       = &old_curvature;
        step.membrane_weight     = membrane_weight;
        step.evaluated_curvature = old_curvature;
        // The first solve of an iterated BDF2 step on the extrapolated surface, of second order: one correction
        // from there leaves an O(τ³) or O(τ²) geometry, one from S^m an O(τ) one (doc/scheme.md, "Second order in
        // time").
        const VectorType *extrapolated = iterating ? start->predicted : nullptr;
        const bool        predicted    = extrapolated != nullptr;
        {
          TimerSection section(step_timer, "assembly");
          if (predicted)
            system.copy_new_position_to_geometry(*extrapolated);
          step.assembly.assemble(assembly_data(step, geometry.normal_field()));
        }
        set_up_global_constraints(step, step.constraints);
        set_constraint_values(step, !predicted);
        BorderedSystem::BlockVector solution = bordered_solver.initial_guess(
          BorderedSystem(system.matrix(), step.constraints.columns, step.constraints.rows),
          system.rhs(),
          step.constraints.columns.size());
        if (!solve(step, solution, result))
          return result;
        if (iterating && !iterate_geometry(step, solution, result))
          return result;
        if (stage + 1 == scheme.n_stages())
          {
            finish(step, solution.block(0), result, candidate);
            return result;
          }
        restore_old_geometry();
        start.emplace(scheme.next_stage(stage + 1, solution.block(0), system, frame, tau));
      }
  }

  double
  SurfaceStep::kinetic_energy(const VectorType &flow_vector) const
  {
    return EnergyFunctionals::kinetic_energy(
      geometry.mapping(), system.dof_handler(), flow_vector, geometry.quadrature(), geometry.get_communicator());
  }

  double
  SurfaceStep::bending_power(const VectorType &solution) const
  {
    VectorType fields = system.ghosted_vector();
    fields            = solution;
    // The assembly's Gauss rule on the surface the step was last assembled on (the geometry, still there).
    const QGauss<2>           gauss(system.fe().degree + 1);
    FEValues<2, 3>            flow_values(geometry.mapping(), system.fe(), gauss, update_values | update_JxW_values);
    FEValues<2, 3>            geometry_values(geometry.mapping(), geometry.fe(), gauss, update_values);
    std::vector<Tensor<1, 3>> velocity(gauss.size()), normal(gauss.size());
    std::vector<double>       bending_scalar(gauss.size());
    const VectorType         &smooth_normal = geometry.normal_field();
    double                    power         = 0;
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          flow_values.reinit(cell);
          geometry_values.reinit(typename DoFHandler<2, 3>::active_cell_iterator(&geometry.triangulation(),
                                                                                 cell->level(),
                                                                                 cell->index(),
                                                                                 &geometry.dof_handler()));
          flow_values[FEValuesExtractors::Vector(DofLayout::velocity_component)].get_function_values(fields, velocity);
          flow_values[FEValuesExtractors::Scalar(DofLayout::bending_component)].get_function_values(fields,
                                                                                                   bending_scalar);
          geometry_values[FEValuesExtractors::Vector(0)].get_function_values(smooth_normal, normal);
          for (unsigned int q = 0; q < gauss.size(); ++q)
            power += bending_scalar[q] * (normal[q] * velocity[q]) * flow_values.JxW(q);
        }
    return parts.bending.inverse_bending_number() * Utilities::MPI::sum(power, geometry.get_communicator());
  }

  double
  SurfaceStep::dissipation_rate(const VectorType &flow_vector, const double area_rate) const
  {
    return EnergyFunctionals::dissipation_rate(geometry.mapping(),
                                               system.dof_handler(),
                                               flow_vector,
                                               geometry.quadrature(),
                                               parts.flow.Re,
                                               geometry.get_communicator(),
                                               parts.flow.grad_div,
                                               area_rate);
  }

  double
  SurfaceStep::area_rate(const StepUnderWay &step) const
  {
    // div_P u = s with s = −(A^m − A₀)/(τ_c A^m) returns any area drift (∫div_P u = dA/dt);
    // τ_c = max(τ, τ_drift) keeps the correction bounded when a rejected step shrinks τ.
    return -(step.old_measures.area - state.target_area) / (drift_time(step.start->tau) * step.old_measures.area);
  }
} // namespace FluidSurface
