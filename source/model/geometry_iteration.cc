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
                      "(what it takes from there: 'implicit') and solved again, at most N_g times. With ε_g > 0 until "
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
    prm.declare_entry("relaxation",
                      "anderson",
                      Patterns::Selection("anderson|aitken|none"),
                      "How the next surface is taken from the last ones, with the residual r_k = G(Ỹ_k) − Ỹ_k (G: the "
                      "new position of the solve on Ỹ_k). anderson: Anderson's mixing of depth m, Ỹ_{k+1} = G(Ỹ_k) − "
                      "Σ γ_i ΔG_i with the γ that minimize |r_k − Σ γ_i Δr_i| over the last m differences (a secant "
                      "method: it converges where the plain fixed point does not); aitken: Ỹ_{k+1} = Ỹ_k + ω_k r_k with "
                      "Aitken's ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1})/|r_k − r_{k−1}|², clipped to [0.1, 2]; none: "
                      "Ỹ_{k+1} = G(Ỹ_k), the plain fixed point.");
    prm.declare_entry("time level",
                      "1",
                      RealRange::closed(0.5, 1),
                      "θ, ½ ≤ θ ≤ 1: the re-assemblies take their geometry from the surface S^{m+θ} with the nodes "
                      "X^m + θ (Ỹ_k − X^m) between the old surface and the iterate: 1 the new time level (backward "
                      "Euler in the geometry), ½ the midpoint.");
    prm.declare_entry("predictor",
                      "linear",
                      Patterns::Selection("linear|quadratic|quadratic normal|old surface"),
                      "The surface S^{m+1,0} the first solve of an iterated step is assembled on: the new position "
                      "extrapolated from the accepted states (carried into the frame of the step), with BDF2 after its "
                      "first step. linear: (1 + ω)X^m − ωX^{m−1}, ω = τ/τ_p, an O(τ²) error; quadratic: through X^m, "
                      "X^{m−1}, X^{m−2} (linear while only two exist), O(τ³), but it amplifies unresolved motion "
                      "sevenfold and broke the mesh of the relaxing prolate; quadratic normal: the linear one plus the "
                      "part along the normal ñ^m of quadratic − linear (the shape to O(τ³), the nodes' tangential "
                      "places to O(τ²)); old surface: S^m, O(τ). One correction "
                      "(N_g = 1) scales that error by the iteration's contraction, which does not fall with τ: from S^m "
                      "the step is first order (doc/scheme.md, \"Second order in time\").");
    prm.declare_entry("anderson depth",
                      "5",
                      Patterns::Integer(1, 20),
                      "m, 1 ≤ m ≤ 20: the number of last residual differences of Anderson's mixing (relaxation = "
                      "anderson).");
    prm.declare_entry("implicit",
                      "all",
                      Patterns::Selection("all|normal|metric"),
                      "What the re-assemblies take from the iterate S^{m+1,k}. all: the surface itself. normal: only "
                      "the normal field ñ and the curvature coefficient c (from ∇ñ), on the metric of S^m. metric: "
                      "only the metric (surface gradients, the cell normal ν and P, the transport gradient ∇_S u^m, "
                      "the mesh law), with ñ of S^m. benchmarks/step_limit measures all three.");
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
    const std::string relax = prm.get("relaxation");
    relaxation     = relax == "none" ? Relaxation::none : relax == "aitken" ? Relaxation::aitken : Relaxation::anderson;
    anderson_depth = prm.get_integer("anderson depth");
    const std::string guess = prm.get("predictor");
    predictor = guess == "old surface"      ? Predictor::old_surface :
                guess == "linear"           ? Predictor::linear :
                guess == "quadratic normal" ? Predictor::quadratic_normal :
                                              Predictor::quadratic;
    time_level     = prm.get_double("time level");
    const std::string mode = prm.get("implicit");
    implicit = mode == "normal" ? Implicit::normal : mode == "metric" ? Implicit::metric : Implicit::all;
    prm.leave_subsection();
  }


  FixedPointAcceleration::FixedPointAcceleration(const GeometryIteration &parameters, InnerProduct dot)
    : relaxation(parameters.relaxation)
    , depth(parameters.anderson_depth)
    , dot(std::move(dot))
  {}


  void
  FixedPointAcceleration::advance(VectorType &x, const VectorType &image)
  {
    VectorType residual = image;
    residual -= x;
    switch (relaxation)
      {
        case GeometryIteration::Relaxation::none:
          x = image;
          break;
        case GeometryIteration::Relaxation::aitken:
          {
            if (iteration > 0)
              {
                VectorType difference = residual;
                difference -= last_residual;
                const double denominator = dot(difference, difference);
                if (denominator > 0)
                  omega = std::min(2.0, std::max(0.1, -omega * dot(last_residual, difference) / denominator));
              }
            x.add(omega, residual);
            break;
          }
        case GeometryIteration::Relaxation::anderson:
          {
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
            break;
          }
      }
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
