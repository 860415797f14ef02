// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_fixed_surface_scene_h
#define fluid_surface_scenes_fixed_surface_scene_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/time_stepping/time_stepper.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/scenes/scene.h>

namespace FluidSurface
{
  /**
   * Scene `fixed surface`: surface Stokes/Navier–Stokes on a surface that does
   * not move (no geometry update, no bending, no volume multiplier), with
   * exact solutions for verification:
   *  - manufactured sphere / ellipsoid: stationary Stokes with u = n × ∇ψ,
   *    ψ = xyz + x²y, p = xy² + z, f = −(2/Re) P div_S σ(u) + ∇_S p;
   *  - killing: u = ω e_z × x on the unit sphere, p = ½ω²(x² + y²), a steady
   *    Navier–Stokes solution that keeps its kinetic energy;
   *  - decaying mode: u = e^{−λt} curl_S Y_l⁰ on the unit sphere,
   *    λ = (l(l+1) − 2)/Re, with or without convection.
   */
  class FixedSurfaceScene : public Scene
  {
  public:
    /// The verification problem.
    enum class Problem
    {
      manufactured_sphere,
      manufactured_ellipsoid,
      killing,
      decaying_mode
    };

    /// Numbers of a finished run, for tests and benchmarks.
    struct Results
    {
      SurfaceFlow::Errors errors;                  ///< at the final time
      double              initial_kinetic_energy = 0;
      double              final_kinetic_energy   = 0;
      double              energy_change          = 0; ///< |F(T) − F(0)| / F(0)
      double              measured_decay_rate    = 0; ///< −ln(F(T)/F(0)) / (2T)
      double              exact_decay_rate       = 0; ///< (l(l+1) − 2)/Re
      unsigned int        steps                  = 0;
      unsigned int        total_iterations       = 0;
      unsigned int        max_iterations         = 0;
      unsigned int        factorizations         = 0;
      double              assemble_time          = 0;
      double              solve_time             = 0;
      double              wall_time              = 0;
      dealii::types::global_dof_index n_dofs     = 0;
    };

    /// See Scene.
    FixedSurfaceScene(SurfaceGeometry                  &geometry,
                      OutputWriter                     &output,
                      StatisticsFile                   &statistics,
                      const dealii::ConditionalOStream &pcout);

    /// Declares `subsection fixed surface`, `subsection time stepping` and (via SurfaceFlow) `subsection flow`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// `model`, `geometry`, `output`, `flow` (not its momentum entries), `fixed surface`, `fixed surface solver`,
    /// `linear solver` and of `time stepping` the end time and the time step.
    ParametersRead
    parameters_read() const override;
    /// Reads them; checks that the problem matches the shape of `subsection geometry` (SurfaceGeometry::parameters(),
    /// which the geometry has parsed first).
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// A whole fixed-surface run: stationary solve or time loop, VTU output, statistics rows, screen lines.
    void
    run() override;

    const Results &
    results() const
    {
      return last_results;
    }

  private:
    /// Whether the problem is a stationary Stokes problem (the manufactured solutions).
    bool
    is_stationary() const;
    /// The decay rate λ = (l(l+1) − 2)/Re of the decaying mode.
    double
    decay_rate() const;
    /// The exact solution of the problem; for the manufactured ones also their body force on @p flow.
    FlowField
    set_up_problem(SurfaceFlow &flow) const;
    /// The stationary solve, its statistics row and output.
    void
    solve_stationary(SurfaceFlow &flow, const FlowField &exact);
    /// The time loop with the fixed step `time stepping/time step` up to `end time`.
    void
    run_time_loop(SurfaceFlow &flow, const FlowField &exact);
    /// One statistics row and screen report at @p time; returns the kinetic energy.
    double
    record(const SurfaceFlow           &flow,
           const FlowField             &exact,
           const unsigned int           step,
           const double                 time,
           const double                 tau,
           const SurfaceFlow::SolveInfo &info);
    /// Writes the VTU file of velocity, pressure and speed at @p time.
    void
    write_output(const SurfaceFlow &flow, const double time);

    /// Wall time since run() started.
    dealii::Timer wall_timer;

    unsigned int            current_step  = 0; ///< the step being computed (for the message of a failure)
    double                  current_time  = 0;
    Problem                 problem       = Problem::manufactured_sphere;
    unsigned int            mode_number   = 2;
    double                  omega         = 1.0;
    TimeStepper::ConstantSteps steps; ///< T, τ and the number of steps (`time stepping`)
    double                  sphere_radius = 1.0;
    dealii::Tensor<1, 3>    semi_axes;
    SurfaceFlow::Parameters flow_parameters;
    Results                 last_results;
  };
} // namespace FluidSurface

#endif
