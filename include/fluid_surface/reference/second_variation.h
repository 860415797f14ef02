// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_reference_second_variation_h
#define fluid_surface_reference_second_variation_h

#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * The second variation of the energy at a rotating axisymmetric equilibrium (AxisymmetricEquilibrium), per
   * azimuthal number m and parity, for normal perturbations f = a(s) cos(mφ) ν₀ of the surface (doc/stability.md,
   * "The second variation at an axisymmetric equilibrium").
   *
   * Two energies, both at fixed area A and volume V:
   * - isolated, at fixed angular momentum L = L e_z: E = W + ½ L·I⁻¹L, I the inertia tensor about the centre of mass;
   * - driven, at fixed angular velocity ω: E = W − ½ω² I_zz.
   * W = (1/(2Be))∫H². Their second variation on the tangent space of the constraints is that of the Lagrangian
   * E + σA − PV with the equilibrium's multipliers σ = −p0, P = −γ. It is assembled from the exact ε² coefficients
   * of the perturbed 3D geometry (NormalGraphExpansion), in the basis a = sin^m θ cos(kθ), θ = πs/(2S), k of the
   * parity (even: up–down symmetric perturbations), with Gauss–Legendre quadrature in θ. The eigenvalues λ are those
   * of δ²E c = λ G c, G the Gram matrix of ∫f² dA, on the subspace where δA = δV = 0 and f is L²-orthogonal to the
   * normal parts of the translations (which are neutral and are removed): E = E₀ + ½λ‖f‖² along an eigenfunction.
   */
  class SecondVariation
  {
  public:
    /// The energy whose second variation is taken.
    enum class Energy
    {
      isolated, ///< W + ½ L·I⁻¹L at fixed L
      driven    ///< W − ½ω² I_zz at fixed ω
    };

    /// The entries of `subsection second variation`.
    struct Parameters
    {
      std::vector<unsigned int> modes;              ///< azimuthal numbers m; empty: no second variation
      unsigned int              n_eigenvalues = 3;  ///< lowest eigenvalues reported per m, parity and energy
      unsigned int              basis_size    = 24; ///< K: basis functions per parity
      std::string               eigenfunction_file; ///< CSV of the eigenfunctions; empty: none
    };

    /// The lowest eigenvalues of one azimuthal number, parity and energy, with their eigenfunctions.
    struct Spectrum
    {
      unsigned int                     m      = 0;
      bool                             odd    = false;
      Energy                           energy = Energy::isolated;
      std::vector<double>              eigenvalues;  ///< λ, ascending
      std::vector<std::vector<double>> coefficients; ///< of the basis, one vector per λ, ∫f² dA = 1
    };

    /// Declares `subsection second variation` (modes, eigenvalues, basis size, eigenfunction file).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads `subsection second variation`.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    SecondVariation() = default;

    /// Sets the inputs directly (no parameter file).
    explicit SecondVariation(const Parameters &parameters);

    /// The inputs in use.
    const Parameters &
    parameters() const
    {
      return prm;
    }

    /// Whether any azimuthal number is asked for.
    bool
    active() const
    {
      return !prm.modes.empty();
    }

    /// Computes the spectra of every asked m, both parities and both energies at @p equilibrium.
    void
    compute(const AxisymmetricEquilibrium &equilibrium);

    /// The spectra, by m, parity (even, odd) and energy (isolated, driven).
    const std::vector<Spectrum> &
    spectra() const
    {
      return results;
    }

    /**
     * The largest first variation of the Lagrangian over the basis functions of all m and parities, in the dual
     * norm of G (relative to that of W): zero at an exact equilibrium, so a check of the multipliers and geometry.
     */
    double
    first_variation_residual() const
    {
      return residual;
    }

    /// Prints `second variation ...: value` lines.
    void
    print(std::ostream &out) const;

    /**
     * Writes the eigenfunctions: header `energy,m,parity,index,eigenvalue,s,r,z,a`, 101 rows per eigenfunction
     * equispaced in arc length s from the north pole, a(s) with ∫f² dA = 1 and its largest value positive.
     */
    void
    write_eigenfunctions_csv(const std::string &file) const;

    /// The basis function b_k(θ) = sin^m θ cos(kθ) and its first two θ-derivatives.
    static std::array<double, 3>
    basis_function(const unsigned int m, const unsigned int k, const double theta);

    /**
     * The second variation δ²E[f, f] (no constraints imposed) and ∫f² dA of the single perturbation f = a(s) cos(mφ),
     * @p a returning (a, a', a'') at arc length s: for checks, e.g. a rigid tilt or translation of the equilibrium.
     */
    static std::array<double, 2>
    quadratic_form(const AxisymmetricEquilibrium                            &equilibrium,
                   const unsigned int                                        m,
                   const Energy                                              energy,
                   const std::function<std::array<double, 3>(const double)> &a);

  private:
    /// Assembles and solves the problems of azimuthal number @p m and one parity.
    void
    compute_mode(const unsigned int m, const bool odd);

    Parameters                     prm;
    const AxisymmetricEquilibrium *equilibrium = nullptr;
    std::vector<Spectrum>          results;
    double                         residual            = 0;
    unsigned int                   quadrature_points_m0 = 0;
  };
} // namespace FluidSurface

#endif
