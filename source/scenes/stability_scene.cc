// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/scenes/stability_scene.h>
#include <fluid_surface/scenes/step_controller.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <algorithm>
#include <limits>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  StabilityScene::StabilityScene(const MPI_Comm            communicator,
                                 SurfaceGeometry          &geometry,
                                 OutputWriter             &output,
                                 StatisticsFile           &statistics,
                                 const ConditionalOStream &pcout,
                                 const Timer              &wall_timer)
    : Scene(geometry, output, statistics, pcout)
    , communicator(communicator)
    , wall_timer(wall_timer)
    , model(geometry)
  {}

  void
  StabilityScene::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("stability");
    prm.declare_entry("wavenumbers",
                      "0, 1, 2, 3, 4",
                      Patterns::List(Patterns::Integer(0, 8), 1, 9),
                      "Azimuthal wavenumbers m, 0 ≤ m ≤ 8, whose leading eigenvalues scene stability computes (one "
                      "Arnoldi run per m and parity, started from the mode h_m of initial state/perturbation form).");
    prm.declare_entry("parities",
                      "even, odd",
                      Patterns::List(Patterns::Selection("even|odd"), 1, 2),
                      "Parities under reflection through the equatorial plane (even: the mode h_m, odd: ζh_m; m = 1 "
                      "odd tilts the axis) of the seeds.");
    prm.declare_entry("map time",
                      "0.3",
                      RealRange::left_open(0, 100),
                      "T, 0 < T ≤ 100, of the time-T map whose multipliers μ give σ = ln|μ|/T and Ω = arg μ/T; a multiple of "
                      "time stepping/time step. Frequencies |Ω| < π/T are resolved; a larger T separates the "
                      "leading eigenvalues more per Krylov vector.");
    prm.declare_entry("base state",
                      "equilibrium",
                      Patterns::Selection("equilibrium|checkpoint"),
                      "The state whose spectrum is computed. equilibrium: the rotating axisymmetric equilibrium of "
                      "geometry/shape = equilibrium, one Arnoldi run per wavenumber and parity. checkpoint: the last "
                      "checkpoint of a run of scene full (an end state, rotating rigidly and not axisymmetric), one "
                      "Arnoldi run from all modes m ≤ 4 at once, the leading `eigenvalues per wavenumber` reported.");
    prm.declare_entry("checkpoint directory",
                      "",
                      Patterns::Anything(),
                      "With base state = checkpoint: the output directory of that run (its subdirectory "
                      "checkpoint/), run with the geometry and model of this file.");
    prm.declare_entry("anchor the end state",
                      "true",
                      Patterns::Bool(),
                      "With base state = checkpoint: anchor the mesh law at the loaded surface (what mesh "
                      "redistribution/anchor time does: the membrane energy, with full weight, relative to that "
                      "surface), so that it holds the nodes of the end state instead of letting them slide; with "
                      "`settling time` for the nodes to settle.");
    prm.declare_entry("settling time",
                      "0",
                      RealRange::closed(0, 1e6),
                      "t_s, 0 ≤ t_s ≤ 1e6, a multiple of time stepping/time step: the unperturbed model runs for t_s before the "
                      "analysis, so that the equilibrium of the continuous problem (interpolated on the mesh) settles "
                      "to that of the discrete one, about which the map is linearized.");
    prm.declare_entry("maximum Krylov dimension",
                      "20",
                      Patterns::Integer(2, 60),
                      "k, 2 ≤ k ≤ 60: map applications per wavenumber and parity at most (each one a run over T).");
    prm.declare_entry("maximum restarts",
                      "5",
                      Patterns::Integer(0, 100),
                      "r, 0 ≤ r ≤ 100: thick (Krylov–Schur) restarts per wavenumber and parity at most. When the "
                      "Krylov space is full and the leading Ritz value has not converged, Arnoldi keeps the invariant "
                      "subspace of the leading Ritz values of the seed's wavenumber and parity (at most half the "
                      "space) and goes on from there; not again once a restart has not halved the smallest leading "
                      "residual (the noise of the finite-difference map). 0: no restart.");
    prm.declare_entry("eigenvalues per wavenumber",
                      "3",
                      Patterns::Integer(1, 60),
                      "Eigenvalue pairs (μ, μ̄) reported per wavenumber and parity: those of largest |μ| whose Ritz "
                      "vectors have that wavenumber and parity.");
    prm.declare_entry("perturbation size",
                      "1e-5",
                      RealRange::closed(1e-9, 1e-2),
                      "ε, 1e-9 ≤ ε ≤ 1e-2, of the finite-difference linearization [Φ_T(x + εv) − Φ_T(x)]/ε, v of unit "
                      "norm (nodal values of X and u).");
    prm.declare_entry("residual tolerance",
                      "1e-3",
                      RealRange::left_open(0, 1),
                      "Tolerance, 0 < tol ≤ 1: Arnoldi stops when the residual r = ‖Az − μz‖/|μ| of the leading Ritz value "
                      "of the seed's wavenumber and parity is below it. One still above it at the maximum Krylov "
                      "dimension after the last restart is written with its residual; if its σ + ln(1/(1 − r))/T is negative it decays "
                      "whatever its error (a warning), else the run ends with exit status 1 after the last wavenumber.");
    prm.declare_entry("equilibrium tolerance",
                      "0.02",
                      RealRange::left_open(0, 1e6),
                      "Largest drift rate, > 0, of the unperturbed map: the largest normal distance of a node of "
                      "Φ_T(x_eq), turned back by the fitted rotation, from x_eq, per radius R = √(A/4π) and unit time "
                      "(the nodes may slide along the surface). Above it "
                      "the start is not an equilibrium of the discrete model and the run ends (exit 2); the "
                      "interpolated equilibrium relaxes to the discrete one at a rate that falls with h.");
    prm.leave_subsection();
  }

  ParametersRead
  StabilityScene::parameters_read() const
  {
    return {"scene stability",
            {"model",
             "geometry",
             "equilibrium",
             "output",
             "initial state",
             "flow",
             "bending",
             "volume constraint",
             "mesh redistribution",
             "conservation projection",
             "geometry iteration",
             "linear solver",
             "time stepping",
             "stability"},
            {"time stepping/end time",
             "time stepping/adaptive",
             "time stepping/minimum time step",
             "time stepping/growth factor",
             "time stepping/shrink factor",
             "time stepping/easy steps before growth",
             "time stepping/energy tolerance",
             "time stepping/backward Euler steps after rejection",
             "time stepping/energy budget"}};
  }

  void
  StabilityScene::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("stability");
    from_checkpoint      = prm.get("base state") == "checkpoint";
    checkpoint_directory = prm.get("checkpoint directory");
    anchor_end_state     = prm.get_bool("anchor the end state");
    prm.leave_subsection();
    if (from_checkpoint && checkpoint_directory.empty())
      throw_invalid_entry("stability/checkpoint directory",
                          "",
                          "the output directory of a run of scene full with base state = checkpoint");
    TimeStepper time;
    time.parse_parameters(prm);
    tau  = time.step_size();
    model.parse_parameters(prm, time.maximum_step_size());
    model.set_time_scheme(time);
    if (!from_checkpoint && geometry.equilibrium_shape() == nullptr)
      throw_invalid_entry("geometry/shape",
                          SurfaceGeometry::shape_name(geometry.parameters().shape),
                          "equilibrium with scene stability (the rotating state whose spectrum is computed)");
    const FluidDeformableSurface::InitialState &initial = model.initial_state();
    if (!from_checkpoint && !initial.equilibrium_rotation)
      throw_invalid_entry("initial state/equilibrium rotation",
                          "false",
                          "true with scene stability (the equilibrium rotates rigidly with its ω)");
    for (const auto &[entry, value] : {std::make_pair("shape perturbation", initial.shape_perturbation),
                                       std::make_pair("velocity perturbation", initial.velocity_perturbation)})
      if (!from_checkpoint && value != 0)
        throw_invalid_entry(std::string("initial state/") + entry,
                            Utilities::to_string(value),
                            "0 with scene stability (it perturbs the equilibrium itself, one mode at a time)");

    prm.enter_subsection("stability");
    wavenumbers.clear();
    for (const std::string &m : Utilities::split_string_list(prm.get("wavenumbers")))
      wavenumbers.push_back(Utilities::string_to_int(m));
    parities.clear();
    for (const std::string &p : Utilities::split_string_list(prm.get("parities")))
      parities.push_back(p == "odd");
    map_time = prm.get_double("map time");
    n_steps  = static_cast<unsigned int>(std::lround(map_time / tau));
    if (n_steps == 0 || std::abs(n_steps * tau - map_time) > 1e-9 * map_time)
      throw_invalid_entry("stability/map time",
                          prm.get("map time"),
                          "a positive multiple of time stepping/time step (" + Utilities::to_string(tau) + ")");
    const double settling_time = prm.get_double("settling time");
    n_settling_steps           = static_cast<unsigned int>(std::lround(settling_time / tau));
    if (std::abs(n_settling_steps * tau - settling_time) > 1e-9 * std::max(settling_time, tau))
      throw_invalid_entry("stability/settling time",
                          prm.get("settling time"),
                          "0 or a multiple of time stepping/time step (" + Utilities::to_string(tau) + ")");
    max_krylov            = prm.get_integer("maximum Krylov dimension");
    max_restarts          = prm.get_integer("maximum restarts");
    n_reported            = prm.get_integer("eigenvalues per wavenumber");
    epsilon               = prm.get_double("perturbation size");
    residual_tolerance    = prm.get_double("residual tolerance");
    equilibrium_tolerance = prm.get_double("equilibrium tolerance");
    if (n_reported > max_krylov)
      throw_invalid_entry("stability/eigenvalues per wavenumber",
                          prm.get("eigenvalues per wavenumber"),
                          "at most the maximum Krylov dimension (" + std::to_string(max_krylov) + ")");
    prm.leave_subsection();
  }

  StabilityScene::Perturbation
  StabilityScene::zero() const
  {
    Perturbation v;
    v.position.reinit(geometry.locally_owned_dofs(), communicator);
    v.velocity.reinit(model.dof_handler().locally_owned_dofs(), communicator);
    return v;
  }

  SurfaceState
  StabilityScene::advanced(const SurfaceState &start, const unsigned int steps, const std::string &what)
  {
    model.restart_from(start);
    // The scheme's start-up in place of the first step (TimeScheme::start_up()), then steps of τ, none retried.
    std::vector<double> sizes;
    if (steps > 0)
      {
        sizes = model.step().flow_time_scheme().start_up(tau).steps;
        sizes.insert(sizes.end(), steps - 1, tau);
      }
    TimeStepper map_steps;
    map_steps.prescribe_steps(sizes);
    StepController controller(model, map_steps, pcout, output.directory(), communicator);
    try
      {
        while (map_steps.before_end())
          controller.attempt(0);
      }
    catch (const RunFailed &failure)
      {
        throw RunFailed("the time map of " + what + ": " + failure.reason(),
                        "the rows of spectrum.csv so far are intact; try a smaller 'time stepping/time step' or "
                        "'stability/perturbation size'");
      }
    return model.accepted_state();
  }

  StabilityScene::Perturbation
  StabilityScene::mapped(const Perturbation &v, const std::string &what)
  {
    SurfaceState start = base;
    VectorType   owned(geometry.locally_owned_dofs(), communicator);
    owned = base.position;
    owned.add(epsilon, v.position);
    start.position = owned;
    VectorType fields(model.dof_handler().locally_owned_dofs(), communicator);
    fields = base.solution;
    fields.add(epsilon, v.velocity);
    start.solution = fields;

    const SurfaceState end = advanced(start, n_steps, what);
    Perturbation       w   = zero();
    positions->rotated_difference(end.position, base_end.position, 1 / epsilon, back_rotation, w.position);
    velocities->rotated_difference(end.solution, base_end.solution, 1 / epsilon, back_rotation, w.velocity);
    return w;
  }

  StabilityScene::Perturbation
  StabilityScene::seed(const unsigned int m, const bool odd) const
  {
    std::vector<AzimuthalHarmonic> harmonics;
    if (from_checkpoint) // every mode of m ≤ 4 at once: the end state has no azimuthal classes
      for (unsigned int k = 0; k <= 4; ++k)
        for (const bool parity : {false, true})
          harmonics.emplace_back(axis, k, parity);
    else
      harmonics.emplace_back(axis, m, odd);
    Perturbation v = zero();
    positions->radial_field(
      centre,
      [&](const Tensor<1, 3> &x) {
        double delta = 0;
        for (const AzimuthalHarmonic &h : harmonics)
          delta += h.normalized_real_part(x);
        return delta;
      },
      v.position);
    v.scale(1 / std::sqrt(v.dot(v)));
    return v;
  }

  std::vector<StabilityScene::Mode>
  StabilityScene::arnoldi(const unsigned int m, const bool odd)
  {
    const std::string what = from_checkpoint ? std::string("the end state") :
                                               "m = " + std::to_string(m) + (odd ? " odd" : " even");
    // The modes of the seed's wavenumber and parity, by |μ|; the Krylov space also holds others (the cube-sphere
    // couples m and m ± 4), which their own seeds find. The end state: all modes.
    const auto of_seed = [&](const std::vector<Mode> &all) {
      std::vector<Mode> selected;
      for (const Mode &mode : all)
        if (from_checkpoint || (mode.m == m && mode.odd == odd))
          selected.push_back(mode);
      return selected;
    };
    // Converged: the leading mode (the end state: the leading `eigenvalues per wavenumber` modes).
    const auto converged = [&](const std::vector<Mode> &selected) {
      if (selected.empty())
        return false;
      const std::size_t n = from_checkpoint ? std::min<std::size_t>(selected.size(), n_reported) : 1;
      if (from_checkpoint && selected.size() < n_reported)
        return false;
      for (std::size_t i = 0; i < n; ++i)
        if (!(selected[i].residual < residual_tolerance))
          return false;
      return true;
    };
    std::vector<Perturbation> V{seed(m, odd)};
    FullMatrix<double>        H(max_krylov + 1, max_krylov);
    std::vector<Mode>         modes;
    unsigned int              restarts = 0;
    // The smallest leading residual of this cycle and of the one before: a restart that does not halve it has
    // met the noise of the finite-difference map, and more restarts do not help.
    double cycle_residual = std::numeric_limits<double>::infinity(), previous_residual = cycle_residual;
    for (unsigned int j = 1;; ++j)
      {
        Perturbation w = mapped(V[j - 1], what + ", Krylov vector " + std::to_string(j));
        const double mapped_norm = std::sqrt(w.dot(w));
        for (unsigned int pass = 0; pass < 2; ++pass) // Gram–Schmidt twice: the basis stays orthonormal
          for (unsigned int i = 0; i < j; ++i)
            {
              const double h = V[i].dot(w);
              H(i, j - 1) += h;
              w.add(-h, V[i]);
            }
        H(j, j - 1) = std::sqrt(w.dot(w));
        modes       = of_seed(ritz_modes(H, j, V));
        const bool found = !modes.empty();
        unconverged_leading = !converged(modes);
        const double sigma = found ? std::log(std::abs(modes[0].multiplier)) / map_time : 0.0;
        statistics.add_value("wavenumber", m);
        statistics.add_value("odd", odd ? 1 : 0);
        statistics.add_value("restarts", restarts);
        statistics.add_value("Krylov dimension", j);
        statistics.add_value("norm of the mapped vector", mapped_norm);
        statistics.add_value("leading growth rate", sigma);
        statistics.add_value("leading frequency", found ? modes[0].frequency : 0.0);
        statistics.add_value("leading residual", found ? modes[0].residual : 1.0);
        statistics.add_value("wall time", wall_timer.wall_time());
        statistics.end_row();
        pcout << "    " << what << ", Krylov dimension " << j << ": ";
        if (found)
          pcout << "σ = " << std::setprecision(6) << sigma << ", Ω = " << modes[0].frequency << ", residual "
                << std::setprecision(2) << std::scientific << modes[0].residual << std::defaultfloat << std::endl;
        else
          pcout << "no Ritz vector of this wavenumber and parity yet" << std::endl;
        if (found)
          cycle_residual = std::min(cycle_residual, modes[0].residual);
        if (converged(modes) || H(j, j - 1) < 1e-12 * mapped_norm)
          break;
        w.scale(1 / H(j, j - 1));
        if (j < max_krylov)
          {
            V.push_back(w);
            continue;
          }
        if (restarts == max_restarts)
          break;
        if (restarts > 0 && !(cycle_residual < 0.5 * previous_residual))
          {
            pcout << "    " << what << ": no restart: the last one did not halve the leading residual ("
                  << std::setprecision(2) << std::scientific << previous_residual << " → " << cycle_residual
                  << std::defaultfloat << ")" << std::endl;
            break;
          }
        previous_residual = cycle_residual;
        cycle_residual    = std::numeric_limits<double>::infinity();
        ++restarts;
        // The seed's modes; none yet: the leading ones of any wavenumber.
        j = restart(H, j, V, modes.empty() ? ritz_modes(H, j, V) : modes, w);
        pcout << "    " << what << ": restart " << restarts << ", " << j << " Ritz vectors kept" << std::endl;
      }
    restarts_used = restarts;
    modes.resize(std::min<std::size_t>(modes.size(), n_reported));
    return modes;
  }

  void
  StabilityScene::write_rows(const unsigned int m, const bool odd, const std::vector<Mode> &modes) const
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ofstream csv(spectrum_file, std::ios::app);
    csv << std::setprecision(8);
    for (const Mode &mode : modes)
      csv << mode.m << ',' << (mode.odd ? "odd" : "even") << ',' << std::log(std::abs(mode.multiplier)) / map_time
          << ',' << mode.frequency << ',' << std::abs(mode.multiplier) << ',' << std::arg(mode.multiplier) << ','
          << mode.residual << ',' << mode.purity << ',' << mode.normal_share << ','
          << (from_checkpoint ? std::string("all") : std::to_string(m)) << ','
          << (from_checkpoint ? "all" : (odd ? "odd" : "even")) << ',' << mode.symmetry_share << '\n';
  }

  void
  StabilityScene::run()
  {
    set_up_base_state();
    measure_unperturbed_map();
    compute_spectrum();
  }

  void
  StabilityScene::set_up_base_state()
  {
    if (from_checkpoint)
      {
        Checkpoint checkpoint;
        checkpoint.initialize(checkpoint_directory + "/checkpoint/", communicator);
        checkpoint.set_resume_mode(Checkpoint::Resume::automatic);
        if (!checkpoint.find(pcout.get_stream()))
          throw_invalid_entry("stability/checkpoint directory",
                              checkpoint_directory,
                              "the output directory of a run of scene full with a usable checkpoint (its "
                              "subdirectory checkpoint/), run with the geometry and model of this file");
        const CheckpointData data = checkpoint.read();
        if (data.get_string("simulation/geometry") != geometry.description())
          throw_invalid_entry("stability/checkpoint directory",
                              checkpoint_directory,
                              "a run on this file's geometry ('" + geometry.description() + "'; the checkpoint has '" +
                                data.get_string("simulation/geometry") + "')");
        model.load(data);
        if (anchor_end_state)
          model.anchor();
        pcout << "-- the base state: " << checkpoint.last_slot() << ", t = " << data.get_double("time stepping/time")
              << std::endl;
      }
    else
      model.setup();
    axis   = model.initial_rotation_axis();
    centre = Point<3>(geometry.measure().centre_of_mass);
    base   = model.accepted_state();
    if (n_settling_steps > 0)
      {
        pcout << "-- settling: " << n_settling_steps << " steps of the unperturbed model" << std::endl;
        base = advanced(base, n_settling_steps, "the settling");
      }
    positions  = std::make_unique<NodalVectorField>(geometry.dof_handler(), 0, geometry.mapping());
    velocities = std::make_unique<NodalVectorField>(model.dof_handler(),
                                                    FluidDeformableSurface::velocity_component,
                                                    geometry.mapping());
  }

  void
  StabilityScene::measure_unperturbed_map()
  {
    const std::string start_up = model.step().flow_time_scheme().start_up(tau).description;
    pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ; the time-" << map_time
          << " map is " << n_steps << " steps of τ = " << tau << (start_up.empty() ? "" : " (" + start_up + ")")
          << std::endl;

    model.restart_from(base);
    base_normal                   = geometry.normal_field();
    base_end                        = advanced(base, n_steps, "the base state");
    const auto [turn, node_distance] = positions->fit_rotation(base.position, base_end.position, centre, base_normal);
    const double radius              = std::sqrt(base.target_area / (4 * numbers::PI));
    // The angle and axis of the nodes' turn: sin θ e = the axial vector of (Q − Qᵀ)/2, cos θ = (tr Q − 1)/2.
    const Tensor<1, 3> axial({0.5 * (turn[2][1] - turn[1][2]), 0.5 * (turn[0][2] - turn[2][0]),
                              0.5 * (turn[1][0] - turn[0][1])});
    const double       theta = std::atan2(axial.norm(), 0.5 * (trace(turn) - 1));
    if (from_checkpoint && axial.norm() > 1e-8)
      axis = axial / axial.norm(); // the end state turns about its own axis
    node_rotation_rate = (axial * axis < 0 ? -theta : theta) / map_time;
    double distance    = node_distance;
    if (from_checkpoint)
      {
        // The vectors of a perturbation turn with the body, whose nodes may slide: its turn from its shape.
        const auto [body_angle, shape_distance] = positions->fit_shape_rotation(
          base.position, base_end.position, centre, base_normal, axis, node_rotation_rate * map_time);
        body_rotation_rate = body_angle / map_time;
        distance           = shape_distance;
        RigidMotion turn_back;
        turn_back.rotation = -body_angle * axis;
        back_rotation      = turn_back.rotation_over(1.0);
      }
    else
      {
        body_rotation_rate = model.initial_angular_velocity();
        back_rotation      = transpose(turn);
      }
    const double drift = distance / (radius * map_time);
    pcout << "-- the unperturbed map: the nodes turn at " << std::setprecision(6) << node_rotation_rate
          << " about (" << axis << "), the body at " << body_rotation_rate << "; the shape moves beyond that at "
          << std::setprecision(2) << std::scientific << drift << " R per unit time" << std::defaultfloat << std::endl;
    if (!(drift <= equilibrium_tolerance))
      {
        std::ostringstream msg;
        msg << "the start is not an equilibrium of the discrete model: its surface moves beyond a rigid rotation at "
            << std::setprecision(3) << drift << " R per unit time, above 'stability/equilibrium tolerance' = "
            << equilibrium_tolerance;
        if (from_checkpoint)
          msg << " (its nodes turn at " << std::setprecision(4) << node_rotation_rate << ", the body at "
              << body_rotation_rate << ": nodes that slide along a curved surface count too)"
              << "; expected a steady state whose nodes turn with the body (a run that ends at its steady state, "
              << "with 'mesh redistribution/anchor time' before its end so that the membrane energy holds the nodes).";
        else
          msg << "; expected an equilibrium (geometry/shape = equilibrium with its ω, a finer "
              << "'geometry/refinement' or 'equilibrium/*' settings that converge).";
        throw EntryError(msg.str());
      }
  }

  void
  StabilityScene::compute_spectrum()
  {
    spectrum_file = output.directory() + "spectrum.csv";
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream csv(spectrum_file);
        csv << "m,parity,growth rate,frequency,multiplier modulus,multiplier argument,residual,purity,normal share,seed m,"
               "seed parity,symmetry share\n";
      }
    std::vector<std::string> unconverged;
    for (const unsigned int m : from_checkpoint ? std::vector<unsigned int>{0} : wavenumbers)
      for (const bool odd : from_checkpoint ? std::vector<bool>{false} : parities)
        {
          const std::vector<Mode> modes = arnoldi(m, odd);
          write_rows(m, odd, modes);
          for (const Mode &mode : modes)
            pcout << "      μ = " << std::setprecision(6) << mode.multiplier << ": σ = "
                  << std::log(std::abs(mode.multiplier)) / map_time << ", Ω = " << mode.frequency << ", m = " << mode.m
                  << (mode.odd ? " odd" : " even") << " (purity " << std::setprecision(3) << mode.purity
                  << ", normal share " << mode.normal_share << ", symmetry share " << mode.symmetry_share
                  << "), residual " << std::setprecision(2) << std::scientific
                  << mode.residual << std::defaultfloat
                  << std::endl;
          // The first reported mode that has not converged (the leading one; of an end state, any of the
          // reported). It still decays if σ plus the bound ln(1/(1 − r))/T on its error (r the relative residual)
          // is negative: the question which modes grow is answered.
          std::size_t first = 0;
          if (from_checkpoint)
            while (first + 1 < modes.size() && modes[first].residual < residual_tolerance)
              ++first;
          const double sigma_bound =
            modes.empty() || !(modes[first].residual < 0.5) ?
              std::numeric_limits<double>::infinity() :
              (std::log(std::abs(modes[first].multiplier)) - std::log(1 - modes[first].residual)) / map_time;
          const std::string which = first == 0 ? "the leading eigenvalue" : "eigenvalue " + std::to_string(first + 1);
          if (unconverged_leading && sigma_bound < 0)
            pcout << "    warning: " << which << " has not reached 'stability/residual tolerance' (residual "
                  << std::setprecision(2) << std::scientific << modes[first].residual << std::defaultfloat
                  << "), but decays: σ ≤ " << std::setprecision(3) << sigma_bound << std::endl;
          else if (unconverged_leading)
            {
              std::ostringstream entry;
              entry << (from_checkpoint ? std::string("the end state") :
                                          "m = " + std::to_string(m) + (odd ? " odd" : " even"))
                    << " (";
              if (modes.empty())
                entry << "no Ritz vector of this wavenumber and parity";
              else
                entry << which << ": residual " << std::setprecision(3) << modes[first].residual;
              entry << ", " << restarts_used << " restart" << (restarts_used == 1 ? "" : "s") << ")";
              unconverged.push_back(entry.str());
            }
        }
    pcout << "-- spectrum written to " << spectrum_file << std::endl;
    if (!unconverged.empty())
      {
        std::ostringstream msg;
        msg << "the spectrum of " << unconverged.front();
        for (unsigned int i = 1; i < unconverged.size(); ++i)
          msg << (i + 1 == unconverged.size() ? " and of " : ", of ") << unconverged[i];
        msg << " did not reach 'stability/residual tolerance' " << residual_tolerance
            << " at the maximum Krylov dimension " << max_krylov;
        throw RunFailed(msg.str(),
                        "all rows are in " + spectrum_file + " (column residual); raise 'stability/maximum Krylov "
                        "dimension', 'stability/maximum restarts' or 'stability/map time'");
      }
  }
} // namespace FluidSurface
