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
   * BGN-type mesh motion: the new position Y follows the normal velocity (kinematics,
   * (Y·ñ, φ)_h = (X^m·ñ, φ)_h + τ(u·ñ, φ)_h), and its tangential motion keeps the mesh regular through
   * (κñ, η)_h + (∇_S Y, ∇_S η) = 0, i.e. κñ = Δ_S Y (κ = H of the new surface), damped towards X^m + τR
   * (R the rigid motion of the shape). (·,·)_h is the nodal (Gauss–Lobatto) quadrature when lumping is on, as
   * in Barrett–Garcke–Nürnberg. Owns `subsection mesh redistribution`.
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

    /// Kinematics (1/τ)(Y·ñ, φ)_h − (u·ñ, φ)_h = (1/τ)(X^m·ñ, φ)_h: the rows of κ, the columns of Y and u.
    void
    assemble_kinematics(const NodalPointValues   &point,
                        const DofLayout          &dofs,
                        const double              tau,
                        dealii::FullMatrix<double> &matrix,
                        dealii::Vector<double>     &rhs) const;

    /// Redistribution, the part (∇_S Y, ∇_S η) of κñ = Δ_S Y at a Gauss point: the rows and columns of Y.
    void
    assemble_surface_laplacian(const SurfacePointValues  &point,
                               const DofLayout           &dofs,
                               dealii::FullMatrix<double> &matrix) const;

    /**
     * Redistribution, the nodal part (κñ, η)_h + (T_r/τ)(P̃Y, η)_h = (T_r/τ)(P̃(X^m + τR), η)_h, P̃ = I − ññ,
     * with the rigid motion R = @p rigid_velocity at the point (0 unless `follow rigid motion`): the rows of
     * Y, the columns of κ and Y.
     */
    void
    assemble_nodal_terms(const NodalPointValues     &point,
                         const DofLayout            &dofs,
                         const double                tau,
                         const dealii::Tensor<1, 3> &rigid_velocity,
                         dealii::FullMatrix<double>  &matrix,
                         dealii::Vector<double>      &rhs) const;

    // The entries of `subsection mesh redistribution`, set by parse_parameters().
    bool   lumped{};              ///< (·,·)_h by the nodal quadrature
    double relaxation_time{};     ///< T_r of the tangential damping (0: plain BGN)
    bool   follow_rigid_motion{}; ///< the damping relaxes towards X^m + τR instead of X^m
    double rigid_motion_cutoff{}; ///< ε of the regularized fit of R
    double mesh_quality_floor{};  ///< a run stops when the mesh quality falls below this
  };
} // namespace FluidSurface

#endif
