#ifndef fluid_surface_model_geometry_iteration_h
#define fluid_surface_model_geometry_iteration_h

#include <deal.II/base/parameter_handler.h>

namespace FluidSurface
{
  /**
   * The implicit geometry of one step (`subsection geometry iteration`): the step system, assembled on the
   * surface S^m of the last step (the lagged scheme), is assembled again on the surface S^{m+1,k} of its own
   * solution and solved again (GMRES preconditioned by the kept factorization), until the new nodes move by
   * less than ε_g h between two iterates (h = √(A/N_cells)/k, the node spacing). The data of the old time level
   * (u^m, X^m, the rigid motion of the shape, the drift corrections) stay those of S^m; the normal ñ, the
   * curvature coefficient c, the metric and the transport gradient G^m = ∇_S u^m are those of the iterate.
   * doc/scheme.md, "Implicit geometry".
   */
  struct GeometryIteration
  {
    /// Declares `subsection geometry iteration`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Reads `subsection geometry iteration`.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether the step iterates its geometry at all (N_g > 0).
    bool
    enabled() const
    {
      return max_iterations > 0;
    }

    /// What the re-assemblies take from the iterate S^{m+1,k}: everything, or (to find out which lagged quantity
    /// limits the lagged step, benchmarks/step_limit) only the normal field ñ (with c, from its gradient) or only
    /// the metric (the mapping: surface gradients, ν, P, the transport gradient, the mesh law), the other from S^m.
    enum class Implicit
    {
      all,
      normal,
      metric
    };

    unsigned int max_iterations = 0;    ///< N_g: re-assemblies after the first solve; 0: the lagged scheme
    Implicit     implicit       = Implicit::all; ///< which geometric quantities come from the iterate
    bool         aitken         = true; ///< Aitken relaxation of the iterates (false: the plain fixed point)
    double       tolerance      = 1e-3; ///< ε_g: the iteration stops when max |Y^{k+1} − Y^k| ≤ ε_g h
  };
} // namespace FluidSurface

#endif
