// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_frame_h
#define fluid_surface_model_step_frame_h

#include <deal.II/base/tensor.h>

#include <fluid_surface/model/rigid_motion.h>

namespace FluidSurface
{
  /**
   * The frame one step is solved in, a value computed once per step (SurfaceStep::advance()) and read by the
   * time scheme's start, the terms, the bordering, the finish and the kept factorization:
   * - `lab`: the lab frame; the mesh may still follow the shape's rigid motion R (law bgn's damping target
   *   X^m + τR);
   * - `carried`: law reference, the frame carried by the rigid motion of the shape (RigidMotion::fit());
   * - `co_rotating`: `time stepping/frame = Tisserand`, the frame that turns with the fluid's rigid motion
   *   Ω = I⁻¹L of u^m (RigidMotion::tisserand()); the convection is transported by u − R and the mesh is
   *   carried with the frame (doc/scheme.md, "The co-rotating step").
   */
  struct StepFrame
  {
    /// The kinds of frame.
    enum class Kind
    {
      lab,
      carried,
      co_rotating
    };

    Kind kind = Kind::lab;
    /// The rigid motion of the frame (or of the shape, in the lab frame) and the momenta of u^m.
    RigidMotion motion;
    /// The rigid motion the mesh follows: `motion`, or none (RigidMotion(): R = 0).
    RigidMotion carried;

    /// Whether the step is solved in the frame carried by `motion` (ũ = Qᵀu; carried or co-rotating).
    bool
    solved_in_frame() const
    {
      return kind != Kind::lab;
    }
    /// Whether the frame turns with the fluid: the convection is transported relative to it, ∇_{u* − R} ũ.
    bool
    co_rotating() const
    {
      return kind == Kind::co_rotating;
    }
    /// The rotation of the mesh by the frame over a step @p tau: Q(τΩ) when co-rotating, else the identity.
    dealii::Tensor<2, 3>
    mesh_rotation(const double tau) const
    {
      if (co_rotating())
        return motion.rotation_over(tau);
      return dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
    }
  };
} // namespace FluidSurface

#endif
