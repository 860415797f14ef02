// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_reference_axisymmetric_equilibrium_h
#define fluid_surface_reference_axisymmetric_equilibrium_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * Rigidly rotating, up–down symmetric axisymmetric equilibrium of a fluid deformable surface (README,
   * "Rotating equilibrium shapes"; method and convergence in benchmarks/equilibrium/README.md).
   *
   * The surface is a surface of revolution about the z axis, rotating with u = ω e_z × X. It is a critical
   * point of F_bend − ½ω² I_zz at fixed area A and enclosed volume V (given ω), or equivalently of
   * F_bend + L²/(2 I_zz) (given angular momentum L = ω I_zz), with F_bend = (1/(2Be))∫H² and
   * I_zz = ∫(x² + y²) dA.
   *
   * Method: the Euler–Lagrange equations of G = F_bend − ½ω² I_zz + σA − PV for the generating curve in
   * arc length s (tangent angle ψ, r' = cos ψ, z' = −sin ψ) are written as the first-order Hamiltonian
   * system of Jülicher & Seifert (PRE 49, 1994) for (ψ, r, H, η), η the multiplier of r' = cos ψ:
   *
   *     ψ' = H − sin ψ / r,     r' = cos ψ,     H' = Be (−½P r cos ψ + η sin ψ / r),
   *     η' = (1/(2Be))(H² − 2H sin ψ / r) + σ − P r sin ψ − (3/2) ω² r²,
   *
   * on the half curve s ∈ [0, S] from the north pole to the equator, with pole conditions ψ = r = η = 0
   * (η(0) = 0 is the vanishing Hamiltonian, i.e. the free length) and equator conditions ψ = π/2, η = 0
   * (mirror symmetry), closed by the area and volume constraints (and ω I_zz = L when L is given).
   * Here H = ψ' + sin ψ / r is positive on a sphere; the public accessors use the sign of the README's
   * "Geometry" section (H = −2/R on a sphere with the outward normal).
   * The system is discretized by Chebyshev collocation in s/S (spectral accuracy) and solved by damped
   * Newton, starting from a spheroid of the same A and V, with continuation in the reduced volume when
   * needed and continuation in ω² (or L) from the resting shape.
   *
   * The collocated equations and Newton: GeneratingCurveCollocation; the start shapes and continuations:
   * EquilibriumContinuation; the interpolant of the curve and its CSV: axisymmetric_equilibrium_curve.cc.
   */
  class AxisymmetricEquilibrium
  {
  public:
    /// The family of up–down symmetric shapes to follow: prolate (elongated along z) or oblate.
    enum class Branch
    {
      prolate,
      oblate
    };

    /// Which rotation quantity is prescribed.
    enum class Prescribed
    {
      angular_velocity,
      angular_momentum
    };

    /// solve() found no equilibrium: Newton failed near the sphere, or a continuation stalled.
    class NoSolution : public std::runtime_error
    {
    public:
      /// Where the solver stopped.
      enum class Stage
      {
        near_sphere,    ///< Newton from the spheroid near v = 1 failed
        reduced_volume, ///< the continuation from the sphere in v stalled at `reached`
        rotation        ///< the continuation from rest in ω² (or L) stalled at `reached`
      };
      NoSolution(const Stage stage, const double reached, const std::string &message)
        : std::runtime_error(message)
        , stage(stage)
        , reached(reached)
      {}
      Stage  stage;
      double reached;
    };

    /// The inputs of one equilibrium computation (the entries of `subsection equilibrium`).
    struct Parameters
    {
      double       area                       = 12.566370614359172; ///< A (4π: the unit sphere's area)
      double       reduced_volume             = 0.75;  ///< v = V / ((4π/3)(A/(4π))^{3/2}), 0 < v ≤ 1
      Branch       branch                     = Branch::prolate;
      double       bending_number             = 1.0;   ///< `Be`; F_bend = (1/(2Be))∫H²
      Prescribed   prescribed                 = Prescribed::angular_velocity; ///< which entry was given
      double       angular_velocity           = 0.0;   ///< ω, used when prescribed = angular_velocity
      double       angular_momentum           = 0.0;   ///< L = ω I_zz, used when prescribed = angular_momentum
      std::string  output_file                = "equilibrium.csv"; ///< CSV of the generating curve
      unsigned int collocation_points         = 48;    ///< N: Chebyshev points 0..N on the half curve
      unsigned int maximal_collocation_points = 512;   ///< N is doubled up to this while under-resolved
      unsigned int output_points              = 401;   ///< rows of the CSV (equispaced in s)
      double       newton_tolerance           = 1e-12; ///< Newton: relative size of the last update
    };

    /// Declares `subsection equilibrium` (area, reduced volume, branch, Be, angular velocity, angular
    /// momentum, output file, collocation points, maximal collocation points, output points, Newton
    /// tolerance).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads `subsection equilibrium`; inconsistent values raise FluidSurface::InputError.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    AxisymmetricEquilibrium() = default;

    /// Sets the inputs directly (no parameter file).
    explicit AxisymmetricEquilibrium(const Parameters &parameters);

    /// The inputs in use.
    const Parameters &
    parameters() const
    {
      return prm;
    }

    /**
     * Computes the equilibrium. N starts at the given number of collocation intervals and is doubled (up to
     * max_collocation) while the virial identity, a consequence of the continuous equations that the
     * discretization does not impose, fails by more than 1e-9. Throws NoSolution if Newton fails to
     * converge, lands on the other branch, or the continuation in ω stalls at a fold of the branch. At reduced
     * volume 1 the only admissible shape is the sphere, whose multipliers are not unique: it is returned with
     * p0 = γ = 0 (then ω must be 0).
     */
    void
    solve();

    /// F_bend = (1/(2Be))∫H² dA.
    double
    bending_energy() const;

    /// I_zz = ∫(x² + y²) dA (unit surface density).
    double
    inertia_zz() const;

    /// ω, the angular velocity about +z.
    double
    angular_velocity() const;

    /// L = ω I_zz.
    double
    angular_momentum() const;

    /// Kinetic energy ½∫|u|² = ½ω² I_zz of the rigid rotation.
    double
    kinetic_energy() const;

    /**
     * The constant p0 of the surface pressure p = p0 + ½ω²r² in the momentum equation (doc/scheme.md,
     * "Unknowns and one step"; strong form −∇_S p − pHν − γν + b). It is minus the Lagrange multiplier σ of
     * the area in G = F_bend − ½ω² I_zz + σA − PV, i.e. p0 = −(surface tension).
     */
    double
    p0() const;

    /**
     * The volume multiplier γ of the momentum equation of doc/scheme.md (force −γν, ν outward); it is minus
     * the multiplier P of the volume in G = F_bend − ½ω² I_zz + σA − PV, i.e. γ = p_outside − p_inside.
     * At rest on a sphere of radius R with b = 0: γ = 2 p0 / R. The scaling (virial) identity reads
     * 3Vγ = 2 p0 A + 2ω² I_zz = 2∫p − (D_t u, X).
     */
    double
    gamma() const;

    /// Radius of the equator (z = 0) circle; for dumbbells this is the neck radius.
    double
    equatorial_radius() const;

    /// z of the north pole (half the extent along the axis; for biconcave shapes the dimple half thickness).
    double
    polar_height() const;

    /// Largest distance of the surface from the z axis.
    double
    max_radius() const;

    /// A = ∫dA of the computed shape.
    double
    area() const;

    /// V, the enclosed volume of the computed shape.
    double
    volume() const;

    /// v = V / ((4π/3)(A/(4π))^{3/2}).
    double
    reduced_volume() const;

    /// Total length 2S of the generating curve from pole to pole.
    double
    curve_length() const;

    /// Relative residual of the scaling identity 3Vγ − 2p0A − 2ω²I_zz (zero at an exact equilibrium).
    double
    virial_residual() const;

    /// Largest collocation residual of the shape equations at the solution, relative.
    double
    shape_equation_residual() const;

    /**
     * Maps the point @p p of the unit sphere (polar angle θ from +z, azimuth φ) to the point of the
     * equilibrium surface with normalized arc length s/(2S) = θ/π along the generating curve (from the north
     * pole) and the same azimuth φ. Spectrally accurate (Chebyshev interpolation of the collocation solution).
     */
    dealii::Point<3>
    map_from_sphere(const dealii::Point<3> &p) const;

    /**
     * Distance from the origin (the centre) to the meridian curve along the ray (sin α, 0, cos α) of the
     * x–z plane, α ∈ [0, 2π) measured from +z. For shapes that are not star-shaped about the centre the
     * largest such distance is returned.
     */
    double
    meridian_radius(const double polar_angle) const;

    /**
     * The generating curve at arc length @p s ∈ [0, 2S] from the north pole: {r, z, ψ, H}, H = k_s + k_φ in
     * the sign convention of the README's "Geometry" section (H = −2/R on a sphere).
     */
    std::vector<double>
    curve_point(const double s) const;

    /**
     * The meridian curvature k_s = dψ/ds of the generating curve and its derivative dk_s/ds at arc length @p s ∈
     * [0, 2S] from the north pole (ψ the tangent angle of curve_point(); k_s = 1/R on a sphere of radius R).
     * k_s = H − sin ψ / r at the collocation nodes (the ψ equation), differentiated once spectrally.
     */
    std::array<double, 2>
    meridian_curvature(const double s) const;

    /// Writes the generating curve pole to pole: header `s,r,z,psi,H`, then `output points` rows.
    void
    write_curve_csv(const std::string &file) const;

    /// Prints `key: value` lines (bending energy, inertia zz, angular velocity, ..., virial residual).
    void
    print(std::ostream &out) const;

    /// Number N of collocation intervals used (`collocation points`, doubled while under-resolved).
    unsigned int
    n_collocation_used() const
    {
      return nodes.empty() ? 0 : nodes.size() - 1;
    }

  private:
    /// Continuation and Newton solve with N collocation intervals.
    void
    solve_collocation(const unsigned int N);

    /// Chebyshev–Lobatto nodes t_j = (1 − cos(πj/N))/2, their barycentric weights and the Clenshaw–Curtis
    /// weights on [0, 1].
    void
    set_collocation_nodes(const unsigned int N);

    /// Values of the half curve at t = s/S ∈ [0, 1] (t = 0 north pole, t = 1 equator): r, z, ψ, H (ψ' + sinψ/r).
    void
    evaluate_half(const double t, double values[4]) const;

    /// Computes the derived quantities from the collocation solution.
    void
    postprocess();

    Parameters prm;

    /// Collocation nodes t_j = s_j / S ∈ [0, 1], barycentric and Clenshaw–Curtis weights.
    std::vector<double> nodes, barycentric_weights, quadrature_weights;

    /// Nodal values on the half curve: ψ, r, z, H (ψ' + sinψ/r, positive on spheres), η.
    std::vector<double> psi, r, z, curvature, eta;

    /// Nodal values on the half curve: the meridian curvature k_s = ψ' and its derivative k_s'.
    std::vector<double> meridian_curvature_values, meridian_curvature_slopes;

    double half_length = 0; ///< S
    double sigma       = 0; ///< multiplier of the area (surface tension)
    double pressure    = 0; ///< multiplier of the volume (inside minus outside pressure)
    double omega       = 0;

    double area_value = 0, volume_value = 0, inertia_value = 0, bending_value = 0, residual_value = 0;
  };

  /**
   * The `--equilibrium FILE.prm` command: declares `subsection equilibrium`, parses @p parameter_file,
   * solves, prints the `key: value` lines on @p out and writes the CSV. Returns 0; bad input throws
   * FluidSurface::InputError.
   */
  int
  run_equilibrium_command(const std::string &parameter_file, std::ostream &out);

  /**
   * Solves @p equilibrium, whose parameters were read from `subsection equilibrium` of the parameter file;
   * an AxisymmetricEquilibrium::NoSolution becomes an InputError that names the entry to change (the
   * angular momentum or velocity when the rotation continuation stalls, the reduced volume when the
   * continuation from the sphere stalls, area and Be when Newton fails near the sphere).
   */
  void
  solve_equilibrium_of_entries(AxisymmetricEquilibrium &equilibrium);
} // namespace FluidSurface

#endif
