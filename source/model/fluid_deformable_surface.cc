#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/geometry/surface_operators.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/postprocess/speed_postprocessor.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/model/fluid_deformable_surface.h>

#include <cmath>
#include <map>
#include <iomanip>
#include <sstream>
#include <limits>

namespace FluidSurface
{
  using namespace dealii;

  FluidDeformableSurface::FluidDeformableSurface(SurfaceGeometry &geometry)
    : geometry(geometry)
    , dofs(geometry.triangulation())
    , linear_solver("Amesos_Mumps") // `direct solver = default` of this scene
    , valve_solver("Amesos_Klu")
  {}

  void
  FluidDeformableSurface::declare_parameters(ParameterHandler &prm)
  {
    SurfaceFluid::declare_parameters(prm);
    BendingForce::declare_parameters(prm);
    VolumeConstraint::declare_parameters(prm);
    MeshRedistribution::declare_parameters(prm);
    ConservationProjection::declare_parameters(prm);
    SurfaceReparametrization::declare_parameters(prm);
    GeometryIteration::declare_parameters(prm);
    prm.enter_subsection("initial state");
    prm.declare_entry("angular velocity",
                      "0",
                      RealRange::closed(-100, 100),
                      "ω₀, |ω₀| ≤ 100, of the initial rigid rotation u₀ = ω₀ e × (x − c). (Velocities are scaled with "
                      "U; faster initial states only shrink τ until the run no longer finishes.)");
    prm.declare_entry("equilibrium rotation",
                      "false",
                      Patterns::Bool(),
                      "With geometry/shape = equilibrium: ω₀ is the equilibrium's angular velocity ω (the entry "
                      "angular velocity is ignored), so that u₀ = ω e × (x − c) with the default e = z, c = 0 "
                      "is the equilibrium's rigid rotation.");
    prm.declare_entry("rotation axis",
                      "0, 0, 1",
                      Patterns::List(RealRange::any(), 3, 3),
                      "Axis e: three finite numbers, not all 0 (normalized).");
    prm.declare_entry("rotation centre",
                      "0, 0, 0",
                      Patterns::List(RealRange::closed(-100, 100), 3, 3),
                      "Centre c: three numbers, each |c_i| ≤ 100.");
    prm.declare_entry("translation velocity",
                      "0, 0, 0",
                      Patterns::List(RealRange::closed(-100, 100), 3, 3),
                      "Uniform velocity U added to u₀ (a rigid translation): three numbers, each |U_i| ≤ 100.");
    prm.declare_entry("velocity perturbation",
                      "0",
                      RealRange::closed(0, 100),
                      "Amplitude ε_u, 0 ≤ ε_u ≤ 100, of a smooth seeded random velocity field added to u₀.");
    prm.declare_entry("shape perturbation",
                      "0",
                      RealRange::closed(0, 1),
                      "Amplitude ε_X, 0 ≤ ε_X ≤ 1, of a smooth seeded random radial displacement of the initial "
                      "shape (at most ε_X; a displacement of the order of the shape's size folds the surface).");
    prm.declare_entry("random seed", "1", Patterns::Integer(0), "Seed ≥ 0 of the perturbations (same on every rank).");
    prm.leave_subsection();
  }

  void
  FluidDeformableSurface::parse_parameters(ParameterHandler &prm, const double maximum_time_step)
  {
    reject_entries_unused_by_scene({"fixed surface/*", "fixed surface solver/*"}, "full");
    flow.parse_parameters(prm);
    bending.parse_parameters(prm);
    volume_constraint.parse_parameters(prm, maximum_time_step);
    redistribution.parse_parameters(prm);
    conservation.parse_parameters(prm);
    reparametrization.parse_parameters(prm, redistribution.mesh_quality_floor);
    geometry_iteration.parse_parameters(prm);
    momentum_constraints = MomentumConstraints(flow);
    // The linear solver of the step (entries shared with scene fixed surface).
    linear_solver.parse_parameters(prm);
    ReusedFactorizationSolver::Parameters valve_parameters = linear_solver.get_parameters();
    valve_parameters.reuse_factorization                    = false;
    valve_parameters.direct_solver                          = "Amesos_Klu";
    valve_solver.set_parameters(valve_parameters);
    prm.enter_subsection("initial state");
    angular_velocity     = prm.get_double("angular velocity");
    equilibrium_rotation = prm.get_bool("equilibrium rotation");
    if (equilibrium_rotation && geometry.equilibrium_shape() == nullptr)
      throw_invalid_entry("initial state/equilibrium rotation",
                          "true",
                          "false unless geometry/shape = equilibrium (there is no equilibrium to take ω from)");
    rotation_axis = unit_vector(get_vector(prm, "rotation axis"));
    if (rotation_axis.norm() == 0)
      throw_invalid_entry("initial state/rotation axis", prm.get("rotation axis"), "a non-zero vector");
    rotation_centre      = Point<3>(get_vector(prm, "rotation centre"));
    translation_velocity = get_vector(prm, "translation velocity");
    velocity_perturbation = prm.get_double("velocity perturbation");
    shape_perturbation    = prm.get_double("shape perturbation");
    random_seed           = prm.get_integer("random seed");
    prm.leave_subsection();
  }

  namespace
  {
    /// A smooth random scalar field: Σ_j a_j sin(k_j·x + c_j), seeded.
    class SmoothRandomField
    {
    public:
      SmoothRandomField(const unsigned int seed, const unsigned int offset)
      {
        std::mt19937                           generator(seed * 7919u + offset);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (auto &mode : modes)
          {
            for (unsigned int d = 0; d < 3; ++d)
              mode.wave[d] = 3.0 * uniform(generator);
            mode.amplitude = uniform(generator) / modes.size();
            mode.phase     = numbers::PI * uniform(generator);
          }
      }
      double
      operator()(const Point<3> &x) const
      {
        double value = 0;
        for (const auto &mode : modes)
          value += mode.amplitude * std::sin(mode.wave * x + mode.phase);
        return value;
      }

    private:
      struct Mode
      {
        Tensor<1, 3> wave;
        double       amplitude, phase;
      };
      std::array<Mode, 8> modes;
    };

    /// u₀ = U + ω e × (x − c) + ε_u r(x) in the velocity components, 0 elsewhere.
    class InitialVelocity : public Function<3>
    {
    public:
      InitialVelocity(const unsigned int  n_components,
                      const Tensor<1, 3> &translation,
                      const double        omega,
                      const Tensor<1, 3> &axis,
                      const Point<3>     &centre,
                      const double        noise,
                      const unsigned int  seed)
        : Function<3>(n_components)
        , translation(translation)
        , omega(omega)
        , axis(axis)
        , centre(centre)
        , noise(noise)
        , random{SmoothRandomField(seed, 1), SmoothRandomField(seed, 2), SmoothRandomField(seed, 3)}
      {}
      double
      value(const Point<3> &x, const unsigned int component) const override
      {
        if (component >= 3)
          return 0;
        const Tensor<1, 3> u = omega * cross_product_3d(axis, x - centre);
        return translation[component] + u[component] + noise * random[component](x);
      }

    private:
      Tensor<1, 3>                     translation;
      double                           omega;
      Tensor<1, 3>                     axis;
      Point<3>                         centre;
      double                           noise;
      std::array<SmoothRandomField, 3> random;
    };

  } // namespace

  void
  FluidDeformableSurface::setup()
  {
    if (shape_perturbation > 0)
      {
        const SmoothRandomField field(random_seed, 0);
        const Point<3>          centre(geometry.measure().centre_of_mass);
        geometry.transform_nodes([&](const Point<3> &x) {
          const Tensor<1, 3> radial = x - centre;
          return Point<3>(x + shape_perturbation * field(x) * radial / radial.norm());
        });
      }
    if (equilibrium_rotation)
      angular_velocity = geometry.equilibrium_shape()->angular_velocity();
    setup_dofs();
    set_initial_velocity();
    // The targets with the quadrature of the projection and the diagnostics (the step's rows use the
    // assembly's: their difference is what ConservationProjection removes).
    if (flow.conserve_momenta)
      rigid_targets = ConservationProjection::momenta(geometry, dofs, current);
    const SurfaceGeometry::Measures m = geometry.measure();
    target_volume                     = m.volume;
    target_area                       = m.area;
    current_position                  = geometry.position();
    old_position                      = geometry.position();
    initial_position                  = geometry.position();
    set_reference_position();
    last_tau                          = 0;
    geometry.compute_curvature();
  }

  void
  FluidDeformableSurface::setup_dofs()
  {
    const unsigned int k = geometry.degree();
    fe = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(2), 3, FE_Q<2, 3>(1), 1, FE_Q<2, 3>(k), 1, FE_Q<2, 3>(k), 1,
                                          FE_Q<2, 3>(k), 3);
    layout = std::make_unique<const DofLayout>(*fe);
    dofs.distribute_dofs(*fe);
    owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, geometry.get_communicator(), relevant);
    system_matrix.reinit(owned, owned, dsp, geometry.get_communicator());
    system_rhs.reinit(owned, geometry.get_communicator());
    volume_column.reinit(owned, geometry.get_communicator());
    for (auto &column : rigid_columns)
      column.reinit(owned, geometry.get_communicator());
    for (auto &row : rigid_rows)
      row.reinit(owned, geometry.get_communicator());
    linear_solver.release();
    current.reinit(owned, relevant, geometry.get_communicator());
    candidate.reinit(owned, relevant, geometry.get_communicator());

    // The nodes of u and Y: the three DoFs of each (for the carried frame of law reference).
    velocity_nodes.clear();
    new_position_nodes.clear();
    {
      std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
      std::vector<bool>                    listed(owned.n_elements(), false);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (const unsigned int i : layout->velocity)
              if (fe->system_to_component_index(i).first == velocity_component && owned.is_element(indices[i]) &&
                  !listed[owned.index_within_set(indices[i])])
                {
                  listed[owned.index_within_set(indices[i])] = true;
                  std::array<types::global_dof_index, 3> node;
                  for (const unsigned int j : layout->velocity)
                    if (fe->system_to_component_index(j).second == fe->system_to_component_index(i).second)
                      node[fe->system_to_component_index(j).first - velocity_component] = indices[j];
                  velocity_nodes.push_back(node);
                }
            for (const auto &rows : layout->new_position_nodes)
              if (owned.is_element(indices[rows[0]]) && !listed[owned.index_within_set(indices[rows[0]])])
                {
                  listed[owned.index_within_set(indices[rows[0]])] = true;
                  new_position_nodes.push_back({{indices[rows[0]], indices[rows[1]], indices[rows[2]]}});
                }
          }
    }

    // Y_d and X_d share the nodes of Q_k: pair their DoFs cell by cell.
    position_pairs.clear();
    const FiniteElement<2, 3>           &gfe = geometry.fe();
    std::vector<types::global_dof_index> flow_indices(fe->n_dofs_per_cell()), geo_indices(gfe.n_dofs_per_cell());
    std::vector<bool>                    seen(geometry.locally_owned_dofs().n_elements(), false);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(flow_indices);
          typename DoFHandler<2, 3>::active_cell_iterator geo_cell(&geometry.triangulation(),
                                                                   cell->level(),
                                                                   cell->index(),
                                                                   &geometry.dof_handler());
          geo_cell->get_dof_indices(geo_indices);
          for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
            {
              const auto ci = fe->system_to_component_index(i);
              if (ci.first < position_component)
                continue;
              for (unsigned int j = 0; j < gfe.n_dofs_per_cell(); ++j)
                {
                  const auto cj = gfe.system_to_component_index(j);
                  if (cj.first + position_component == ci.first && cj.second == ci.second &&
                      geometry.locally_owned_dofs().is_element(geo_indices[j]))
                    {
                      const auto local = geometry.locally_owned_dofs().index_within_set(geo_indices[j]);
                      if (!seen[local])
                        position_pairs.emplace_back(flow_indices[i], geo_indices[j]);
                      seen[local] = true;
                    }
                }
            }
        }

    // The geometry DoFs of the owned nodes of Y (the error estimate reads X^m and ñ^m there).
    std::map<types::global_dof_index, types::global_dof_index> geometry_dof;
    for (const auto &pair : position_pairs)
      geometry_dof[pair.first] = pair.second;
    new_position_geometry_dofs.clear();
    for (const auto &node : new_position_nodes)
      {
        std::array<types::global_dof_index, 3> geo;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const auto found = geometry_dof.find(node[d]);
            AssertThrow(found != geometry_dof.end(), ExcMessage("a node of Y without its position DoF"));
            geo[d] = found->second;
          }
        new_position_geometry_dofs.push_back(geo);
      }
  }

  double
  FluidDeformableSurface::largest_node_move(const VectorType &a, const VectorType &b) const
  {
    double largest = 0;
    for (const auto &node : new_position_nodes)
      {
        double square = 0;
        for (unsigned int d = 0; d < 3; ++d)
          square += (a[node[d]] - b[node[d]]) * (a[node[d]] - b[node[d]]);
        largest = std::max(largest, square);
      }
    return std::sqrt(Utilities::MPI::max(largest, geometry.get_communicator()));
  }

  void
  FluidDeformableSurface::copy_new_position_to_geometry(const VectorType &flow_solution)
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    for (const auto &pair : position_pairs)
      position[pair.second] = flow_solution[pair.first];
    position.compress(VectorOperation::insert);
    geometry.set_position(position);
  }

  void
  FluidDeformableSurface::copy_position_into(const VectorType &x, VectorType &flow_vector) const
  {
    for (const auto &pair : position_pairs)
      flow_vector[pair.first] = x[pair.second];
    flow_vector.compress(VectorOperation::insert);
  }

  void
  FluidDeformableSurface::set_reference_surface(const VectorType &position)
  {
    initial_position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), geometry.get_communicator());
    VectorType owned_position(geometry.locally_owned_dofs(), geometry.get_communicator());
    owned_position   = position;
    initial_position = owned_position;
    set_reference_position();
  }

  void
  FluidDeformableSurface::set_reference_position()
  {
    VectorType reference(owned, geometry.get_communicator());
    copy_position_into(initial_position, reference);
    reference_position.reinit(owned, relevant, geometry.get_communicator());
    reference_position = reference;
  }

  void
  FluidDeformableSurface::leave_carried_frame(const RigidMotion &carried, const double tau, VectorType &solution) const
  {
    const Tensor<2, 3> Q = carried.rotation_over(tau);
    for (const auto &node : velocity_nodes)
      {
        Tensor<1, 3> u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = solution[node[d]];
        u = Q * u;
        for (unsigned int d = 0; d < 3; ++d)
          solution[node[d]] = u[d];
      }
    for (const auto &node : new_position_nodes)
      {
        Point<3> y;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] = solution[node[d]];
        y = carried.carry(y, tau);
        for (unsigned int d = 0; d < 3; ++d)
          solution[node[d]] = y[d];
      }
    solution.compress(VectorOperation::insert);
  }

  void
  FluidDeformableSurface::set_prescribed_velocity(const Function<3> &velocity)
  {
    AssertDimension(velocity.n_components, 3);
    AssertThrow(!volume_constraint.enabled && !rigid_constraints(),
                ExcMessage("a prescribed motion needs the volume and momentum constraints off"));
    prescribed_velocity = &velocity;
  }

  void
  FluidDeformableSurface::set_initial_velocity()
  {
    VectorType initial(owned, geometry.get_communicator());
    VectorTools::interpolate(geometry.mapping(),
                             dofs,
                             InitialVelocity(fe->n_components(),
                                             translation_velocity,
                                             angular_velocity,
                                             rotation_axis,
                                             rotation_centre,
                                             velocity_perturbation,
                                             random_seed),
                             initial);
    // Y starts at X so that the state is complete; κ, y, p are outputs of a step.
    copy_position_into(geometry.position(), initial);
    constraints.distribute(initial);
    current = initial;
  }
} // namespace FluidSurface

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// A TimerOutput section for the lifetime of the object (nothing without a timer).
    class TimerSection
    {
    public:
      TimerSection(TimerOutput *timer, const std::string &name)
        : timer(timer)
        , name(name)
      {
        if (timer)
          timer->enter_subsection(name);
      }
      ~TimerSection()
      {
        if (timer)
          timer->leave_subsection(name);
      }
      TimerSection(const TimerSection &) = delete;
      TimerSection &
      operator=(const TimerSection &) = delete;

    private:
      TimerOutput *timer;
      std::string  name;
    };

  } // namespace

  /// Per-thread FEValues (flow and geometry elements, Gauss and nodal rules) and point values of a cell.
  struct FluidDeformableSurface::AssemblyScratch
  {
    AssemblyScratch(const Mapping<2, 3>       &mapping,
                    const FiniteElement<2, 3> &flow_fe,
                    const FiniteElement<2, 3> &geometry_fe,
                    const Quadrature<2>       &gauss,
                    const Quadrature<2>       &nodal)
      : flow(mapping, flow_fe, gauss, update_values | update_gradients | update_normal_vectors |
                                        update_quadrature_points | update_JxW_values)
      , flow_nodal(mapping, flow_fe, nodal, update_values | update_gradients | update_quadrature_points |
                                              update_JxW_values)
      , geometry(mapping, geometry_fe, gauss, update_values | update_gradients)
      , geometry_nodal(mapping, geometry_fe, nodal, update_values)
      , point(flow_fe.n_dofs_per_cell())
      , nodal_point(flow_fe.n_dofs_per_cell())
      , smooth_normal(gauss.size())
      , smooth_normal_gradient(gauss.size())
      , old_velocity(gauss.size())
      , old_velocity_gradient(gauss.size())
      , nodal_smooth_normal(nodal.size())
      , old_position(gauss.size())
      , nodal_old_position(nodal.size())
      , reference_gradient(gauss.size())
    {}
    AssemblyScratch(const AssemblyScratch &other)
      : AssemblyScratch(other.flow.get_mapping(),
                        other.flow.get_fe(),
                        other.geometry.get_fe(),
                        other.flow.get_quadrature(),
                        other.flow_nodal.get_quadrature())
    {}

    FEValues<2, 3>            flow, flow_nodal, geometry, geometry_nodal;
    SurfacePointValues        point;
    NodalPointValues          nodal_point;
    std::vector<Tensor<1, 3>> smooth_normal;          ///< ñ^m at the Gauss points
    std::vector<Tensor<2, 3>> smooth_normal_gradient; ///< ∇ñ^m
    std::vector<Tensor<1, 3>> old_velocity;           ///< u^m
    std::vector<Tensor<2, 3>> old_velocity_gradient;  ///< G^m
    std::vector<Tensor<1, 3>> nodal_smooth_normal;    ///< ñ^m at the nodal points
    std::vector<Tensor<1, 3>> old_position;           ///< X^m at the Gauss points
    std::vector<Tensor<1, 3>> nodal_old_position;     ///< X^m at the nodal points
    // Law reference: ∇_{S^m}X₀ at the Gauss points, ñ^m by node, the rows of Y before their projection.
    std::vector<Tensor<2, 3>> reference_gradient;
    std::vector<Tensor<1, 3>> node_normals;
    FullMatrix<double>        normal_rows, tangential_rows;
    Vector<double>            tangential_rhs;
  };

  void
  FluidDeformableSurface::assemble(const double tau, const RigidMotion &motion, const SurfaceGeometry::Measures &old_measures)
  {
    system_matrix = 0;
    system_rhs    = 0;
    volume_column = 0;
    for (auto &column : rigid_columns)
      column = 0;
    for (auto &row : rigid_rows)
      row = 0;
    const bool rigid = rigid_constraints();

    const SurfaceGeometry::Measures m = geometry.measure();
    // div_P u = s with s = −(A^m − A₀)/(τ_c A^m) returns any area drift (∫div_P u = dA/dt);
    // τ_c = max(τ, τ_drift) keeps the correction bounded when a rejected step shrinks τ.
    const double area_rate = -(old_measures.area - target_area) / (drift_time(tau) * old_measures.area);
    // The mesh moves along with the rigid motion R of the shape (fit of u^m·ν): law bgn relaxes towards
    // X^m + τR, law reference carries the nodes by the rotation itself.
    const bool        carry   = redistribution.follow_rigid_motion &&
                        (redistribution.law == MeshRedistribution::Law::reference || redistribution.damping(tau) > 0);
    const RigidMotion carried = carry ? motion : RigidMotion();
    const double      area_scale = target_area / m.area;

    const QGauss<2>     gauss(fe->degree + 1);
    const Quadrature<2> nodal = redistribution.nodal_quadrature(gauss, geometry.degree());

    auto worker = [&](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                      AssemblyScratch                                      &scratch,
                      LocalSystem                                          &local) {
      assemble_cell(cell, tau, area_rate, carried, area_scale, scratch, local);
    };
    auto copier = [&](const LocalSystem &local) {
      constraints.distribute_local_to_global(local.matrix, local.rhs, local.indices, system_matrix, system_rhs);
      constraints.distribute_local_to_global(local.volume_column, local.indices, volume_column);
      if (rigid)
        for (unsigned int k = 0; k < 6; ++k)
          {
            constraints.distribute_local_to_global(local.rigid_columns[k], local.indices, rigid_columns[k]);
            constraints.distribute_local_to_global(local.rigid_rows[k], local.indices, rigid_rows[k]);
          }
    };

    using Iterator = typename DoFHandler<2, 3>::active_cell_iterator;
    WorkStream::run(FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.begin_active()),
                    FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.end()),
                    worker,
                    copier,
                    AssemblyScratch(geometry.mapping(), *fe, geometry.fe(), gauss, nodal),
                    LocalSystem());
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    volume_column.compress(VectorOperation::add);
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        {
          rigid_columns[k].compress(VectorOperation::add);
          rigid_rows[k].compress(VectorOperation::add);
        }
  }

  void
  FluidDeformableSurface::assemble_cell(const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                                        const double                                         tau,
                                        const double                                         area_rate,
                                        const RigidMotion                                   &carried,
                                        const double                                         area_scale,
                                        AssemblyScratch                                     &scratch,
                                        LocalSystem                                         &local) const
  {
    const bool rigid = momentum_constraints.active();
    local.reinit(fe->n_dofs_per_cell(), rigid);
    cell->get_dof_indices(local.indices);
    const typename DoFHandler<2, 3>::active_cell_iterator geometry_cell(&geometry.triangulation(),
                                                                        cell->level(),
                                                                        cell->index(),
                                                                        &geometry.dof_handler());
    const FEValuesExtractors::Vector vector(0);
    const bool reference_law = redistribution.law == MeshRedistribution::Law::reference;
    // Law reference: (∇_S Y, ∇_S η) only defines κ (normal rows), the membrane energy moves the nodes
    // tangentially, and both are projected at the nodes after the nodal loop.
    const Tensor<2, 3> rotation = unit_symmetric_tensor<3>(); // the carried frame: Z = X^m
    if (reference_law)
      {
        scratch.normal_rows.reinit(fe->n_dofs_per_cell(), fe->n_dofs_per_cell());
        scratch.tangential_rows.reinit(fe->n_dofs_per_cell(), fe->n_dofs_per_cell());
        scratch.tangential_rhs.reinit(fe->n_dofs_per_cell());
        scratch.node_normals.resize(layout->new_position_nodes.size());
      }

    // Gauss points: the flow terms, the bending force and scalar, (∇_S Y, ∇_S η), the global columns.
    scratch.flow.reinit(cell);
    scratch.geometry.reinit(geometry_cell);
    const VectorType &normal = assembly_normal != nullptr ? *assembly_normal : geometry.normal_field();
    scratch.geometry[vector].get_function_values(normal, scratch.smooth_normal);
    scratch.geometry[vector].get_function_gradients(normal, scratch.smooth_normal_gradient);
    scratch.flow[vector].get_function_values(current, scratch.old_velocity);
    scratch.flow[vector].get_function_gradients(current, scratch.old_velocity_gradient);
    scratch.geometry[vector].get_function_values(current_position, scratch.old_position);
    if (reference_law)
      scratch.flow[FEValuesExtractors::Vector(position_component)].get_function_gradients(
        reference_position, scratch.reference_gradient);
    SurfacePointValues &point = scratch.point;
    for (unsigned int q = 0; q < scratch.flow.n_quadrature_points; ++q)
      {
        point.reinit(scratch.flow,
                     q,
                     scratch.smooth_normal[q],
                     scratch.smooth_normal_gradient[q],
                     scratch.old_velocity[q],
                     scratch.old_velocity_gradient[q]);
        assemble_flow_terms(point, Point<3>(scratch.old_position[q]), tau, area_rate, carried, local);
        if (prescribed_velocity == nullptr)
          bending.assemble_force(point, *layout, local.matrix);
        bending.assemble_bending_scalar(point, *layout, local.matrix);
        if (reference_law)
          {
            redistribution.assemble_surface_laplacian(point, *layout, scratch.normal_rows);
            redistribution.assemble_reference_terms(point,
                                                    scratch.reference_gradient[q],
                                                    rotation,
                                                    area_scale,
                                                    *layout,
                                                    scratch.tangential_rows,
                                                    scratch.tangential_rhs);
          }
        else
          redistribution.assemble_surface_laplacian(point, *layout, local.matrix);
        volume_constraint.assemble_column(point, *layout, local.volume_column);
        if (rigid)
          momentum_constraints.assemble_columns(point, *layout, local.rigid_columns);
        if (momentum_constraints.on_new_surface())
          momentum_constraints.assemble_new_surface_rows(point, *layout, local.rigid_rows);
      }
    // The constraint rows equal the columns in the velocity DoFs.
    if (rigid)
      for (unsigned int k = 0; k < 6; ++k)
        for (const unsigned int i : layout->velocity)
          local.rigid_rows[k](i) = local.rigid_columns[k](i);

    // Nodal points: the kinematics (κ rows) and the nodal terms of the redistribution (Y rows).
    scratch.flow_nodal.reinit(cell);
    scratch.geometry_nodal.reinit(geometry_cell);
    scratch.geometry_nodal[vector].get_function_values(normal, scratch.nodal_smooth_normal);
    scratch.geometry_nodal[vector].get_function_values(current_position, scratch.nodal_old_position);
    NodalPointValues &nodal = scratch.nodal_point;
    for (unsigned int q = 0; q < scratch.flow_nodal.n_quadrature_points; ++q)
      {
        nodal.reinit(scratch.flow_nodal, q, scratch.nodal_smooth_normal[q]);
        const Point<3> x(scratch.nodal_old_position[q]); // X^m (the mapped point unless the geometry is iterated)
        if (reference_law)
          {
            // In the carried frame: Ỹ·ñ = X^m·ñ + τ(ũ − R)·ñ, damped towards X^m.
            redistribution.assemble_kinematics(
              nodal, *layout, tau, x - tau * carried.value(x), local.matrix, local.rhs);
            redistribution.assemble_nodal_terms(nodal, *layout, tau, x, local.matrix, local.rhs);
            // The nodal rule's points are the nodes: the node whose shape function is 1 here.
            for (unsigned int n = 0; n < layout->new_position_nodes.size(); ++n)
              if (std::abs(nodal.new_position[layout->new_position_nodes[n][0]][0] - 1.0) < 1e-8)
                scratch.node_normals[n] = nodal.smooth_normal;
          }
        else
          {
            redistribution.assemble_kinematics(nodal, *layout, tau, x, local.matrix, local.rhs);
            redistribution.assemble_nodal_terms(
              nodal, *layout, tau, x + tau * carried.value(x), local.matrix, local.rhs);
          }
      }
    if (reference_law)
      MeshRedistribution::project_position_rows(scratch.node_normals,
                                                *layout,
                                                scratch.normal_rows,
                                                scratch.tangential_rows,
                                                scratch.tangential_rhs,
                                                local.matrix,
                                                local.rhs);
  }

  void
  FluidDeformableSurface::assemble_flow_terms(const SurfacePointValues &point,
                                              const Point<3>           &old_point,
                                              const double              tau,
                                              const double              area_rate,
                                              const RigidMotion        &carried,
                                              LocalSystem              &local) const
  {
    const FlowPointValues &p       = point.flow;
    const double           dA      = p.JxW;
    const double           inv_tau = 1.0 / tau;
    if (prescribed_velocity != nullptr)
      {
        // (u, v) = (u_prescribed, v) and (p, q) = 0: the L² projection of the prescribed velocity.
        // In the carried frame: Qᵀ u_prescribed at the carried point.
        const Point<3> y = carried.carry(p.position, tau);
        Tensor<1, 3>   u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = prescribed_velocity->value(y, d);
        u = transpose(carried.rotation_over(tau)) * u;
        for (const unsigned int i : layout->velocity)
          {
            local.rhs(i) += (u * p.velocity[i]) * dA;
            for (const unsigned int j : layout->velocity)
              local.matrix(i, j) += (p.velocity[i] * p.velocity[j]) * dA;
          }
        for (const unsigned int i : layout->pressure)
          for (const unsigned int j : layout->pressure)
            local.matrix(i, j) += p.pressure[i] * p.pressure[j] * dA;
        return;
      }
    // The mass term: the inertia (1/τ)(u, v), or the Stokes limit's regularization ε(u, v).
    const double mass = flow.inertia ? inv_tau : momentum_constraints.regularization();
    // Law reference solves the step in the frame carried by the rigid motion R of the shape (ũ = Qᵀu, the new
    // position relative to the carry; advance() maps back): the frame's rotation adds (Ω × ũ, v), and the mesh
    // velocity in the convection is R + (Ỹ − X^m)/τ, i.e. W = X^m − τR.
    const bool     carried_frame = redistribution.law == MeshRedistribution::Law::reference;
    const Point<3> start         = carried_frame ? old_point - tau * carried.value(old_point) : old_point;
    for (const unsigned int i : layout->velocity)
      {
        if (flow.inertia)
          local.rhs(i) += SurfaceFluid::mass_term_rhs(p, i, inv_tau) * dA;
        if (flow.convection)
          local.rhs(i) += SurfaceFluid::mesh_motion_term_rhs(p, i, inv_tau, start) * dA;
        for (const unsigned int j : layout->velocity)
          {
            double a = flow.viscous_term(p, i, j);
            a += SurfaceFluid::mass_term(p, i, j, mass);
            if (carried_frame && flow.inertia)
              a += SurfaceFluid::frame_rotation_term(p, i, j, carried.rotation);
            // (∇_w u, v) with w = u^m, consistent (not skew-symmetrized; doc/scheme.md).
            if (flow.convection)
              a += SurfaceFluid::convection_term(p, i, j);
            local.matrix(i, j) += a * dA;
          }
        for (const unsigned int j : layout->pressure)
          local.matrix(i, j) += SurfaceFluid::pressure_term(p, i, j) * dA;
        if (flow.convection)
          for (const unsigned int j : layout->new_position)
            local.matrix(i, j) += SurfaceFluid::mesh_motion_term(p, i, point.new_position[j], inv_tau) * dA;
      }
    for (const unsigned int i : layout->pressure)
      {
        local.rhs(i) += SurfaceFluid::continuity_term_rhs(p, i, area_rate) * dA;
        for (const unsigned int j : layout->velocity)
          local.matrix(i, j) += SurfaceFluid::continuity_term(p, i, j) * dA;
      }
  }

  ReusedFactorizationSolver::Result
  FluidDeformableSurface::solve_system(const BorderedSystem              &system,
                                       BorderedSystem::BlockVector       &x,
                                       const BorderedSystem::BlockVector &b)
  {
    ReusedFactorizationSolver &solver = reparametrizing ? valve_solver : linear_solver;
    solver.matrix_changed(); // every step assembles its matrix on the new surface
    BorderedFactorizationPreconditioner     preconditioner(system);
    const ReusedFactorizationSolver::Result result = solver.solve(system_matrix, system, x, b, preconditioner);
    preconditioner.enforce_constraints(x, BorderedSystem::multipliers(b)); // a few vector operations, not timed
    return result;
  }

  Tensor<1, 3>
  FluidDeformableSurface::RigidMotion::value(const Point<3> &x) const
  {
    return translation + cross_product_3d(rotation, x - centre);
  }

  Tensor<2, 3>
  FluidDeformableSurface::RigidMotion::rotation_over(const double tau) const
  {
    const double angle = tau * rotation.norm();
    Tensor<2, 3> Q     = unit_symmetric_tensor<3>();
    if (angle == 0)
      return Q;
    const Tensor<1, 3> axis = rotation / rotation.norm();
    Tensor<2, 3>       cross; // [axis]×
    cross[0][1] = -axis[2];
    cross[0][2] = axis[1];
    cross[1][0] = axis[2];
    cross[1][2] = -axis[0];
    cross[2][0] = -axis[1];
    cross[2][1] = axis[0];
    Q += std::sin(angle) * cross + (1.0 - std::cos(angle)) * (cross * cross);
    return Q;
  }

  Point<3>
  FluidDeformableSurface::RigidMotion::carry(const Point<3> &x, const double tau) const
  {
    // The flow of R = U + Ω × (x − x_c) over τ: x_c + Q(x − x_c) + ∫₀^τ Q(s) ds U, with
    // ∫₀^τ Q(s) ds = τ[I + (1 − cos θ)/θ [ê]× + (1 − sin θ/θ)[ê]×²], θ = τ|Ω| (series for small θ).
    const double omega = rotation.norm();
    if (omega == 0)
      return x + tau * translation;
    const Tensor<1, 3> axis  = rotation / omega;
    const double       theta = tau * omega;
    const double       c1 = theta < 1e-6 ? theta / 2 : (1.0 - std::cos(theta)) / theta;
    const double       c2 = theta < 1e-6 ? theta * theta / 6 : 1.0 - std::sin(theta) / theta;
    const Tensor<1, 3> turned  = cross_product_3d(axis, translation);
    const Tensor<1, 3> shifted = tau * (translation + c1 * turned + c2 * cross_product_3d(axis, turned));
    return centre + rotation_over(tau) * (x - centre) + shifted;
  }


  FluidDeformableSurface::RigidMotion
  FluidDeformableSurface::rigid_motion(const VectorType &state) const
  {
    const QGauss<2>                  q(fe->degree + 1);
    FEValues<2, 3>                   fe_values(geometry.mapping(), *fe, q,
                                               update_values | update_quadrature_points | update_normal_vectors |
                                                 update_JxW_values);
    const FEValuesExtractors::Vector velocity(velocity_component);
    std::vector<Tensor<1, 3>>        u(q.size());
    const SurfaceGeometry::Measures  m = geometry.measure();
    RigidMotion                      motion;
    motion.centre = Point<3>(m.centre_of_mass);
    // The radius of gyration makes the rotations r_{3+d} = e_d × (x − x_c)/R_g commensurate with the translations.
    double gyration = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int k = 0; k < q.size(); ++k)
            gyration += (fe_values.quadrature_point(k) - motion.centre).norm_square() * fe_values.JxW(k);
        }
    gyration = std::sqrt(Utilities::MPI::sum(gyration, geometry.get_communicator()) / m.area);

    // [0..5] (r_k, u) about the origin; [6..11] ∫(u·ν)(r_k·ν); [12..47] ∫(r_j·ν)(r_k·ν), r about x_c.
    std::array<double, 48> sums{};
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (prescribed_velocity != nullptr)
            for (unsigned int k = 0; k < q.size(); ++k)
              for (unsigned int d = 0; d < 3; ++d)
                u[k][d] = prescribed_velocity->value(fe_values.quadrature_point(k), d);
          else
            fe_values[velocity].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const double        dA = fe_values.JxW(k);
              const Point<3>     &x  = fe_values.quadrature_point(k);
              const Tensor<1, 3> &nu = fe_values.normal_vector(k);
              const Tensor<1, 3>  L  = cross_product_3d(x, u[k]);
              // r_k·ν: ν_d for the translations, (e_d × r)·ν = (r × ν)_d for the rotations.
              const Tensor<1, 3> moment = cross_product_3d(x - motion.centre, nu) / gyration;
              double             rn[6];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  rn[d]     = nu[d];
                  rn[3 + d] = moment[d];
                  sums[d] += u[k][d] * dA;
                  sums[3 + d] += L[d] * dA;
                }
              for (unsigned int j = 0; j < 6; ++j)
                {
                  sums[6 + j] += (u[k] * nu) * rn[j] * dA;
                  for (unsigned int l = 0; l < 6; ++l)
                    sums[12 + 6 * j + l] += rn[j] * rn[l] * dA;
                }
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), geometry.get_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    std::copy(sums.begin(), sums.begin() + 6, motion.momenta.begin());

    // The rigid motion of the shape: R minimizing ∫(u·ν − R·ν)² + ε|S| |c|², c the coefficients of R in the
    // scaled basis. ε cuts off the motions that hardly move the shape: the rotation of a body about its own
    // axis of symmetry (R·ν ≡ 0) moves no surface, and its mesh need not move.
    Vector<double> rhs(6), coefficients(6);
    for (unsigned int j = 0; j < 6; ++j)
      rhs(j) = sums[6 + j];
    const double cutoff = redistribution.rigid_motion_cutoff * m.area;
    if (redistribution.law == MeshRedistribution::Law::reference)
      {
        // A spectral cutoff of the Gram matrix G instead: the motions with ∫(R·ν)² ≥ 2ε|S| per unit coefficient
        // are fitted exactly (a rigid velocity is followed to round-off), those below ε|S| not at all (the spin
        // of an axisymmetric body), with a smooth step between.
        LAPACKFullMatrix<double> gram(6, 6);
        for (unsigned int j = 0; j < 6; ++j)
          for (unsigned int l = 0; l < 6; ++l)
            gram(j, l) = sums[12 + 6 * j + l];
        FullMatrix<double> eigenvectors(6, 6); // the columns
        Vector<double>     eigenvalues(6);
        gram.compute_eigenvalues_symmetric(-1.0, std::numeric_limits<double>::max(), 0.0, eigenvalues, eigenvectors);
        for (unsigned int k = 0; k < eigenvalues.size(); ++k)
          {
            const double ratio  = std::min(1.0, std::max(0.0, eigenvalues(k) / cutoff - 1.0));
            const double filter = ratio * ratio * (3.0 - 2.0 * ratio);
            if (filter == 0)
              continue;
            double projection = 0;
            for (unsigned int j = 0; j < 6; ++j)
              projection += eigenvectors(j, k) * rhs(j);
            for (unsigned int j = 0; j < 6; ++j)
              coefficients(j) += filter * projection / eigenvalues(k) * eigenvectors(j, k);
          }
      }
    else
      {
        FullMatrix<double> normal_matrix(6, 6), inverse(6, 6);
        for (unsigned int j = 0; j < 6; ++j)
          for (unsigned int l = 0; l < 6; ++l)
            normal_matrix(j, l) = sums[12 + 6 * j + l] + (j == l ? cutoff : 0.0);
        inverse.invert(normal_matrix);
        inverse.vmult(coefficients, rhs);
      }
    for (unsigned int d = 0; d < 3; ++d)
      {
        motion.translation[d] = coefficients(d);
        motion.rotation[d]    = coefficients(3 + d) / gyration;
      }
    return motion;
  }

  FluidDeformableSurface::StepResult
  FluidDeformableSurface::advance(const double tau)
  {
    StepResult result;
    // The momenta of u^m and the rigid motion of the shape, once per step (the mesh damping target and the
    // constant parts of the momentum constraints).
    const bool need_motion =
      (redistribution.follow_rigid_motion &&
       (redistribution.relaxation_time > 0 || redistribution.law == MeshRedistribution::Law::reference)) ||
      (rigid_constraints() && flow.inertia);
    const RigidMotion motion      = need_motion ? rigid_motion(current) : RigidMotion();
    // Law reference solves the step in the frame carried by the rigid motion of the shape (assemble_cell()).
    const bool carried_frame = redistribution.law == MeshRedistribution::Law::reference &&
                               redistribution.follow_rigid_motion;
    const SurfaceGeometry::Measures old_measures = geometry.measure();
    shape_radius                                 = std::sqrt(old_measures.area / (4 * numbers::PI));
    const VectorType                old_normal(geometry.normal_field()); // ñ^m (the geometry may be iterated)
    {
      TimerSection section(step_timer, "assembly");
      assemble(tau, motion, old_measures);
    }

    // Bordering: the global constraints c_k·x = g_k with multipliers μ_k (force μ_k c_k in the
    // momentum rows): the volume row (u·ñ, 1) = −(V^m − V₀)/τ_c (μ = γ) and, in the Stokes limit,
    // ∫u = 0, ∫x × u = 0; one solve of the bordered system per step (BorderedSystem).
    std::vector<const VectorType *> columns, rows;
    std::vector<double>             rates;
    // The mesh relaxation of reparametrize() moves no surface: none of the global constraints.
    const bool volume_row = volume_constraint.enabled && !relaxing_mesh;
    const bool rigid_rows_on = rigid_constraints() && !relaxing_mesh;
    if (volume_row)
      {
        columns.push_back(&volume_column);
        rows.push_back(&volume_column);
        rates.push_back(-(old_measures.volume - target_volume) / drift_time(tau));
      }
    // The momentum targets in the frame of the step (the constant parts of the rows are added by set_rates()).
    std::array<double, 6> targets = {{0, 0, 0, 0, 0, 0}};
    if (rigid_rows_on)
      {
        // The constant parts of the linearized momenta on S^{m+1} (see assemble()) move to the right:
        // with δ = Y − X^m and div_S X^m = 2 they are −2∫u^m and −3∫x × u^m.
        // A drift P^m − P₀ (from the linearization) is returned by the fraction τ/τ_c per step, like the area
        // and volume drifts, so that a retry with a smaller τ asks for a smaller change of u.
        const std::array<double, 6> old_momenta =
          flow.inertia ? motion.momenta : std::array<double, 6>{{0, 0, 0, 0, 0, 0}};
        const double fraction = flow.inertia ? std::min(1.0, tau / drift_time(tau)) : 1.0;
        for (unsigned int k = 0; k < 6; ++k)
          targets[k] = old_momenta[k] + fraction * (rigid_targets[k] - old_momenta[k]);
        if (carried_frame)
          {
            // In the carried frame (Y = QỸ + c, u = Qũ): P̃ = QᵀP, L̃ = Qᵀ(L − c × P).
            const Tensor<2, 3> Q = motion.rotation_over(tau);
            const Tensor<1, 3> c = motion.carry(Point<3>(), tau);
            Tensor<1, 3>       P, L;
            for (unsigned int d = 0; d < 3; ++d)
              {
                P[d] = targets[d];
                L[d] = targets[3 + d];
              }
            const Tensor<1, 3> P_frame = transpose(Q) * P, L_frame = transpose(Q) * (L - cross_product_3d(c, P));
            for (unsigned int d = 0; d < 3; ++d)
              {
                targets[d]     = P_frame[d];
                targets[3 + d] = L_frame[d];
              }
          }
        for (unsigned int k = 0; k < rigid_columns.size(); ++k)
          {
            columns.push_back(&rigid_columns[k]);
            rows.push_back(&rigid_rows[k]);
          }
      }
    const unsigned int first_rigid = volume_row ? 1 : 0;
    // The rows are linearized about the surface they were assembled on: their constant parts are the momenta
    // of u^m there (@p assembly_momenta).
    const auto set_rates = [&](const std::array<double, 6> &assembly_momenta) {
      rates.resize(first_rigid);
      if (rigid_rows_on)
        for (unsigned int k = 0; k < 6; ++k)
          rates.push_back(targets[k] + (k < 3 ? 2.0 : 3.0) * (flow.inertia ? assembly_momenta[k] : 0.0));
    };
    set_rates(motion.momenta);

    AssertDimension(columns.size(), (volume_row ? 1 : 0) + (rigid_rows_on ? 6 : 0));
    AssertDimension(rates.size(), columns.size());
    const BorderedSystem system(system_matrix, columns, rows);
    BorderedSystem::BlockVector solution = system.make_vector(system_rhs), rhs = solution;
    if (last_solution.n_blocks() == 2 && last_solution.block(1).size() == columns.size())
      solution = last_solution;
    const auto solve = [&]() {
      rhs.block(0) = system_rhs;
      BorderedSystem::set_multipliers(rhs, rates);
      try
        {
          const ReusedFactorizationSolver::Result solve = solve_system(system, solution, rhs);
          result.linear_iterations += solve.iterations;
          result.factorized = result.factorized || solve.factorized;
          last_solution     = solution;
          const std::vector<double> mu = BorderedSystem::multipliers(solution);
          if (volume_row)
            result.gamma = mu[0];
          double rigid = 0;
          for (unsigned int k = first_rigid; k < mu.size(); ++k)
            rigid += mu[k] * mu[k];
          result.rigid_force = std::sqrt(rigid);
        }
      catch (const LinearSolverError &exc)
        {
          linear_solver.request_factorization();
          result.failure         = std::string("linear solver failed: ") + exc.what();
          result.failure_details = exc.details();
          return false;
        }
      catch (const std::exception &exc)
        {
          linear_solver.request_factorization();
          result.failure         = "linear solver failed: " + one_line_message(exc, 200);
          result.failure_details = exc.what();
          return false;
        }
      if (!std::isfinite(solution.block(0).l2_norm()))
        {
          result.failure = "the solution is not finite";
          return false;
        }
      constraints.distribute(solution.block(0));
      return true;
    };
    if (!solve())
      return result;

    // The implicit geometry: the same step assembled again on the surface of its own solution (in the frame of
    // the step, before the carry), until the nodes stop moving.
    if (geometry_iteration.enabled() && prescribed_velocity == nullptr && !relaxing_mesh)
      {
        const double node_spacing =
          std::sqrt(old_measures.area / geometry.triangulation().n_global_active_cells()) / geometry.degree();
        using Implicit            = GeometryIteration::Implicit;
        const Implicit   implicit = geometry_iteration.implicit;
        VectorType       iterate_normal;
        bool             converged = false;
        for (unsigned int k = 1; k <= geometry_iteration.max_iterations && !converged; ++k)
          {
            candidate = solution.block(0);
            copy_new_position_to_geometry(candidate);
            {
              TimerSection section(step_timer, "assembly");
              geometry.compute_curvature();
              if (implicit == Implicit::normal)
                {
                  iterate_normal = geometry.normal_field();
                  assembly_normal = &iterate_normal;
                  restore_last_state_geometry();
                }
              else if (implicit == Implicit::metric)
                assembly_normal = &old_normal;
              assemble(tau, motion, old_measures);
              assembly_normal = nullptr;
              if (rigid_rows_on && flow.inertia && implicit != Implicit::normal)
                set_rates(rigid_motion(current).momenta);
            }
            const VectorType previous = solution.block(0);
            if (!solve())
              return result;
            result.geometry_iterations = k;
            result.geometry_change     = largest_node_move(solution.block(0), previous) / node_spacing;
            converged                  = result.geometry_change <= geometry_iteration.tolerance;
          }
        if (!converged)
          {
            std::ostringstream why;
            why << "the geometry iteration did not converge: after " << geometry_iteration.max_iterations
                << " re-assemblies the nodes still moved by " << std::setprecision(3) << result.geometry_change
                << " h (tolerance 'geometry iteration/tolerance' = " << geometry_iteration.tolerance << ")";
            result.failure = why.str();
            return result;
          }
      }
    VectorType &x1 = solution.block(0);
    if (estimating_error)
      result.error_estimate = estimate_error(x1, old_normal, tau);
    candidate = x1;
    {
      TimerSection section(step_timer, "diagnostics");
      result.dissipation_rate = dissipation_rate(candidate); // of ũ on S^m, that of u on the carried surface
    }
    if (carried_frame)
      {
        leave_carried_frame(motion, tau, x1);
        candidate = x1;
      }
    copy_new_position_to_geometry(candidate);
    if (conservation.enabled && prescribed_velocity == nullptr)
      {
        result.node_correction =
          conservation.project_area_and_volume(geometry, target_area, target_volume, volume_constraint.enabled);
        VectorType state(owned, geometry.get_communicator());
        state = candidate;
        copy_position_into(geometry.position(), state);
        if (flow.conserve_momenta && flow.inertia)
          result.momentum_correction = conservation.project_momenta(geometry, dofs, rigid_targets, state);
        candidate = state;
      }
    last_step_tau = tau;
    result.solved = true;
    return result;
  }

  double
  FluidDeformableSurface::estimate_error(const VectorType &new_state, const VectorType &old_normal, const double tau)
  {
    if (candidate_normal_speed.size() != current.size())
      candidate_normal_speed.reinit(owned, geometry.get_communicator());
    double largest_difference = 0;
    for (unsigned int n = 0; n < new_position_nodes.size(); ++n)
      {
        const auto  &node = new_position_nodes[n];
        Tensor<1, 3> move, normal;
        for (unsigned int d = 0; d < 3; ++d)
          {
            move[d]   = new_state[node[d]] - current_position[new_position_geometry_dofs[n][d]];
            normal[d] = old_normal[new_position_geometry_dofs[n][d]];
          }
        const double w = move * normal / tau;
        candidate_normal_speed[node[0]] = w;
        if (normal_speed_step > 0)
          largest_difference = std::max(largest_difference, std::abs(w - normal_speed[node[0]]));
      }
    candidate_normal_speed.compress(VectorOperation::insert);
    largest_difference = Utilities::MPI::max(largest_difference, geometry.get_communicator());
    if (normal_speed_step == 0)
      return -1;
    return tau * tau / (tau + normal_speed_step) * largest_difference / shape_radius;
  }

  void
  FluidDeformableSurface::accept()
  {
    if (estimating_error)
      {
        normal_speed.reinit(owned, relevant, geometry.get_communicator());
        normal_speed      = candidate_normal_speed;
        normal_speed_step = last_step_tau;
      }
    old_position     = current_position;
    current_position = geometry.position();
    current          = candidate;
    last_tau         = last_step_tau;
  }

  FluidDeformableSurface::Reparametrization
  FluidDeformableSurface::reparametrize()
  {
    Reparametrization result;
    const MPI_Comm    comm   = geometry.get_communicator();
    reparametrizing          = true;
    struct Finish
    {
      FluidDeformableSurface &model;
      ~Finish()
      {
        model.reparametrizing = false;
        model.valve_solver.release();
      }
    } finish{*this};
    result.quality_before    = geometry.measure().mesh_quality;
    const auto total_energy  = [&]() {
      return (flow.inertia ? kinetic_energy(current) : 0.0) + bending.energy(geometry.compute_curvature());
    };
    const double energy_before = total_energy();
    const VectorType  kept_state = current, kept_position = current_position, kept_old_position = old_position;
    const auto        restore    = [&](const std::string &why) {
      current          = kept_state;
      current_position = kept_position;
      old_position     = kept_old_position;
      last_solution.reinit(0);
      VectorType position(geometry.locally_owned_dofs(), comm);
      position = kept_position;
      geometry.set_position(position);
      geometry.compute_curvature();
      linear_solver.request_factorization();
      result.failure = why;
      return result;
    };

    // New nodes on the current surface: solves of the mesh law alone (the velocity held at zero, no global
    // constraints, weak damping), each followed by the closest-point projection of the nodes onto the surface
    // before it and the transfer of the fields. Projecting onto the previous iterate, not onto the first
    // surface, keeps every search within the ghost layer of a parallel mesh as long as a solve moves no node
    // by more than a cell; the surface then changes by its interpolation error once per iteration.
    VectorType state(owned, comm);
    state = current;
    {
      static const Functions::ZeroFunction<3> at_rest(3);
      const Function<3> *const                kept_velocity = prescribed_velocity;
      const MeshRedistribution::Law           kept_law      = redistribution.law;
      prescribed_velocity                                   = &at_rest;
      relaxing_mesh                                         = true;
      // The target is always the membrane energy relative to S₀: with law bgn the conformal distribution of
      // the current surface is the one that degraded (a bgn prolate went from quality 0.098 to 0.088).
      redistribution.law = MeshRedistribution::Law::reference;
      const double tau = redistribution.relaxation_time > 0 ? 10 * redistribution.relaxation_time : 1.0;
      VectorType   surface = kept_position, fields = current;
      std::string  failure;
      for (unsigned int iteration = 0; iteration < reparametrization.iterations && failure.empty(); ++iteration)
        {
          current_position            = surface; // each relaxation starts from the surface it projects onto
          const StepResult relaxation = advance(tau);
          if (!relaxation.solved)
            {
              failure = relaxation.failure;
              break;
            }
          geometry.set_position(SurfaceReparametrization::closest_points(geometry, surface));
          SurfaceReparametrization::transfer(geometry, surface, geometry.position(), dofs, fields, state);
          surface = geometry.position();
          fields  = state;
          geometry.compute_curvature();
        }
      prescribed_velocity = kept_velocity;
      relaxing_mesh       = false;
      redistribution.law  = kept_law;
      if (!failure.empty())
        return restore("the relaxation of the mesh failed: " + failure);
    }
    geometry.compute_curvature();
    // The relaxed surface differs from the old one by its interpolation error, far more than a step's drift:
    // the projection's modes ñ, Hñ are those of the surface it starts from, so it is repeated on the
    // projected surface.
    if (conservation.enabled && prescribed_velocity == nullptr)
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          result.node_correction +=
            conservation.project_area_and_volume(geometry, target_area, target_volume, volume_constraint.enabled);
          geometry.compute_curvature();
        }
    copy_position_into(geometry.position(), state);
    if (!std::isfinite(state.l2_norm()))
      return restore("the transferred fields are not finite");
    current          = state;
    current_position = geometry.position();
    old_position     = current_position;
    normal_speed_step = 0; // the transferred state has no history
    last_solution.reinit(0);
    linear_solver.request_factorization();

    // The velocity back onto the discrete constraints: a step of the scheme in the limit τ → 0.
    if (flow.inertia && prescribed_velocity == nullptr)
      {
        const StepResult projection = advance(projection_time_step);
        if (!projection.solved)
          return restore("the projection of the velocity failed: " + projection.failure);
        state = candidate;
        copy_position_into(current_position, state);
        VectorType position(geometry.locally_owned_dofs(), comm);
        position = current_position;
        geometry.set_position(position);
        if (conservation.enabled && flow.conserve_momenta)
          conservation.project_momenta(geometry, dofs, rigid_targets, state);
        current = state;
        last_solution.reinit(0);
        linear_solver.request_factorization();
      }

    geometry.compute_curvature();
    result.quality_after = geometry.measure().mesh_quality;
    // A worse mesh is not taken (a relaxation that changes nothing, as on the initial mesh, is).
    if (!(result.quality_after >= (1 - 1e-3) * result.quality_before))
      {
        std::ostringstream why;
        why << "it did not raise the mesh quality (" << result.quality_before << " -> " << result.quality_after << ")";
        return restore(why.str());
      }
    const double energy_after = total_energy();
    if (!(std::abs(energy_after - energy_before) <= reparametrization.maximum_energy_jump * std::abs(energy_before)))
      {
        std::ostringstream why;
        why << "it changed F by " << std::setprecision(3) << (energy_after - energy_before) / std::abs(energy_before)
            << " relative, more than 'reparametrization/maximum energy jump' = "
            << reparametrization.maximum_energy_jump;
        return restore(why.str());
      }
    result.done = true;
    return result;
  }

  void
  FluidDeformableSurface::restore_last_state()
  {
    restore_last_state_geometry();
    geometry.compute_curvature();
    linear_solver.request_factorization();
  }

  void
  FluidDeformableSurface::restore_last_state_geometry()
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = current_position;
    geometry.set_position(position);
  }

  double
  FluidDeformableSurface::kinetic_energy(const VectorType &state) const
  {
    return EnergyFunctionals::kinetic_energy(
      geometry.mapping(), dofs, state, geometry.quadrature(), geometry.get_communicator());
  }

  double
  FluidDeformableSurface::dissipation_rate(const VectorType &state) const
  {
    return EnergyFunctionals::dissipation_rate(
      geometry.mapping(), dofs, state, geometry.quadrature(), flow.Re, geometry.get_communicator());
  }

  void
  FluidDeformableSurface::add_output_fields(DataOut<2, 3> &data_out) const
  {
    std::vector<std::string> names(3, "velocity");
    names.insert(names.end(), {"pressure", "curvature_kappa", "bending_scalar", "new_position", "new_position",
                               "new_position"});
    std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
      3, DataComponentInterpretation::component_is_part_of_vector);
    kinds.insert(kinds.end(), 3, DataComponentInterpretation::component_is_scalar);
    kinds.insert(kinds.end(), 3, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(dofs, current, names, kinds);
    static const SpeedPostprocessor speed;
    data_out.add_data_vector(dofs, current, speed);
  }

  void
  FluidDeformableSurface::save(CheckpointData &data) const
  {
    data.set_fields("flow", dofs, {&current});
    data.set_fields("geometry", geometry.dof_handler(), {&current_position, &old_position});
    data.set_fields("mesh reference", geometry.dof_handler(), {&initial_position});
    data.set("model/element", fe->get_name());
    data.set("model/target volume", target_volume);
    data.set("model/target area", target_area);
    data.set("model/factorizations", linear_solver.n_factorizations());
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      data.set("model/rigid target " + std::to_string(k), rigid_targets[k]);
    data.set("model/last tau", last_tau);
    data.set("model/last step tau", last_step_tau);
    if (estimating_error && normal_speed_step > 0)
      {
        data.set("model/normal speed step", normal_speed_step);
        data.set_fields("normal speed", dofs, {&normal_speed});
      }
    // The seeded random fields are drawn in setup() only; the seed is kept for the record.
    data.set("model/random seed", random_seed);
  }

  void
  FluidDeformableSurface::load(const CheckpointData &data)
  {
    setup_dofs();
    if (data.get_string("model/element") != fe->get_name())
      throw std::runtime_error("the checkpoint holds the element " + data.get_string("model/element") +
                               ", this run uses " + fe->get_name());
    const MPI_Comm comm = geometry.get_communicator();
    VectorType     state, position, previous;
    data.get_fields("flow", dofs, {&state});
    data.get_fields("geometry", geometry.dof_handler(), {&position, &previous});
    current = state;
    geometry.set_position(position);
    current_position = geometry.position();
    old_position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), comm);
    old_position  = previous;
    VectorType initial;
    data.get_fields("mesh reference", geometry.dof_handler(), {&initial});
    initial_position.reinit(geometry.locally_owned_dofs(), geometry.locally_relevant_dofs(), comm);
    initial_position = initial;
    set_reference_position();
    target_volume = data.get_double("model/target volume");
    target_area   = data.get_double("model/target area");
    linear_solver.set_n_factorizations(data.get_unsigned("model/factorizations"));
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      rigid_targets[k] = data.get_double("model/rigid target " + std::to_string(k));
    last_tau      = data.get_double("model/last tau");
    last_step_tau = data.get_double("model/last step tau");
    normal_speed_step = 0;
    if (estimating_error && data.has("model/normal speed step"))
      {
        VectorType w;
        data.get_fields("normal speed", dofs, {&w});
        normal_speed.reinit(owned, relevant, comm);
        normal_speed      = w;
        normal_speed_step = data.get_double("model/normal speed step");
      }
    geometry.compute_curvature();
  }
} // namespace FluidSurface
