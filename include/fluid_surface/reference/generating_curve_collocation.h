// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_reference_generating_curve_collocation_h
#define fluid_surface_reference_generating_curve_collocation_h

#include <deal.II/base/numbers.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <cmath>
#include <vector>

namespace FluidSurface
{
  /**
   * Chebyshev collocation of the half-curve boundary value problem of AxisymmetricEquilibrium: the
   * Hamiltonian shape equations for (ψ, r, H, η) in t = s/S ∈ [0, 1] with the pole conditions ψ = r = η = 0,
   * the equator conditions ψ = π/2, η = 0, and the area, volume (and angular momentum) constraints; their
   * residual, Jacobian and damped Newton solve.
   *
   * Unknown vector x: ψ_0..ψ_N, r_0..r_N, H_0..H_N, η_0..η_N, S, σ, P [, ω when L is prescribed].
   */
  class GeneratingCurveCollocation
  {
  public:
    /// The collocation on the nodes @p t ∈ [0, 1] with barycentric weights @p bary and quadrature weights @p cc.
    GeneratingCurveCollocation(const std::vector<double> &t,
                               const std::vector<double> &bary,
                               const std::vector<double> &cc);

    unsigned int        N;       ///< number of collocation intervals
    std::vector<double> nodes;   ///< t_j
    std::vector<double> weights; ///< Clenshaw–Curtis weights of ∫₀¹
    std::vector<double> D;       ///< differentiation matrix d/dt, row-major (N+1)×(N+1)

    double Be = 1;                                        ///< bending number
    double A0 = 4 * dealii::numbers::PI;                  ///< prescribed area
    double V0 = 4 * dealii::numbers::PI / 3;              ///< prescribed volume
    bool   momentum_prescribed = false;                   ///< L prescribed (ω an unknown) instead of ω
    double omega = 0;                                     ///< ω when it is prescribed
    double L0    = 0;                                     ///< L when it is prescribed

    /// Number of unknowns without ω: the four fields, S, σ and P.
    unsigned int
    size_at_rest() const
    {
      return 4 * (N + 1) + 3;
    }
    /// Number of unknowns.
    unsigned int
    size() const
    {
      return size_at_rest() + (momentum_prescribed ? 1 : 0);
    }
    /// Index of ψ_j.
    unsigned int
    psi(unsigned int j) const
    {
      return j;
    }
    /// Index of r_j.
    unsigned int
    r(unsigned int j) const
    {
      return N + 1 + j;
    }
    /// Index of H_j.
    unsigned int
    H(unsigned int j) const
    {
      return 2 * (N + 1) + j;
    }
    /// Index of η_j.
    unsigned int
    eta(unsigned int j) const
    {
      return 3 * (N + 1) + j;
    }
    /// Index of the half length S.
    unsigned int
    S() const
    {
      return 4 * (N + 1);
    }
    /// Index of the area multiplier σ.
    unsigned int
    sigma() const
    {
      return S() + 1;
    }
    /// Index of the volume multiplier P.
    unsigned int
    P() const
    {
      return S() + 2;
    }
    /// Index of ω (only when L is prescribed).
    unsigned int
    w() const
    {
      return S() + 3;
    }

    /// ω of the state @p x: its unknown ω when L is prescribed, else the prescribed ω.
    double
    omega_of(const std::vector<double> &x) const
    {
      return momentum_prescribed ? x[w()] : omega;
    }

    /// Reference moment of inertia of the sphere of area A0, to scale the angular momentum row.
    double
    inertia_scale() const
    {
      const double R2 = A0 / (4 * dealii::numbers::PI);
      return 8 * dealii::numbers::PI / 3 * R2 * R2;
    }

    /// Radius R of the sphere of area A0.
    double
    sphere_radius() const
    {
      return std::sqrt(A0 / (4 * dealii::numbers::PI));
    }

    /// Volume of a shape of area A0 and reduced volume @p v.
    double
    volume_at(const double v) const
    {
      const double R_area = sphere_radius();
      return v * 4 * dealii::numbers::PI / 3 * R_area * R_area * R_area;
    }

    /// (Dv)_j for the block of x starting at @p offset.
    double
    derivative(const std::vector<double> &x, const unsigned int offset, const unsigned int j) const;

    /// The residual at @p x: the collocated shape equations with the pole and equator conditions, then the
    /// equator angle and the relative area, volume (and angular momentum) defects.
    void
    residual(const std::vector<double> &x, std::vector<double> &R) const;

    /// The Jacobian of residual() at @p x.
    void
    jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const;

    /// The state is admissible: positive length and r > 0 away from the pole.
    bool
    admissible(const std::vector<double> &x) const;

    /// Damped Newton; returns true when the update fell below @p tolerance and the residual is small.
    bool
    newton(std::vector<double> &x, const double tolerance, unsigned int &iterations) const;

    /**
     * Least-squares fit of the multipliers η_0..η_N, σ, P to the H and η equations at the shape (ψ, r, H, S)
     * held in @p y, with η(0) = η(S) = 0 as heavily weighted rows; writes them into @p y. Solved with the
     * pseudo-inverse of LAPACK's singular value decomposition.
     */
    void
    fit_multipliers(std::vector<double> &y) const;

    /// Euclidean norm.
    static double
    norm(const std::vector<double> &v);

  private:
    /// The rows of the collocated shape equations (ψ, r, H, η at every node) of the Jacobian.
    void
    add_shape_equation_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const;

    /// The rows of the equator condition and the area, volume (and angular momentum) constraints.
    void
    add_constraint_jacobian(const std::vector<double> &x, dealii::LAPACKFullMatrix<double> &J) const;
  };
} // namespace FluidSurface

#endif
