// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_request_h
#define fluid_surface_model_step_request_h

#include <deal.II/base/function.h>

#include <fluid_surface/model/mesh_redistribution.h>

namespace FluidSurface
{
  /**
   * What one SurfaceStep::advance() solves for: where the velocity comes from, whether the global constraints
   * (volume row, rigid-motion rows) are part of the system, which mesh law moves the nodes and which linear
   * solver solves it. The time step of the run is flow_step(); the safety valve asks for a relaxation of the
   * mesh (the velocity at rest, no global constraints, law `reference`, a fresh KLU factorization) and for
   * a projection of the velocity (the flow with τ → 0).
   */
  struct StepRequest
  {
    /// Where u comes from.
    enum class Velocity
    {
      flow,       ///< the flow of the model (momentum and continuity rows, the bending force)
      prescribed, ///< the L² projection of the function `prescribed`; no bending force, no area correction
      at_rest     ///< u = 0 (the prescribed velocity zero)
    };
    /// Which linear solver solves the bordered system.
    enum class Solver
    {
      kept_factorization, ///< the step's solver (`subsection linear solver`), its factorization kept across steps
      fresh_factorization ///< a factorization without reuse, MUMPS or, where MUMPS refuses, KLU (the valve's solves)
    };

    /// A step of the flow with the model's mesh law @p law and its solver.
    static StepRequest
    flow_step(const MeshRedistribution::Law law)
    {
      StepRequest request;
      request.law = law;
      return request;
    }

    /// The velocity of the step as a function, or nullptr for Velocity::flow.
    const dealii::Function<3> *
    prescribed_velocity() const
    {
      static const dealii::Functions::ZeroFunction<3> zero(3);
      return velocity == Velocity::flow ? nullptr : velocity == Velocity::at_rest ? &zero : prescribed;
    }

    Velocity                   velocity   = Velocity::flow;
    const dealii::Function<3> *prescribed = nullptr; ///< u with Velocity::prescribed (3 components)
    /// Whether the volume row and (if MomentumConstraints::active()) the rigid-motion rows are part of the step.
    bool                       global_constraints = true;
    MeshRedistribution::Law    law                = MeshRedistribution::Law::bgn; ///< the mesh law of the step
    Solver                     solver             = Solver::kept_factorization;
  };
} // namespace FluidSurface

#endif
