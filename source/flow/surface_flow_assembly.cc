// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/flow/surface_flow.h>
#include <fluid_surface/geometry/surface_operators.h>

#include <numeric>

namespace FluidSurface
{
  using namespace dealii;
  namespace SO = SurfaceOperators;

  // ---------------------------------------------------------------- the cell terms

  struct SurfaceFlow::ScratchData
  {
    ScratchData(const Mapping<2, 3>       &mapping,
                const FiniteElement<2, 3> &flow_fe,
                const FiniteElement<2, 3> &geometry_fe,
                const Quadrature<2>       &quadrature,
                const FiniteElement<2, 3> &lor_fe,
                const Quadrature<2>       &lor_quadrature)
      : flow_values(mapping,
                    flow_fe,
                    quadrature,
                    update_values | update_gradients | update_normal_vectors | update_JxW_values |
                      update_quadrature_points)
      , geometry_values(mapping, geometry_fe, quadrature, update_values)
      , lor_values(mapping,
                   lor_fe,
                   lor_quadrature,
                   update_values | update_gradients | update_normal_vectors | update_JxW_values |
                     update_quadrature_points)
      , lor_geometry_values(mapping,
                            geometry_fe,
                            Quadrature<2>(flow_fe.base_element(0).base_element(0).get_unit_support_points()),
                            update_values | update_quadrature_points)
      , lor_normal(lor_geometry_values.n_quadrature_points)
      , point(flow_fe.n_dofs_per_cell())
      , lor_point(lor_fe.n_dofs_per_cell())
      , grad_psi(flow_fe.n_dofs_per_cell())
      , normal_phi(flow_fe.n_dofs_per_cell())
      , multiplier(flow_fe.n_dofs_per_cell())
      , old_u(quadrature.size())
      , older_u(quadrature.size())
      , smooth_normal(quadrature.size())
    {}
    ScratchData(const ScratchData &other)
      : ScratchData(other.flow_values.get_mapping(),
                    other.flow_values.get_fe(),
                    other.geometry_values.get_fe(),
                    other.flow_values.get_quadrature(),
                    other.lor_values.get_fe(),
                    other.lor_values.get_quadrature())
    {}

    FEValues<2, 3>            flow_values;
    FEValues<2, 3>            geometry_values;
    FEValues<2, 3>            lor_values;          ///< low-order-refined velocity operator
    FEValues<2, 3>            lor_geometry_values; ///< ñ at the 9 nodes of the cell
    std::vector<Tensor<1, 3>> lor_normal;
    FlowPointValues           point;      ///< the flow terms' data at one quadrature point
    FlowPointValues           lor_point;  ///< the same for the piecewise bilinear functions (low-order refined)
    std::vector<Tensor<1, 3>> grad_psi;   ///< pressure gradients (the L_p of the preconditioner)
    std::vector<double>       normal_phi; ///< u·n of the velocity shape functions, n the penalty normal
    std::vector<double>       multiplier; ///< shape values of λ (Tangentiality::multiplier)
    std::vector<Tensor<1, 3>> old_u, older_u, smooth_normal;
  };

  struct SurfaceFlow::CopyData
  {
    explicit CopyData(const unsigned int n)
      : matrix(n, n)
      , velocity_and_pressure_mass(n, n)
      , pressure_laplace(n, n)
      , rhs(n)
      , indices(n)
      , lor_matrices(4, FullMatrix<double>(12, 12))
      , lor_indices(4, std::vector<types::global_dof_index>(12))
    {}
    FullMatrix<double>                   matrix;
    FullMatrix<double>                   velocity_and_pressure_mass; ///< A_uu (no convection) ⊕ M_p
    FullMatrix<double>                   pressure_laplace;           ///< L_p
    Vector<double>                       rhs;
    std::vector<Vector<double>>          killing_moments; ///< (a × x, φ_i) per Killing axis a
    std::vector<types::global_dof_index> indices;
    bool                                 with_matrix = true;
    bool                                 with_lor    = false; ///< the sub-cell matrices are filled
    std::vector<FullMatrix<double>>                   lor_matrices; ///< per sub-cell, its 12 velocity DoFs
    std::vector<std::vector<types::global_dof_index>> lor_indices;
  };

  namespace
  {
    /// η = β h_K^{−q}, h_K = |K|^{1/2}, of the cell of @p fv; 0 when a multiplier imposes u·n = 0.
    double
    tangentiality_penalty(const FEValues<2, 3> &fv, const SurfaceFlow::Parameters &parameters)
    {
      double cell_area = 0;
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
        cell_area += fv.JxW(q);
      const bool with_multiplier = parameters.tangentiality == SurfaceFlow::Tangentiality::multiplier;
      return with_multiplier ? 0.0 :
                               parameters.penalty_factor * std::pow(cell_area, -0.5 * parameters.penalty_exponent);
    }
  } // namespace

  void
  SurfaceFlow::local_assemble(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                              ScratchData                                           &scratch,
                              CopyData                                              &copy) const
  {
    reinit_cell(cell, scratch, copy);
    const std::array<double, 3> bdf = bdf_coefficients();
    const bool                  build_preconditioner =
      copy.with_matrix && parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated;
    const double penalty = tangentiality_penalty(scratch.flow_values, parameters);
    for (unsigned int q = 0; q < scratch.flow_values.n_quadrature_points; ++q)
      {
        scratch.point.reinit(scratch.flow_values, q);
        if (with_time_derivative)
          set_old_velocities(scratch, q, bdf);
        add_point_terms(scratch, copy, q, penalty, bdf, build_preconditioner);
      }

    const bool lor = build_preconditioner && parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined;
    copy.with_lor  = lor;
    if (build_preconditioner && (lor || parameters.velocity_amg_node_frames))
      assemble_amg_matrices(cell, scratch, copy, penalty);
  }

  void
  SurfaceFlow::reinit_cell(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                           ScratchData                                           &scratch,
                           CopyData                                              &copy) const
  {
    FEValues<2, 3> &fv = scratch.flow_values;
    fv.reinit(cell);
    const FEValuesExtractors::Vector velocity(0);
    copy.matrix                     = 0;
    copy.velocity_and_pressure_mass = 0;
    copy.pressure_laplace           = 0;
    copy.rhs                        = 0;
    copy.killing_moments.resize(with_time_derivative ? 0 : killing.size(), Vector<double>(fe.n_dofs_per_cell()));
    for (Vector<double> &moment : copy.killing_moments)
      moment = 0;
    cell->get_dof_indices(copy.indices);

    if (parameters.penalty_normal == PenaltyNormal::continuous)
      {
        scratch.geometry_values.reinit(geometry_cell(cell));
        scratch.geometry_values[velocity].get_function_values(geometry.normal_field(), scratch.smooth_normal);
      }
    if (with_time_derivative)
      {
        fv[velocity].get_function_values(old, scratch.old_u);
        fv[velocity].get_function_values(older, scratch.older_u);
      }
  }

  Tensor<1, 3>
  SurfaceFlow::penalty_normal_at(const ScratchData &scratch, const unsigned int q) const
  {
    switch (parameters.penalty_normal)
      {
        case PenaltyNormal::exact:
          return exact_normal(scratch.point.position);
        case PenaltyNormal::continuous:
          return scratch.smooth_normal[q] / scratch.smooth_normal[q].norm();
        case PenaltyNormal::cell:
          break;
      }
    return scratch.point.normal;
  }

  void
  SurfaceFlow::set_old_velocities(ScratchData &scratch, const unsigned int q, const std::array<double, 3> &bdf) const
  {
    // Second order with BDF2: the extrapolation 2u^m − u^{m−1} of the convection velocity.
    FlowPointValues &point = scratch.point;
    point.old_velocity     = bdf[1] * scratch.old_u[q] + bdf[2] * scratch.older_u[q];
    point.transport_velocity =
      (bdf[2] == 0.0) ? scratch.old_u[q] : Tensor<1, 3>(2.0 * scratch.old_u[q] - scratch.older_u[q]);
  }

  void
  SurfaceFlow::add_point_terms(ScratchData                 &scratch,
                               CopyData                    &copy,
                               const unsigned int           q,
                               const double                 penalty,
                               const std::array<double, 3> &bdf,
                               const bool                   build_preconditioner) const
  {
    const FEValues<2, 3>  &fv              = scratch.flow_values;
    const FlowPointValues &point           = scratch.point;
    const unsigned int     n               = fe.n_dofs_per_cell();
    const double           dA              = point.JxW;
    const double           tau             = current_tau;
    const bool             with_multiplier = parameters.tangentiality == Tangentiality::multiplier;
    const Tensor<1, 3>     n_penalty       = penalty_normal_at(scratch, q);
    for (unsigned int i = 0; i < n; ++i)
      {
        scratch.grad_psi[i]   = fv[FEValuesExtractors::Scalar(3)].gradient(i, q);
        scratch.normal_phi[i] = SO::normal_component(point.velocity[i], n_penalty);
        scratch.multiplier[i] = with_multiplier ? fv[FEValuesExtractors::Scalar(4)].value(i, q) : 0.0;
      }
    Tensor<1, 3> force;
    if (body_force)
      force = body_force(point.position, current_time_for_force);

    for (unsigned int a = 0; a < copy.killing_moments.size(); ++a)
      {
        const Tensor<1, 3> rotation = cross_product_3d(killing[a], point.position);
        for (unsigned int i = 0; i < n; ++i)
          copy.killing_moments[a](i) += rotation * point.velocity[i] * dA;
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        copy.rhs(i) += force * point.velocity[i] * dA;
        if (with_time_derivative)
          copy.rhs(i) += SurfaceFluid::mass_term_rhs(point, i, 1.0 / tau) * dA;
        if (!copy.with_matrix)
          continue;
        for (unsigned int j = 0; j < n; ++j)
          {
            double velocity_block =
              parameters.fluid.viscous_term(point, i, j) + penalty * scratch.normal_phi[i] * scratch.normal_phi[j];
            if (with_time_derivative)
              velocity_block += SurfaceFluid::mass_term(point, i, j, bdf[0] / tau);
            // The skew-symmetric form ½[(∇_w u, v) − (∇_w v, u)].
            double convection = 0;
            if (with_convection)
              convection =
                0.5 * (SurfaceFluid::convection_term(point, i, j) - SurfaceFluid::convection_term(point, j, i));
            copy.matrix(i, j) += (velocity_block + convection + SurfaceFluid::pressure_term(point, i, j) +
                                  SurfaceFluid::continuity_term(point, i, j) +
                                  scratch.normal_phi[i] * scratch.multiplier[j] +
                                  scratch.multiplier[i] * scratch.normal_phi[j]) *
                                 dA;
            if (build_preconditioner)
              {
                copy.velocity_and_pressure_mass(i, j) +=
                  (velocity_block + point.pressure[i] * point.pressure[j]) * dA;
                if (with_time_derivative)
                  copy.pressure_laplace(i, j) += (scratch.grad_psi[i] * scratch.grad_psi[j] +
                                                  1e-2 * point.pressure[i] * point.pressure[j]) *
                                                 dA;
              }
          }
      }
  }

  // ---------------------------------------------------------------- the velocity AMG

  void
  SurfaceFlow::assemble_amg_matrices(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                                     ScratchData                                           &scratch,
                                     CopyData                                              &copy,
                                     const double                                           penalty) const
  {
    // Node frames [t₁ t₂ n] (Cartesian at constrained nodes): the AMG sees the velocity block in
    // tangential and normal components, so the penalty, which acts on the normal component only,
    // stays on the normal DoFs instead of mixing all three Cartesian ones.
    const NodeFrames frames = node_frames(cell, scratch, copy);
    if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
      {
        assemble_lor_matrices(cell, scratch, copy, penalty, frames);
        return;
      }
    std::vector<unsigned int> all(fe.n_dofs_per_cell());
    std::iota(all.begin(), all.end(), 0u);
    const FullMatrix<double> cartesian(copy.velocity_and_pressure_mass);
    rotate_into_frames(all, frames, cartesian, copy.velocity_and_pressure_mass);
  }

  SurfaceFlow::NodeFrames
  SurfaceFlow::node_frames(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                           ScratchData                                           &scratch,
                           const CopyData                                        &copy) const
  {
    NodeFrames frames;
    for (unsigned int k = 0; k < 9; ++k)
      frames[k] = Tensor<2, 3>(unit_symmetric_tensor<3>());
    if (!parameters.velocity_amg_node_frames)
      return frames;
    scratch.lor_geometry_values.reinit(geometry_cell(cell));
    scratch.lor_geometry_values[FEValuesExtractors::Vector(0)].get_function_values(geometry.normal_field(),
                                                                                   scratch.lor_normal);
    std::array<bool, 9> constrained{};
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (lor_dof_node[i] != numbers::invalid_unsigned_int && constraints.is_constrained(copy.indices[i]))
        constrained[lor_dof_node[i]] = true;
    for (unsigned int k = 0; k < 9; ++k)
      frames[k] = lor_frame(scratch.lor_geometry_values.quadrature_point(k), scratch.lor_normal[k], constrained[k]);
    return frames;
  }

  void
  SurfaceFlow::assemble_lor_matrices(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                                     ScratchData                                           &scratch,
                                     CopyData                                              &copy,
                                     const double                                           penalty,
                                     const NodeFrames                                      &frames) const
  {
    FEValues<2, 3> &lv = scratch.lor_values;
    lv.reinit(typename Triangulation<2, 3>::cell_iterator(cell));
    FlowPointValues   &point = scratch.lor_point;
    const double       mass  = with_time_derivative ? bdf_coefficients()[0] / current_tau : 0.0;
    FullMatrix<double> cartesian(12, 12);
    for (unsigned int s = 0; s < 4; ++s)
      {
        const std::vector<unsigned int> &dofs = lor_subcell_dofs[s];
        cartesian                             = 0;
        for (unsigned int a = 0; a < 12; ++a)
          copy.lor_indices[s][a] = copy.indices[dofs[a]];
        for (const unsigned int q : lor_subcell_points[s])
          {
            point.reinit(lv, q);
            const double dA = point.JxW;
            // The exact normal if the penalty uses it, else ν_h (for a preconditioner, ñ and ν_h are alike).
            const Tensor<1, 3> n_penalty =
              parameters.penalty_normal == PenaltyNormal::exact ? exact_normal(point.position) : point.normal;
            for (unsigned int a = 0; a < 12; ++a)
              scratch.normal_phi[a] = SO::normal_component(point.velocity[dofs[a]], n_penalty);
            for (unsigned int a = 0; a < 12; ++a)
              for (unsigned int b = 0; b < 12; ++b)
                cartesian(a, b) += (parameters.fluid.viscous_term(point, dofs[a], dofs[b]) +
                                    penalty * scratch.normal_phi[a] * scratch.normal_phi[b] +
                                    mass * point.velocity[dofs[a]] * point.velocity[dofs[b]]) *
                                   dA;
          }
        rotate_into_frames(dofs, frames, cartesian, copy.lor_matrices[s]);
      }
  }

  void
  SurfaceFlow::rotate_into_frames(const std::vector<unsigned int> &dofs,
                                  const NodeFrames                &frames,
                                  const FullMatrix<double>        &A,
                                  FullMatrix<double>              &A_R) const
  {
    // Q(a, b) = R_k[c_a][c_b] for DoFs a, b at the same node k (c: Cartesian component of a, frame direction
    // of b). Q has at most 3 entries per column, so A_R = Qᵀ(AQ) costs 6m² operations.
    const unsigned int                                          m = dofs.size();
    std::vector<std::array<std::pair<unsigned int, double>, 3>> column(m);
    std::vector<unsigned int>                                   count(m, 0);
    for (unsigned int b = 0; b < m; ++b)
      if (lor_dof_node[dofs[b]] == numbers::invalid_unsigned_int)
        column[b][count[b]++] = {b, 1.0};
      else
        for (unsigned int a = 0; a < m; ++a)
          if (lor_dof_node[dofs[a]] == lor_dof_node[dofs[b]])
            column[b][count[b]++] = {a,
                                     frames[lor_dof_node[dofs[a]]][fe.system_to_component_index(dofs[a]).first]
                                           [fe.system_to_component_index(dofs[b]).first]};
    FullMatrix<double> AQ(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int b = 0; b < m; ++b)
        for (unsigned int t = 0; t < count[b]; ++t)
          AQ(i, b) += A(i, column[b][t].first) * column[b][t].second;
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int b = 0; b < m; ++b)
        {
          double sum = 0;
          for (unsigned int t = 0; t < count[a]; ++t)
            sum += column[a][t].second * AQ(column[a][t].first, b);
          A_R(a, b) = sum;
        }
  }

  Tensor<2, 3>
  SurfaceFlow::lor_frame(const Point<3> &x, const Tensor<1, 3> &smooth_normal, const bool cartesian) const
  {
    // Constrained nodes (the Killing pins, hanging nodes) keep the Cartesian frame, in which their
    // constraints are written.
    if (cartesian || hanging_nodes)
      return Tensor<2, 3>(unit_symmetric_tensor<3>());
    // n is the exact normal if there is one, else ñ.
    return BlockStokesPreconditioner::node_frame(exact_normal ? exact_normal(x) :
                                                                Tensor<1, 3>(smooth_normal / smooth_normal.norm()));
  }

  // ---------------------------------------------------------------- the global system

  void
  SurfaceFlow::copy_local_to_global(const CopyData &copy)
  {
    if (copy.with_lor)
      for (unsigned int s = 0; s < 4; ++s)
        constraints.distribute_local_to_global(copy.lor_matrices[s], copy.lor_indices[s], lor_velocity_matrix);
    if (!copy.killing_moments.empty())
      {
        unconstrained_rhs.add(copy.indices, copy.rhs);
        for (unsigned int a = 0; a < copy.killing_moments.size(); ++a)
          killing_moments[a].add(copy.indices, copy.killing_moments[a]);
      }
    if (copy.with_matrix)
      {
        constraints.distribute_local_to_global(copy.matrix, copy.rhs, copy.indices, system_matrix, system_rhs);
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            constraints.distribute_local_to_global(copy.velocity_and_pressure_mass,
                                                   copy.indices,
                                                   preconditioner_matrix);
            if (with_time_derivative)
              constraints.distribute_local_to_global(copy.pressure_laplace, copy.indices, pressure_laplace);
          }
      }
    else
      constraints.distribute_local_to_global(copy.rhs, copy.indices, system_rhs);
  }

  void
  SurfaceFlow::assemble(const double time, const double tau, const bool assemble_matrix)
  {
    current_tau            = tau;
    current_time_for_force = time;
    system_rhs             = 0;
    const bool make_consistent = !with_time_derivative && !killing.empty();
    if (make_consistent)
      {
        unconstrained_rhs.reinit(owned, communicator);
        killing_moments.assign(killing.size(), unconstrained_rhs);
      }
    if (assemble_matrix)
      {
        system_matrix = 0;
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            preconditioner_matrix = 0;
            pressure_laplace      = 0;
            if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
              lor_velocity_matrix = 0;
          }
      }
    // The normal field is computed lazily; the node frames of the workers read it, so it is filled here, on
    // one thread (the workers would otherwise race to fill the geometry's cache).
    if (assemble_matrix && parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated &&
        parameters.velocity_amg_node_frames)
      geometry.normal_field();
    using CellFilter = FilteredIterator<typename DoFHandler<2, 3>::active_cell_iterator>;
    CopyData copy(fe.n_dofs_per_cell());
    copy.with_matrix = assemble_matrix;
    WorkStream::run(CellFilter(IteratorFilters::LocallyOwnedCell(), flow_dofs.begin_active()),
                    CellFilter(IteratorFilters::LocallyOwnedCell(), flow_dofs.end()),
                    [this](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                           ScratchData                                           &scratch,
                           CopyData &local) { local_assemble(cell, scratch, local); },
                    [this](const CopyData &local) { copy_local_to_global(local); },
                    ScratchData(geometry.mapping(), fe, geometry.fe(), geometry.quadrature(), lor_fe, lor_quadrature()),
                    copy);
    if (assemble_matrix)
      {
        system_matrix.compress(VectorOperation::add);
        if (parameters.solver == LinearSolver::block_preconditioned && preconditioner_outdated)
          {
            preconditioner_matrix.compress(VectorOperation::add);
            pressure_laplace.compress(VectorOperation::add);
            if (parameters.velocity_amg_operator == VelocityAMGOperator::low_order_refined)
              lor_velocity_matrix.compress(VectorOperation::add);
          }
        matrix_assembled = true;
      }
    system_rhs.compress(VectorOperation::add);
    if (make_consistent)
      {
        unconstrained_rhs.compress(VectorOperation::add);
        for (VectorType &moment : killing_moments)
          moment.compress(VectorOperation::add);
        remove_killing_components_from_rhs();
      }
  }

  void
  SurfaceFlow::remove_killing_components_from_rhs()
  {
    // The stationary operator annihilates the Killing fields k_a = I_h(a × x) (exactly for k ≤ 2 with
    // the exact normal, nearly otherwise), so A u = F needs k_aᵀF = 0. The discrete F misses that by
    // quadrature and geometry errors; the defect would otherwise act as point forces at the fixed
    // nodes. Subtract the Killing force Σ_b μ_b m_b, m_b = (b × x, φ), with k_aᵀ(F − Σ_b μ_b m_b) = 0.
    const unsigned int n_k = killing.size();
    FullMatrix<double> gram(n_k, n_k);
    Vector<double>     moments(n_k), mu(n_k);
    for (unsigned int a = 0; a < n_k; ++a)
      {
        FlowField rotation;
        const Tensor<1, 3> axis = killing[a];
        rotation.velocity = [axis](const Point<3> &x, const double) { return cross_product_3d(axis, x); };
        const VectorType interpolant = interpolate(rotation, 0.0);
        moments(a) = interpolant * unconstrained_rhs;
        for (unsigned int b = 0; b < n_k; ++b)
          gram(a, b) = interpolant * killing_moments[b];
      }
    gram.gauss_jordan();
    gram.vmult(mu, moments);
    for (unsigned int b = 0; b < n_k; ++b)
      system_rhs.add(-mu(b), killing_moments[b]);
    constraints.set_zero(system_rhs);
  }
} // namespace FluidSurface
