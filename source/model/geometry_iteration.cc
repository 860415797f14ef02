#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/geometry_iteration.h>

namespace FluidSurface
{
  using namespace dealii;

  void
  GeometryIteration::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry iteration");
    prm.declare_entry("maximum iterations",
                      "0",
                      Patterns::Integer(0, 50),
                      "N_g, 0 ≤ N_g ≤ 50: the step is assembled again on the surface of its own solution S^{m+1,k} "
                      "(normal, curvature coefficient, metric and transport gradient of the iterate; u^m, X^m and "
                      "the rigid motion of S^m) and solved again, at most N_g times, until the nodes move by less "
                      "than ε_g h. A step whose iteration has not converged after N_g re-assemblies is rejected "
                      "(τ halves). 0: the lagged scheme, one solve on S^m.");
    prm.declare_entry("tolerance",
                      "1e-3",
                      RealRange::closed(1e-12, 1),
                      "ε_g, 1e-12 ≤ ε_g ≤ 1: the iteration has converged when no node of the new surface moved by "
                      "more than ε_g h between two iterates, h = √(A/N_cells)/k the node spacing.");
    prm.declare_entry("relaxation",
                      "aitken",
                      Patterns::Selection("aitken|none"),
                      "How the next surface is taken from the last: aitken: Ỹ_{k+1} = Ỹ_k + ω_k r_k with the residual "
                      "r_k = G(Ỹ_k) − Ỹ_k (G: the new position of the solve on Ỹ_k) and Aitken's ω_k = −ω_{k−1} "
                      "r_{k−1}·(r_k − r_{k−1})/|r_k − r_{k−1}|², clipped to [0.1, 2]; none: Ỹ_{k+1} = G(Ỹ_k), the plain "
                      "fixed point.");
    prm.declare_entry("implicit",
                      "all",
                      Patterns::Selection("all|normal|metric"),
                      "What the re-assemblies take from the iterate S^{m+1,k}. all: the surface itself. normal: only "
                      "the normal field ñ and the curvature coefficient c (from ∇ñ), on the metric of S^m. metric: "
                      "only the metric (surface gradients, the cell normal ν and P, the transport gradient ∇_S u^m, "
                      "the mesh law), with ñ of S^m. normal and metric are for the study of which lagged quantity "
                      "limits the step (benchmarks/step_limit).");
    prm.leave_subsection();
  }

  void
  GeometryIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry iteration");
    max_iterations = prm.get_integer("maximum iterations");
    tolerance      = prm.get_double("tolerance");
    aitken                 = prm.get("relaxation") == "aitken";
    const std::string mode = prm.get("implicit");
    implicit = mode == "normal" ? Implicit::normal : mode == "metric" ? Implicit::metric : Implicit::all;
    prm.leave_subsection();
  }
} // namespace FluidSurface
