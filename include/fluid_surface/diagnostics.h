#ifndef fluid_surface_diagnostics_h
#define fluid_surface_diagnostics_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <fluid_surface/statistics_file.h>
#include <fluid_surface/surface_geometry.h>

#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;

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
      double               eigenvalues[3]     = {0, 0, 0};
      double               symmetry_deviation = 0, tilt_angle = 0, rigid_fraction = 0;
    };

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

    /// Remembers the first values (drifts are relative to them) and updates running extrema and crossings.
    void
    record(const Values &values, const double time, const double tau);

    /// Adds the columns of design §4 for @p values to the current statistics row.
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
    dealii::Tensor<1, 3> axis;
    double               window_begin = 5, window_end = 10;

    bool   have_initial = false;
    Values initial;
    double area_drift = 0, volume_drift = 0, angular_momentum_drift = 0;
    double crossing_1e4 = std::numeric_limits<double>::quiet_NaN();
    double crossing_1e2 = std::numeric_limits<double>::quiet_NaN();
    double omega_integral = 0, omega_time = 0;
  };
} // namespace FluidSurface

#endif
