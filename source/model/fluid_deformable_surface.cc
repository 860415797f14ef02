#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/linear_algebra/bordered_system.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/postprocess/speed_postprocessor.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/geometry/surface_operators.h>

#include <cmath>

namespace FluidSurface
{
  using namespace dealii;

  void
  BendingForce::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("bending");
    prm.declare_entry("enabled", "true", Patterns::Bool(), "Assemble the Helfrich bending force b.");
    prm.declare_entry("Be",
                      "1",
                      Patterns::Double(0, Patterns::Double::max_double_value),
                      "Bending capillary number Be = ρU²L²/κ_b; the bending energy is (1/2Be)∫H².");
    prm.leave_subsection();
  }

  void
  BendingForce::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("bending");
    enabled        = prm.get_bool("enabled");
    bending_number = prm.get_double("Be");
    if (!(bending_number > 0))
      throw_invalid_entry("bending/Be", prm.get("Be"), "a positive bending number Be");
    prm.leave_subsection();
  }

  void
  VolumeConstraint::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("volume constraint");
    prm.declare_entry("enabled",
                      "true",
                      Patterns::Bool(),
                      "Keep the enclosed volume V with the global multiplier γ: ∫u·ν = −(V − V₀)/τ_c.");
    prm.declare_entry("drift correction time",
                      "0.01",
                      Patterns::Double(0),
                      "τ_drift: volume and area drifts are returned at the rate (V − V₀)/τ_c with "
                      "τ_c = max(τ_drift, τ_max) (τ_max = time stepping/maximum time step; likewise for the area "
                      "through div_P u, and with `conserve momenta` the momenta by the fraction τ/τ_c per step). "
                      "τ_c does not depend on the step τ, so a step retried with a smaller τ asks for a "
                      "proportionally smaller correction.");
    prm.leave_subsection();
  }

  void
  VolumeConstraint::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("volume constraint");
    enabled = prm.get_bool("enabled");
    prm.leave_subsection();
  }

  void
  MeshRedistribution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    prm.declare_entry("lumped",
                      "true",
                      Patterns::Bool(),
                      "Nodal (Gauss–Lobatto) quadrature for (Y·ñ, φ) and (κñ, η), as in the BGN scheme.");
    prm.declare_entry("relaxation time",
                      "0.05",
                      Patterns::Double(0),
                      "T_r of the tangential damping (T_r/τ)(P̃(Y − X^m), η)_h added to the BGN equation: "
                      "the mesh relaxes towards the BGN distribution on the time scale T_r h² instead of "
                      "jumping there within one step, so that steps τ → 0 change nothing. 0: plain BGN.");
    prm.declare_entry("follow rigid motion",
                      "true",
                      Patterns::Bool(),
                      "The tangential damping relaxes the nodes towards X^m + τR instead of X^m, R = U + Ω × (x − x_c) "
                      "the rigid motion of the shape (its normal part R·ν fits u^m·ν in L²): a rotating or "
                      "translating body carries its mesh along instead of moving through it, while a body spinning "
                      "about its own axis of symmetry (R·ν ≡ 0) leaves its mesh in place. No effect when T_r = 0.");
    prm.declare_entry("rigid motion cutoff",
                      "0.01",
                      Patterns::Double(0),
                      "ε of the fit of R: min ∫(u·ν − R·ν)² + ε|S||c|², c the coefficients of R in the basis e_d, "
                      "e_d × (x − x_c)/R_g (R_g the radius of gyration); rigid motions with ∫(R·ν)² ≪ ε|S||c|² are "
                      "not followed.");
    prm.declare_entry("mesh quality floor",
                      "0.02",
                      Patterns::Double(0, 1),
                      "q_min: the run stops when min over cells of σ_min/σ_max of the Jacobian falls below.");
    prm.leave_subsection();
  }

  void
  MeshRedistribution::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    lumped             = prm.get_bool("lumped");
    relaxation_time    = prm.get_double("relaxation time");
    follow_rigid_motion = prm.get_bool("follow rigid motion");
    shape_motion_cutoff = prm.get_double("rigid motion cutoff");
    mesh_quality_floor = prm.get_double("mesh quality floor");
    prm.leave_subsection();
  }

  FluidDeformableSurface::FluidDeformableSurface(SurfaceGeometry &geometry)
    : geometry(geometry)
    , rotation_axis({0., 0., 1.})
    , dofs(geometry.triangulation())
  {}

  void
  FluidDeformableSurface::declare_parameters(ParameterHandler &prm)
  {
    BendingForce::declare_parameters(prm);
    VolumeConstraint::declare_parameters(prm);
    MeshRedistribution::declare_parameters(prm);
    prm.enter_subsection("initial state");
    prm.declare_entry("angular velocity",
                      "0",
                      Patterns::Double(),
                      "ω₀ of the initial rigid rotation u₀ = ω₀ e × (x − c).");
    prm.declare_entry("equilibrium rotation",
                      "false",
                      Patterns::Bool(),
                      "With geometry/shape = equilibrium: ω₀ is the equilibrium's angular velocity ω (the entry "
                      "angular velocity is ignored), so that u₀ = ω e × (x − c) with the default e = z, c = 0 "
                      "is the equilibrium's rigid rotation.");
    prm.declare_entry("rotation axis", "0, 0, 1", Patterns::List(Patterns::Double(), 3, 3), "Axis e (normalized).");
    prm.declare_entry("rotation centre", "0, 0, 0", Patterns::List(Patterns::Double(), 3, 3), "Centre c.");
    prm.declare_entry("translation velocity",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "Uniform velocity U added to u₀ (a rigid translation).");
    prm.declare_entry("velocity perturbation",
                      "0",
                      Patterns::Double(0),
                      "Amplitude ε_u of a smooth seeded random velocity field added to u₀.");
    prm.declare_entry("shape perturbation",
                      "0",
                      Patterns::Double(0),
                      "Amplitude ε_X of a smooth seeded random radial displacement of the initial shape.");
    prm.declare_entry("random seed", "1", Patterns::Integer(0), "Seed of the perturbations (same on every rank).");
    prm.leave_subsection();
    prm.enter_subsection("flow");
    prm.declare_entry("conserve momenta",
                      "false",
                      Patterns::Bool(),
                      "With inertia: keep the linear and angular momenta ∫u = P₀ and ∫x × u = L₀ (about the "
                      "origin, P₀ and L₀ of the initial state) at every step by six global multipliers μ_k, "
                      "force Σμ_k r_k for the rigid motions r = e_d, e_d × x (the same columns as the Stokes "
                      "limit). The continuous model conserves both exactly; without the multipliers the "
                      "discrete model loses angular momentum while the shape deforms fast (the prolate "
                      "equilibrium perturbed by 2e-2, refinement 3: 11 % of L by the time F has fallen by 10 % "
                      "with τ ≤ 0.05, still 8 % with τ ≤ 0.0125: mostly a space-discretization error). |μ| is the statistics column 'rigid multiplier'.");
    prm.declare_entry("rigid motion regularization",
                      "1e-6",
                      Patterns::Double(0),
                      "Scene full with inertia = false (Stokes limit): ε of the term ε(u, v) that makes the "
                      "step matrix invertible on the rigid motions (translations and rotations dissipate "
                      "nothing and, without the mass term, nothing else fixes them). Their amplitude is "
                      "then set exactly by the multipliers of ∫u = 0 and ∫x × u = 0; ε only adds the "
                      "dissipation ε‖u‖² to the other modes (relative size ε·Re/2).");
    prm.leave_subsection();
  }

  void
  FluidDeformableSurface::parse_parameters(ParameterHandler &prm)
  {
    bending.parse_parameters(prm);
    volume_constraint.parse_parameters(prm);
    redistribution.parse_parameters(prm);
    prm.enter_subsection("volume constraint");
    drift_correction_time = prm.get_double("drift correction time");
    prm.leave_subsection();
    prm.enter_subsection("time stepping");
    drift_correction_time = std::max(drift_correction_time, prm.get_double("maximum time step"));
    prm.leave_subsection();
    prm.enter_subsection("flow");
    flow.reynolds_number = prm.get_double("Re");
    flow.inertia         = prm.get_bool("inertia");
    flow.convection      = prm.get_bool("convection") && flow.inertia;
    flow.conserve_momenta = prm.get_bool("conserve momenta") && flow.inertia;
    linear_solver.reuse_factorization       = prm.get_bool("reuse factorization");
    linear_solver.refactorization_threshold = prm.get_integer("max reuse iterations");
    linear_solver.tolerance                 = prm.get_double("linear solver tolerance");
    stokes_regularization                   = prm.get_double("rigid motion regularization");
    if (!flow.inertia && !(stokes_regularization > 0))
      throw_invalid_entry("flow/rigid motion regularization",
                          prm.get("rigid motion regularization"),
                          "ε > 0 when inertia = false (the step matrix is singular on rigid motions otherwise)");
    prm.leave_subsection();
    prm.enter_subsection("initial state");
    initial_angular_velocity = prm.get_double("angular velocity");
    equilibrium_rotation = prm.get_bool("equilibrium rotation");
    if (equilibrium_rotation && geometry.equilibrium_shape() == nullptr)
      throw_invalid_entry("initial state/equilibrium rotation",
                          "true",
                          "false unless geometry/shape = equilibrium (there is no equilibrium to take ω from)");
    const auto axis          = Utilities::split_string_list(prm.get("rotation axis"));
    const auto centre        = Utilities::split_string_list(prm.get("rotation centre"));
    for (unsigned int d = 0; d < 3; ++d)
      {
        rotation_axis[d]   = Utilities::string_to_double(axis[d]);
        rotation_centre[d] = Utilities::string_to_double(centre[d]);
      }
    if (rotation_axis.norm() == 0)
      throw_invalid_entry("initial state/rotation axis", prm.get("rotation axis"), "a non-zero vector");
    rotation_axis /= rotation_axis.norm();
    const auto U = Utilities::split_string_list(prm.get("translation velocity"));
    for (unsigned int d = 0; d < 3; ++d)
      translation_velocity[d] = Utilities::string_to_double(U[d]);
    velocity_noise = prm.get_double("velocity perturbation");
    shape_noise    = prm.get_double("shape perturbation");
    random_seed    = prm.get_integer("random seed");
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
    if (shape_noise > 0)
      {
        const SmoothRandomField field(random_seed, 0);
        const Point<3>          centre(geometry.measure().centre_of_mass);
        geometry.transform_nodes([&](const Point<3> &x) {
          const Tensor<1, 3> radial = x - centre;
          return Point<3>(x + shape_noise * field(x) * radial / radial.norm());
        });
      }
    if (equilibrium_rotation)
      initial_angular_velocity = geometry.equilibrium_shape()->angular_velocity();
    setup_dofs();
    set_initial_velocity();
    if (flow.conserve_momenta)
      rigid_targets = rigid_motion(current).momenta;
    const SurfaceGeometry::Measures m = geometry.measure();
    target_volume                     = m.volume;
    target_area                       = m.area;
    current_position                  = geometry.position();
    old_position                      = geometry.position();
    last_tau                          = 0;
    geometry.compute_curvature();
  }

  void
  FluidDeformableSurface::setup_dofs()
  {
    const unsigned int k = geometry.degree();
    fe = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(2), 3, FE_Q<2, 3>(1), 1, FE_Q<2, 3>(k), 1, FE_Q<2, 3>(k), 1,
                                          FE_Q<2, 3>(k), 3);
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
    factorization.reset();
    refactorize_next = true;
    current.reinit(owned, relevant, geometry.get_communicator());
    candidate.reinit(owned, relevant, geometry.get_communicator());

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
  FluidDeformableSurface::copy_position_into(VectorType &flow_vector) const
  {
    const VectorType &x = geometry.position();
    for (const auto &pair : position_pairs)
      flow_vector[pair.first] = x[pair.second];
    flow_vector.compress(VectorOperation::insert);
  }

  void
  FluidDeformableSurface::set_initial_velocity()
  {
    VectorType initial(owned, geometry.get_communicator());
    VectorTools::interpolate(geometry.mapping(),
                             dofs,
                             InitialVelocity(fe->n_components(),
                                             translation_velocity,
                                             initial_angular_velocity,
                                             rotation_axis,
                                             rotation_centre,
                                             velocity_noise,
                                             random_seed),
                             initial);
    // Y starts at X so that the state is complete; κ, y, p are outputs of a step.
    copy_position_into(initial);
    constraints.distribute(initial);
    current = initial;
  }
} // namespace FluidSurface

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// Per-thread FEValues: flow and geometry elements, Gauss and nodal (Gauss–Lobatto) rules.
    struct ScratchData
    {
      ScratchData(const Mapping<2, 3>       &mapping,
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
      {}
      ScratchData(const ScratchData &other)
        : flow(other.flow.get_mapping(), other.flow.get_fe(), other.flow.get_quadrature(), other.flow.get_update_flags())
        , flow_nodal(other.flow_nodal.get_mapping(),
                     other.flow_nodal.get_fe(),
                     other.flow_nodal.get_quadrature(),
                     other.flow_nodal.get_update_flags())
        , geometry(other.geometry.get_mapping(),
                   other.geometry.get_fe(),
                   other.geometry.get_quadrature(),
                   other.geometry.get_update_flags())
        , geometry_nodal(other.geometry_nodal.get_mapping(),
                         other.geometry_nodal.get_fe(),
                         other.geometry_nodal.get_quadrature(),
                         other.geometry_nodal.get_update_flags())
      {}
      FEValues<2, 3> flow, flow_nodal, geometry, geometry_nodal;
    };

    struct CopyData
    {
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs, volume_column;
      std::array<Vector<double>, 6>        rigid, rigid_rows;
      std::vector<types::global_dof_index> indices;
    };

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

  void
  FluidDeformableSurface::assemble(const double tau, const RigidMotion &motion)
  {
    system_matrix = 0;
    system_rhs    = 0;
    volume_column = 0;
    for (auto &column : rigid_columns)
      column = 0;
    for (auto &row : rigid_rows)
      row = 0;
    const bool   stokes         = !flow.inertia;
    const bool   rigid          = rigid_constraints();
    const double regularization = stokes ? stokes_regularization : 0.0;

    const SurfaceGeometry::Measures m = geometry.measure();
    // div_P u = s with s = −(A^m − A₀)/(τ_c A^m) returns any area drift (∫div_P u = dA/dt);
    // τ_c = max(τ, τ_drift) keeps the correction bounded when a rejected step shrinks τ.
    const double area_rate = area_correction ? -(m.area - target_area) / (drift_time(tau) * m.area) : 0.0;
    const double inv_tau   = 1.0 / tau;
    const double viscosity = 2.0 / flow.reynolds_number;
    const double inv_be    = bending.enabled ? 1.0 / bending.bending_number : 0.0;
    const double damping   = redistribution.relaxation_time / tau;
    // With inertia the momenta are held on the new surface S^{m+1} (linearized), so that no lag of one
    // step's mesh motion has to be made up in the next step whatever its τ.
    const bool momenta_on_new_surface = rigid && flow.inertia;
    // The damping target X^m + τR: the mesh moves along with the rigid motion R of the shape (fit of u^m·ν).
    const RigidMotion carried = redistribution.follow_rigid_motion && damping > 0 ? motion : RigidMotion();

    const FEValuesExtractors::Vector velocity(velocity_component), position(position_component), vec(0);
    const FEValuesExtractors::Scalar pressure(pressure_component), curvature(curvature_component),
      bending_scalar(bending_component);
    const QGauss<2>         gauss(fe->degree + 1);
    const QGaussLobatto<2>  lobatto(geometry.degree() + 1);
    const Quadrature<2>    &nodal = redistribution.lumped ? static_cast<const Quadrature<2> &>(lobatto) : gauss;
    const unsigned int      n     = fe->n_dofs_per_cell();

    auto worker = [&](const typename DoFHandler<2, 3>::active_cell_iterator &cell,
                      ScratchData                                         &scratch,
                      CopyData                                            &copy) {
      copy.matrix.reinit(n, n);
      copy.rhs.reinit(n);
      copy.volume_column.reinit(n);
      if (rigid)
        for (unsigned int k = 0; k < 6; ++k)
          {
            copy.rigid[k].reinit(n);
            copy.rigid_rows[k].reinit(n);
          }
      copy.indices.resize(n);
      cell->get_dof_indices(copy.indices);
      typename DoFHandler<2, 3>::active_cell_iterator geo_cell(&geometry.triangulation(),
                                                               cell->level(),
                                                               cell->index(),
                                                               &geometry.dof_handler());
      scratch.flow.reinit(cell);
      scratch.geometry.reinit(geo_cell);
      const unsigned int        nq = scratch.flow.n_quadrature_points;
      std::vector<Tensor<1, 3>> normal(nq), u_old(nq);
      std::vector<Tensor<2, 3>> grad_u_old(nq);
      std::vector<Tensor<2, 3>> normal_gradient(nq);
      scratch.geometry[vec].get_function_values(geometry.normal_field(), normal);
      scratch.geometry[vec].get_function_gradients(geometry.normal_field(), normal_gradient);
      scratch.flow[velocity].get_function_values(current, u_old);
      scratch.flow[velocity].get_function_gradients(current, grad_u_old);

      std::vector<Tensor<1, 3>> phi_u(n), phi_Y(n);
      std::vector<Tensor<2, 3>> grad_u(n), grad_Y(n), sigma_u(n);
      std::vector<double>       div_u(n), phi_p(n), phi_k(n), phi_y(n);
      std::vector<Tensor<1, 3>> grad_k(n), grad_y(n);
      for (unsigned int q = 0; q < nq; ++q)
        {
          const double        dA = scratch.flow.JxW(q);
          const Tensor<1, 3> &nu = scratch.flow.normal_vector(q);
          const Tensor<2, 3>  P  = SurfaceOperators::projection(nu);
          // Lagged shape operator B = −P∇ñ and c = |B|² − ½H² (vanishes on spheres).
          const Tensor<2, 3> B = -P * normal_gradient[q];
          const double       H = trace(B);
          const double       c = scalar_product(B, B) - 0.5 * H * H;
          // ∇_w u with w = u − (Y − X^m)/τ, linearized as ∇u^{m+1} u^m − ∇u^m (Y − X^m)/τ: the
          // mesh velocity of this very step, so that a tangential jump of the nodes (BGN) carries
          // the nodal velocities along consistently.
          const Tensor<1, 3> &w        = u_old[q];
          const Tensor<1, 3>  x_m      = scratch.flow.quadrature_point(q);
          const Tensor<1, 3>  grad_u_x = grad_u_old[q] * x_m;
          for (unsigned int i = 0; i < n; ++i)
            {
              phi_u[i]   = scratch.flow[velocity].value(i, q);
              grad_u[i]  = scratch.flow[velocity].gradient(i, q);
              div_u[i]   = SurfaceOperators::surface_divergence(grad_u[i]);
              sigma_u[i] = SurfaceOperators::strain_rate(grad_u[i], nu);
              phi_p[i]   = scratch.flow[pressure].value(i, q);
              phi_k[i]   = scratch.flow[curvature].value(i, q);
              grad_k[i]  = scratch.flow[curvature].gradient(i, q);
              phi_y[i]   = scratch.flow[bending_scalar].value(i, q);
              grad_y[i]  = scratch.flow[bending_scalar].gradient(i, q);
              phi_Y[i]   = scratch.flow[position].value(i, q);
              grad_Y[i]  = scratch.flow[position].gradient(i, q);
            }
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int ci = fe->system_to_component_index(i).first;
              if (ci < pressure_component)
                {
                  if (flow.inertia)
                    copy.rhs(i) += inv_tau * (u_old[q] * phi_u[i]) * dA;
                  if (flow.convection)
                    copy.rhs(i) -= inv_tau * (grad_u_x * phi_u[i]) * dA;
                  copy.volume_column(i) += (phi_u[i] * normal[q]) * dA;
                  if (rigid)
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        // (r, v) for r = e_d and r = e_d × x: ∫u and ∫x × u against the multipliers.
                        copy.rigid[d](i) += phi_u[i][d] * dA;
                        copy.rigid[3 + d](i) +=
                          (cross_product_3d(Tensor<1, 3>(Point<3>::unit_vector(d)), x_m) * phi_u[i]) * dA;
                        copy.rigid_rows[d](i) = copy.rigid[d](i);
                        copy.rigid_rows[3 + d](i) = copy.rigid[3 + d](i);
                      }
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int cj = fe->system_to_component_index(j).first;
                      double             a  = 0;
                      if (cj < pressure_component)
                        {
                          a += viscosity * scalar_product(sigma_u[i], sigma_u[j]);
                          if (flow.inertia)
                            a += inv_tau * (phi_u[i] * phi_u[j]);
                          else
                            a += regularization * (phi_u[i] * phi_u[j]);
                          // (∇_w u, v). Its skew-symmetric form ½[(∇u w, v) − (∇v w, u)] is
                          // inconsistent on a deforming surface (it drops ½(div_S(Pw) u, v), and
                          // div_S(Pw) = H u·ν ≠ 0), and costs angular momentum.
                          if (flow.convection)
                            a += (grad_u[j] * w) * phi_u[i];
                        }
                      else if (cj == pressure_component)
                        a -= phi_p[j] * div_u[i];
                      else if (cj >= position_component && flow.convection)
                        a -= inv_tau * ((grad_u_old[q] * phi_Y[j]) * phi_u[i]);
                      else if (cj == bending_component)
                        a -= inv_be * phi_y[j] * (normal[q] * phi_u[i]);
                      copy.matrix(i, j) += a * dA;
                    }
                }
              else if (ci == pressure_component)
                {
                  copy.rhs(i) -= area_rate * phi_p[i] * dA;
                  for (unsigned int j = 0; j < n; ++j)
                    if (fe->system_to_component_index(j).first < pressure_component)
                      copy.matrix(i, j) -= phi_p[i] * div_u[j] * dA;
                }
              else if (ci == bending_component)
                {
                  // (y, φ) − (∇κ, ∇φ) + (cκ, φ) = 0.
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int cj = fe->system_to_component_index(j).first;
                      if (cj == bending_component)
                        copy.matrix(i, j) += phi_y[i] * phi_y[j] * dA;
                      else if (cj == curvature_component)
                        copy.matrix(i, j) += (-grad_k[j] * grad_y[i] + c * phi_k[j] * phi_y[i]) * dA;
                    }
                }
              else if (ci >= position_component)
                {
                  if (momenta_on_new_surface)
                    {
                      // The momenta on S^{m+1} to first order in δ = Y − X^m (u ≈ u^m in the correction):
                      // ∫_{S^{m+1}} u ≈ ∫u + ∫u^m div_S δ, ∫_{S^{m+1}} x × u ≈ ∫x × u + ∫δ × u^m + (x × u^m) div_S δ.
                      // The Y-dependent parts are the Y entries of the constraint rows.
                      const double       div_Y = trace(grad_Y[i]);
                      const Tensor<1, 3> L_old = cross_product_3d(x_m, u_old[q]);
                      const Tensor<1, 3> Y_u   = cross_product_3d(phi_Y[i], u_old[q]);
                      for (unsigned int d = 0; d < 3; ++d)
                        {
                          copy.rigid_rows[d](i) += u_old[q][d] * div_Y * dA;
                          copy.rigid_rows[3 + d](i) += (Y_u[d] + L_old[d] * div_Y) * dA;
                        }
                    }
                  // (∇_S Y, ∇_S η) of κñ = Δ_S Y.
                  for (unsigned int j = 0; j < n; ++j)
                    if (fe->system_to_component_index(j).first >= position_component)
                      copy.matrix(i, j) += scalar_product(grad_Y[i], grad_Y[j]) * dA;
                }
            }
        }

      // Nodal terms: (1/τ)(Y·ñ − τu·ñ, φ)_h = (1/τ)(X^m·ñ, φ)_h in the κ rows; (κñ, η)_h in the Y rows.
      scratch.flow_nodal.reinit(cell);
      typename DoFHandler<2, 3>::active_cell_iterator geo_cell_nodal = geo_cell;
      scratch.geometry_nodal.reinit(geo_cell_nodal);
      const unsigned int        nl = scratch.flow_nodal.n_quadrature_points;
      std::vector<Tensor<1, 3>> nodal_normal(nl);
      scratch.geometry_nodal[vec].get_function_values(geometry.normal_field(), nodal_normal);
      for (unsigned int q = 0; q < nl; ++q)
        {
          const double        dA = scratch.flow_nodal.JxW(q);
          const Tensor<1, 3> &nt = nodal_normal[q];
          const Point<3>     &x  = scratch.flow_nodal.quadrature_point(q);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int ci = fe->system_to_component_index(i).first;
              if (ci == curvature_component)
                {
                  const double phi = scratch.flow_nodal[curvature].value(i, q);
                  copy.rhs(i) += inv_tau * (x * nt) * phi * dA;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int cj = fe->system_to_component_index(j).first;
                      if (cj >= position_component)
                        copy.matrix(i, j) += inv_tau * (scratch.flow_nodal[position].value(j, q) * nt) * phi * dA;
                      else if (cj < pressure_component)
                        copy.matrix(i, j) -= (scratch.flow_nodal[velocity].value(j, q) * nt) * phi * dA;
                    }
                }
              else if (ci >= position_component)
                {
                  // (κñ, η)_h, and the tangential damping (T_r/τ)(P̃(Y − X^m − τR), η)_h, P̃ = I − ññ.
                  const Tensor<1, 3> eta         = scratch.flow_nodal[position].value(i, q);
                  const Tensor<1, 3> eta_tangent = eta - (eta * nt) * nt;
                  copy.rhs(i) += damping * ((x + tau * carried.value(x)) * eta_tangent) * dA;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int cj = fe->system_to_component_index(j).first;
                      if (cj == curvature_component)
                        copy.matrix(i, j) += scratch.flow_nodal[curvature].value(j, q) * (nt * eta) * dA;
                      else if (cj >= position_component && damping > 0)
                        copy.matrix(i, j) += damping * (scratch.flow_nodal[position].value(j, q) * eta_tangent) * dA;
                    }
                }
            }
        }
    };

    auto copier = [&](const CopyData &copy) {
      constraints.distribute_local_to_global(copy.matrix, copy.rhs, copy.indices, system_matrix, system_rhs);
      constraints.distribute_local_to_global(copy.volume_column, copy.indices, volume_column);
      if (rigid)
        for (unsigned int k = 0; k < 6; ++k)
          {
            constraints.distribute_local_to_global(copy.rigid[k], copy.indices, rigid_columns[k]);
            constraints.distribute_local_to_global(copy.rigid_rows[k], copy.indices, rigid_rows[k]);
          }
    };

    using Iterator = typename DoFHandler<2, 3>::active_cell_iterator;
    WorkStream::run(FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.begin_active()),
                    FilteredIterator<Iterator>(IteratorFilters::LocallyOwnedCell(), dofs.end()),
                    worker,
                    copier,
                    ScratchData(geometry.mapping(), *fe, geometry.fe(), gauss, nodal),
                    CopyData());
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
  FluidDeformableSurface::factorize()
  {
    TimerSection section(step_timer, "factorization");
    factorization = std::make_unique<TrilinosWrappers::SolverDirect>(
      factorization_control, TrilinosWrappers::SolverDirect::AdditionalData(false, direct_solver));
    factorization->initialize(system_matrix);
    factorization_current = true;
    refactorize_next      = false;
    ++factorization_count;
  }

  unsigned int
  FluidDeformableSurface::solve_system(const BorderedSystem        &system,
                                       BorderedSystem::BlockVector &x,
                                       const BorderedSystem::BlockVector &b)
  {
    TimerSection                              section(step_timer, "linear solve");
    const BorderedFactorizationPreconditioner preconditioner(*factorization, system);
    unsigned int                              iterations = 0;
    if (factorization_current)
      preconditioner.vmult(x, b);
    else
      {
        // Right preconditioning: GMRES measures the true residual ‖b − Kx‖.
        SolverControl control(linear_solver.refactorization_threshold, linear_solver.tolerance * b.l2_norm());
        SolverGMRES<BorderedSystem::BlockVector>::AdditionalData data(linear_solver.refactorization_threshold + 2,
                                                                      true);
        SolverGMRES<BorderedSystem::BlockVector> gmres(control, data);
        gmres.solve(system, x, b, preconditioner);
        iterations = control.last_step();
      }
    preconditioner.enforce_constraints(x, BorderedSystem::multipliers(b));
    return iterations;
  }

  Tensor<1, 3>
  FluidDeformableSurface::RigidMotion::value(const Point<3> &x) const
  {
    return translation + cross_product_3d(rotation, x - centre);
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
    FullMatrix<double> normal_matrix(6, 6), inverse(6, 6);
    Vector<double>     rhs(6), coefficients(6);
    for (unsigned int j = 0; j < 6; ++j)
      {
        rhs(j) = sums[6 + j];
        for (unsigned int l = 0; l < 6; ++l)
          normal_matrix(j, l) = sums[12 + 6 * j + l] + (j == l ? redistribution.shape_motion_cutoff * m.area : 0.0);
      }
    inverse.invert(normal_matrix);
    inverse.vmult(coefficients, rhs);
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
    const bool        need_motion = (redistribution.follow_rigid_motion && redistribution.relaxation_time > 0) ||
                             (rigid_constraints() && flow.inertia);
    const RigidMotion motion      = need_motion ? rigid_motion(current) : RigidMotion();
    {
      TimerSection section(step_timer, "assembly");
      assemble(tau, motion);
    }

    // Bordering: the global constraints c_k·x = g_k with multipliers μ_k (force μ_k c_k in the
    // momentum rows): the volume row (u·ñ, 1) = −(V^m − V₀)/τ_c (μ = γ) and, in the Stokes limit,
    // ∫u = 0, ∫x × u = 0; one solve of the bordered system per step (BorderedSystem).
    std::vector<const VectorType *> columns, rows;
    std::vector<double>             rates;
    if (volume_constraint.enabled)
      {
        columns.push_back(&volume_column);
        rows.push_back(&volume_column);
        rates.push_back(-(geometry.measure().volume - target_volume) / drift_time(tau));
      }
    if (rigid_constraints())
      {
        // The constant parts of the linearized momenta on S^{m+1} (see assemble()) move to the right:
        // with δ = Y − X^m and div_S X^m = 2 they are −2∫u^m and −3∫x × u^m.
        // A drift P^m − P₀ (from the linearization) is returned by the fraction τ/τ_c per step, like the area
        // and volume drifts, so that a retry with a smaller τ asks for a smaller change of u.
        const std::array<double, 6> old_momenta =
          flow.inertia ? motion.momenta : std::array<double, 6>{{0, 0, 0, 0, 0, 0}};
        const double fraction = flow.inertia ? std::min(1.0, tau / drift_time(tau)) : 1.0;
        for (unsigned int k = 0; k < rigid_columns.size(); ++k)
          {
            const double target = old_momenta[k] + fraction * (rigid_targets[k] - old_momenta[k]);
            columns.push_back(&rigid_columns[k]);
            rows.push_back(&rigid_rows[k]);
            rates.push_back(target + (k < 3 ? 2.0 : 3.0) * old_momenta[k]);
          }
      }

    const BorderedSystem system(system_matrix, columns, rows);
    BorderedSystem::BlockVector solution = system.make_vector(system_rhs), rhs = solution;
    rhs.block(0) = system_rhs;
    BorderedSystem::set_multipliers(rhs, rates);
    try
      {
        factorization_current = false;
        if (!factorization || !linear_solver.reuse_factorization || refactorize_next)
          factorize();
        if (last_solution.n_blocks() == 2 && last_solution.block(1).size() == columns.size())
          solution = last_solution;
        // An old factorization preconditions GMRES on the bordered system; when GMRES needs more than the
        // threshold, this step's matrix is factorized and the system solved directly.
        try
          {
            result.linear_iterations += solve_system(system, solution, rhs);
          }
        catch (const SolverControl::NoConvergence &)
          {
            result.linear_iterations += linear_solver.refactorization_threshold;
            factorize();
            solve_system(system, solution, rhs);
          }
        last_solution = solution;
        result.factorized = factorization_current;
        const std::vector<double> mu          = BorderedSystem::multipliers(solution);
        const unsigned int        first_rigid = volume_constraint.enabled ? 1 : 0;
        if (volume_constraint.enabled)
          result.gamma = mu[0];
        double rigid = 0;
        for (unsigned int k = first_rigid; k < mu.size(); ++k)
          rigid += mu[k] * mu[k];
        result.rigid_force = std::sqrt(rigid);
      }
    catch (const std::exception &exc)
      {
        refactorize_next = true;
        result.failure   = std::string("linear solver failed: ") + exc.what();
        return result;
      }
    VectorType &x1 = solution.block(0);
    if (!std::isfinite(x1.l2_norm()))
      {
        result.failure = "the solution is not finite";
        return result;
      }
    constraints.distribute(x1);
    candidate = x1;
    {
      TimerSection section(step_timer, "diagnostics");
      result.dissipation_rate = dissipation_rate(candidate);
    }
    copy_new_position_to_geometry(candidate);
    last_step_tau = tau;
    result.solved = true;
    return result;
  }

  void
  FluidDeformableSurface::accept()
  {
    old_position     = current_position;
    current_position = geometry.position();
    current          = candidate;
    last_tau         = last_step_tau;
  }

  void
  FluidDeformableSurface::restore_last_state()
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = current_position;
    geometry.set_position(position);
    geometry.compute_curvature();
    refactorize_next = true;
  }

  double
  FluidDeformableSurface::kinetic_energy(const VectorType &state) const
  {
    const QGauss<2>                  q = geometry.quadrature();
    FEValues<2, 3>                   fe_values(geometry.mapping(), *fe, q, update_values | update_JxW_values);
    const FEValuesExtractors::Vector velocity(velocity_component);
    std::vector<Tensor<1, 3>>        u(q.size());
    double                           energy = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[velocity].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            energy += 0.5 * u[k].norm_square() * fe_values.JxW(k);
        }
    return Utilities::MPI::sum(energy, geometry.get_communicator());
  }

  double
  FluidDeformableSurface::dissipation_rate(const VectorType &state) const
  {
    const QGauss<2>                  q = geometry.quadrature();
    FEValues<2, 3>                   fe_values(geometry.mapping(), *fe, q, update_gradients | update_normal_vectors |
                                                                   update_JxW_values);
    const FEValuesExtractors::Vector velocity(velocity_component);
    std::vector<Tensor<2, 3>>        grad(q.size());
    double                           rate = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[velocity].get_function_gradients(state, grad);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const Tensor<2, 3> sigma = SurfaceOperators::strain_rate(grad[k], fe_values.normal_vector(k));
              rate += scalar_product(sigma, sigma) * fe_values.JxW(k);
            }
        }
    return 2.0 / flow.reynolds_number * Utilities::MPI::sum(rate, geometry.get_communicator());
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
    data.set("model/element", fe->get_name());
    data.set("model/target volume", target_volume);
    data.set("model/target area", target_area);
    data.set("model/factorizations", factorization_count);
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      data.set("model/rigid target " + std::to_string(k), rigid_targets[k]);
    data.set("model/last tau", last_tau);
    data.set("model/last step tau", last_step_tau);
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
    target_volume = data.get_double("model/target volume");
    target_area   = data.get_double("model/target area");
    factorization_count = data.get_unsigned("model/factorizations");
    for (unsigned int k = 0; k < rigid_targets.size(); ++k)
      rigid_targets[k] = data.get_double("model/rigid target " + std::to_string(k));
    last_tau      = data.get_double("model/last tau");
    last_step_tau = data.get_double("model/last step tau");
    geometry.compute_curvature();
  }
} // namespace FluidSurface
