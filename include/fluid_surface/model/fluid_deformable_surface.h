// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_fluid_deformable_surface_h
#define fluid_surface_model_fluid_deformable_surface_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/numerics/data_out.h>

#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/step_request.h>
#include <fluid_surface/model/surface_reparametrization.h>
#include <fluid_surface/model/surface_state.h>
#include <fluid_surface/model/surface_step.h>

#include <memory>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The fluid deformable surface of scene full: the initial state (`subsection initial state`), the accepted
   * SurfaceState, the SurfaceStep that advances it (its components own their subsections) and the safety
   * valve (SurfaceReparametrization). A step is solved by advance() as the run's StepRequest says (the flow,
   * or a prescribed velocity for the tests of the mesh law) and kept until accept() or restore_last_state().
   */
  class FluidDeformableSurface
  {
  public:
    /// `subsection initial state`, parsed once: u₀ = U + ω₀ e × (x − c) + ε_u r(x), the shape perturbed by ε_X.
    struct InitialState
    {
      /// `perturbation form`: the form δ(x) of the radial displacement ε_X δ(x).
      enum class PerturbationForm
      {
        random,
        azimuthal
      };

      dealii::Tensor<1, 3> translation_velocity;       ///< U
      double               angular_velocity = 0;       ///< ω₀ as given
      bool                 equilibrium_rotation = false; ///< ω₀ from the geometry's equilibrium shape
      dealii::Tensor<1, 3> rotation_axis;              ///< e (normalized)
      dealii::Point<3>     rotation_centre;            ///< c as given
      double               velocity_perturbation = 0;  ///< ε_u
      double               shape_perturbation    = 0;  ///< ε_X
      PerturbationForm     perturbation_form     = PerturbationForm::random;
      unsigned int         azimuthal_wavenumber  = 2;     ///< m of the azimuthal form
      bool                 azimuthal_odd         = false; ///< its parity (`azimuthal parity = odd`)
      unsigned int         random_seed           = 1;     ///< seed of the perturbations
    };

    /// The model on @p geometry (kept by reference; setup() or load() moves it to the state).
    FluidDeformableSurface(SurfaceGeometry &geometry);

    /// Declares the subsections of the step's components, `reparametrization` and `initial state`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Reads them; τ_max = @p maximum_time_step of the run bounds the drift-correction time from below.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const double maximum_time_step);

    /// Distributes DoFs, sets the initial velocity and remembers V₀, A₀ and S₀.
    void
    setup();

    /**
     * Assembles and solves one step of size @p tau on the current surface into the candidate and moves the
     * geometry to the candidate's surface. The old state is kept until accept() or restore_last_state().
     */
    SurfaceStep::Result
    advance(const double tau);

    /**
     * A prescribed motion instead of the flow: from now on advance() moves the surface with the velocity
     * @p velocity (3 components, evaluated at its current time on S^m; u is its L² projection), through the
     * same mesh law (kinematics and tangential redistribution) as the coupled problem. No bending force acts;
     * the volume and momentum constraints must be off. For tests and benchmarks of the mesh law.
     */
    void
    set_prescribed_velocity(const dealii::Function<3> &velocity);
    /**
     * Makes the last advance() the current state, which is that of time @p time. Returns true when this step
     * anchored the mesh law (`mesh redistribution/anchor time`): S₀ is now the current surface.
     */
    bool
    accept(const double time);
    /// Anchors the mesh law now (what `anchor time` does): S₀ becomes the accepted surface, with full weight.
    void
    anchor();
    /// Whether the mesh law is anchored.
    bool
    is_anchored() const
    {
      return anchored;
    }
    /// Undoes the last advance() (geometry and fields).
    void
    restore_last_state();
    /// The accepted state.
    const SurfaceState &
    accepted_state() const
    {
      return state;
    }
    /**
     * Makes @p new_state (of this model's DoFs, with its targets A₀, V₀, g_k) the accepted state, Y = X: moves the
     * geometry to its X and starts afresh, without the history of BDF2 or of the error estimate (the next step
     * is a backward-Euler step) and with a new factorization. The mesh law's reference S₀ is that of @p new_state.
     */
    void
    restart_from(const SurfaceState &new_state);
    /// The entries of `subsection initial state` (the scenes that check the initial state read them here).
    const InitialState &
    initial_state() const
    {
      return initial_entries;
    }
    /// The axis e of the initial rotation (`initial state/rotation axis`, normalized).
    const dealii::Tensor<1, 3> &
    initial_rotation_axis() const
    {
      return initial_entries.rotation_axis;
    }
    /// ω₀ of the initial rotation (after setup(): the equilibrium's ω with `equilibrium rotation`).
    double
    initial_angular_velocity() const
    {
      return angular_velocity;
    }

    /**
     * Replaces the reference surface S₀ of the mesh law `reference` (set by setup() to the initial surface) by
     * @p position (geometry numbering, the same connectivity): the parametrization the law and the
     * re-parametrization pull towards. Kept in checkpoints.
     */
    void
    set_reference_surface(const VectorType &position);
    /// The safety valve on the accepted state (SurfaceReparametrization::reparametrize()).
    SurfaceReparametrization::Result
    reparametrize();

    /**
     * Displaces the nodes of the accepted state by ε h(x − c) along x − c (c the centre of mass, h @p mode's
     * normalized real part, ε = @p amplitude), as `initial state/perturbation form = azimuthal` does at the start;
     * then A, V and (with `conserve momenta`) the momenta are projected back onto their targets and the step
     * forgets its history. Leaving a saddle of the energy (EndStateStability).
     */
    void
    perturb_shape(const AzimuthalHarmonic &mode, const double amplitude);
    /// The safety valve: its parameters and its record of the run.
    SurfaceReparametrization &
    safety_valve()
    {
      return reparametrization;
    }
    const SurfaceReparametrization &
    safety_valve() const
    {
      return reparametrization;
    }

    /**
     * The total energy F = F_kin + F_bend of a state with kinetic energy @p kinetic_energy = ½∫|u|² and
     * Willmore energy @p willmore_energy = ½∫|κ|², F_bend = (1/2Be)∫|κ|²; in the Stokes limit (no inertia)
     * F = F_bend alone. Every energy of the run (the step's check, the statistics, the valve) is this one.
     */
    double
    total_energy(const double kinetic_energy, const double willmore_energy) const;
    /// ½∫|u^m|² of the accepted state, on the current surface.
    double
    kinetic_energy() const
    {
      return surface_step.kinetic_energy(state.solution);
    }
    /// ½∫|κ|² and F of a state.
    struct Energies
    {
      double willmore = 0;
      double total    = 0;
    };
    /// The energies of the result of the last advance(), before accept(), on its surface (StepCandidate).
    Energies
    candidate_energies() const
    {
      const double willmore = candidate.curvature.willmore_energy;
      return {willmore, total_energy(candidate.kinetic_energy, willmore)};
    }
    /**
     * The time scheme and frame of the flow steps (`time stepping/scheme`, `frame` of @p time), checked against
     * its rules: an input error if @p time grows τ faster than the scheme's step ratio allows, or if the
     * scheme needs the geometry of its new time level and the flow steps do not iterate their geometry to it.
     */
    void
    set_time_scheme(const TimeStepper &time);

    /**
     * The step that advances the state: its components (the parsed subsections), its DoFs of (u, p, κ, y, Y),
     * its solver (factorizations), its time scheme and its controls (error estimation, timer, corrected steps,
     * backward-Euler fallback).
     */
    SurfaceStep &
    step()
    {
      return surface_step;
    }
    const SurfaceStep &
    step() const
    {
      return surface_step;
    }
    /// The DoFs of (u, p, κ, y, Y) of the state (those of the step).
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return surface_step.dof_handler();
    }
    /// u, p, κ, y, Y of the current state, ghosted.
    const VectorType &
    solution() const
    {
      return state.solution;
    }
    /// The components of u and Y in the element (DofLayout).
    static constexpr unsigned int velocity_component = DofLayout::velocity_component;
    static constexpr unsigned int position_component = DofLayout::new_position_component;


    /// Adds u, |u| and p to a DataOut.
    void
    add_output_fields(dealii::DataOut<2, 3> &data_out) const;

    /**
     * Writes the accepted state into a checkpoint (SurfaceState::save()), the element, the number of
     * factorizations, the random seed and the valve's record. Collective.
     */
    void
    save(CheckpointData &data) const;
    /**
     * Instead of setup(): distributes DoFs, reads the state of a checkpoint (written on any number of ranks)
     * and moves the geometry to its X^m.
     */
    void
    load(const CheckpointData &data);

  private:
    /// u₀ of `initial state` and Y = X into state.solution.
    void
    set_initial_velocity();
    /// S₀ (state.reference_surface) → its copy in the flow numbering, state.reference_position.
    void
    set_reference_position();

    SurfaceGeometry         &geometry;
    SurfaceState             state;
    SurfaceStep              surface_step;
    /// The result of the last advance(), until accept() or restore_last_state().
    StepCandidate            candidate;
    SurfaceReparametrization reparametrization;
    /// What advance() asks of the step: the flow (or the prescribed velocity) with the parsed mesh law.
    StepRequest run_request;

    InitialState     initial_entries;
    double           angular_velocity{}; ///< ω₀ (the equilibrium's with `equilibrium rotation`, after setup())
    dealii::Point<3> rotation_centre;    ///< c, moved with the centre of mass by a shape perturbation
    bool anchored = false; ///< `mesh redistribution/anchor time` has passed (checkpoint key `model/anchored`)
    /// The single mode of `perturbation form = azimuthal`; nullptr for the random field.
    std::unique_ptr<AzimuthalHarmonic> azimuthal_perturbation;
  };
} // namespace FluidSurface

#endif
