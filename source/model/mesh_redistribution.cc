#include <deal.II/base/quadrature_lib.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/mesh_redistribution.h>

namespace FluidSurface
{
  using namespace dealii;

  void
  MeshRedistribution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    prm.declare_entry("lumped",
                      "true",
                      Patterns::Bool(),
                      "Nodal (Gauss–Lobatto) quadrature for (Y·ñ, φ) and (κñ, η), as in the BGN scheme.");
    prm.declare_entry("relaxation time",
                      "0.05",
                      RealRange::closed(0, 1e6),
                      "T_r, 0 ≤ T_r ≤ 1e6, of the tangential damping (T_r/τ)(P̃(Y − X^m), η)_h added to the BGN equation: "
                      "the mesh relaxes towards the BGN distribution on the time scale T_r h² instead of "
                      "jumping there within one step, so that steps τ → 0 change nothing. 0: plain BGN.");
    prm.declare_entry("follow rigid motion",
                      "true",
                      Patterns::Bool(),
                      "The tangential damping relaxes the nodes towards X^m + τR instead of X^m, R = U + Ω × (x − x_c) "
                      "the rigid motion of the shape (its normal part R·ν fits u^m·ν in L²): a rotating or "
                      "translating body carries its mesh along instead of moving through it, while a body spinning "
                      "about its own axis of symmetry (R·ν ≡ 0) leaves its mesh in place. No effect when T_r = 0.");
    prm.declare_entry("rigid motion cutoff",
                      "0.01",
                      RealRange::at_least(0),
                      "ε ≥ 0 of the fit of R: min ∫(u·ν − R·ν)² + ε|S||c|², c the coefficients of R in the basis e_d, "
                      "e_d × (x − x_c)/R_g (R_g the radius of gyration); rigid motions with ∫(R·ν)² ≪ ε|S||c|² are "
                      "not followed.");
    prm.declare_entry("mesh quality floor",
                      "0.02",
                      RealRange::closed(0, 1),
                      "q_min, 0 ≤ q_min ≤ 1: the run stops when min over cells of σ_min/σ_max of the Jacobian falls below.");
    prm.leave_subsection();
  }

  void
  MeshRedistribution::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    lumped              = prm.get_bool("lumped");
    relaxation_time     = prm.get_double("relaxation time");
    follow_rigid_motion = prm.get_bool("follow rigid motion");
    rigid_motion_cutoff = prm.get_double("rigid motion cutoff");
    mesh_quality_floor  = prm.get_double("mesh quality floor");
    prm.leave_subsection();
  }

  Quadrature<2>
  MeshRedistribution::nodal_quadrature(const Quadrature<2> &gauss, const unsigned int degree) const
  {
    if (lumped)
      return QGaussLobatto<2>(degree + 1);
    return gauss;
  }

  void
  MeshRedistribution::assemble_kinematics(const NodalPointValues &point,
                                          const DofLayout        &dofs,
                                          const double            tau,
                                          FullMatrix<double>     &matrix,
                                          Vector<double>         &rhs) const
  {
    const double        inv_tau = 1.0 / tau;
    const double        dA      = point.JxW;
    const Tensor<1, 3> &nt      = point.smooth_normal;
    for (const unsigned int i : dofs.curvature)
      {
        const double phi = point.curvature[i];
        rhs(i) += inv_tau * (point.position * nt) * phi * dA;
        for (const unsigned int j : dofs.new_position)
          matrix(i, j) += inv_tau * (point.new_position[j] * nt) * phi * dA;
        for (const unsigned int j : dofs.velocity)
          matrix(i, j) -= (point.velocity[j] * nt) * phi * dA;
      }
  }

  void
  MeshRedistribution::assemble_surface_laplacian(const SurfacePointValues &point,
                                                 const DofLayout          &dofs,
                                                 FullMatrix<double>       &matrix) const
  {
    const double dA = point.flow.JxW;
    for (const unsigned int i : dofs.new_position)
      for (const unsigned int j : dofs.new_position)
        matrix(i, j) += scalar_product(point.new_position_gradient[i], point.new_position_gradient[j]) * dA;
  }

  void
  MeshRedistribution::assemble_nodal_terms(const NodalPointValues &point,
                                           const DofLayout        &dofs,
                                           const double            tau,
                                           const Tensor<1, 3>     &rigid_velocity,
                                           FullMatrix<double>     &matrix,
                                           Vector<double>         &rhs) const
  {
    const double        damping_factor = damping(tau);
    const double        dA             = point.JxW;
    const Tensor<1, 3> &nt             = point.smooth_normal;
    const Point<3>     &x              = point.position;
    for (const unsigned int i : dofs.new_position)
      {
        // (κñ, η)_h, and the tangential damping (T_r/τ)(P̃(Y − X^m − τR), η)_h.
        const Tensor<1, 3> &eta         = point.new_position[i];
        const Tensor<1, 3>  eta_tangent = eta - (eta * nt) * nt;
        rhs(i) += damping_factor * ((x + tau * rigid_velocity) * eta_tangent) * dA;
        for (const unsigned int j : dofs.curvature)
          matrix(i, j) += point.curvature[j] * (nt * eta) * dA;
        if (damping_factor > 0)
          for (const unsigned int j : dofs.new_position)
            matrix(i, j) += damping_factor * (point.new_position[j] * eta_tangent) * dA;
      }
  }
} // namespace FluidSurface
