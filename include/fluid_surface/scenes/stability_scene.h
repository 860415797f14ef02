// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_scenes_stability_scene_h
#define fluid_surface_scenes_stability_scene_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/model/nodal_vector_field.h>
#include <fluid_surface/scenes/scene.h>

#include <complex>
#include <memory>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * Scene `stability`: the leading eigenvalues of the rotating axisymmetric equilibrium of `geometry/shape =
   * equilibrium`, by azimuthal wavenumber m and parity, from the time-T map of the full model (time-stepper based
   * stability, Tuckerman & Barkley). The map Φ_T advances a state (X, u) by T/τ steps of the model's own step (as
   * `time stepping/scheme` says; BDF2's first step split into τ/8, τ/8, τ/4, τ/2) with the targets A₀, V₀, L₀ of
   * the equilibrium, so that a perturbation is carried on the constraints. Its linearization
   *   A v = R(−θ)[Φ_T(x_eq + εv) − Φ_T(x_eq)]/ε
   * about x_eq (the equilibrium after `settling time`), θ the angle through which the nodes of the unperturbed
   * map turned, is the linearized full model over T in the frame of the nodes. Arnoldi on A from the seed h_m of
   * (m, parity) gives multipliers μ with growth rates σ = ln|μ|/T; each Ritz vector is classified by its azimuthal
   * content (NodalVectorField::azimuthal_content()), and its frequency arg μ/T is turned into the co-rotating one.
   * The rows go to `spectrum.csv` in the output directory, written after each wavenumber (a run that stops keeps
   * the rows so far); the Arnoldi iterations to the statistics file. doc/stability.md describes the method.
   */
  class StabilityScene : public Scene
  {
  public:
    /// See Scene; @p wall_timer is the Simulation's clock.
    StabilityScene(const MPI_Comm                    communicator,
                   SurfaceGeometry                  &geometry,
                   OutputWriter                     &output,
                   StatisticsFile                   &statistics,
                   const dealii::ConditionalOStream &pcout,
                   const dealii::Timer              &wall_timer);

    /// Declares `subsection stability`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Those of scene full but `reparametrization` (the map has no safety valve), `steady state`,
    /// `diagnostics` and `checkpoint`, with `stability`; of `time stepping` not the end time nor the entries of
    /// the step size control (each map takes T/τ steps of τ).
    ParametersRead
    parameters_read() const override;
    /// Reads it, the time stepping (τ, scheme) and the model; InputError unless the shape is an unperturbed
    /// equilibrium rotating rigidly with its ω.
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// The unperturbed map (and the check that it is an equilibrium), then Arnoldi for each wavenumber and parity.
    void
    run() override;

  private:
    /// The base state: the equilibrium of the geometry, or the end state of a checkpoint, settled if asked for.
    void
    set_up_base_state();
    /// The unperturbed time-T map: the nodes' turn, the body's, and the check that the base state is an equilibrium
    /// of the discrete model (InputError otherwise).
    void
    measure_unperturbed_map();
    /// Arnoldi per wavenumber and parity, the rows of spectrum.csv, and RunFailed if a reported value did not converge.
    void
    compute_spectrum();
    /// A perturbation (δX, δu): the position in the geometry numbering, the velocity in the flow numbering
    /// (zero on p, κ, y, Y); both owned.
    struct Perturbation
    {
      VectorType position;
      VectorType velocity;
      double
      dot(const Perturbation &other) const
      {
        return position * other.position + velocity * other.velocity;
      }
      void
      add(const double a, const Perturbation &other)
      {
        position.add(a, other.position);
        velocity.add(a, other.velocity);
      }
      void
      scale(const double a)
      {
        position *= a;
        velocity *= a;
      }
    };

    /// One eigenvalue (with its conjugate) of the map, classified.
    struct Mode
    {
      std::complex<double> multiplier; ///< μ, Im μ ≥ 0
      double               residual;   ///< ‖A z − μ z‖/|μ| of its unit Ritz vector z
      unsigned int         m;          ///< the wavenumber of the largest azimuthal content
      bool                 odd;        ///< its parity
      double               purity;     ///< the share of that content in the whole
      double               normal_share; ///< the share of δX normal to the surface (NodalVectorField::normal_share())
      /// the share of δX·n that the translations and the turn about the rotation axis give: ≈ 1 for the neutral
      /// modes of the symmetries (NodalVectorField::symmetry_share())
      double symmetry_share;
      double frequency; ///< the co-rotating frequency of arg Q_m (signed, in (−π/T, π/T])
    };

    /// A zero perturbation.
    Perturbation
    zero() const;
    /// The state after @p steps steps from @p start; RunFailed (naming @p what) if a step is not solved.
    SurfaceState
    advanced(const SurfaceState &start, const unsigned int steps, const std::string &what);
    /// A v (see the class); @p what names the map application in a failure.
    Perturbation
    mapped(const Perturbation &v, const std::string &what);
    /// The unit seed: the radial displacement Re h_m/max|h_m| (AzimuthalHarmonic), no velocity.
    Perturbation
    seed(const unsigned int m, const bool odd) const;
    /// Arnoldi from seed(m, odd) until the leading Ritz value of (m, odd) converges, or the Krylov space is full
    /// after `maximum restarts` thick restarts (restart()); the leading modes of (m, odd).
    std::vector<Mode>
    arnoldi(const unsigned int m, const bool odd);
    /**
     * The thick (Krylov–Schur) restart of a full Arnoldi factorization A V_j = V_j H_j + h v e_jᵀ, with
     * @p next = v the unit vector that would extend the basis. Keeps the real invariant subspace of H_j spanned by
     * the Ritz vectors of @p kept (the leading modes of the seed's wavenumber and parity; complex pairs as their
     * real and imaginary parts), of dimension p ≤ j/2: with Y its orthonormal basis, A (V_j Y) = (V_j Y)(YᵀH_jY) +
     * h v (e_jᵀY). @p basis becomes [V_j Y, v] and @p H holds YᵀH_jY with the row h e_jᵀY below it. Returns p.
     */
    unsigned int
    restart(dealii::FullMatrix<double>  &H,
            const unsigned int           j,
            std::vector<Perturbation>   &basis,
            const std::vector<Mode>     &kept,
            const Perturbation          &next) const;
    /// The Ritz values of the leading j×j block of @p H with their residuals and the classification of their Ritz
    /// vectors in the Krylov @p basis; sorted by |μ|, one per conjugate pair.
    std::vector<Mode>
    ritz_modes(const dealii::FullMatrix<double> &H, const unsigned int j, const std::vector<Perturbation> &basis) const;
    /// Appends @p modes of the run from (m, parity) to spectrum.csv (rank 0).
    void
    write_rows(const unsigned int m, const bool odd, const std::vector<Mode> &modes) const;

    MPI_Comm             communicator;
    const dealii::Timer &wall_timer;
    FluidDeformableSurface model;

    // subsection stability
    std::vector<unsigned int> wavenumbers;           ///< m
    std::vector<bool>         parities;              ///< false: even, true: odd
    double                    map_time = 0;          ///< T
    unsigned int              n_steps  = 0;          ///< T/τ
    unsigned int              n_settling_steps = 0;  ///< t_s/τ
    double                    tau      = 0;          ///< τ
    unsigned int              max_krylov = 0;        ///< largest Krylov dimension
    unsigned int              max_restarts = 0;      ///< thick restarts per (m, parity) at most
    unsigned int              n_reported = 0;        ///< eigenvalue pairs reported per (m, parity)
    double                    epsilon    = 0;        ///< ε
    double                    residual_tolerance = 0;    ///< convergence of the leading Ritz value
    double                    equilibrium_tolerance = 0; ///< largest drift of the unperturbed map, relative

    SurfaceState                      base;     ///< x_eq
    SurfaceState                      base_end; ///< Φ_T(x_eq)
    VectorType                        base_normal; ///< the nodal normal ñ of x_eq
    dealii::Tensor<2, 3>              back_rotation; ///< R(−θ)
    double                            node_rotation_rate = 0; ///< θ/T
    double body_rotation_rate = 0; ///< ω of the equilibrium; that of the nodes for an end state (carried nodes)
    bool        from_checkpoint = false; ///< `base state = checkpoint`
    std::string checkpoint_directory;    ///< `checkpoint directory`
    bool        anchor_end_state = true; ///< `anchor the end state`
    bool        unconverged_leading = false; ///< the last arnoldi() ended without convergence
    unsigned int restarts_used = 0;           ///< the restarts of the last arnoldi()
    dealii::Tensor<1, 3>              axis;
    dealii::Point<3>                  centre;
    std::unique_ptr<NodalVectorField> positions, velocities;
    std::string                       spectrum_file;
  };
} // namespace FluidSurface

#endif
