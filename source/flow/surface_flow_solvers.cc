// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_values.h>

#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/linear_algebra/factorization_preconditioner.h>

namespace FluidSurface
{
  using namespace dealii;

  std::vector<BlockStokesPreconditioner::VelocityNode>
  SurfaceFlow::velocity_nodes() const
  {
    const IndexSet                                      &owned_velocity = owned_partitioning[0];
    std::vector<BlockStokesPreconditioner::VelocityNode> nodes;
    std::vector<bool>                                    listed(owned_velocity.n_elements(), false);
    const Quadrature<2> support_points(fe.base_element(0).get_unit_support_points());
    FEValues<2, 3>      node_values(geometry.mapping(),
                               geometry.fe(),
                               support_points,
                               update_values | update_quadrature_points);
    std::vector<Tensor<1, 3>>            normals(support_points.size());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : flow_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          node_values.reinit(geometry_cell(cell));
          node_values[FEValuesExtractors::Vector(0)].get_function_values(geometry.normal_field(), normals);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              // A node is listed at the first cell that has its x component.
              if (fe.system_to_base_index(i).first.first != 0 || fe.system_to_component_index(i).first != 0 ||
                  !owned_velocity.is_element(indices[i]) || listed[owned_velocity.index_within_set(indices[i])])
                continue;
              listed[owned_velocity.index_within_set(indices[i])] = true;
              BlockStokesPreconditioner::VelocityNode node;
              bool                                    constrained = false;
              for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                if (lor_dof_node[j] == lor_dof_node[i])
                  {
                    node.dofs[fe.system_to_component_index(j).first] = owned_velocity.index_within_set(indices[j]);
                    constrained = constrained || constraints.is_constrained(indices[j]);
                  }
              const unsigned int point = fe.system_to_base_index(i).second;
              node.position            = node_values.quadrature_point(point);
              node.normal              = normals[point] / normals[point].norm();
              node.frame = parameters.velocity_amg_node_frames ? lor_frame(node.position, normals[point], constrained) :
                                                        Tensor<2, 3>(unit_symmetric_tensor<3>());
              nodes.push_back(node);
            }
        }
    return nodes;
  }

  unsigned int
  SurfaceFlow::solve_block_preconditioned(VectorType &x)
  {
    if (!block_preconditioner.initialized())
      {
        const bool lor = parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined;
        block_preconditioner.initialize(lor ? lor_velocity_matrix : preconditioner_matrix.block(0, 0),
                                        velocity_nodes(),
                                        preconditioner_matrix.block(1, 1),
                                        with_time_derivative ? &pressure_laplace.block(1, 1) : nullptr,
                                        {parameters.velocity_amg_smoother,
                                         parameters.velocity_amg_aggregation_threshold,
                                         !lor,
                                         parameters.velocity_amg_node_frames,
                                         linear_solver.direct_solver()});
      }
    const double alpha0 = with_time_derivative ? bdf_coefficients()[0] : 0.0;
    return block_preconditioner.solve(system_matrix,
                                      x,
                                      system_rhs,
                                      1.0 / parameters.fluid.Re,
                                      with_time_derivative ? alpha0 / current_tau : 0.0,
                                      linear_solver.get_parameters().tolerance,
                                      parameters.max_linear_iterations);
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::solve(const bool matrix_changed, const bool coefficients_changed)
  {
    SolveInfo  info;
    Timer      timer;
    VectorType x(owned, communicator);
    x = current;
    if (parameters.solver == LinearSolver::block_preconditioned)
      {
        // The preconditioner blocks (A without convection, M_p, L_p) change only with τ and α₀.
        if (coefficients_changed)
          block_preconditioner.clear();
        info.factorized = !block_preconditioner.initialized();
        info.iterations = solve_block_preconditioned(x);
      }
    else
      {
        // The factorization of a matrix with an older convection velocity preconditions GMRES; one with
        // another τ or α₀ is replaced at once.
        if (coefficients_changed)
          linear_solver.request_factorization();
        if (matrix_changed)
          linear_solver.matrix_changed();
        FactorizationPreconditioner                   preconditioner;
        const ReusedFactorizationSolver::Result result =
          linear_solver.solve(system_matrix, system_matrix, x, system_rhs, preconditioner);
        info.iterations = result.iterations;
        info.factorized = result.factorized;
      }
    constraints.distribute(x);
    current         = x;
    info.solve_time = timer.wall_time();
    return info;
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::solve_stationary()
  {
    Timer timer;
    preconditioner_outdated = true;
    assemble(0.0, 1.0, true);
    const double assemble_time = timer.wall_time();
    SolveInfo    info          = solve(true, true);
    info.assemble_time         = assemble_time;
    return info;
  }

  SurfaceFlow::SolveInfo
  SurfaceFlow::advance(const double time, const double tau)
  {
    // The matrix depends on τ and α₀ (BDF2 starts with a BDF1 step) and, with convection, on w.
    const double alpha0               = bdf_coefficients()[0];
    const bool   coefficients_changed = !matrix_assembled || tau != assembled_tau || alpha0 != assembled_alpha0;
    const bool   matrix_changed       = with_convection || coefficients_changed;
    assembled_tau                     = tau;
    assembled_alpha0                  = alpha0;
    // The preconditioner matrices (A without convection, M_p, L_p) change only with τ and α₀; they are
    // assembled only when the AMG hierarchies are rebuilt.
    preconditioner_outdated = coefficients_changed || !block_preconditioner.initialized();
    Timer timer;
    assemble(time, tau, matrix_changed);
    const double assemble_time = timer.wall_time();
    SolveInfo    info          = solve(matrix_changed, coefficients_changed);
    info.assemble_time         = assemble_time;
    older                      = old;
    old                        = current;
    ++n_steps_done;
    return info;
  }
} // namespace FluidSurface
