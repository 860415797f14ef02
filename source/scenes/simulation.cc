#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/linear_algebra/reused_factorization_solver.h>
#include <fluid_surface/scenes/simulation.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iomanip>

namespace FluidSurface
{
  using namespace dealii;

  Simulation::Simulation(const MPI_Comm communicator)
    : communicator(communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    , computing_timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , geometry(communicator)
    , model(geometry)
  {}

  void
  Simulation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("model");
    prm.declare_entry("scene",
                      "geometry",
                      Patterns::Selection("geometry|fixed surface|full"),
                      "What the run computes. geometry: build the surface, measure it (area, volume, "
                      "reduced volume, Willmore energy ½∫H²) and write it; no time steps. fixed surface: surface "
                      "(Navier–)Stokes on the frozen surface, the verification problems of subsection fixed "
                      "surface (no geometry update, bending or volume multiplier). full: the fluid "
                      "deformable surface (surface Navier–Stokes, bending, volume constraint, mesh "
                      "redistribution) on the moving surface.");
    prm.leave_subsection();
    SurfaceFlow::declare_parameters(prm);
    ReusedFactorizationSolver::declare_parameters(prm);
    FixedSurfaceScene::declare_parameters(prm);
    SurfaceGeometry::declare_parameters(prm);
    OutputWriter::declare_parameters(prm);
    TimeStepper::declare_parameters(prm);
    FluidDeformableSurface::declare_parameters(prm);
    Diagnostics::declare_parameters(prm);
    Checkpoint::declare_parameters(prm);
  }

  void
  Simulation::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("model");
    const std::string name = prm.get("scene");
    scene = (name == "full" ? Scene::full : name == "fixed surface" ? Scene::fixed_surface : Scene::geometry);
    prm.leave_subsection();
    geometry.parse_parameters(prm);
    output.parse_parameters(prm);
    if (scene == Scene::fixed_surface)
      fixed_surface_scene.parse_parameters(prm);
    if (scene == Scene::full)
      {
        time.parse_parameters(prm);
        model.parse_parameters(prm);
        diagnostics.parse_parameters(prm);
      }
    checkpoint.parse_parameters(prm);
    if (scene != Scene::full && checkpoint.resume_mode() == Checkpoint::Resume::yes)
      throw_invalid_entry("checkpoint/resume", "true", "false or auto: only scene full writes checkpoints");
  }

  void
  Simulation::record_geometry_statistics(const unsigned int step, const double time)
  {
    const SurfaceGeometry::Measures m       = geometry.measure();
    const double                    willmore = geometry.compute_curvature();
    statistics.add_value("time step", step);
    statistics.add_value("time", time);
    statistics.add_value("bending energy", willmore);
    statistics.add_value("area", m.area);
    statistics.add_value("volume", m.volume);
    statistics.add_value("reduced volume", m.reduced_volume);
    statistics.add_value("mesh quality", m.mesh_quality);
    statistics.add_value("wall time", wall_timer.wall_time());
    statistics.end_row();

    pcout << "*** Step " << step << "  t = " << time << '\n'
          << std::setprecision(10) << "    area = " << m.area << "  volume = " << m.volume
          << "  reduced volume = " << m.reduced_volume << '\n'
          << "    Willmore energy ½∫H² = " << willmore << "  mesh quality = " << std::setprecision(4)
          << m.mesh_quality << std::endl;
  }

  void
  Simulation::run(const ParameterHandler &prm)
  {
    wall_timer.restart();
    wall_time_before_restart = 0;
    bool resuming            = false;
    if (scene == Scene::full)
      {
        checkpoint.initialize(output.directory() + "checkpoint/", communicator);
        resuming = checkpoint.find(std::cout);
      }
    output.prepare_directory(communicator, resuming);
    if (scene == Scene::full && !resuming)
      checkpoint.clear();
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream used(output.directory() + "used_parameters.prm");
        prm.print_parameters(used, ParameterHandler::PRM);
      }

    geometry.create();
    pcout << "-- fluid_surface: " << geometry.description() << '\n'
          << "   " << geometry.triangulation().n_global_active_cells() << " cells, "
          << geometry.dof_handler().n_dofs() << " position DoFs, "
          << Utilities::MPI::n_mpi_processes(communicator) << " MPI rank(s)" << std::endl;

    if (!resuming)
      statistics.open(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator));
    if (scene == Scene::geometry)
      {
        record_geometry_statistics(0, 0.0);
        output.write(geometry, 0.0);
      }
    else if (scene == Scene::fixed_surface)
      fixed_surface_scene.run(geometry, output, statistics, pcout);
    else
      run_full_model(resuming);
  }

  void
  Simulation::record_full_model_step(const double                              tau,
                                     const double                              willmore,
                                     const FluidDeformableSurface::StepResult &step)
  {
    TimerOutput::Scope        section(computing_timer, "diagnostics");
    const Diagnostics::Values v = diagnostics.evaluate(geometry, model.dof_handler(), model.solution());
    diagnostics.record(v, time.time(), tau);
    const double bending_energy = model.bending_energy(willmore);
    // The Stokes limit has no kinetic energy: F is the bending energy alone.
    total_energy = (model.has_inertia() ? v.kinetic_energy : 0.0) + bending_energy;

    statistics.add_value("time step", time.step_number());
    statistics.add_value("time", time.time());
    statistics.add_value("tau", tau);
    statistics.add_value("kinetic energy", v.kinetic_energy);
    statistics.add_value("bending energy", bending_energy);
    statistics.add_value("total energy", total_energy);
    statistics.add_value("dissipation rate", step.dissipation_rate);
    diagnostics.add_to_statistics(v, statistics);
    statistics.add_value("volume multiplier", step.gamma);
    statistics.add_value("linear iterations", step.linear_iterations);
    statistics.add_value("factorized", step.factorized ? 1 : 0);
    statistics.add_value("rigid multiplier", step.rigid_force);
    statistics.add_value("wall time", elapsed_wall_time());
    statistics.end_row();

    if (time.step_number() % output.screen_interval() == 0 || !time.before_end())
      {
        const double elapsed = elapsed_wall_time();
        const double per_step = time.step_number() > 0 ? elapsed / time.step_number() : 0.0;
        const double eta =
          time.time() > 0 ? elapsed * (time.final_time() - time.time()) / time.time() : 0.0;
        pcout << "*** Step " << time.step_number() << "  t = " << std::setprecision(5) << time.time()
              << "  τ = " << std::setprecision(3) << tau << "  (" << time.n_rejected_steps() << " rejected so far)\n"
              << std::setprecision(8) << "    F = " << total_energy << " (kin " << v.kinetic_energy << ", bend "
              << bending_energy << ")  ω = " << std::setprecision(5) << v.angular_velocity
              << "  |∫u| = " << v.linear_momentum.norm() << '\n'
              << std::setprecision(2) << std::scientific << "    ΔA/A = " << diagnostics.max_area_drift()
              << "  ΔV/V = " << diagnostics.max_volume_drift()
              << "  ΔL/L = " << diagnostics.max_angular_momentum_drift() << "  e(λ) = " << v.symmetry_deviation
              << "  mesh quality " << std::fixed << v.mesh_quality << std::defaultfloat << '\n';
        if (diagnostics.reference() != nullptr)
          pcout << std::setprecision(3) << std::scientific << "    E(L2) = " << v.l2_distance << " (axial "
                << v.l2_distance_axial << ", equatorial " << v.l2_distance_equatorial << ")" << std::defaultfloat
                << '\n';
        if (output.report_wall_time())
          pcout << "    " << std::setprecision(3) << per_step << " s/step, ETA " << static_cast<long>(eta) << " s\n";
        pcout << std::flush;
      }
  }

  void
  Simulation::run_full_model(const bool resuming)
  {
    model.set_timer(computing_timer);
    // The timing is written however the run ends (a failed run's timing shows where it spent its time),
    // and the factorization kept across steps is freed.
    struct TimingAtExit
    {
      Simulation &simulation;
      ~TimingAtExit()
      {
        simulation.model.release_factorization();
        try
          {
            simulation.write_timing();
          }
        catch (...)
          {}
      }
    } timing_at_exit{*this};
    double       previous_rate  = 0;
    double       tau_before_rejections = 0;
    unsigned int n_energy_rises = 0;
    // Accepted steps on which F rose at all (within the tolerance), and their largest relative rate rise/(τ|F|).
    unsigned int n_rising_steps = 0;
    double       max_rise_rate  = 0;
    double       willmore       = 0;
    if (resuming)
      {
        const CheckpointData data = checkpoint.read();
        if (data.get_string("simulation/geometry") != geometry.description())
          throw InputError((parameter_file_name().empty() ? std::string("parameters") : parameter_file_name()) +
                           ": the checkpoint " + checkpoint.last_slot() +
                           " was written for the geometry '" + data.get_string("simulation/geometry") +
                           "', the parameter file describes '" + geometry.description() +
                           "'; expected the geometry of the run to resume, or resume = false.");
        model.load(data);
        time.load(data);
        diagnostics.load(data);
        output.load(data, communicator);
        statistics.resume(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator), data);
        total_energy             = data.get_double("simulation/total energy");
        previous_rate            = data.get_double("simulation/previous rate");
        tau_before_rejections    = data.get_double("simulation/tau before rejections");
        n_energy_rises           = data.get_unsigned("simulation/energy rises");
        n_rising_steps           = data.get_unsigned("simulation/rising steps");
        max_rise_rate            = data.get_double("simulation/max rise rate");
        wall_time_before_restart = data.get_double("simulation/wall time");
        willmore                 = geometry.compute_curvature();
        // The restored fields must reproduce the energy recorded with them (to rounding: the rank count may differ).
        const double energy = model.kinetic_energy() + model.bending_energy(willmore);
        if (!(std::abs(energy - total_energy) <= 1e-10 * std::abs(total_energy)))
          {
            std::ostringstream msg;
            msg << "the checkpoint " << checkpoint.last_slot() << " does not reproduce its total energy ("
                << std::setprecision(17) << total_energy << " recorded, " << energy << " from its fields)";
            throw std::runtime_error(msg.str());
          }
        std::ostringstream report;
        diagnostics.set_reference(diagnostics.initial_values(), model.bending_number(), report);
        pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ"
              << (model.has_inertia() ? "" : " (Stokes limit: + 6 rigid-motion multipliers)") << '\n'
              << report.str() << "-- resumed from " << checkpoint.last_slot() << ": step " << time.step_number()
              << ", t = " << time.time() << std::endl;
      }
    else
      {
        model.setup();
        pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ"
              << (model.has_inertia() ? "" : " (Stokes limit: + 6 rigid-motion multipliers)") << std::endl;
        std::ostringstream report;
        diagnostics.set_reference(diagnostics.evaluate(geometry, model.dof_handler(), model.solution()),
                                  model.bending_number(),
                                  report);
        pcout << report.str() << std::flush;
        willmore = geometry.compute_curvature();
        record_full_model_step(0.0, willmore, FluidDeformableSurface::StepResult());
        TimerOutput::Scope section(computing_timer, "output");
        output.write(geometry, time.time(), [&](DataOut<2, 3> &data_out) { model.add_output_fields(data_out); });
      }

    // Everything a resumed run needs to continue bit for bit.
    auto write_checkpoint = [&]() {
      CheckpointData data;
      data.set("simulation/geometry", geometry.description());
      data.set("simulation/total energy", total_energy);
      data.set("simulation/previous rate", previous_rate);
      data.set("simulation/tau before rejections", tau_before_rejections);
      data.set("simulation/energy rises", n_energy_rises);
      data.set("simulation/rising steps", n_rising_steps);
      data.set("simulation/max rise rate", max_rise_rate);
      data.set("simulation/wall time", elapsed_wall_time());
      model.save(data);
      time.save(data);
      diagnostics.save(data);
      output.save(data);
      statistics.save(data);
      return checkpoint.write(data, time.step_number(), time.time(), std::cout);
    };
    // SIGINT/SIGTERM only set a flag while the loop runs; the defaults come back however it ends.
    struct SignalScope
    {
      SignalScope()
      {
        Checkpoint::install_signal_handlers();
      }
      ~SignalScope()
      {
        Checkpoint::remove_signal_handlers();
      }
    } signal_scope;

    unsigned int steps_this_run       = 0;
    unsigned int last_checkpoint_step = resuming ? time.step_number() : numbers::invalid_unsigned_int;
    while (time.before_end())
      {
        const double                             tau  = time.step_size();
        const FluidDeformableSurface::StepResult step = model.advance(tau);
        if (!step.solved)
          {
            model.restore_last_state();
            time.reject(step.failure);
            continue;
          }
        computing_timer.enter_subsection("curvature and energy");
        const double new_willmore = geometry.compute_curvature();
        const double new_energy =
          (model.has_inertia() ? model.kinetic_energy(model.candidate_solution()) : 0.0) +
          model.bending_energy(new_willmore);
        computing_timer.leave_subsection("curvature and energy");
        const double rise = new_energy - total_energy;
        if (!time.energy_acceptable(total_energy, new_energy, tau))
          {
            // A rise whose rate rise/τ does not fall when τ is halved is a space-discretization
            // effect that no step size removes: accept it and count it, unless it exceeds 1e-3 F
            // in one step (then the run stops once τ < τ_min).
            const double rate = rise / tau;
            if (!(std::isfinite(rise) && previous_rate > 0 && rate > 0.5 * previous_rate &&
                  rise < 1e-3 * std::abs(total_energy)))
              {
                if (previous_rate == 0)
                  tau_before_rejections = tau;
                previous_rate = rate;
                model.restore_last_state();
                std::ostringstream reason;
                reason << "energy " << std::setprecision(10) << total_energy << " → " << new_energy;
                time.reject(reason.str());
                continue;
              }
            ++n_energy_rises;
            pcout << "    warning: energy rose by " << std::setprecision(3) << rise << " at t = " << time.time()
                  << " at a rate that does not fall with τ (space discretization); step accepted" << std::endl;
            time.set_step_size(tau_before_rejections);
          }
        else if (previous_rate > 0 && rise > 0 && rise / tau > 0.5 * previous_rate)
          // The retry after a rejection passed, but its rise rate rise/τ hardly fell with τ: the rejection
          // did not remove a time-step error, so τ returns to its value before the rejections (otherwise
          // a steady rise rate just below the tolerance shrinks τ towards τ_min, one rejection at a time).
          time.set_step_size(tau_before_rejections);
        previous_rate = 0;
        if (rise > 1e-11 * std::abs(total_energy)) // above the rounding of F
          {
            ++n_rising_steps;
            max_rise_rate = std::max(max_rise_rate, rise / (tau * std::abs(total_energy)));
          }
        model.accept();
        time.accept(tau);
        willmore = new_willmore;
        record_full_model_step(tau, willmore, step);
        const double quality = geometry.measure().mesh_quality;
        if (quality < model.mesh_quality_floor())
          {
            std::ostringstream msg;
            msg << "mesh quality " << quality << " fell below the 'mesh quality floor' "
                << model.mesh_quality_floor() << " at t = " << time.time()
                << "; the output up to the previous step is intact";
            throw std::runtime_error(msg.str());
          }
        if (output.due(time.time()) || !time.before_end())
          {
            TimerOutput::Scope section(computing_timer, "output");
            output.write(geometry, time.time(), [&](DataOut<2, 3> &data_out) { model.add_output_fields(data_out); });
          }

        ++steps_this_run;
        const int  signal = checkpoint.received_signal();
        const bool stop   = time.before_end() && (signal != 0 || (checkpoint.steps_per_run() > 0 &&
                                                                  steps_this_run >= checkpoint.steps_per_run()));
        bool written = false;
        if (stop || (checkpoint.enabled() && checkpoint.due(time.step_number())))
          {
            written = write_checkpoint();
            if (written)
              last_checkpoint_step = time.step_number();
            // A resumed run starts without the factorization kept across steps; dropping it here too
            // makes the step after a checkpoint factorize in both, so that they agree bit for bit.
            model.release_factorization();
          }
        if (stop)
          {
            std::ostringstream msg;
            msg << (signal == SIGINT ? "interrupted (SIGINT)" : signal != 0 ? "terminated (SIGTERM)" :
                                                                               "stopped after 'steps per run'")
                << " at step " << time.step_number() << ", t = " << time.time() << "; ";
            if (written)
              msg << "checkpoint written to " << checkpoint.last_slot()
                  << "; continue with 'set resume = auto' in subsection checkpoint";
            else
              msg << "the checkpoint could not be written"
                  << (checkpoint.last_slot().empty() ? std::string() :
                                                       "; the last good one is " + checkpoint.last_slot());
            throw RunStopped(msg.str(), signal != 0 ? 128 + signal : (written ? 0 : 1));
          }
      }
    // A final checkpoint lets a finished run be extended (a later end time, resume = auto).
    if (checkpoint.enabled() && last_checkpoint_step != time.step_number())
      write_checkpoint();

    diagnostics.compare_with_mean_rotation(geometry);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ostringstream text;
        diagnostics.write_summary(text, total_energy, time.step_number(), time.n_rejected_steps(),
                                  elapsed_wall_time());
        text << "energy rises accepted: " << n_energy_rises << '\n';
        text << "steps with rising energy: " << n_rising_steps << '\n';
        text << "max relative energy rise rate: " << std::setprecision(3) << max_rise_rate << '\n';
        text << "LU factorizations: " << model.n_factorizations() << '\n';
        {
          std::ofstream summary(output.directory() + "summary.tmp");
          summary << text.str();
        }
        std::filesystem::rename(output.directory() + "summary.tmp", output.directory() + "summary");
        std::istringstream lines(text.str());
        std::cout << "--- summary\n";
        for (std::string line; std::getline(lines, line);)
          if (output.report_wall_time() || line.rfind("wall time", 0) != 0)
            std::cout << line << '\n';
        std::cout << std::flush;
      }
  }

  void
  Simulation::write_timing()
  {
    const auto wall  = computing_timer.get_summary_data(TimerOutput::total_wall_time);
    const auto calls = computing_timer.get_summary_data(TimerOutput::n_calls);
    const double total = wall_timer.wall_time();
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream file(output.directory() + "timing");
        file << "# section, calls, wall time [s], share of the run, wall time per accepted step [s]\n"
             << "# run: " << total << " s, " << time.step_number() << " accepted steps, "
             << time.n_rejected_steps() << " rejected, " << model.n_factorizations() << " LU factorizations\n";
        for (const auto &entry : wall)
          file << '"' << entry.first << "\", " << calls.at(entry.first) << ", " << entry.second << ", "
               << entry.second / total << ", " << entry.second / std::max(1u, time.step_number()) << '\n';
      }
    if (output.report_wall_time())
      {
        pcout << "--- wall time per section (" << std::setprecision(4) << total / std::max(1u, time.step_number())
              << " s per accepted step, " << model.n_factorizations() << " LU factorizations in "
              << time.step_number() + time.n_rejected_steps() << " step attempts)\n";
        computing_timer.print_summary();
      }
  }
} // namespace FluidSurface
