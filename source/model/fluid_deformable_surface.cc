// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/base/vector_math.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/fluid_deformable_surface.h>
#include <fluid_surface/postprocess/speed_postprocessor.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

namespace FluidSurface
{
  using namespace dealii;

  FluidDeformableSurface::FluidDeformableSurface(SurfaceGeometry &geometry)
    : geometry(geometry)
    , surface_step(geometry, state)
  {}

  void
  FluidDeformableSurface::declare_parameters(ParameterHandler &prm)
  {
    SurfaceStep::declare_parameters(prm);
    SurfaceReparametrization::declare_parameters(prm);
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
                      "Centre c of the initial rigid rotation, three numbers, each |c_i| ≤ 100. A shape "
                      "perturbation moves c with the centre of mass, so that a perturbed surface spins about its own "
                      "centre and starts without linear momentum.");
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
    prm.declare_entry("perturbation form",
                      "random",
                      Patterns::Selection("random|azimuthal"),
                      "Form of the radial displacement ε_X δ(x) of `shape perturbation`. random: δ a smooth seeded "
                      "random field. azimuthal: one azimuthal mode about the rotation axis e through the centre of "
                      "mass, δ = Re h_m(x̂)/max|h_m| with x̂ the unit vector from the centre, h_m = ξ^m (even; "
                      "ξ(5ζ² − 1) for m = 1) or ζξ^m (odd), ξ = x̂·e₁ + i x̂·e₂, ζ = x̂·e (m = 0: the axisymmetric "
                      "P₂, P₃); for growth rates by azimuthal wavenumber (with diagnostics/azimuthal modes).");
    prm.declare_entry("azimuthal wavenumber",
                      "2",
                      Patterns::Integer(0, 16),
                      "m, 0 ≤ m ≤ 16, of perturbation form = azimuthal.");
    prm.declare_entry("azimuthal parity",
                      "even",
                      Patterns::Selection("even|odd"),
                      "Parity of perturbation form = azimuthal under reflection through the equatorial plane "
                      "(ζ → −ζ); m = 1 odd tilts the axis.");
    prm.declare_entry("random seed", "1", Patterns::Integer(0), "Seed ≥ 0 of the perturbations (same on every rank).");
    prm.leave_subsection();
  }

  void
  FluidDeformableSurface::parse_parameters(ParameterHandler &prm, const double maximum_time_step)
  {
    surface_step.parse_parameters(prm, maximum_time_step);
    reparametrization.parse_parameters(prm, surface_step.components().redistribution.mesh_quality_floor);
    run_request = StepRequest::flow_step(surface_step.components().redistribution.law);
    prm.enter_subsection("initial state");
    initial_entries.angular_velocity     = prm.get_double("angular velocity");
    initial_entries.equilibrium_rotation = prm.get_bool("equilibrium rotation");
    if (initial_entries.equilibrium_rotation && geometry.equilibrium_shape() == nullptr)
      throw_invalid_entry("initial state/equilibrium rotation",
                          "true",
                          "false unless geometry/shape = equilibrium (there is no equilibrium to take ω from)");
    initial_entries.rotation_axis = unit_vector(get_vector(prm, "rotation axis"));
    if (initial_entries.rotation_axis.norm() == 0)
      throw_invalid_entry("initial state/rotation axis", prm.get("rotation axis"), "a non-zero vector");
    initial_entries.rotation_centre       = Point<3>(get_vector(prm, "rotation centre"));
    initial_entries.translation_velocity  = get_vector(prm, "translation velocity");
    initial_entries.velocity_perturbation = prm.get_double("velocity perturbation");
    initial_entries.shape_perturbation    = prm.get_double("shape perturbation");
    initial_entries.random_seed           = prm.get_integer("random seed");
    initial_entries.perturbation_form     = prm.get("perturbation form") == "azimuthal" ?
                                      InitialState::PerturbationForm::azimuthal :
                                      InitialState::PerturbationForm::random;
    initial_entries.azimuthal_wavenumber  = prm.get_integer("azimuthal wavenumber");
    initial_entries.azimuthal_odd         = prm.get("azimuthal parity") == "odd";
    prm.leave_subsection();
    if (initial_entries.perturbation_form == InitialState::PerturbationForm::azimuthal && initial_entries.shape_perturbation == 0)
      throw_invalid_entry("initial state/perturbation form",
                          "azimuthal",
                          "random unless shape perturbation > 0 (the mode is the form of that displacement)");
    azimuthal_perturbation.reset();
    if (initial_entries.perturbation_form == InitialState::PerturbationForm::azimuthal)
      azimuthal_perturbation = std::make_unique<AzimuthalHarmonic>(initial_entries.rotation_axis,
                                                                   initial_entries.azimuthal_wavenumber,
                                                                   initial_entries.azimuthal_odd);
    angular_velocity = initial_entries.angular_velocity;
    rotation_centre  = initial_entries.rotation_centre;
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

    /// Moves every node x to x + ε δ(x, x − c)(x − c)/|x − c|, c the centre of mass before the move; returns c.
    template <typename Form>
    Point<3>
    displace_radially(SurfaceGeometry &geometry, const double amplitude, const Form &delta)
    {
      const Point<3> centre(geometry.measure().centre_of_mass);
      geometry.transform_nodes([&](const Point<3> &x) {
        const Tensor<1, 3> radial = x - centre;
        return Point<3>(x + amplitude * delta(x, radial) * radial / radial.norm());
      });
      return centre;
    }

  } // namespace

  void
  FluidDeformableSurface::setup()
  {
    if (initial_entries.shape_perturbation > 0)
      {
        const SmoothRandomField field(initial_entries.random_seed, 0);
        const auto              delta = [&](const Point<3> &x, const Tensor<1, 3> &radial) {
          return azimuthal_perturbation ? azimuthal_perturbation->normalized_real_part(radial) : field(x);
        };
        const Point<3> centre = displace_radially(geometry, initial_entries.shape_perturbation, delta);
        // Spinning about the unperturbed centre would give the surface the momentum ω e × A(c' − c), and L
        // about its centre of mass would then change by (c(t) − c(0)) × P wherever the discrete centre of
        // mass does not move exactly with P/A.
        rotation_centre += Point<3>(geometry.measure().centre_of_mass) - centre;
      }
    if (initial_entries.equilibrium_rotation)
      angular_velocity = geometry.equilibrium_shape()->angular_velocity();
    surface_step.setup_system();
    state.reinit(surface_step.dof_handler(), geometry);
    set_initial_velocity();
    // The targets with the quadrature of the projection and the diagnostics (the step's rows use the
    // assembly's: their difference is what ConservationProjection removes).
    if (surface_step.components().flow.conserve_momenta)
      state.rigid_targets = ConservationProjection::momenta(geometry, surface_step.dof_handler(), state.solution);
    const SurfaceGeometry::Measures m = geometry.measure();
    state.target_volume               = m.volume;
    state.target_area                 = m.area;
    state.position                    = geometry.position();
    state.reference_surface           = geometry.position();
    set_reference_position();
  }

  void
  FluidDeformableSurface::set_reference_surface(const VectorType &position)
  {
    state.reference_surface.reinit(geometry.locally_owned_dofs(),
                                   geometry.locally_relevant_dofs(),
                                   geometry.get_communicator());
    VectorType owned_position(geometry.locally_owned_dofs(), geometry.get_communicator());
    owned_position          = position;
    state.reference_surface = owned_position;
    set_reference_position();
  }

  void
  FluidDeformableSurface::set_reference_position()
  {
    VectorType reference(surface_step.dof_handler().locally_owned_dofs(), geometry.get_communicator());
    surface_step.copy_position_into(state.reference_surface, reference);
    state.reference_position = reference;
  }

  void
  FluidDeformableSurface::set_prescribed_velocity(const Function<3> &velocity)
  {
    AssertDimension(velocity.n_components, 3);
    AssertThrow(!surface_step.components().volume_constraint.enabled && !surface_step.components().momentum_constraints.active(),
                ExcMessage("a prescribed motion needs the volume and momentum constraints off"));
    run_request.velocity   = StepRequest::Velocity::prescribed;
    run_request.prescribed = &velocity;
  }

  void
  FluidDeformableSurface::set_initial_velocity()
  {
    VectorType initial(surface_step.dof_handler().locally_owned_dofs(), geometry.get_communicator());
    VectorTools::interpolate(geometry.mapping(),
                             surface_step.dof_handler(),
                             InitialVelocity(surface_step.dof_handler().get_fe().n_components(),
                                             initial_entries.translation_velocity,
                                             angular_velocity,
                                             initial_entries.rotation_axis,
                                             rotation_centre,
                                             initial_entries.velocity_perturbation,
                                             initial_entries.random_seed),
                             initial);
    // Y starts at X so that the state is complete; κ, y, p are outputs of a surface_step.
    surface_step.copy_position_into(geometry.position(), initial);
    surface_step.hanging_node_constraints().distribute(initial);
    state.solution = initial;
  }
} // namespace FluidSurface

namespace FluidSurface
{
  using namespace dealii;

  SurfaceStep::Result
  FluidDeformableSurface::advance(const double tau)
  {
    return surface_step.advance(run_request, tau, candidate);
  }

  bool
  FluidDeformableSurface::accept(const double time)
  {
    surface_step.accept_history(candidate); // before the state moves on: BDF2 keeps it as x^{m−1}
    state.position  = candidate.position;
    state.curvature = candidate.curvature;
    state.solution  = candidate.solution;
    const double anchor_time = surface_step.components().redistribution.anchor_time;
    if (anchored || anchor_time < 0 || time < anchor_time)
      return false;
    anchor();
    return true;
  }

  void
  FluidDeformableSurface::anchor()
  {
    set_reference_surface(state.position);
    surface_step.pull_fully();
    anchored = true;
  }

  void
  FluidDeformableSurface::restore_last_state()
  {
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = state.position;
    if (state.curvature)
      geometry.set_position(position, *state.curvature);
    else
      geometry.set_position(position);
    surface_step.solver().request_factorization();
  }

  void
  FluidDeformableSurface::restart_from(const SurfaceState &new_state)
  {
    state = new_state;
    state.curvature.reset(); // new_state's position need not be the one its curvature was taken of
    VectorType position(geometry.locally_owned_dofs(), geometry.get_communicator());
    position = state.position;
    geometry.set_position(position);
    VectorType solution(surface_step.dof_handler().locally_owned_dofs(), geometry.get_communicator());
    solution = state.solution;
    surface_step.copy_position_into(position, solution);
    surface_step.hanging_node_constraints().distribute(solution);
    state.solution = solution;
    set_reference_position();
    surface_step.forget_history();
    surface_step.solver().request_factorization();
  }

  SurfaceReparametrization::Result
  FluidDeformableSurface::reparametrize()
  {
    const SurfaceReparametrization::Result result =
      reparametrization.reparametrize(surface_step, state, run_request, [&]() {
        return total_energy(kinetic_energy(), geometry.willmore_energy());
      });
    if (result.done)
      surface_step.forget_history(); // the transferred state has no history
    return result;
  }

  void
  FluidDeformableSurface::perturb_shape(const AzimuthalHarmonic &mode, const double amplitude)
  {
    displace_radially(geometry, amplitude, [&](const Point<3> &, const Tensor<1, 3> &radial) {
      return mode.normalized_real_part(radial);
    });
    const StepComponents &components = surface_step.components();
    if (components.conservation.enabled)
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          const SurfaceGeometry::Curvature modes = geometry.curvature(); // held while the nodes move
          components.conservation.project_area_and_volume(
            geometry, modes, state.target_area, state.target_volume, components.volume_constraint.enabled);
        }
    VectorType owned(surface_step.dof_handler().locally_owned_dofs(), geometry.get_communicator());
    owned = state.solution;
    surface_step.copy_position_into(geometry.position(), owned);
    if (components.conservation.enabled && components.flow.conserve_momenta)
      components.conservation.project_momenta(geometry, surface_step.dof_handler(), state.rigid_targets, owned);
    state.solution = owned;
    state.position = geometry.position();
    surface_step.forget_history();
    surface_step.solver().forget_last_solution();
    surface_step.solver().request_factorization();
  }

  double
  FluidDeformableSurface::total_energy(const double kinetic_energy, const double willmore_energy) const
  {
    return (surface_step.components().flow.inertia ? kinetic_energy : 0.0) + surface_step.components().bending.energy(willmore_energy);
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
    data_out.add_data_vector(surface_step.dof_handler(), state.solution, names, kinds);
    static const SpeedPostprocessor speed;
    data_out.add_data_vector(surface_step.dof_handler(), state.solution, speed);
  }

  void
  FluidDeformableSurface::save(CheckpointData &data) const
  {
    state.save(data, surface_step.dof_handler(), geometry);
    data.set("model/element", surface_step.dof_handler().get_fe().get_name());
    data.set("model/factorizations", surface_step.solver().n_factorizations());
    // The seeded random fields are drawn in setup() only; the seed is kept for the record.
    data.set("model/random seed", initial_entries.random_seed);
    reparametrization.save(data);
    surface_step.save_history(data);
    if (anchored)
      data.set("model/anchored", 1u);
  }

  void
  FluidDeformableSurface::load(const CheckpointData &data)
  {
    surface_step.setup_system();
    const std::string element = surface_step.dof_handler().get_fe().get_name();
    if (data.get_string("model/element") != element)
      throw std::runtime_error("the checkpoint holds the element " + data.get_string("model/element") +
                               ", this run uses " + element);
    state.load(data, surface_step.dof_handler(), geometry);
    set_reference_position();
    surface_step.solver().set_n_factorizations(data.get_unsigned("model/factorizations"));
    reparametrization.load(data);
    surface_step.load_history(data);
    anchored = data.has("model/anchored");
  }

  void
  FluidDeformableSurface::set_time_scheme(const TimeStepper &time)
  {
    surface_step.set_time_scheme(time.scheme(), time.frame());
    const TimeScheme                &scheme = surface_step.flow_time_scheme();
    const TimeScheme::StepRatioLimit limit  = scheme.step_ratio_limit();
    time.limit_step_ratio(limit.ratio, limit.reason);
    const GeometryIteration &iteration = surface_step.components().geometry_iteration;
    if (scheme.needs_new_level_geometry() && !(iteration.enabled() && iteration.apply == GeometryIteration::Apply::always))
      throw_invalid_entry("time stepping/scheme",
                          scheme.name(),
                          "'backward Euler', or 'geometry iteration/maximum iterations' ≥ 1 with apply = always (a "
                          "second-order scheme needs the geometry of its new time level; a lagged geometry is first "
                          "order)");
  }
} // namespace FluidSurface
