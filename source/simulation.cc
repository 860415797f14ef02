#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fluid_surface/parameter_file.h>
#include <fluid_surface/simulation.h>

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
    FixedSurfaceScene::declare_parameters(prm);
    SurfaceGeometry::declare_parameters(prm);
    OutputWriter::declare_parameters(prm);
    TimeStepper::declare_parameters(prm);
    FluidDeformableSurface::declare_parameters(prm);
    Diagnostics::declare_parameters(prm);
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
    output.prepare_directory(communicator, false);
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

    statistics.open(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator));
    if (scene == Scene::geometry)
      {
        record_geometry_statistics(0, 0.0);
        output.write(geometry, 0.0);
      }
    else if (scene == Scene::fixed_surface)
      fixed_surface_scene.run(geometry, output, statistics, pcout);
    else
      run_full_model();
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
    statistics.add_value("wall time", wall_timer.wall_time());
    statistics.end_row();

    if (time.step_number() % output.screen_interval() == 0 || !time.before_end())
      {
        const double elapsed = wall_timer.wall_time();
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
        if (output.report_wall_time())
          pcout << "    " << std::setprecision(3) << per_step << " s/step, ETA " << static_cast<long>(eta) << " s\n";
        pcout << std::flush;
      }
  }

  void
  Simulation::run_full_model()
  {
    model.setup();
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
    pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ"
          << (model.has_inertia() ? "" : " (Stokes limit: + 6 rigid-motion multipliers)") << std::endl;
    double willmore = geometry.compute_curvature();
    record_full_model_step(0.0, willmore, FluidDeformableSurface::StepResult());
    {
      TimerOutput::Scope section(computing_timer, "output");
      output.write(geometry, time.time(), [&](DataOut<2, 3> &data_out) { model.add_output_fields(data_out); });
    }

    double       previous_rate  = 0;
    double       tau_before_rejections = 0;
    unsigned int n_energy_rises = 0;
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
      }

    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream summary(output.directory() + "summary");
        diagnostics.write_summary(summary, total_energy, time.step_number(), time.n_rejected_steps(),
                                  wall_timer.wall_time());
        summary << "energy rises accepted: " << n_energy_rises << '\n';
        summary << "LU factorizations: " << model.n_factorizations() << '\n';
        std::ostringstream text;
        diagnostics.write_summary(text, total_energy, time.step_number(), time.n_rejected_steps(),
                                  wall_timer.wall_time());
        text << "energy rises accepted: " << n_energy_rises << '\n';
        text << "LU factorizations: " << model.n_factorizations() << '\n';
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
