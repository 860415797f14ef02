// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/io/stop_signals.h>
#include <fluid_surface/scenes/full_model_scene.h>

#include <cmath>
#include <csignal>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace FluidSurface
{
  using namespace dealii;

  FullModelScene::FullModelScene(const MPI_Comm            communicator,
                                 SurfaceGeometry          &geometry,
                                 OutputWriter             &output,
                                 StatisticsFile           &statistics,
                                 const ConditionalOStream &pcout,
                                 const Timer              &wall_timer)
    : Scene(geometry, output, statistics, pcout)
    , communicator(communicator)
    , wall_timer(wall_timer)
    , computing_timer(this->pcout, TimerOutput::never, TimerOutput::wall_times)
    , model(geometry)
  {}

  ParametersRead
  FullModelScene::parameters_read() const
  {
    return {"scene full",
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
             "reparametrization",
             "linear solver",
             "time stepping",
             "steady state",
             "diagnostics",
             "checkpoint"},
            {}};
  }

  void
  FullModelScene::parse_parameters(ParameterHandler &prm)
  {
    time.parse_parameters(prm);
    energy_control = EnergyStepController(time.energy_tolerance(), time.energy_law_tolerance(), time.energy_law_action());
    model.parse_parameters(prm, time.maximum_step_size());
    model.step().set_error_estimation(time.error_control());
    // `energy law = retry` reads the bending defect of a step that breaks the law (StepController::attempt()).
    model.step().set_energy_budget(time.energy_budget() || time.energy_law_action() == "retry");
    model.set_time_scheme(time);
    diagnostics.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    steady_state.parse_parameters(prm);
    end_state_stability.parse_parameters(prm);
  }

  bool
  FullModelScene::find_checkpoint()
  {
    checkpoint.initialize(output.directory() + "checkpoint/", communicator);
    resuming = checkpoint.find(pcout.get_stream());
    return resuming;
  }

  void
  FullModelScene::run()
  {
    if (!resuming)
      {
        checkpoint.clear(); // those of an earlier run in the same directory
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          {
            std::filesystem::remove(output.directory() + "error.log");
            std::filesystem::remove(output.directory() + "energy_budget");
          }
      }
    model.step().set_timer(computing_timer);
    // The timing is written however the run ends (a failed run's timing shows where it spent its time),
    // and the factorization kept across steps is freed.
    struct TimingAtExit
    {
      FullModelScene &scene;
      ~TimingAtExit()
      {
        scene.model.step().solver().release_factorization();
        try
          {
            scene.write_timing();
          }
        catch (...)
          {}
      }
    } timing_at_exit{*this};

    if (resuming)
      resume_from_checkpoint();
    else
      set_up_initial_state();

    const StopSignals stop_signals(communicator);
    StepController    controller(model, time, pcout, output.directory(), communicator);
    controller.check_energy(energy_control);
    steps_this_run       = 0;
    last_checkpoint_step = resuming ? time.step_number() : numbers::invalid_unsigned_int;
    // A run that stops early still writes its summary, with the reason in its status line.
    try
      {
        while (time.before_end())
          if (!attempt_step(controller, stop_signals))
            break; // the steady state
      }
    catch (const RunStopped &stop)
      {
        write_summary_of_stopped_run(stop.what());
        throw;
      }
    catch (const RunFailed &failure)
      {
        write_summary_of_stopped_run(failure.reason());
        throw;
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &exc)
      {
        // Anything else (a failed write, a deal.II error): one line on the screen, the whole report in error.log.
        std::ostringstream reason;
        reason << "step " << time.step_number() + 1 << " failed at t = " << time.time() << ": "
               << one_line_message(exc, 200);
        log_error(reason.str() + '\n' + exc.what());
        write_summary_of_stopped_run(reason.str());
        throw RunFailed(reason.str(), "the report is in " + output.directory() + "error.log");
      }
    // A final checkpoint lets a finished run be extended (a later end time, resume = auto).
    if (checkpoint.enabled() && last_checkpoint_step != time.step_number())
      write_checkpoint();

    diagnostics.compare_with_mean_rotation(geometry);
    write_summary("completed");
  }

  bool
  FullModelScene::attempt_step(StepController &controller, const StopSignals &stop_signals)
  {
    const std::optional<StepController::AcceptedStep> step = controller.attempt(total_energy);
    if (!step)
      return true;
    willmore                                    = step->willmore;
    const SurfaceReparametrization::Jumps jumps = reparametrize_if_due();
    const Diagnostics::Values    values = record_step(step->tau, step->result, jumps);
    check_mesh_quality();
    anchor_if_rigid(values);
    const SteadyState::Verdict verdict = steady_state.assess(
      {time.time(), total_energy, {{values.eigenvalues[0], values.eigenvalues[1], values.eigenvalues[2]}}, 0},
      kinetic_energy_excess(values),
      step->tau,
      step->result.dissipation_rate);
    if (verdict != SteadyState::Verdict::running && end_state_stability.enabled() && leave_saddle(values))
      {
        checkpoint_or_stop(stop_signals.received());
        return true;
      }
    const bool ends = verdict != SteadyState::Verdict::running;
    if (output.due(time.time()) || !time.before_end() || ends)
      write_output();
    ++steps_this_run;
    if (ends)
      {
        std::ostringstream report;
        if (verdict == SteadyState::Verdict::reached)
          report << "reached at t = " << std::setprecision(8) << time.time() << ": " << steady_state.description();
        else
          report << "plateau at t = " << std::setprecision(8) << time.time()
                 << ", not an end state: F is flat only because the discretization supplies more than half of "
                    "what the flow dissipates (doc/scheme.md, \"The discrete energy law\"; a finer mesh shrinks it): "
                 << steady_state.description();
        steady_state_report = report.str();
        pcout << "-- steady state " << steady_state_report << std::endl;
        return false;
      }
    checkpoint_or_stop(stop_signals.received());
    return true;
  }

  bool
  FullModelScene::leave_saddle(const Diagnostics::Values &values)
  {
    EndStateStability::Measures state;
    state.area           = values.area;
    state.reduced_volume = values.reduced_volume;
    const double inverse_be = model.step().components().bending.inverse_bending_number();
    state.bending_number = inverse_be > 0 ? 1 / inverse_be : 1;
    for (unsigned int i = 0; i < 3; ++i)
      state.inertia[i] = values.eigenvalues[i];
    state.least_inertia_axis   = values.elongation_axis;
    state.largest_inertia_axis = values.largest_inertia_axis;
    state.angular_momentum     = values.angular_momentum;
    state.rotation_vector      = values.rotation_vector;
    state.total_energy         = total_energy;
    const EndStateStability::Assessment assessment = end_state_stability.assess(state);
    end_state_class = assessment.description;
    if (!assessment.saddle())
      return false;
    pcout << "-- t = " << time.time() << ": not an end state, " << assessment.description
          << "; the surface is displaced along m = " << assessment.m << (assessment.odd ? " odd" : " even")
          << " by " << end_state_stability.perturbation() << " and the run goes on" << std::endl;
    end_state_stability.record_saddle(time.time(), assessment);
    model.perturb_shape(AzimuthalHarmonic(assessment.axis, assessment.m, assessment.odd),
                        end_state_stability.perturbation());
    willmore        = geometry.willmore_energy();
    total_energy    = model.total_energy(model.kinetic_energy(), willmore);
    end_state_class = "";
    steady_state.restart_after_saddle();
    return true;
  }

  void
  FullModelScene::write_summary_of_stopped_run(const std::string &reason)
  {
    std::ostringstream status;
    status << "stopped at t = " << time.time() << ": " << reason;
    // Without the comparison of the final surface with the mean-rotation equilibrium: it is collective, and
    // a failure need not have reached every rank.
    try
      {
        write_summary(status.str());
      }
    catch (const std::exception &exc)
      {
        // The reason the run stopped matters more than its summary.
        pcout << "    warning: the summary could not be written (" << one_line_message(exc, 200) << ")" << std::endl;
      }
  }

  void
  FullModelScene::log_error(const std::string &text) const
  {
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      append_to_error_log(output.directory(), text);
  }

  void
  FullModelScene::set_up_initial_state()
  {
    model.setup();
    pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ"
          << (model.step().components().flow.inertia ? "" : " (Stokes limit: + 6 rigid-motion multipliers)") << std::endl;
    std::ostringstream report;
    diagnostics.set_reference(diagnostics.evaluate(geometry, model.dof_handler(), model.solution()),
                              model.step().components().bending.Be,
                              report);
    pcout << report.str() << std::flush;
    willmore = geometry.willmore_energy();
    record_step(0.0, SurfaceStep::Result());
    write_output();
  }

  void
  FullModelScene::resume_from_checkpoint()
  {
    const CheckpointData data = checkpoint.read();
    if (data.get_string("simulation/geometry") != geometry.description())
      throw EntryError("the checkpoint " + checkpoint.last_slot() + " was written for the geometry '" +
                       data.get_string("simulation/geometry") + "', the parameter file describes '" +
                       geometry.description() + "'; expected the geometry of the run to resume, or resume = false.");
    model.load(data);
    time.load(data);
    diagnostics.load(data);
    output.load(data, communicator);
    statistics.resume(output.directory() + "statistics", Utilities::MPI::this_mpi_process(communicator), data);
    total_energy = data.get_double("simulation/total energy");
    energy_control.load(data);
    steady_state.load(data);
    end_state_stability.load(data);
    wall_time_before_restart = data.get_double("simulation/wall time");
    flow_was_non_rigid       = data.has("simulation/flow was non-rigid");
    willmore                 = geometry.willmore_energy();
    // The restored fields must reproduce the energy recorded with them (to rounding: the rank count may differ).
    const double energy = model.total_energy(model.kinetic_energy(), willmore);
    if (!(std::abs(energy - total_energy) <= 1e-10 * std::abs(total_energy)))
      {
        std::ostringstream msg;
        msg << "the checkpoint " << checkpoint.last_slot() << " does not reproduce its total energy ("
            << std::setprecision(17) << total_energy << " recorded, " << energy << " from its fields)";
        throw std::runtime_error(msg.str());
      }
    std::ostringstream report;
    diagnostics.set_reference(diagnostics.initial_values(), model.step().components().bending.Be, report);
    pcout << "   " << model.dof_handler().n_dofs() << " unknowns (u, p, κ, y, Y) + γ"
          << (model.step().components().flow.inertia ? "" : " (Stokes limit: + 6 rigid-motion multipliers)") << '\n'
          << report.str() << "-- resumed from " << checkpoint.last_slot() << ": step " << time.step_number()
          << ", t = " << time.time() << std::endl;
  }

  double
  FullModelScene::kinetic_energy_excess(const Diagnostics::Values &v)
  {
    return v.kinetic_energy - v.angular_momentum.norm_square() / (2 * v.eigenvalues[2]);
  }

  void
  FullModelScene::anchor_if_rigid(const Diagnostics::Values &v)
  {
    const double epsilon   = model.step().components().redistribution.anchor_non_rigid_energy;
    const double non_rigid = (1 - v.rigid_fraction) * v.kinetic_energy; // F_kin − ½Ω·L
    if (epsilon == 0 || model.is_anchored())
      return;
    // Only once the flow has left a rigid start and come back to a rigid rotation: a run that starts rigid has its
    // transformation still ahead.
    if (non_rigid > epsilon * std::abs(total_energy))
      {
        flow_was_non_rigid = true;
        return;
      }
    if (!flow_was_non_rigid)
      return;
    model.anchor();
    pcout << "    mesh law anchored at t = " << std::setprecision(6) << time.time()
          << ": the body rotates rigidly (non-rigid kinetic energy "
          << std::setprecision(3) << non_rigid << " ≤ 'anchor non-rigid energy' · |F|)" << std::endl;
  }

  SurfaceReparametrization::Jumps
  FullModelScene::reparametrize_if_due()
  {
    SurfaceReparametrization &valve = model.safety_valve();
    if (!valve.enabled())
      return {{0, 0, 0, 0}};
    const double quality = geometry.measure().mesh_quality;
    if (!valve.due(quality))
      return {{0, 0, 0, 0}};
    TimerOutput::Scope section(computing_timer, "reparametrization");
    // F, A, V and L as the statistics measure them, before and after.
    const auto measures = [&]() {
      const Diagnostics::Values v = diagnostics.evaluate(geometry, model.dof_handler(), model.solution());
      return SurfaceReparametrization::Measures{
        model.total_energy(v.kinetic_energy, willmore), v.area, v.volume, v.angular_momentum};
    };
    const SurfaceReparametrization::Measures before = measures();
    const SurfaceReparametrization::Result   result = model.reparametrize();
    willmore                                        = geometry.willmore_energy();
    if (!result.done)
      {
        valve.record(result, quality, before, before);
        pcout << "    warning: the re-parametrization at step " << time.step_number() << ", t = " << time.time()
              << " failed (" << result.failure << "); the run goes on with the old mesh" << std::endl;
        return {{0, 0, 0, 0}};
      }
    const SurfaceReparametrization::Jumps jumps = valve.record(result, quality, before, measures());
    pcout << "-- mesh re-parametrized at step " << time.step_number() << ", t = " << std::setprecision(6)
          << time.time() << ": mesh quality " << std::setprecision(3) << result.quality_before << " -> "
          << result.quality_after << std::scientific << std::setprecision(2) << "; jumps ΔF/F = " << jumps[0]
          << ", ΔA/A = " << jumps[1] << ", ΔV/V = " << jumps[2] << ", ΔL/L = " << jumps[3] << std::defaultfloat
          << std::endl;
    return jumps;
  }

  Diagnostics::Values
  FullModelScene::record_step(const double                              tau,
                              const SurfaceStep::Result &step,
                              const SurfaceReparametrization::Jumps    &jumps)
  {
    TimerOutput::Scope        section(computing_timer, "diagnostics");
    const Diagnostics::Values v = diagnostics.evaluate(geometry, model.dof_handler(), model.solution());
    diagnostics.record(v, time.time(), tau);
    const double bending_energy = model.step().components().bending.energy(willmore);
    total_energy                = model.total_energy(v.kinetic_energy, willmore);

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
    // Written with the lagged step too (zeros), so that a run can be resumed with the other setting.
    statistics.add_value("geometry iterations", step.geometry_iterations);
    statistics.add_value("geometry change", step.geometry_change);
    model.safety_valve().add_to_statistics(statistics, jumps);
    statistics.add_value("wall time", elapsed_wall_time());
    statistics.end_row();
    if (time.energy_budget())
      write_energy_budget(tau, step, model.step().components().flow.inertia ? v.kinetic_energy : 0.0, bending_energy);

    if (time.step_number() % output.screen_interval() == 0 || !time.before_end())
      {
        const double elapsed  = elapsed_wall_time();
        const double per_step = time.step_number() > 0 ? elapsed / time.step_number() : 0.0;
        const double eta      = time.time() > 0 ? elapsed * (time.final_time() - time.time()) / time.time() : 0.0;
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
        if (model.step().components().geometry_iteration.enabled())
          pcout << "    geometry iterations " << step.geometry_iterations << ", last node move " << std::setprecision(2)
                << std::scientific << step.geometry_change << " h" << std::defaultfloat << '\n';
        if (output.report_wall_time())
          pcout << "    " << std::setprecision(3) << per_step << " s/step, ETA " << static_cast<long>(eta) << " s to t = "
                << time.final_time() << (steady_state.enabled() ? " (a steady state, which cannot be foreseen, ends it earlier)\n" : "\n");
        pcout << std::flush;
      }
    return v;
  }

  void
  FullModelScene::write_energy_budget(const double               tau,
                                      const SurfaceStep::Result &step,
                                      const double               kinetic,
                                      const double               bending) const
  {
    const SurfaceStep::Result::EnergyBudget &b = step.energy_budget;
    if (Utilities::MPI::this_mpi_process(communicator) != 0 || !std::isfinite(b.bending_power))
      return;
    const std::string name     = output.directory() + "energy_budget";
    const bool        new_file = !std::filesystem::exists(name);
    std::ofstream     file(name, std::ios::app);
    if (new_file)
      {
        // A resumed run appends from its checkpoint on: a step may appear twice, the later row is the run's.
        const char *columns[] = {"time step",
                                 "time",
                                 "tau",
                                 "dissipation rate",
                                 "bending energy at the start",
                                 "kinetic energy at the start",
                                 "bending force power",
                                 "multiplier power",
                                 "bending energy of the solve",
                                 "kinetic energy of the solve",
                                 "kinetic energy after the area and volume projection",
                                 "bending energy",
                                 "kinetic energy"};
        for (unsigned int c = 0; c < std::size(columns); ++c)
          file << "# " << c + 1 << ": " << columns[c] << '\n';
      }
    file << std::setprecision(12) << time.step_number() << ' ' << time.time() << ' ' << tau << ' '
         << step.dissipation_rate << ' ' << b.bending_start << ' ' << b.kinetic_start << ' ' << b.bending_power << ' ' << b.multiplier_power << ' '
         << b.bending_solved << ' ' << b.kinetic_solved << ' ' << b.kinetic_projected << ' ' << bending << ' '
         << kinetic << '\n';
  }

  void
  FullModelScene::check_mesh_quality() const
  {
    const double quality = geometry.measure().mesh_quality;
    if (quality < model.step().components().redistribution.mesh_quality_floor)
      {
        std::ostringstream msg;
        msg << "mesh quality " << quality << " fell below the 'mesh quality floor' " << model.step().components().redistribution.mesh_quality_floor
            << " at step " << time.step_number() << ", t = " << time.time();
        throw RunFailed(msg.str(),
                        "the output up to the previous step, the summary and the last checkpoint are intact; a "
                        "finer 'geometry/refinement' keeps the cells less distorted, a lower 'mesh "
                        "redistribution/mesh quality floor' lets the run go on");
      }
  }

  void
  FullModelScene::write_output()
  {
    TimerOutput::Scope section(computing_timer, "output");
    output.write(geometry, time.time(), [&](DataOut<2, 3> &data_out) { model.add_output_fields(data_out); });
  }

  bool
  FullModelScene::write_checkpoint()
  {
    CheckpointData data;
    data.set("simulation/geometry", geometry.description());
    data.set("simulation/total energy", total_energy);
    energy_control.save(data);
    steady_state.save(data);
    end_state_stability.save(data);
    data.set("simulation/wall time", elapsed_wall_time());
    if (flow_was_non_rigid)
      data.set("simulation/flow was non-rigid", 1u);
    model.save(data);
    time.save(data);
    diagnostics.save(data);
    output.save(data);
    statistics.save(data);
    return checkpoint.write(data, time.step_number(), time.time(), pcout.get_stream());
  }

  void
  FullModelScene::checkpoint_or_stop(const int signal)
  {
    const bool stop = time.before_end() && (signal != 0 || (checkpoint.steps_per_run() > 0 &&
                                                            steps_this_run >= checkpoint.steps_per_run()));
    bool       written = false;
    if (stop || (checkpoint.enabled() && checkpoint.due(time.step_number())))
      {
        written = write_checkpoint();
        if (written)
          last_checkpoint_step = time.step_number();
        // A resumed run starts without the factorization kept across steps and without the last solution;
        // dropping both here too makes the step after a checkpoint factorize and start GMRES (with
        // single-precision factors a solve is GMRES also right after a factorization) from the same guess in
        // both, so that they agree bit for bit.
        model.step().solver().release_factorization();
        model.step().solver().forget_last_solution();
      }
    if (!stop)
      return;
    std::ostringstream msg;
    msg << (signal == SIGINT ? "interrupted (SIGINT)" : signal != 0 ? "terminated (SIGTERM)" :
                                                                       "stopped after 'steps per run'")
        << " at step " << time.step_number() << ", t = " << time.time() << "; ";
    if (written)
      msg << "checkpoint written to " << checkpoint.last_slot()
          << "; continue with 'set resume = auto' in subsection checkpoint";
    else
      msg << "the checkpoint could not be written"
          << (checkpoint.last_slot().empty() ? std::string() : "; the last good one is " + checkpoint.last_slot());
    throw RunStopped(msg.str(), signal != 0 ? 128 + signal : (written ? 0 : 1));
  }

  void
  FullModelScene::write_summary(const std::string &status) const
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ostringstream text;
    text << "status: " << status << '\n';
    diagnostics.write_summary(text, total_energy, time.step_number(), time.n_rejected_steps(), elapsed_wall_time());
    energy_control.write_summary(text);
    if (steady_state.enabled())
      text << "steady state: " << (steady_state_report.empty() ? "not reached" : steady_state_report) << '\n';
    if (steady_state.enabled() && end_state_stability.enabled())
      {
        text << "saddles left: " << end_state_stability.saddles_left() << '\n';
        if (!end_state_class.empty())
          text << "end state class: " << end_state_class << '\n';
      }
    model.safety_valve().write_summary(text);
    text << "LU factorizations: " << model.step().solver().n_factorizations() << '\n';
    {
      std::ofstream summary(output.directory() + "summary.tmp");
      summary << text.str();
    }
    std::filesystem::rename(output.directory() + "summary.tmp", output.directory() + "summary");
    std::istringstream lines(text.str());
    pcout << "--- summary\n";
    for (std::string line; std::getline(lines, line);)
      if (output.report_wall_time() || line.rfind("wall time", 0) != 0)
        pcout << line << '\n';
    pcout << std::flush;
  }

  void
  FullModelScene::write_timing()
  {
    const auto   wall  = computing_timer.get_summary_data(TimerOutput::total_wall_time);
    const auto   calls = computing_timer.get_summary_data(TimerOutput::n_calls);
    const double total = wall_timer.wall_time();
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream file(output.directory() + "timing");
        file << "# section, calls, wall time [s], share of the run, wall time per accepted step [s]\n"
             << "# run: " << total << " s, " << time.step_number() << " accepted steps, " << time.n_rejected_steps()
             << " rejected, " << model.step().solver().n_factorizations() << " LU factorizations\n";
        for (const auto &entry : wall)
          file << '"' << entry.first << "\", " << calls.at(entry.first) << ", " << entry.second << ", "
               << entry.second / total << ", " << entry.second / std::max(1u, time.step_number()) << '\n';
      }
    if (output.report_wall_time())
      {
        pcout << "--- wall time per section (" << std::setprecision(4) << total / std::max(1u, time.step_number())
              << " s per accepted step, " << model.step().solver().n_factorizations() << " LU factorizations in "
              << time.step_number() + time.n_rejected_steps() << " step attempts)\n";
        computing_timer.print_summary();
      }
  }
} // namespace FluidSurface
