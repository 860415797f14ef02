// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/model/surface_step.h>
#include <fluid_surface/model/surface_reparametrization.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    using CellIterator = DoFHandler<2, 3>::active_cell_iterator;

    /// The same cell of the triangulation as an iterator of @p dofs.
    template <class Iterator>
    CellIterator
    cell_of(const Iterator &cell, const DoFHandler<2, 3> &dofs)
    {
      return CellIterator(&dofs.get_triangulation(), cell->level(), cell->index(), &dofs);
    }

    /// The point X(ξ) of a cell of a vector Q_k position element with the cell values @p values, and its two
    /// tangent vectors ∂X/∂ξ_0, ∂X/∂ξ_1.
    Point<3>
    position_at(const FiniteElement<2, 3> &fe,
                const Vector<double>      &values,
                const Point<2>            &xi,
                Tensor<1, 3>              *d0 = nullptr,
                Tensor<1, 3>              *d1 = nullptr)
    {
      Point<3>     x;
      Tensor<1, 3> t0, t1;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          x[c] += values[i] * fe.shape_value(i, xi);
          if (d0 != nullptr)
            {
              const Tensor<1, 2> g = fe.shape_grad(i, xi);
              t0[c] += values[i] * g[0];
              t1[c] += values[i] * g[1];
            }
        }
      if (d0 != nullptr)
        {
          *d0 = t0;
          *d1 = t1;
        }
      return x;
    }

    /**
     * The closest point on the discrete surface given by a position field: a projected Gauss–Newton iteration
     * for the reference point ξ ∈ [0, 1]² in a cell, and a walk through the cells around the vertices of the
     * best cell while the foot point lies on a cell's boundary. Cells must be locally owned or ghost cells
     * (the position vector ghosted); points farther than a few cells from their starting cell are not meant.
     */
    class SurfacePointLocator
    {
    public:
      struct Location
      {
        CellIterator cell;
        Point<2>     xi;
        Point<3>     point;
        Tensor<1, 3> normal; ///< unit normal of the surface at the point (orientation of the cell)
        double       distance = 0;
      };

      SurfacePointLocator(const DoFHandler<2, 3> &dofs, const VectorType &position)
        : dofs(dofs)
        , position(position)
        , vertex_cells(GridTools::vertex_to_cell_map(dofs.get_triangulation()))
      {}

      /// The closest point to @p p, searched from the cell @p start.
      Location
      locate(const Point<3> &p, const CellIterator &start) const
      {
        Location     best   = closest_in_cell(start, p);
        CellIterator centre = start;
        for (unsigned int round = 0; round < 16 && !interior(best.xi); ++round)
          {
            for (unsigned int v = 0; v < GeometryInfo<2>::vertices_per_cell; ++v)
              for (const auto &neighbour : vertex_cells[centre->vertex_index(v)])
                if (!neighbour->is_artificial() && neighbour != centre)
                  {
                    const Location candidate = closest_in_cell(cell_of(neighbour, dofs), p);
                    if (candidate.distance < best.distance - 1e-15)
                      best = candidate;
                  }
            if (best.cell == centre)
              break;
            centre = best.cell;
          }
        return best;
      }

    private:
      static bool
      interior(const Point<2> &xi)
      {
        return xi[0] > 1e-12 && xi[0] < 1 - 1e-12 && xi[1] > 1e-12 && xi[1] < 1 - 1e-12;
      }

      Location
      closest_in_cell(const CellIterator &cell, const Point<3> &p) const
      {
        const FiniteElement<2, 3> &fe = dofs.get_fe();
        Vector<double>             values(fe.n_dofs_per_cell());
        cell->get_dof_values(position, values);
        Location     location;
        Point<2>     xi(0.5, 0.5);
        Tensor<1, 3> d0, d1;
        Point<3>     x = position_at(fe, values, xi, &d0, &d1);
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            const Tensor<1, 3> r = x - p;
            const double       a = d0 * d0, b = d0 * d1, c = d1 * d1, det = a * c - b * b;
            if (!(det > 0))
              break;
            const double g0 = d0 * r, g1 = d1 * r;
            Point<2>     next(xi[0] - (c * g0 - b * g1) / det, xi[1] - (a * g1 - b * g0) / det);
            for (unsigned int d = 0; d < 2; ++d)
              next[d] = std::clamp(next[d], 0.0, 1.0);
            const double change = (next - xi).norm();
            xi                  = next;
            x                   = position_at(fe, values, xi, &d0, &d1);
            if (change < 1e-14)
              break;
          }
        location.cell     = cell;
        location.xi       = xi;
        location.point    = x;
        location.normal   = cross_product_3d(d0, d1);
        location.normal  /= location.normal.norm();
        location.distance = (x - p).norm();
        return location;
      }

      const DoFHandler<2, 3>                                             &dofs;
      const VectorType                                                   &position;
      const std::vector<std::set<Triangulation<2, 3>::active_cell_iterator>> vertex_cells;
    };
  } // namespace

  void
  SurfaceReparametrization::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("reparametrization");
    prm.declare_entry("quality threshold",
                      "0.1",
                      RealRange::closed(0, 1),
                      "q_r, 0 ≤ q_r ≤ 1: when the mesh quality (min over cells of σ_min/σ_max of the Jacobian) of an "
                      "accepted step falls below q_r, the surface is re-parametrized at fixed connectivity (new "
                      "nodes on the current surface, fields transferred, A, V, incompressibility and momenta "
                      "restored; the jumps go to the statistics and the summary). 0: never. Must exceed 'mesh "
                      "redistribution/mesh quality floor'.");
    prm.declare_entry("relaxation iterations",
                      "5",
                      Patterns::Integer(1, 100),
                      "n_r, 1 ≤ n_r ≤ 100: linearized solves of the mesh law alone (velocity zero, no global "
                      "constraints, damping T_r/τ with τ = 10 T_r) that place the new nodes, each followed by the "
                      "closest-point projection of the nodes onto the surface before it and the transfer of the "
                      "fields.");
    prm.declare_entry("maximum energy jump",
                      "0.01",
                      RealRange::closed(0, 1),
                      "ε_J, 0 ≤ ε_J ≤ 1: a re-parametrization that changes the total energy F by more than ε_J|F| is "
                      "not taken (the state is restored, a warning printed, and the run goes on towards the mesh "
                      "quality floor). The new surface interpolates the old one; on a degraded mesh its curvature "
                      "picks up the old cells' kinks (doc/scheme.md, \"Safety valve\").");
    prm.leave_subsection();
  }

  void
  SurfaceReparametrization::parse_parameters(ParameterHandler &prm, const double mesh_quality_floor)
  {
    prm.enter_subsection("reparametrization");
    quality_threshold = prm.get_double("quality threshold");
    iterations          = prm.get_integer("relaxation iterations");
    maximum_energy_jump = prm.get_double("maximum energy jump");
    prm.leave_subsection();
    if (quality_threshold > 0 && quality_threshold <= mesh_quality_floor)
      {
        std::ostringstream expected;
        expected << "0 (off) or a number above 'mesh redistribution/mesh quality floor' = " << mesh_quality_floor
                 << " (a run stops at the floor, so the valve would never act)";
        std::ostringstream value;
        value << quality_threshold;
        throw_invalid_entry("reparametrization/quality threshold", value.str(), expected.str());
      }
  }

  bool
  SurfaceReparametrization::due(const double quality, const double quality_after_last) const
  {
    return enabled() && quality < quality_threshold &&
           (quality_after_last >= quality_threshold || quality < 0.9 * quality_after_last);
  }

  VectorType
  SurfaceReparametrization::closest_points(const SurfaceGeometry &geometry, const VectorType &old_position)
  {
    // The old position field evaluated where each node now lies on the old surface: its closest point.
    VectorType result(geometry.locally_owned_dofs(), geometry.get_communicator());
    transfer(geometry, old_position, geometry.position(), geometry.dof_handler(), old_position, result);
    return result;
  }

  void
  SurfaceReparametrization::transfer(const SurfaceGeometry  &geometry,
                                     const VectorType       &old_position,
                                     const VectorType       &new_position,
                                     const DoFHandler<2, 3> &field_dofs,
                                     const VectorType       &old_field,
                                     VectorType             &new_field)
  {
    const SurfacePointLocator  locator(geometry.dof_handler(), old_position);
    const FiniteElement<2, 3> &position_fe = geometry.fe();
    const FiniteElement<2, 3> &field_fe    = field_dofs.get_fe();
    const IndexSet             owned       = field_dofs.locally_owned_dofs();
    Vector<double>             new_nodes(position_fe.n_dofs_per_cell()), old_values(field_fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> indices(field_fe.n_dofs_per_cell());
    std::vector<double>                  by_component(field_fe.n_components());
    for (const auto &cell : field_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const CellIterator geometry_cell = cell_of(cell, geometry.dof_handler());
          geometry_cell->get_dof_values(new_position, new_nodes);
          cell->get_dof_indices(indices);
          std::vector<bool> done(field_fe.n_dofs_per_cell(), false);
          for (unsigned int i = 0; i < field_fe.n_dofs_per_cell(); ++i)
            {
              if (done[i] || !owned.is_element(indices[i]))
                continue;
              const Point<2> xi       = field_fe.unit_support_point(i);
              const auto     location = locator.locate(position_at(position_fe, new_nodes, xi), geometry_cell);
              cell_of(location.cell, field_dofs)->get_dof_values(old_field, old_values);
              std::fill(by_component.begin(), by_component.end(), 0.0);
              for (unsigned int k = 0; k < field_fe.n_dofs_per_cell(); ++k)
                by_component[field_fe.system_to_component_index(k).first] +=
                  old_values[k] * field_fe.shape_value(k, location.xi);
              for (unsigned int j = i; j < field_fe.n_dofs_per_cell(); ++j)
                if (!done[j] && owned.is_element(indices[j]) && field_fe.unit_support_point(j).distance(xi) < 1e-12)
                  {
                    new_field[indices[j]] = by_component[field_fe.system_to_component_index(j).first];
                    done[j]               = true;
                  }
            }
        }
    new_field.compress(VectorOperation::insert);
  }

  std::string
  SurfaceReparametrization::relax_mesh(SurfaceStep      &step,
                                       const VectorType &start_surface,
                                       const VectorType &start_fields,
                                       VectorType       &state) const
  {
    SurfaceGeometry        &geometry = step.moved_geometry();
    const DoFHandler<2, 3> &dofs     = step.dof_handler();
    StepRequest relaxation_request;
    relaxation_request.velocity           = StepRequest::Velocity::at_rest;
    relaxation_request.global_constraints = false;
    // The target is always the membrane energy relative to S₀: with law bgn the conformal distribution of
    // the current surface is the one that degraded (a bgn prolate went from quality 0.098 to 0.088).
    relaxation_request.law    = MeshRedistribution::Law::reference;
    relaxation_request.solver = StepRequest::Solver::fresh_factorization;
    const double relaxation_time = step.components().redistribution.relaxation_time;
    const double tau             = relaxation_time > 0 ? 10 * relaxation_time : 1.0;
    VectorType   surface = start_surface, fields = start_fields;
    std::string  failure;
    StepCandidate relaxed;
    for (unsigned int iteration = 0; iteration < iterations && failure.empty(); ++iteration)
      {
        const SurfaceStep::Result relaxation = step.advance(relaxation_request, tau, relaxed);
        if (!relaxation.solved)
          {
            failure = relaxation.message;
            break;
          }
        geometry.set_position(closest_points(geometry, surface));
        transfer(geometry, surface, geometry.position(), dofs, fields, state);
        surface = geometry.position();
        fields  = state;
      }
    return failure;
  }

  std::string
  SurfaceReparametrization::project_velocity(SurfaceStep       &step,
                                             SurfaceState      &accepted,
                                             const StepRequest &run_request) const
  {
    SurfaceGeometry              &geometry     = step.moved_geometry();
    const ConservationProjection &conservation = step.components().conservation;
    StepRequest                   projection_request = run_request;
    projection_request.solver                        = StepRequest::Solver::fresh_factorization;
    StepCandidate             projected;
    const SurfaceStep::Result projection = step.advance(projection_request, projection_time_step, projected);
    if (!projection.solved)
      return projection.message;
    VectorType state(step.dof_handler().locally_owned_dofs(), geometry.get_communicator());
    state = projected.solution;
    step.copy_position_into(accepted.position, state);
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = accepted.position;
    geometry.set_position(position);
    if (conservation.enabled && step.components().flow.conserve_momenta)
      conservation.project_momenta(geometry, step.dof_handler(), accepted.rigid_targets, state);
    accepted.solution = state;
    step.solver().forget_last_solution();
    step.solver().request_factorization();
    return "";
  }

  SurfaceReparametrization::Result
  SurfaceReparametrization::reparametrize(SurfaceStep                   &step,
                                          SurfaceState                  &accepted,
                                          const StepRequest             &run_request,
                                          const std::function<double()> &total_energy) const
  {
    Result           result;
    SurfaceGeometry &geometry = step.moved_geometry();
    const MPI_Comm   comm     = geometry.get_communicator();
    // The solves of the valve use a fresh factorization, freed at the end.
    struct Finish
    {
      SurfaceStep &step;
      ~Finish()
      {
        step.solver().release_fresh_factorization();
      }
    } finish{step};
    result.quality_before      = geometry.measure().mesh_quality;
    const double energy_before = total_energy();
    const VectorType  kept_state = accepted.solution, kept_position = accepted.position;
    const auto        restore    = [&](const std::string &why) {
      accepted.solution = kept_state;
      accepted.position = kept_position;
      step.solver().forget_last_solution();
      VectorType position(geometry.locally_owned_dofs(), comm);
      position = kept_position;
      geometry.set_position(position);
      step.solver().request_factorization();
      result.failure = why;
      return result;
    };

    // New nodes on the current surface: solves of the mesh law alone (the velocity held at zero, no global
    // constraints, weak damping), each followed by the closest-point projection of the nodes onto the surface
    // before it and the transfer of the fields. Projecting onto the previous iterate, not onto the first
    // surface, keeps every search within the ghost layer of a parallel mesh as long as a solve moves no node
    // by more than a cell; the surface then changes by its interpolation error once per iteration.
    const SurfaceFluid           &flow         = step.components().flow;
    const ConservationProjection &conservation = step.components().conservation;
    const DoFHandler<2, 3>       &dofs         = step.dof_handler();
    VectorType                    state(dofs.locally_owned_dofs(), comm);
    state = accepted.solution;
    const std::string failure = relax_mesh(step, kept_position, accepted.solution, state);
    if (!failure.empty())
      return restore("the relaxation of the mesh failed: " + failure);
    // The relaxed surface differs from the old one by its interpolation error, far more than a step's drift:
    // the projection's modes ñ, Hñ are those of the surface it starts from, so it is repeated on the
    // projected surface.
    if (conservation.enabled && run_request.prescribed_velocity() == nullptr)
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          const SurfaceGeometry::Curvature modes = geometry.curvature();
          result.node_correction += conservation.project_area_and_volume(
            geometry, modes, accepted.target_area, accepted.target_volume, step.components().volume_constraint.enabled);
        }
    step.copy_position_into(geometry.position(), state);
    if (!std::isfinite(state.l2_norm()))
      return restore("the transferred fields are not finite");
    accepted.solution = state;
    accepted.position = geometry.position();
    step.solver().forget_last_solution();
    step.solver().request_factorization();

    // The velocity back onto the discrete constraints: a step of the scheme in the limit τ → 0.
    if (flow.inertia && run_request.prescribed_velocity() == nullptr)
      {
        const std::string projection_failure = project_velocity(step, accepted, run_request);
        if (!projection_failure.empty())
          return restore("the projection of the velocity failed: " + projection_failure);
      }

    result.quality_after = geometry.measure().mesh_quality;
    // A worse mesh is not taken (a relaxation that changes nothing, as on the initial mesh, is).
    if (!(result.quality_after >= (1 - 1e-3) * result.quality_before))
      {
        std::ostringstream why;
        why << "it did not raise the mesh quality (" << result.quality_before << " -> " << result.quality_after << ")";
        return restore(why.str());
      }
    const double energy_after = total_energy();
    if (!(std::abs(energy_after - energy_before) <= maximum_energy_jump * std::abs(energy_before)))
      {
        std::ostringstream why;
        why << "it changed F by " << std::setprecision(3) << (energy_after - energy_before) / std::abs(energy_before)
            << " relative, more than 'reparametrization/maximum energy jump' = "
            << maximum_energy_jump;
        return restore(why.str());
      }
    result.done = true;
    return result;
  }

  SurfaceReparametrization::Jumps
  SurfaceReparametrization::record(const Result &result, const double quality, const Measures &before, const Measures &after)
  {
    if (!result.done)
      {
        // Not again before the quality has fallen by another 10 %.
        quality_after_last = quality;
        return {{0, 0, 0, 0}};
      }
    const auto relative = [](const double change, const double scale) {
      return std::abs(change) / (scale != 0 ? std::abs(scale) : 1.0);
    };
    const Jumps jumps{{relative(after.energy - before.energy, before.energy),
                       relative(after.area - before.area, before.area),
                       relative(after.volume - before.volume, before.volume),
                       relative((after.angular_momentum - before.angular_momentum).norm(),
                                before.angular_momentum.norm())}};
    ++count;
    quality_after_last = result.quality_after;
    for (unsigned int k = 0; k < jumps.size(); ++k)
      largest_jumps[k] = std::max(largest_jumps[k], jumps[k]);
    return jumps;
  }

  void
  SurfaceReparametrization::add_to_statistics(StatisticsFile &statistics, const Jumps &jumps) const
  {
    if (!enabled())
      return;
    statistics.add_value("reparametrizations", count);
    statistics.add_value("reparametrization energy jump", jumps[0]);
    statistics.add_value("reparametrization area jump", jumps[1]);
    statistics.add_value("reparametrization volume jump", jumps[2]);
    statistics.add_value("reparametrization angular momentum jump", jumps[3]);
  }

  void
  SurfaceReparametrization::write_summary(std::ostream &text) const
  {
    if (!enabled())
      return;
    text << "re-parametrizations: " << count;
    if (count > 0)
      text << std::scientific << std::setprecision(2) << " (largest jumps: ΔF/F = " << largest_jumps[0]
           << ", ΔA/A = " << largest_jumps[1] << ", ΔV/V = " << largest_jumps[2] << ", ΔL/L = " << largest_jumps[3]
           << ")" << std::defaultfloat;
    text << '\n';
  }

  void
  SurfaceReparametrization::save(CheckpointData &data) const
  {
    data.set("reparametrization/count", count);
    data.set("reparametrization/quality after last", quality_after_last);
    for (unsigned int k = 0; k < largest_jumps.size(); ++k)
      data.set("reparametrization/largest jump " + std::to_string(k), largest_jumps[k]);
  }

  void
  SurfaceReparametrization::load(const CheckpointData &data)
  {
    if (!data.has("reparametrization/count"))
      return;
    count              = data.get_unsigned("reparametrization/count");
    quality_after_last = data.get_double("reparametrization/quality after last");
    for (unsigned int k = 0; k < largest_jumps.size(); ++k)
      largest_jumps[k] = data.get_double("reparametrization/largest jump " + std::to_string(k));
  }
} // namespace FluidSurface
