// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_geometry_iteration_h
#define fluid_surface_model_geometry_iteration_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fluid_surface/base/types.h>

#include <deque>
#include <functional>

namespace FluidSurface
{
  /**
   * The implicit geometry of one step (`subsection geometry iteration`): the step system, assembled on the
   * surface S^m of the last step (the lagged scheme), is assembled again on the surface S^{m+1,k} of its own
   * solution and solved again (GMRES preconditioned by the kept factorization), N_g times or until the new nodes
   * move by less than ε_g h between two iterates (h = √(A/N_cells)/k, the node spacing). The data of the old time
   * level (u^m, X^m, the drift corrections) stay those of S^m, the rest comes from the iterate; the next iterate is
   * formed by Anderson's mixing (FixedPointAcceleration); one re-assembly without a test (ε_g = 0) is a
   * predictor–corrector step.
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


    /// Which flow steps iterate their geometry.
    enum class Apply
    {
      always,
      after_rejection
    };

    /// The surface the first solve of an iterated step is assembled on.
    enum class Predictor
    {
      old_surface, ///< S^m: the corrections start from the lagged geometry (an O(τ) error)
      linear,      ///< BDF2 with history: (1 + ω)X^m − ωX^{m−1} in the frame of the step (an O(τ²) error)
      /// BDF2 with two states of history: the linear one plus the normal part (along ñ^m) of the difference of
      /// the quadratic one through X^m, X^{m−1}, X^{m−2} from it: the shape to O(τ³), the nodes' tangential places
      /// to O(τ²)
      quadratic_normal
    };


    unsigned int max_iterations = 0;    ///< N_g: re-assemblies after the first solve; 0: the lagged scheme
    Apply        apply          = Apply::always; ///< every flow step, or the K steps after a rejected lagged one
    unsigned int corrected_steps = 20;  ///< K: accepted steps with iterated geometry after a rejection
    Predictor    predictor      = Predictor::linear; ///< the surface of the first solve
    double       tolerance      = 1e-3; ///< ε_g: the iteration stops when max |Y^{k+1} − Y^k| ≤ ε_g h; 0: after N_g

    /// Whether the iteration stops at iterate @p k (1 ≤ k ≤ N_g) whose nodes moved by @p change (in units of h).
    bool
    converged(const unsigned int k, const double change) const
    {
      return tolerance > 0 ? change <= tolerance : k == max_iterations;
    }
  };

  /**
   * The next iterate x_{k+1} of a fixed point x = G(x) from x_k, its image G(x_k) and the earlier iterates, with
   * the residual r_k = G(x_k) − x_k measured by a given inner product (the step: the new positions only), by
   * Anderson's mixing of depth m (Walker & Ni 2011): x_{k+1} = G(x_k) − Σ_i γ_i ΔG_i with the γ that minimize
   * |r_k − Σ_i γ_i Δr_i| over the last m differences Δr_i = r_{i+1} − r_i, ΔG_i = G(x_{i+1}) − G(x_i). For a
   * linear G it is GMRES on x − G(x) = 0, so it converges where the plain fixed point x_{k+1} = G(x_k) does not (a
   * few eigenvalues of G' outside the unit disc) and in fewer iterations where it does; Aitken's relaxation, one
   * factor for all directions, does not (tests/geometry_fixed_point_acceleration).
   */
  class FixedPointAcceleration
  {
  public:
    using VectorType = FluidSurface::VectorType;
    /// The inner product in which the residuals are measured.
    using InnerProduct = std::function<double(const VectorType &, const VectorType &)>;

    /// Anderson's mixing of depth @p depth, the residuals measured by @p dot.
    explicit FixedPointAcceleration(InnerProduct dot, const unsigned int depth = 5);

    /// Replaces @p x (the iterate x_k) by x_{k+1}, given @p image = G(x_k).
    void
    advance(VectorType &x, const VectorType &image);

  private:
    const InnerProduct                  dot;
    const unsigned int                  depth;
    unsigned int                        iteration = 0;
    VectorType                          last_residual;     ///< r_{k−1}
    VectorType                          last_image;        ///< G(x_{k−1})
    std::deque<VectorType>              residual_changes;  ///< Δr_i, the newest last
    std::deque<VectorType>              image_changes;     ///< ΔG_i, the newest last
  };
} // namespace FluidSurface


namespace FluidSurface
{
  class CheckpointData;

  /**
   * `geometry iteration/apply = after rejection`: after a rejected lagged step, the retry and the next K
   * accepted steps iterate their geometry (checkpoint key `model/corrected steps left`).
   */
  class CorrectedSteps
  {
  public:
    /// Whether the next flow step iterates its geometry under @p iteration.
    bool
    iterating(const GeometryIteration &iteration) const
    {
      return iteration.enabled() && (iteration.apply == GeometryIteration::Apply::always || left > 0);
    }
    /**
     * A step was rejected: with apply = after rejection and no corrected steps under way (the rejected step was
     * lagged), starts K corrected steps. Returns whether it did.
     */
    bool
    start_after_rejection(const GeometryIteration &iteration)
    {
      if (!iteration.enabled() || iteration.apply != GeometryIteration::Apply::after_rejection || left > 0)
        return false;
      left = iteration.corrected_steps;
      return true;
    }
    /// A step was accepted: one corrected step is used up.
    void
    accept()
    {
      if (left > 0)
        --left;
    }
    /// Writes the count into a checkpoint (nothing while it is 0).
    void
    save(CheckpointData &data) const;
    /// Reads it (0 if the checkpoint has none).
    void
    load(const CheckpointData &data);

  private:
    unsigned int left = 0;
  };
} // namespace FluidSurface

#endif
