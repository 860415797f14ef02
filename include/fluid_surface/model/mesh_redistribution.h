// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_mesh_redistribution_h
#define fluid_surface_model_mesh_redistribution_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/model/dof_layout.h>
#include <fluid_surface/model/nodal_point_values.h>
#include <fluid_surface/model/surface_point_values.h>

namespace FluidSurface
{
  /**
   * The mesh motion: the new position Y follows the normal velocity (kinematics) and κñ = Δ_S Y defines the
   * curvature κ of the new surface (Barrett–Garcke–Nürnberg); the tangential motion of the nodes is the mesh
   * law, one of
   *
   * - `bgn`: the tangential part of (κñ, η)_h + (∇_S Y, ∇_S η) = 0 (a conformal parametrization of the current
   *   surface), damped towards X^m + τR, R the rigid motion of the shape;
   * - `reference`: the nodes are carried by the exact rigid motion Z = x_c + Q(τΩ)(X^m − x_c) + τU of the shape
   *   and relax tangentially, on the time scale T_r, towards a minimizer of a frame-invariant membrane energy
   *   of the map from the initial (reference) surface S₀: the shear energy μ∫_{S₀}(½|∇_{S₀}Y|² − J) (zero
   *   iff the map is conformal relative to S₀) plus the area energy (K/2)∫_{S₀}(J − 1)², J = dA/dA₀. A rigid
   *   motion of S₀ costs nothing, so a tumbling body keeps its mesh; element shape and size stay those of S₀.
   *
   * (·,·)_h is the nodal (Gauss–Lobatto) quadrature when lumping is on. Owns `subsection mesh redistribution`.
   * doc/scheme.md has the discrete equations.
   */
  class MeshRedistribution
  {
  public:
    /// Declares `subsection mesh redistribution`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads `subsection mesh redistribution`.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The quadrature of (·,·)_h: Gauss–Lobatto with the nodes of Q_@p degree if lumped, else @p gauss.
    dealii::Quadrature<2>
    nodal_quadrature(const dealii::Quadrature<2> &gauss, const unsigned int degree) const;

    /// T_r/τ, the factor of the tangential damping.
    double
    damping(const double tau) const
    {
      return relaxation_time / tau;
    }

    /// The mesh laws of `law`.
    enum class Law
    {
      bgn,
      reference
    };

    /**
     * Kinematics (1/τ)(Y·ñ, φ)_h − (u·ñ, φ)_h = (1/τ)(W·ñ, φ)_h with W = @p start at the point: X^m (law bgn),
     * or Z − τR (law reference: the exact rigid carry minus its linearization, so that a rigid velocity moves
     * the nodes by the rotation itself). The rows of κ, the columns of Y and u.
     */
    void
    assemble_kinematics(const NodalPointValues   &point,
                        const DofLayout          &dofs,
                        const double              tau,
                        const dealii::Point<3>   &start,
                        dealii::FullMatrix<double> &matrix,
                        dealii::Vector<double>     &rhs) const;

    /// Redistribution, the part (∇_S Y, ∇_S η) of κñ = Δ_S Y at a Gauss point: the rows and columns of Y.
    void
    assemble_surface_laplacian(const SurfacePointValues  &point,
                               const DofLayout           &dofs,
                               dealii::FullMatrix<double> &matrix) const;

    /**
     * Redistribution, the nodal part (κñ, η)_h + (T_r/τ)(P̃Y, η)_h = (T_r/τ)(P̃W, η)_h, P̃ = I − ññ, with the
     * damping target W = @p target at the point: X^m + τR (law bgn) or the carried position Z (law
     * reference). The rows of Y, the columns of κ and Y.
     */
    void
    assemble_nodal_terms(const NodalPointValues     &point,
                         const DofLayout            &dofs,
                         const double                tau,
                         const dealii::Point<3>     &target,
                         dealii::FullMatrix<double>  &matrix,
                         dealii::Vector<double>      &rhs) const;

    /**
     * Law reference, the membrane energy at a Gauss point of S^m, linearized about the carried surface
     * Z = Q X^m + const: with G₀ = ∇_{S^m}X₀ (@p reference_gradient), M = G₀ᵀG₀, J_m = det₂(M)^{−1/2} (area of
     * S^m over S₀) and A = (tr M P − M)/√det₂ M (= b_m/J_m, b_m the left Cauchy–Green tensor of S₀ → S^m),
     *
     *   μ[(∇Y A, ∇η) − (Q, ∇η)] + K s[(s J_m (Q:∇Y) (Q:∇η)) − ((s J_m + 1) Q:∇η)],
     *
     * Q:∇η = div_{S^m}(Qᵀη), s = A₀/A^m (@p area_scale, so that J averages 1). Both parts vanish at Y = Z when
     * S^m is a rigid image of S₀. μ and K are multiplied by @p weight (membrane_weight()). Adds to @p matrix and
     * @p rhs in the rows of Y; they are tested with tangential η only (project_position_rows()).
     */
    void
    assemble_reference_terms(const SurfacePointValues   &point,
                             const dealii::Tensor<2, 3> &reference_gradient,
                             const dealii::Tensor<2, 3> &rotation,
                             const double                area_scale,
                             const double                weight,
                             const DofLayout            &dofs,
                             dealii::FullMatrix<double>  &matrix,
                             dealii::Vector<double>      &rhs) const;

    /**
     * Law reference: the rows of Y at each node n become ñ_nñ_nᵀ (the rows of @p normal_rows: (∇_S Y, ∇_S η),
     * which define κ) plus P̃_n (the rows of @p tangential_rows and @p tangential_rhs: the membrane energy), added
     * to @p matrix and @p rhs. @p node_normals[n] is ñ^m at node n.
     */
    static void
    project_position_rows(const std::vector<dealii::Tensor<1, 3>> &node_normals,
                          const DofLayout                          &dofs,
                          const dealii::FullMatrix<double>         &normal_rows,
                          const dealii::FullMatrix<double>         &tangential_rows,
                          const dealii::Vector<double>             &tangential_rhs,
                          dealii::FullMatrix<double>               &matrix,
                          dealii::Vector<double>                   &rhs);

    /**
     * The weight w(q) of the membrane energy at the mesh quality @p quality of S^m: 1 for q ≤ q₁ (`full pull
     * quality`), 0 for q ≥ q₀ (`pull onset quality`), a smoothstep between. With the conformal rows the
     * nodes keep BGN's distribution while the mesh is good and are pulled towards the membrane energy's
     * minimizer only where the conformal distribution degrades. SurfaceStep uses the largest w of the run.
     */
    double
    membrane_weight(const double quality) const;

    // The entries of `subsection mesh redistribution`, set by parse_parameters().
    Law    law{};                 ///< the tangential mesh law
    /// Law reference: the tangential rows from BGN's (∇_S Y, ∇_S η) instead of the membrane energy.
    bool   conformal_tangential{};
    double shear_stiffness{};     ///< μ of law reference
    double area_stiffness{};      ///< K of law reference
    double pull_onset_quality{};  ///< q₀: the membrane energy acts below this mesh quality
    double full_pull_quality{};   ///< q₁: … and with its full weight below this one
    double anchor_time{};         ///< t_a: S₀ becomes the surface of that time, with full weight (−1: never)
    /// ε_a: the law is also anchored once the non-rigid kinetic energy is at most ε_a|F| (0: never).
    double anchor_non_rigid_energy = 0;
    bool   lumped{};              ///< (·,·)_h by the nodal quadrature
    double relaxation_time{};     ///< T_r of the tangential damping (0: plain BGN)
    bool   follow_rigid_motion{}; ///< the damping relaxes towards X^m + τR instead of X^m
    double rigid_motion_cutoff{}; ///< ε of the regularized fit of R
    double mesh_quality_floor{};  ///< a run stops when the mesh quality falls below this
  };
} // namespace FluidSurface

#endif
