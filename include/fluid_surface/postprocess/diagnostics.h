// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_postprocess_diagnostics_h
#define fluid_surface_postprocess_diagnostics_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <array>
#include <complex>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

  /**
   * A plane section of the surface in polar form: the distance r(φ_j) from @p centre to the surface along the
   * ray centre + r (cos φ_j e₁ + sin φ_j e₂), φ_j = 2πj/n, j = 0..n−1, in the plane spanned by the orthonormal
   * @p e1 and @p e2. The points are the exact intersections of the ray with the discrete (curved) surface,
   * found by Newton's method on the cell map started from a piecewise linear section; where a ray meets the
   * surface more than once the largest distance is taken, and a ray that meets it nowhere gives NaN.
   */
  std::vector<double>
  section_polar_radius(const SurfaceGeometry      &geometry,
                       const dealii::Point<3>     &centre,
                       const dealii::Tensor<1, 3> &e1,
                       const dealii::Tensor<1, 3> &e2,
                       const unsigned int          n_angles);

  /**
   * E(L²) = (∫₀^{2π} |r_O(φ) − r_E(φ)|² dφ)^{1/2} (seed eq. 8) by the trapezoidal rule on the angles
   * φ_j = 2πj/n of @p r_E and @p r_O (spectrally accurate for smooth periodic curves).
   */
  double
  polar_l2_distance(const std::vector<double> &r_E, const std::vector<double> &r_O);

  /**
   * The seed paper's measures of a rotating surface (its section 3.1) and the
   * conservation checks, from the surface S and the velocity u:
   * ω(t) = (1/|S|)∫ (u·e_φ)/r about the axis e through the centre of mass,
   * linear momentum ∫u, angular momentum L = ∫(x − x_c) × u, the inertia
   * tensor I = ∫(|x − x_c|² 1 − (x − x_c)⊗(x − x_c)) with ascending
   * eigenvalues λ₁ ≤ λ₂ ≤ λ₃, the elongation axis (eigenvector of λ₁: the
   * direction of smallest moment, i.e. the long axis), the symmetry deviation
   * e(λ) = |λ_a − λ_b|/⟨λ⟩ over the closest pair, the rigid-body angular
   * velocity Ω = I⁻¹L, the tilt angle between Ω and the elongation axis (in
   * degrees, 0…90), and the rigid fraction ½Ω·L / F_kin (1 for a Killing field).
   */
  class Diagnostics
  {
  public:
    /// The values of one evaluation.
    struct Values
    {
      double               area = 0, volume = 0, reduced_volume = 0, mesh_quality = 0;
      double               kinetic_energy = 0, angular_velocity = 0, max_normal_velocity = 0;
      dealii::Tensor<1, 3> linear_momentum, angular_momentum, rotation_vector, elongation_axis;
      /// The eigenvector of λ₃ (the axis of an oblate body of revolution).
      dealii::Tensor<1, 3> largest_inertia_axis;
      double               eigenvalues[3]     = {0, 0, 0};
      double               symmetry_deviation = 0, tilt_angle = 0, rigid_fraction = 0;
      /// E(L²) to the reference equilibrium: the section through the axis, the one normal to it (through
      /// the centre of mass), and their root sum of squares (NaN without a reference).
      double l2_distance_axial      = std::numeric_limits<double>::quiet_NaN();
      double l2_distance_equatorial = std::numeric_limits<double>::quiet_NaN();
      double l2_distance            = std::numeric_limits<double>::quiet_NaN();
      /// Q_m (even, odd) for each of the `azimuthal modes` (AzimuthalHarmonic), in that order.
      std::vector<std::complex<double>> azimuthal_moments;
    };

    /// E(L²) of the axial and equatorial sections of @p geometry (about its centre of mass and the axis e) to
    /// @p shape: {axial, equatorial}.
    std::pair<double, double>
    l2_distance(const SurfaceGeometry &geometry, const AxisymmetricEquilibrium &shape) const;

    /// The same for a reference given by its meridian radii r_O(φ_j) (φ from the axis) and its equator radius.
    std::pair<double, double>
    l2_distance(const SurfaceGeometry &geometry, const std::vector<double> &meridian, const double equator) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Evaluates every measure on the current surface for the velocity in the
     * first three components of @p state (a field on @p dofs).
     */
    Values
    evaluate(const SurfaceGeometry &geometry, const dealii::DoFHandler<2, 3> &dofs, const VectorType &state) const;

    /**
     * When `reference equilibrium` is not `none`: computes the reference shape of E(L²), the rotating
     * axisymmetric equilibrium (about e) with the area, reduced volume and angular momentum L·e of
     * @p initial and the bending number @p bending_number. Screen report on @p out.
     */
    void
    set_reference(const Values &initial, const double bending_number, std::ostream &out);

    /// The values of the first record() (restored by load()).
    const Values &
    initial_values() const
    {
      return initial;
    }

    /// The reference equilibrium of E(L²), or nullptr.
    const AxisymmetricEquilibrium *
    reference() const
    {
      return reference_shape.get();
    }

    /**
     * At the end of a run: the equilibrium rotating with the measured ⟨ω⟩ (same area, reduced volume and Be as
     * the reference) and the E(L²) of the final surface @p geometry to it, for the summary.
     */
    void
    compare_with_mean_rotation(const SurfaceGeometry &geometry);

    /// Remembers the first values (drifts are relative to them) and updates running extrema and crossings.
    void
    record(const Values &values, const double time, const double tau);

    /// Adds the diagnostics' columns of the `statistics` file (listed in the README, "Scenes and experiments")
    /// for @p values to the current statistics row.
    void
    add_to_statistics(const Values &values, StatisticsFile &statistics) const;

    /// Writes the `summary` keys (one `key: value` per line) to @p out.
    void
    write_summary(std::ostream      &out,
                  const double        final_total_energy,
                  const unsigned int  steps,
                  const unsigned int  rejected_steps,
                  const double        wall_time) const;

    double
    max_area_drift() const
    {
      return area_drift;
    }
    double
    max_volume_drift() const
    {
      return volume_drift;
    }
    double
    max_angular_momentum_drift() const
    {
      return angular_momentum_drift;
    }

    /// Writes the reference values, running drifts, crossing times and the ω integral into a checkpoint.
    void
    save(CheckpointData &data) const;
    void
    load(const CheckpointData &data);

  private:
    dealii::Tensor<1, 3>  axis;                                ///< `axis` e, normalized
    std::array<double, 2> angular_velocity_window = {{5, 10}}; ///< `angular velocity window` [t₀, t₁]

    bool   have_initial = false;
    Values initial;
    double area_drift = 0, volume_drift = 0, angular_momentum_drift = 0;
    double crossing_1e4 = std::numeric_limits<double>::quiet_NaN();
    double crossing_1e2 = std::numeric_limits<double>::quiet_NaN();
    /// t and e(λ) of the last recorded step: a crossing is interpolated in ln e(λ) between it and the next.
    double last_time      = std::numeric_limits<double>::quiet_NaN();
    double last_deviation = std::numeric_limits<double>::quiet_NaN();
    /// ω = |Ω| of the last recorded step: with the steady-state stop, the end state's angular velocity.
    double last_angular_velocity = std::numeric_limits<double>::quiet_NaN();
    double omega_integral = 0, omega_time = 0;

    /// `reference equilibrium`: the branch of the reference shape of E(L²); none: no reference
    std::optional<AxisymmetricEquilibrium::Branch> reference_equilibrium;
    unsigned int section_angles        = 256;    ///< `section angles`: n of section_polar_radius
    std::vector<unsigned int> azimuthal_modes; ///< `azimuthal modes`: the m of the moments Q_m
    std::unique_ptr<AxisymmetricEquilibrium> reference_shape;
    std::vector<double> reference_meridian; ///< r_O(φ_j) of reference_shape's meridian section
    double       min_l2_distance = std::numeric_limits<double>::quiet_NaN(), min_l2_time = 0;
    /// From compare_with_mean_rotation(): ⟨ω⟩-equilibrium bending energy, I_zz, and the final E(L²) to it.
    std::string  mean_rotation_comparison;
  };
} // namespace FluidSurface

#endif
