// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <fluid_surface/geometry/surface_operators.h>
#include <fluid_surface/linear_algebra/block_stokes_preconditioner.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <functional>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    using VectorType = BlockStokesPreconditioner::VectorType;

    /**
     * y_p = −S̃⁻¹ r_p, y_u = Ã⁻¹(r_u − Bᵀ y_p) on monolithic vectors (velocity DoFs first); Bᵀ y_p is the
     * velocity part of the system matrix times (0, y_p).
     */
    class BlockTriangularPreconditioner
    {
    public:
      BlockTriangularPreconditioner(const TrilinosWrappers::SparseMatrix                        &system,
                                    const std::function<void(VectorType &, const VectorType &)> &velocity,
                                    const TrilinosWrappers::PreconditionAMG                     &pressure_mass,
                                    const TrilinosWrappers::PreconditionAMG                     *pressure_laplace,
                                    const double                                                 viscosity,
                                    const double                                                 alpha_over_tau,
                                    const std::vector<IndexSet>                                 &partitioning,
                                    const MPI_Comm                                               communicator)
        : system(system)
        , velocity(velocity)
        , pressure_mass(pressure_mass)
        , pressure_laplace(pressure_laplace)
        , viscosity(viscosity)
        , alpha_over_tau(alpha_over_tau)
        , n_u(partitioning[0].size())
        , block_src(partitioning, communicator)
        , block_dst(partitioning, communicator)
        , block_tmp(partitioning, communicator)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        split(src, block_src);
        pressure_mass.vmult(block_dst.block(1), block_src.block(1));
        block_dst.block(1) *= -viscosity;
        if (pressure_laplace)
          {
            pressure_laplace->vmult(block_tmp.block(1), block_src.block(1));
            block_dst.block(1).add(-alpha_over_tau, block_tmp.block(1));
          }
        block_tmp.block(0) = 0;
        block_tmp.block(1) = block_dst.block(1);
        VectorType monolithic_tmp(dst), monolithic_product(dst);
        merge(block_tmp, monolithic_tmp);
        system.vmult(monolithic_product, monolithic_tmp);
        split(monolithic_product, block_tmp);
        block_tmp.block(0).sadd(-1.0, 1.0, block_src.block(0));
        velocity(block_dst.block(0), block_tmp.block(0));
        merge(block_dst, dst);
      }

    private:
      void
      split(const VectorType &mono, TrilinosWrappers::MPI::BlockVector &blocks) const
      {
        for (const types::global_dof_index i : mono.locally_owned_elements())
          if (i < n_u)
            blocks.block(0)[i] = mono[i];
          else
            blocks.block(1)[i - n_u] = mono[i];
      }
      void
      merge(const TrilinosWrappers::MPI::BlockVector &blocks, VectorType &mono) const
      {
        for (const types::global_dof_index i : mono.locally_owned_elements())
          mono[i] = (i < n_u) ? blocks.block(0)[i] : blocks.block(1)[i - n_u];
      }

      const TrilinosWrappers::SparseMatrix                       &system;
      const std::function<void(VectorType &, const VectorType &)> velocity;
      const TrilinosWrappers::PreconditionAMG                    &pressure_mass;
      const TrilinosWrappers::PreconditionAMG                    *pressure_laplace;
      const double                                                viscosity;
      const double                                                alpha_over_tau;
      const types::global_dof_index                               n_u;
      mutable TrilinosWrappers::MPI::BlockVector                  block_src, block_dst, block_tmp;
    };

    /**
     * ML's near-null space of the velocity block, node-wise (mode k of local DoF i at k n_local + i): smooth
     * tangential fields. Constant vectors are not (their normal part meets the penalty), so these are the
     * tangential projections P e_a of the translations and P(e_a × x) of the rotations, written in the
     * node frames (t·m for the frame direction t of each DoF).
     */
    std::vector<double>
    tangential_rigid_motions(const std::vector<BlockStokesPreconditioner::VelocityNode> &nodes,
                             const unsigned int                                          n_local)
    {
      std::vector<double> modes(6 * n_local, 0.0);
      for (const BlockStokesPreconditioner::VelocityNode &node : nodes)
        {
          const Tensor<2, 3> P = SurfaceOperators::projection(node.normal);
          for (unsigned int c = 0; c < 3; ++c)
            {
              Tensor<1, 3> t;
              for (unsigned int d = 0; d < 3; ++d)
                t[d] = node.frame[d][c];
              for (unsigned int a = 0; a < 3; ++a)
                {
                  Tensor<1, 3> axis;
                  axis[a]                                 = 1.0;
                  modes[a * n_local + node.dofs[c]]       = t * (P * axis);
                  modes[(3 + a) * n_local + node.dofs[c]] = t * (P * cross_product_3d(axis, node.position));
                }
            }
        }
      return modes;
    }
  } // namespace

  Tensor<2, 3>
  BlockStokesPreconditioner::node_frame(const Tensor<1, 3> &n)
  {
    unsigned int axis = 0;
    for (unsigned int d = 1; d < 3; ++d)
      if (std::abs(n[d]) < std::abs(n[axis]))
        axis = d;
    Tensor<1, 3> e;
    e[axis]               = 1.0;
    Tensor<1, 3> t1       = cross_product_3d(e, n);
    t1                    /= t1.norm();
    const Tensor<1, 3> t2 = cross_product_3d(n, t1);
    Tensor<2, 3>       frame;
    for (unsigned int c = 0; c < 3; ++c)
      {
        frame[c][0] = t1[c];
        frame[c][1] = t2[c];
        frame[c][2] = n[c];
      }
    return frame;
  }

  void
  BlockStokesPreconditioner::initialize(const TrilinosWrappers::SparseMatrix &velocity_matrix,
                                        const std::vector<VelocityNode>      &nodes,
                                        const TrilinosWrappers::SparseMatrix &pressure_mass,
                                        const TrilinosWrappers::SparseMatrix *pressure_laplace,
                                        const VelocityAMGParameters          &parameters)
  {
    AssertDimension(3 * nodes.size(), velocity_matrix.locally_owned_range_indices().n_elements());
    velocity_partition = velocity_matrix.locally_owned_range_indices();
    pressure_partition = pressure_mass.locally_owned_range_indices();
    initialize_velocity(velocity_matrix, nodes, parameters);

    TrilinosWrappers::PreconditionAMG::AdditionalData pressure_data;
    pressure_data.elliptic = true;
    pressure_mass_amg      = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    pressure_mass_amg->initialize(pressure_mass, pressure_data);
    pressure_laplace_amg.reset();
    if (pressure_laplace)
      {
        pressure_laplace_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        pressure_laplace_amg->initialize(*pressure_laplace, pressure_data);
      }
  }

  void
  BlockStokesPreconditioner::initialize_velocity(const TrilinosWrappers::SparseMatrix &matrix,
                                                 const std::vector<VelocityNode>      &nodes,
                                                 const VelocityAMGParameters          &parameters)
  {
    // Rigid translations per component (DoFTools::extract_constant_modes has no <2,3> instance).
    const unsigned int             n_local = velocity_partition.n_elements();
    std::vector<std::vector<bool>> constant_modes(3, std::vector<bool>(n_local, false));
    for (const VelocityNode &node : nodes)
      for (unsigned int c = 0; c < 3; ++c)
        constant_modes[c][node.dofs[c]] = true;
    TrilinosWrappers::PreconditionAMG::AdditionalData velocity_data;
    velocity_data.constant_modes        = constant_modes;
    velocity_data.elliptic              = true;
    velocity_data.higher_order_elements = parameters.higher_order_elements;
    velocity_data.smoother_sweeps       = 2;
    velocity_data.aggregation_threshold = parameters.aggregation_threshold;
    velocity_data.smoother_type         = parameters.smoother.c_str();
    velocity_data.coarse_type           = "Amesos-KLU";

    Teuchos::ParameterList              ml_parameters;
    std::unique_ptr<Epetra_MultiVector> translations;
    velocity_data.set_parameters(ml_parameters, translations, matrix);
    rigid_motions = tangential_rigid_motions(nodes, n_local);
    ml_parameters.set("null space: type", "pre-computed");
    ml_parameters.set("null space: dimension", 6);
    ml_parameters.set("null space: vectors", rigid_motions.data());
    ml_parameters.set("PDE equations", 3);

    node_frames = parameters.node_frames;
    frames.clear();
    if (node_frames)
      for (const VelocityNode &node : nodes)
        frames.emplace_back(node.dofs, node.frame);

    velocity_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    velocity_direct.reset();
    if (parameters.smoother == "exact")
      {
        velocity_direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          direct_control, TrilinosWrappers::SolverDirect::AdditionalData(false, parameters.direct_solver));
        velocity_direct->initialize(matrix);
      }
    else
      velocity_amg->initialize(matrix, ml_parameters);
  }

  void
  BlockStokesPreconditioner::clear()
  {
    velocity_amg.reset();
    velocity_direct.reset();
    pressure_mass_amg.reset();
    pressure_laplace_amg.reset();
  }

  void
  BlockStokesPreconditioner::rotate(VectorType &v, const bool transpose) const
  {
    double *values = v.begin(); // the owned entries, in the order of the velocity partition
    for (const auto &[dofs, frame] : frames)
      {
        Tensor<1, 3> in, out;
        for (unsigned int c = 0; c < 3; ++c)
          in[c] = values[dofs[c]];
        out = transpose ? in * frame : frame * in; // in * frame = frameᵀ in
        for (unsigned int c = 0; c < 3; ++c)
          values[dofs[c]] = out[c];
      }
  }

  void
  BlockStokesPreconditioner::apply_velocity_inverse(VectorType &dst, const VectorType &src) const
  {
    const auto inverse = [this](VectorType &y, const VectorType &r) {
      if (velocity_direct)
        velocity_direct->solve(y, r);
      else
        velocity_amg->vmult(y, r);
    };
    if (!node_frames)
      {
        inverse(dst, src);
        return;
      }
    VectorType rotated(src);
    rotate(rotated, true);
    inverse(dst, rotated);
    rotate(dst, false);
  }

  unsigned int
  BlockStokesPreconditioner::solve(const TrilinosWrappers::SparseMatrix &system,
                                   VectorType                           &x,
                                   const VectorType                     &b,
                                   const double                          viscosity,
                                   const double                          alpha_over_tau,
                                   const double                          tolerance,
                                   const unsigned int                    max_iterations) const
  {
    Assert(initialized(), ExcNotInitialized());
    AssertDimension(system.m(), velocity_partition.size() + pressure_partition.size());
    const BlockTriangularPreconditioner preconditioner(
      system,
      [this](VectorType &dst, const VectorType &src) { apply_velocity_inverse(dst, src); },
      *pressure_mass_amg,
      pressure_laplace_amg.get(),
      viscosity,
      alpha_over_tau,
      {velocity_partition, pressure_partition},
      system.get_mpi_communicator());
    SolverControl                           control(max_iterations, tolerance * b.l2_norm());
    SolverGMRES<VectorType>::AdditionalData gmres_data(100, true);
    SolverGMRES<VectorType>                 gmres(control, gmres_data);
    gmres.solve(system, x, b, preconditioner);
    return control.last_step();
  }
} // namespace FluidSurface
