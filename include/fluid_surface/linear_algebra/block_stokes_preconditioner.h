// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_linear_algebra_block_stokes_preconditioner_h
#define fluid_surface_linear_algebra_block_stokes_preconditioner_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fluid_surface/base/types.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace FluidSurface
{
  /**
   * The iterative solver of the Taylor–Hood saddle-point system [A Bᵀ; B 0] of the fixed-surface flow
   * (velocity DoFs first): GMRES with the block upper-triangular preconditioner
   * @f[ y_p = -\tilde S^{-1} r_p, \qquad y_u = \tilde A^{-1}(r_u - B^T y_p), @f]
   * with Ã⁻¹ one AMG V-cycle (ML) on the velocity block A, or on its low-order-refined counterpart (the same
   * operator with Q1 on the 4 sub-cells of each cell), and the Cahouet–Chabard Schur complement
   * S̃⁻¹ = (1/Re) M_p⁻¹ + (α₀/τ) L_p⁻¹, each inverse one V-cycle. The velocity AMG can work in node frames
   * [t₁ t₂ n], in which the tangentiality penalty acts on the normal DoFs only: Ã⁻¹ = R Ã_R⁻¹ Rᵀ, with Ã_R
   * the velocity matrix assembled in those frames.
   */
  class BlockStokesPreconditioner
  {
  public:
    using VectorType = FluidSurface::VectorType;

    /// How the velocity AMG is built.
    struct VelocityAMGParameters
    {
      std::string smoother;              ///< ML smoother name; "exact": a sparse LU of the matrix instead
      double      aggregation_threshold; ///< ML aggregation threshold θ
      bool        higher_order_elements; ///< the matrix is the Q2 block (false: the low-order-refined one)
      bool        node_frames;           ///< the matrix is written in the node frames
      std::string direct_solver;         ///< Amesos package of the "exact" smoother
    };

    /// An owned velocity node: the DoFs of its x, y, z components and what the AMG's null space needs.
    struct VelocityNode
    {
      std::array<dealii::types::global_dof_index, 3> dofs; ///< local indices in the owned velocity block
      dealii::Point<3>                               position;
      dealii::Tensor<1, 3>                           normal; ///< unit normal of the tangential projection P
      dealii::Tensor<2, 3>                           frame;  ///< columns t₁, t₂, n; the identity if Cartesian
    };

    /// The frame [t₁ t₂ n] of a node with unit normal @p n, t₁ ⊥ the axis least aligned with n.
    static dealii::Tensor<2, 3>
    node_frame(const dealii::Tensor<1, 3> &n);

    /**
     * Builds the AMG hierarchies: of the velocity on @p velocity_matrix (in node frames if the parameters
     * say so) with the tangential rigid motions at @p nodes as near-null space, of the pressure mass matrix
     * @p pressure_mass and, for time-dependent problems, of the pressure Laplacian @p pressure_laplace
     * (nullptr: stationary).
     */
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &velocity_matrix,
               const std::vector<VelocityNode>              &nodes,
               const dealii::TrilinosWrappers::SparseMatrix &pressure_mass,
               const dealii::TrilinosWrappers::SparseMatrix *pressure_laplace,
               const VelocityAMGParameters                  &parameters);

    /// Whether initialize() was called since the last clear().
    bool
    initialized() const
    {
      return pressure_mass_amg != nullptr;
    }

    /// Frees the hierarchies (the matrices changed).
    void
    clear();

    /**
     * Solves @p system x = @p b by GMRES (initial guess @p x, restarted after 98 iterations) to the
     * relative residual @p tolerance, with S̃⁻¹ = @p viscosity M_p⁻¹ + @p alpha_over_tau L_p⁻¹. Returns the
     * number of iterations; throws SolverControl::NoConvergence after @p max_iterations.
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &system,
          VectorType                                   &x,
          const VectorType                             &b,
          const double                                  viscosity,
          const double                                  alpha_over_tau,
          const double                                  tolerance,
          const unsigned int                            max_iterations) const;

  private:
    void
    initialize_velocity(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                        const std::vector<VelocityNode>              &nodes,
                        const VelocityAMGParameters                  &parameters);
    /// Ã⁻¹: one V-cycle (or the exact solve), in node frames if the matrix is written in them.
    void
    apply_velocity_inverse(VectorType &dst, const VectorType &src) const;
    /// v ← Rᵀv (@p transpose) or v ← Rv at every node.
    void
    rotate(VectorType &v, const bool transpose) const;

    /// ML's near-null space of the velocity block (6 modes, node-wise): the tangential rigid motions.
    std::vector<double>                                        rigid_motions;
    std::vector<std::pair<std::array<dealii::types::global_dof_index, 3>, dealii::Tensor<2, 3>>> frames;
    bool                                                       node_frames = false;
    dealii::SolverControl                                      direct_control;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> velocity_amg;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>    velocity_direct;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> pressure_mass_amg;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> pressure_laplace_amg;
    dealii::IndexSet                                           velocity_partition, pressure_partition;
  };
} // namespace FluidSurface

#endif
