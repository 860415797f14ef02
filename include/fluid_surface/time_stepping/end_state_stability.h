// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_time_stepping_end_state_stability_h
#define fluid_surface_time_stepping_end_state_stability_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * The energetic class of an end state that is a body of revolution spinning about its symmetry axis, or one at
   * rest (`steady state/saddle check`). Such a state is the rotating axisymmetric equilibrium of its area A,
   * reduced volume v, angular momentum |L| and Be; AxisymmetricEquilibrium computes it and SecondVariation the
   * second variation of W + ½ L·I⁻¹L there at fixed A, V and L, per azimuthal number m = 0…4 and parity
   * (doc/stability.md). An eigenvalue below −1e-7 (the rigid tilt at rest is a zero mode) is a direction in which
   * the energy falls: one for m = 0, two (cos mφ, sin mφ) for m ≥ 1. By the Kelvin–Tait–Chetaev theorem the
   * dissipative flow leaves such a saddle along it, but only from a perturbation that has that mode: a run whose
   * symmetry-breaking mode is below the rounding of the eigenvalues (an unperturbed start) stays. So a saddle is
   * not an end state: the scene displaces the surface along the most negative class by `saddle perturbation`
   * and goes on (FluidDeformableSurface::perturb_shape()).
   *
   * A state is taken as a body of revolution when two inertia eigenvalues agree to `axisymmetry tolerance` λ₃
   * and the third differs by more: λ₁ ≈ λ₂ an oblate about the axis of λ₃, λ₂ ≈ λ₃ a prolate about the axis of
   * λ₁; it must rotate about that axis (or not at all).
   */
  class EndStateStability
  {
  public:
    /// Declares the entries `saddle check`, `saddle perturbation`, `axisymmetry tolerance` of `steady state`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads them.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether end states are checked.
    bool
    enabled() const
    {
      return check;
    }

    /// The amplitude of the displacement along a falling mode, relative to the distance from the centre of mass.
    double
    perturbation() const
    {
      return amplitude;
    }

    /// What the end state is.
    struct Measures
    {
      double               area = 0, reduced_volume = 0, bending_number = 1;
      double               inertia[3] = {0, 0, 0}; ///< λ₁ ≤ λ₂ ≤ λ₃
      dealii::Tensor<1, 3> least_inertia_axis, largest_inertia_axis, angular_momentum, rotation_vector;
      double               total_energy = 0;
    };

    /// The class of one end state.
    struct Assessment
    {
      bool                 axisymmetric = false; ///< a body of revolution spinning about its axis, or at rest
      bool                 classified   = false; ///< the equilibrium and its second variation were computed
      dealii::Tensor<1, 3> axis;                 ///< its symmetry axis
      unsigned int         directions = 0;       ///< directions in which the energy falls
      unsigned int         m          = 0;       ///< the class of the lowest eigenvalue
      bool                 odd        = false;
      double               lowest     = 0;       ///< the lowest eigenvalue over the classes
      std::string          description;          ///< one line: branch, equilibrium energy, the class

      bool
      saddle() const
      {
        return classified && directions > 0;
      }
    };

    /// The class of the end state @p state.
    Assessment
    assess(const Measures &state) const;

    /// Counts a saddle left at time @p time (for the summary).
    void
    record_saddle(const double time, const Assessment &assessment);

    /// The saddles left so far, for the summary: "none" or "N (at t = …: m = … …; …)".
    std::string
    saddles_left() const;

    void
    save(CheckpointData &data) const;

    void
    load(const CheckpointData &data);

  private:
    bool         check                 = true;
    double       amplitude             = 1e-3;
    double       axisymmetry_tolerance = 1e-3;
    unsigned int n_saddles             = 0;
    std::string  saddle_history;
  };
} // namespace FluidSurface

#endif
