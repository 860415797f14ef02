// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

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
                      "(its metric, normal field and mesh law; the old time level stays that of S^m) and solved again, "
                      "the next surface by Anderson's mixing of the last five iterates, at most N_g times. With ε_g > 0 until "
                      "the nodes move by less than ε_g h, and a step whose iteration has not converged after N_g "
                      "re-assemblies is rejected (τ halves); with ε_g = 0 the N_g-th solve is taken (N_g = 1: a "
                      "predictor–corrector step of two solves). 0: the lagged scheme, one solve on S^m (doc/scheme.md, "
                      "\"Implicit geometry\": why it is the default).");
    prm.declare_entry("apply",
                      "always",
                      Patterns::Selection("always|after rejection"),
                      "Which flow steps iterate their geometry (N_g > 0). always: every one. after rejection: the "
                      "lagged step (one solve) until the energy check rejects one; that step is retried at the same "
                      "τ with the iterated geometry, and so are the next K accepted steps ('corrected steps'). The "
                      "lagged step keeps the growth rate of a small non-axisymmetric mode and is stable except in "
                      "fast shape changes; the iterated one is stable there but, with backward Euler, damps that growth "
                      "(not with time stepping/scheme = BDF2, which needs apply = always; doc/scheme.md, \"Implicit "
                      "geometry\").");
    prm.declare_entry("corrected steps",
                      "20",
                      Patterns::Integer(1, 100000),
                      "K, 1 ≤ K ≤ 100000: with apply = after rejection, the number of accepted steps with the iterated "
                      "geometry after a rejected lagged step, before the lagged step is tried again.");
    prm.declare_entry("tolerance",
                      "1e-3",
                      RealRange::closed(0, 1),
                      "ε_g, 0 ≤ ε_g ≤ 1: the iteration has converged when no node of the new surface moved by more "
                      "than ε_g h between two iterates, h = √(A/N_cells)/k the node spacing. 0: no test, the step takes "
                      "the solve of the N_g-th re-assembly.");
    prm.declare_entry("predictor",
                      "linear",
                      Patterns::Selection("linear|quadratic normal|old surface"),
                      "The surface S^{m+1,0} the first solve of an iterated step is assembled on: the new position "
                      "extrapolated from the accepted states (carried into the frame of the step), with BDF2 after its "
                      "first step. linear: (1 + ω)X^m − ωX^{m−1}, ω = τ/τ_p, an O(τ²) error; quadratic normal: the "
                      "linear one plus the part along the normal ñ^m of the difference of the quadratic extrapolation "
                      "through X^m, X^{m−1}, X^{m−2} from it (the shape to O(τ³), the nodes' tangential places to "
                      "O(τ²); the full quadratic one amplifies unresolved tangential motion sevenfold and broke the "
                      "mesh of the relaxing prolate); old surface: S^m, O(τ). One correction "
                      "(N_g = 1) scales that error by the iteration's contraction, which does not fall with τ: from S^m "
                      "the step is first order (doc/scheme.md, \"Second order in time\").");
    prm.leave_subsection();
  }

  void
  GeometryIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry iteration");
    max_iterations = prm.get_integer("maximum iterations");
    apply           = prm.get("apply") == "always" ? Apply::always : Apply::after_rejection;
    corrected_steps = prm.get_integer("corrected steps");
    if (apply == Apply::after_rejection && max_iterations == 0)
      throw_invalid_entry("geometry iteration/apply",
                          prm.get("apply"),
                          "'always' with 'maximum iterations' = 0 (the lagged step has nothing to apply after a "
                          "rejection; set 'maximum iterations' ≥ 1)");
    tolerance      = prm.get_double("tolerance");
    const std::string guess = prm.get("predictor");
    predictor = guess == "old surface" ? Predictor::old_surface :
                guess == "linear"      ? Predictor::linear :
                                         Predictor::quadratic_normal;
    prm.leave_subsection();
  }


  FixedPointAcceleration::FixedPointAcceleration(InnerProduct dot, const unsigned int depth)
    : dot(std::move(dot))
    , depth(depth)
  {}


  void
  FixedPointAcceleration::advance(VectorType &x, const VectorType &image)
  {
    VectorType residual = image;
    residual -= x;
    if (iteration > 0)
      {
        residual_changes.push_back(residual);
        residual_changes.back() -= last_residual;
        image_changes.push_back(image);
        image_changes.back() -= last_image;
        if (residual_changes.size() > depth)
          {
            residual_changes.pop_front();
            image_changes.pop_front();
          }
      }
    x = image;
    const unsigned int n = residual_changes.size();
    if (n > 0)
      {
        // The normal equations of the small least-squares problem, slightly regularized: the differences
        // become nearly dependent as the iteration converges.
        FullMatrix<double> gram(n, n);
        Vector<double>     right(n), gamma(n);
        double             largest = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            right(i) = dot(residual_changes[i], residual);
            for (unsigned int j = 0; j <= i; ++j)
              gram(i, j) = gram(j, i) = dot(residual_changes[i], residual_changes[j]);
            largest = std::max(largest, gram(i, i));
          }
        if (largest > 0)
          {
            for (unsigned int i = 0; i < n; ++i)
              gram(i, i) += 1e-12 * largest;
            gram.gauss_jordan();
            gram.vmult(gamma, right);
            for (unsigned int i = 0; i < n; ++i)
              x.add(-gamma(i), image_changes[i]);
          }
      }
    last_image = image;
    last_residual = residual;
    ++iteration;
  }
} // namespace FluidSurface

#include <fluid_surface/io/checkpoint.h>

namespace FluidSurface
{
  void
  CorrectedSteps::save(CheckpointData &data) const
  {
    if (left > 0)
      data.set("model/corrected steps left", left);
  }

  void
  CorrectedSteps::load(const CheckpointData &data)
  {
    left = data.has("model/corrected steps left") ? data.get_unsigned("model/corrected steps left") : 0;
  }
} // namespace FluidSurface
