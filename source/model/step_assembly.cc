// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>

#include <fluid_surface/model/local_system.h>
#include <fluid_surface/model/nodal_point_values.h>
#include <fluid_surface/model/step_assembly.h>
#include <fluid_surface/model/surface_point_values.h>

#include <cmath>

namespace FluidSurface
{
  using namespace dealii;

  /**
   * One thread's view of the cell under assembly: the FEValues of the flow and geometry elements on the Gauss
   * and nodal rules, the fields at the points, the point values, the cell's LocalSystem, and the rows law
   * reference projects at the nodes.
   */
  struct CellContext
  {
    CellContext(const Mapping<2, 3>       &mapping,
                const FiniteElement<2, 3> &flow_fe,
                const FiniteElement<2, 3> &geometry_fe,
                const Quadrature<2>       &gauss,
                const Quadrature<2>       &nodal_rule)
      : flow(mapping, flow_fe, gauss, update_values | update_gradients | update_normal_vectors |
                                        update_quadrature_points | update_JxW_values)
      , flow_nodal(mapping, flow_fe, nodal_rule, update_values | update_gradients | update_quadrature_points |
                                                   update_JxW_values)
      , geometry(mapping, geometry_fe, gauss, update_values | update_gradients)
      , geometry_nodal(mapping, geometry_fe, nodal_rule, update_values)
      , point(flow_fe.n_dofs_per_cell())
      , nodal(flow_fe.n_dofs_per_cell())
      , smooth_normal(gauss.size())
      , smooth_normal_gradient(gauss.size())
      , old_velocity(gauss.size())
      , transport_velocity(gauss.size())
      , old_velocity_gradient(gauss.size())
      , nodal_smooth_normal(nodal_rule.size())
      , old_position(gauss.size())
      , nodal_old_position(nodal_rule.size())
      , reference_gradient(gauss.size())
      , trial_velocity(flow_fe.n_dofs_per_cell())
    {}
    CellContext(const CellContext &other)
      : CellContext(other.flow.get_mapping(),
                    other.flow.get_fe(),
                    other.geometry.get_fe(),
                    other.flow.get_quadrature(),
                    other.flow_nodal.get_quadrature())
    {}

    FEValues<2, 3>            flow, flow_nodal, geometry, geometry_nodal;
    SurfacePointValues        point;
    NodalPointValues          nodal;
    std::vector<Tensor<1, 3>> smooth_normal;          ///< ñ at the Gauss points
    std::vector<Tensor<2, 3>> smooth_normal_gradient; ///< ∇ñ
    std::vector<Tensor<1, 3>> old_velocity;           ///< û
    std::vector<Tensor<1, 3>> transport_velocity;     ///< w of the convection (u^m, or BDF2's u*)
    std::vector<Tensor<2, 3>> old_velocity_gradient;  ///< G of the transport fields
    std::vector<Tensor<1, 3>> nodal_smooth_normal;    ///< ñ at the nodal points
    std::vector<Tensor<1, 3>> old_position;           ///< X̂ at the Gauss points
    std::vector<Tensor<1, 3>> nodal_old_position;     ///< X̂ at the nodal points
    // By local DoF j of u at the current Gauss point: c φ_j + Ω × φ_j + G(φ_j) w (the same for every test function).
    std::vector<Tensor<1, 3>> trial_velocity;
    // Law reference: ∇_{S^m}X₀ at the Gauss points, ñ by node, the rows of Y before their projection.
    std::vector<Tensor<2, 3>> reference_gradient;
    std::vector<Tensor<1, 3>> node_normals;
    FullMatrix<double>        normal_rows, tangential_rows;
    Vector<double>            tangential_rhs;

    const StepAssemblyData *data   = nullptr; ///< the assembly under way
    const DofLayout        *layout = nullptr; ///< the local DoFs of u, p, κ, y, Y
    LocalSystem            *local  = nullptr; ///< the cell's contribution
  };

  namespace
  {
    /**
     * The surface fluid's rows (SurfaceFluid): (1/τ)(u − û, v) + (G u, v) − (1/τ)(G (Y − X̂), v) + (2/Re)(σ(u),
     * σ(v)) + γ_gd(div_P u − s, div_P v) − (p, div_P v) (in the Stokes limit ε(u, v) instead of the inertia, no
     * convection) and −(div_P u, q) = −(s, q). With law reference in the frame carried by the rigid motion: (Ω × u, v) and the
     * mesh velocity R + (Y − Z)/τ.
     */
    class FlowTerm : public StepTerm
    {
    public:
      explicit FlowTerm(const StepComponents &components)
        : flow(components.flow)
        , regularization(components.momentum_constraints.regularization())
        , grad_div(flow.grad_div > 0)
      {}
      void
      gauss_point(const unsigned int q, CellContext &cell) const override
      {
        const StepAssemblyData &data    = *cell.data;
        const DofLayout        &layout  = *cell.layout;
        LocalSystem            &local   = *cell.local;
        const FlowPointValues  &p       = cell.point.flow;
        const double            dA      = p.JxW;
        const double            tau     = data.tau;
        const double            inv_tau = 1.0 / tau;
        const Point<3>          old_point(cell.old_position[q]);
        // The mass term: the inertia (1/τ)(u, v), or the Stokes limit's regularization ε(u, v).
        const double mass = flow.inertia ? inv_tau : regularization;
        // In the carried frame (ũ = Qᵀu, the new position relative to the carry) the frame's rotation adds
        // (Ω × ũ, v), and the mesh velocity in the convection is R + (Ỹ − X^m)/τ, i.e. W = X^m − τR.
        const Point<3> frame_point = data.frame_velocity_on_new_surface ? p.position : old_point;
        const Point<3> start       = data.frame->kind == StepFrame::Kind::carried ?
                                       old_point - tau * data.frame->carried.value(frame_point) :
                                       old_point;
        const bool turning = data.frame->solved_in_frame() && flow.inertia;
        // The mass, frame and convection terms are each φ_i · (a vector of the trial function φ_j): their sum
        // is one product with c φ_j + Ω × φ_j + G(φ_j) w, formed once per j. (∇_w u, v) with w = u^m,
        // consistent (not skew-symmetrized; doc/scheme.md).
        for (const unsigned int j : layout.velocity)
          {
            Tensor<1, 3> trial = mass * p.velocity[j];
            if (turning)
              trial += SurfaceFluid::turned_velocity(p, j, data.frame->carried.rotation);
            if (flow.convection)
              trial += SurfaceFluid::convected_velocity(p, j);
            cell.trial_velocity[j] = trial;
          }
        // The viscous term is symmetric: one evaluation serves (i, j) and (j, i). φ_i = φ e_d has one direction d,
        // so φ_i · t = φ t_d (the same number as the full product).
        const std::vector<unsigned int> &velocity = layout.velocity, &direction = layout.velocity_direction;
        for (unsigned int a = 0; a < velocity.size(); ++a)
          {
            const unsigned int i   = velocity[a];
            const double       phi = p.velocity[i][direction[a]];
            if (flow.inertia)
              local.rhs(i) += SurfaceFluid::mass_term_rhs(p, i, inv_tau) * dA;
            if (flow.convection)
              local.rhs(i) += SurfaceFluid::mesh_motion_term_rhs(p, i, inv_tau, start) * dA;
            if (grad_div)
              local.rhs(i) += flow.grad_div * data.area_rate * p.divergence[i] * dA;
            local.matrix(i, i) += (viscous_term(p, i, i) + phi * cell.trial_velocity[i][direction[a]]) * dA;
            for (unsigned int b = a + 1; b < velocity.size(); ++b)
              {
                const unsigned int j       = velocity[b];
                const double       viscous = viscous_term(p, i, j);
                local.matrix(i, j) += (viscous + phi * cell.trial_velocity[j][direction[a]]) * dA;
                local.matrix(j, i) += (viscous + p.velocity[j][direction[b]] * cell.trial_velocity[i][direction[b]]) * dA;
              }
            for (const unsigned int j : layout.pressure)
              local.matrix(i, j) += SurfaceFluid::pressure_term(p, i, j) * dA;
            if (flow.convection)
              for (const unsigned int j : layout.new_position)
                local.matrix(i, j) += SurfaceFluid::mesh_motion_term(p, i, cell.point.new_position[j], inv_tau) * dA;
          }
        for (const unsigned int i : layout.pressure)
          {
            local.rhs(i) += SurfaceFluid::continuity_term_rhs(p, i, data.area_rate) * dA;
            for (const unsigned int j : layout.velocity)
              local.matrix(i, j) += SurfaceFluid::continuity_term(p, i, j) * dA;
          }
      }

    private:
      /// The viscous term and, with γ_gd > 0, the grad-div term γ_gd div_P φ_i div_P φ_j (both symmetric).
      double
      viscous_term(const FlowPointValues &p, const unsigned int i, const unsigned int j) const
      {
        const double viscous = flow.viscous_term(p, i, j);
        return grad_div ? viscous + flow.grad_div * p.divergence[i] * p.divergence[j] : viscous;
      }

      const SurfaceFluid &flow;
      const double        regularization;
      const bool          grad_div; ///< γ_gd > 0
    };

    /// (u, v) = (u_prescribed, v) and (p, q) = 0: the L² projection of a prescribed velocity (in the carried
    /// frame: Qᵀ u_prescribed at the carried point).
    class PrescribedVelocityTerm : public StepTerm
    {
    public:
      explicit PrescribedVelocityTerm(const Function<3> &velocity)
        : velocity(velocity)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        const StepAssemblyData &data   = *cell.data;
        const DofLayout        &layout = *cell.layout;
        LocalSystem            &local  = *cell.local;
        const FlowPointValues  &p      = cell.point.flow;
        const double            dA     = p.JxW;
        const Point<3>          y      = data.frame->carried.carry(p.position, data.tau);
        Tensor<1, 3>            u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = velocity.value(y, d);
        u = transpose(data.frame->carried.rotation_over(data.tau)) * u;
        for (const unsigned int i : layout.velocity)
          {
            local.rhs(i) += (u * p.velocity[i]) * dA;
            for (const unsigned int j : layout.velocity)
              local.matrix(i, j) += (p.velocity[i] * p.velocity[j]) * dA;
          }
        for (const unsigned int i : layout.pressure)
          for (const unsigned int j : layout.pressure)
            local.matrix(i, j) += p.pressure[i] * p.pressure[j] * dA;
      }

    private:
      const Function<3> &velocity;
    };

    /// The Helfrich force on the momentum rows (BendingForce::assemble_force()).
    class BendingForceTerm : public StepTerm
    {
    public:
      explicit BendingForceTerm(const BendingForce &bending)
        : bending(bending)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        bending.assemble_force(cell.point, *cell.layout, cell.local->matrix);
      }

    private:
      const BendingForce &bending;
    };

    /// The rows of the bending scalar y (BendingForce::assemble_bending_scalar()).
    class BendingScalarTerm : public StepTerm
    {
    public:
      explicit BendingScalarTerm(const BendingForce &bending)
        : bending(bending)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        bending.assemble_bending_scalar(cell.point, *cell.layout, cell.local->matrix);
      }

    private:
      const BendingForce &bending;
    };

    /// Mesh law bgn: (∇_S Y, ∇_S η) defines κ and moves the nodes tangentially; the kinematics and the
    /// tangential damping towards X^m + τR at the nodes (in the co-rotating frame: Ỹ·ñ = X^m·ñ + τ(ũ − R)·ñ,
    /// damped towards X^m).
    class BgnMeshLawTerm : public StepTerm
    {
    public:
      explicit BgnMeshLawTerm(const MeshRedistribution &redistribution)
        : redistribution(redistribution)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        redistribution.assemble_surface_laplacian(cell.point, *cell.layout, cell.local->matrix);
      }
      void
      nodal_point(const unsigned int q, CellContext &cell) const override
      {
        const StepAssemblyData &data = *cell.data;
        const Point<3>          x(cell.nodal_old_position[q]);
        LocalSystem            &local = *cell.local;
        if (data.frame->co_rotating())
          {
            const Point<3> frame_point = data.frame_velocity_on_new_surface ? cell.nodal.position : x;
            redistribution.assemble_kinematics(
              cell.nodal, *cell.layout, data.tau, x - data.tau * data.frame->carried.value(frame_point), local.matrix, local.rhs);
            redistribution.assemble_nodal_terms(cell.nodal, *cell.layout, data.tau, x, local.matrix, local.rhs);
            return;
          }
        redistribution.assemble_kinematics(cell.nodal, *cell.layout, data.tau, x, local.matrix, local.rhs);
        redistribution.assemble_nodal_terms(
          cell.nodal, *cell.layout, data.tau, x + data.tau * data.frame->carried.value(x), local.matrix, local.rhs);
      }

    private:
      const MeshRedistribution &redistribution;
    };

    /**
     * Mesh law reference: (∇_S Y, ∇_S η) only defines κ (normal rows), the membrane energy towards S₀ moves the
     * nodes tangentially, and both are projected at the nodes once the cell is done. The kinematics in the
     * carried frame: Ỹ·ñ = X^m·ñ + τ(ũ − R)·ñ, damped towards X^m.
     */
    class ReferenceMeshLawTerm : public StepTerm
    {
    public:
      explicit ReferenceMeshLawTerm(const MeshRedistribution &redistribution)
        : redistribution(redistribution)
        , membrane(redistribution.shear_stiffness > 0 || redistribution.area_stiffness > 0)
      {}
      void
      reinit_cell(CellContext &cell) const override
      {
        const unsigned int n = cell.local->rhs.size();
        cell.normal_rows.reinit(n, n);
        cell.tangential_rows.reinit(n, n);
        cell.tangential_rhs.reinit(n);
        cell.node_normals.resize(cell.layout->new_position_nodes.size());
        cell.flow[FEValuesExtractors::Vector(DofLayout::new_position_component)].get_function_gradients(
          *cell.data->reference_position, cell.reference_gradient);
      }
      void
      gauss_point(const unsigned int q, CellContext &cell) const override
      {
        const StepAssemblyData &data = *cell.data;
        redistribution.assemble_surface_laplacian(cell.point, *cell.layout, cell.normal_rows);
        if (redistribution.conformal_tangential)
          redistribution.assemble_surface_laplacian(cell.point, *cell.layout, cell.tangential_rows);
        if (membrane && data.membrane_weight > 0)
          redistribution.assemble_reference_terms(cell.point,
                                                  cell.reference_gradient[q],
                                                  unit_symmetric_tensor<3>(), // the carried frame: Z = X^m
                                                  data.area_scale,
                                                  data.membrane_weight,
                                                  *cell.layout,
                                                  cell.tangential_rows,
                                                  cell.tangential_rhs);
      }
      void
      nodal_point(const unsigned int q, CellContext &cell) const override
      {
        const StepAssemblyData &data   = *cell.data;
        const DofLayout        &layout = *cell.layout;
        const NodalPointValues &nodal  = cell.nodal;
        LocalSystem            &local  = *cell.local;
        const Point<3>          x(cell.nodal_old_position[q]);
        const Point<3> frame_point = data.frame_velocity_on_new_surface ? nodal.position : x;
        redistribution.assemble_kinematics(
          nodal, layout, data.tau, x - data.tau * data.frame->carried.value(frame_point), local.matrix, local.rhs);
        redistribution.assemble_nodal_terms(nodal, layout, data.tau, x, local.matrix, local.rhs);
        // The nodal rule's points are the nodes: the node whose shape function is 1 here.
        for (unsigned int n = 0; n < layout.new_position_nodes.size(); ++n)
          if (std::abs(nodal.new_position[layout.new_position_nodes[n][0]][0] - 1.0) < 1e-8)
            cell.node_normals[n] = nodal.smooth_normal;
      }
      void
      finish_cell(CellContext &cell) const override
      {
        MeshRedistribution::project_position_rows(cell.node_normals,
                                                  *cell.layout,
                                                  cell.normal_rows,
                                                  cell.tangential_rows,
                                                  cell.tangential_rhs,
                                                  cell.local->matrix,
                                                  cell.local->rhs);
      }

    private:
      const MeshRedistribution &redistribution;
      const bool                membrane; ///< μ > 0 or K > 0
    };

    /// γ's column (ñ, v) and the volume row (VolumeConstraint::assemble_column()).
    class VolumeColumnTerm : public StepTerm
    {
    public:
      explicit VolumeColumnTerm(const VolumeConstraint &volume_constraint)
        : volume_constraint(volume_constraint)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        volume_constraint.assemble_column(cell.point, *cell.layout, cell.local->volume_column);
      }

    private:
      const VolumeConstraint &volume_constraint;
    };

    /// The rigid-motion columns and constraint rows (MomentumConstraints); the rows equal the columns in the
    /// velocity DoFs.
    class MomentumConstraintTerm : public StepTerm
    {
    public:
      explicit MomentumConstraintTerm(const MomentumConstraints &constraints)
        : constraints(constraints)
      {}
      void
      gauss_point(const unsigned int, CellContext &cell) const override
      {
        constraints.assemble_columns(cell.point, *cell.layout, cell.local->rigid_columns);
        if (constraints.on_new_surface())
          constraints.assemble_new_surface_rows(cell.point, *cell.layout, cell.local->rigid_rows);
      }
      void
      finish_cell(CellContext &cell) const override
      {
        for (unsigned int k = 0; k < 6; ++k)
          for (const unsigned int i : cell.layout->velocity)
            cell.local->rigid_rows[k](i) = cell.local->rigid_columns[k](i);
      }

    private:
      const MomentumConstraints &constraints;
    };
  } // namespace

  StepAssembly::StepAssembly(const StepComponents &components, const StepRequest &request, StepSystem &system)
    : components(components)
    , system(system)
    , rigid(components.momentum_constraints.active())
    , reference(request.law == MeshRedistribution::Law::reference)
  {
    if (request.prescribed_velocity() != nullptr)
      terms.push_back(std::make_unique<PrescribedVelocityTerm>(*request.prescribed_velocity()));
    else
      {
        terms.push_back(std::make_unique<FlowTerm>(components));
        terms.push_back(std::make_unique<BendingForceTerm>(components.bending));
      }
    terms.push_back(std::make_unique<BendingScalarTerm>(components.bending));
    if (reference)
      terms.push_back(std::make_unique<ReferenceMeshLawTerm>(components.redistribution));
    else
      terms.push_back(std::make_unique<BgnMeshLawTerm>(components.redistribution));
    terms.push_back(std::make_unique<VolumeColumnTerm>(components.volume_constraint));
    if (rigid)
      terms.push_back(std::make_unique<MomentumConstraintTerm>(components.momentum_constraints));
  }

  StepAssembly::~StepAssembly() = default;

  void
  StepAssembly::assemble(const StepAssemblyData &data) const
  {
    system.zero();
    const SurfaceGeometry &geometry = system.geometry();
    const QGauss<2>        gauss(system.fe().degree + 1);
    const Quadrature<2>    nodal_rule = components.redistribution.nodal_quadrature(gauss, geometry.degree());
    const unsigned int     n_dofs     = system.fe().n_dofs_per_cell();
    const FEValuesExtractors::Vector vector(0);

    auto worker = [&](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                      CellContext                                          &context,
                      LocalSystem                                          &local) {
      local.reinit(n_dofs, rigid);
      cell->get_dof_indices(local.indices);
      context.data   = &data;
      context.layout = &system.layout();
      context.local  = &local;
      const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                          cell->level(),
                                                                          cell->index(),
                                                                          &geometry.dof_handler());
      context.flow.reinit(cell);
      context.geometry.reinit(geometry_cell);
      context.geometry[vector].get_function_values(*data.normal, context.smooth_normal);
      context.geometry[vector].get_function_gradients(*data.normal, context.smooth_normal_gradient);
      context.flow[vector].get_function_values(*data.old_fields, context.old_velocity);
      if (data.transport_fields != data.old_fields)
        context.flow[vector].get_function_values(*data.transport_fields, context.transport_velocity);
      else
        context.transport_velocity = context.old_velocity;
      context.flow[vector].get_function_gradients(*data.transport_fields, context.old_velocity_gradient);
      context.geometry[vector].get_function_values(*data.old_position, context.old_position);
      if (data.frame->co_rotating())
        for (unsigned int q = 0; q < context.flow.n_quadrature_points; ++q)
          context.transport_velocity[q] -= data.frame->carried.value(data.frame_velocity_on_new_surface ?
                                                                context.flow.quadrature_point(q) :
                                                                Point<3>(context.old_position[q]));
      for (const auto &term : terms)
        term->reinit_cell(context);

      for (unsigned int q = 0; q < context.flow.n_quadrature_points; ++q)
        {
          context.point.reinit(context.flow,
                               q,
                               context.smooth_normal[q],
                               context.smooth_normal_gradient[q],
                               context.old_velocity[q],
                               context.transport_velocity[q],
                               context.old_velocity_gradient[q]);
          for (const auto &term : terms)
            term->gauss_point(q, context);
        }

      context.flow_nodal.reinit(cell);
      context.geometry_nodal.reinit(geometry_cell);
      context.geometry_nodal[vector].get_function_values(*data.normal, context.nodal_smooth_normal);
      context.geometry_nodal[vector].get_function_values(*data.old_position, context.nodal_old_position);
      for (unsigned int q = 0; q < context.flow_nodal.n_quadrature_points; ++q)
        {
          context.nodal.reinit(context.flow_nodal, q, context.nodal_smooth_normal[q]);
          for (const auto &term : terms)
            term->nodal_point(q, context);
        }
      for (const auto &term : terms)
        term->finish_cell(context);
    };
    auto copier = [&](const LocalSystem &local) { system.distribute_local_to_global(local, rigid); };

    using Iterator = typename DoFHandler<2, 3>::active_cell_iterator;
    const DoFHandler<2, 3> &dofs = system.dof_handler();
    WorkStream::run(FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.begin_active()),
                    FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.end()),
                    worker,
                    copier,
                    CellContext(geometry.mapping(), system.fe(), geometry.fe(), gauss, nodal_rule),
                    LocalSystem());
    system.compress(rigid);
  }
} // namespace FluidSurface
