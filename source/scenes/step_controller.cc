// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/scenes/step_controller.h>

#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  StepController::StepController(FluidDeformableSurface   &model,
                                 TimeStepper              &time,
                                 const ConditionalOStream &pcout,
                                 const std::string        &output_directory,
                                 const MPI_Comm            communicator)
    : model(model)
    , time(time)
    , pcout(pcout)
    , output_directory(output_directory)
    , communicator(communicator)
  {}

  std::optional<StepController::AcceptedStep>
  StepController::attempt(const double energy)
  {
    AcceptedStep step;
    step.tau    = time.step_size();
    step.result = model.advance(step.tau);
    if (!step.result.solved)
      {
        retry(step.tau, step.result.failure, step.result.message, step.result.failure_details);
        return std::nullopt;
      }
    if (time.error_control() && step.result.error_estimate > time.error_bound())
      {
        std::ostringstream reason;
        reason << "local error estimate " << std::setprecision(3) << step.result.error_estimate
               << " above 'error tolerance' " << time.error_bound();
        retry(step.tau,
              StepFailure::error_estimate,
              reason.str(),
              "",
              std::max(0.2, time.error_step_factor(step.result.error_estimate)));
        return std::nullopt;
      }
    EnergyStepController::Decision decision;
    if (energy_control)
      {
        const FluidDeformableSurface::Energies candidate = model.candidate_energies();
        step.willmore                                    = candidate.willmore;
        step.total_energy                                = candidate.total;
        decision = energy_control->decide(energy, step.total_energy, step.tau, step.result.dissipation_rate);
      }
    if (decision.verdict == EnergyStepController::Verdict::stop)
      {
        model.restore_last_state();
        std::ostringstream reason;
        reason << "step at t = " << time.time() << " with τ = " << step.tau << " broke the energy law: " << decision.reason;
        throw RunFailed(reason.str(),
                        "refine the mesh (geometry/refinement), or set 'time stepping/energy law' = retry to accept and "
                        "count such steps; the output up to the last accepted step, the summary and the last "
                        "checkpoint are intact");
      }
    if (decision.verdict == EnergyStepController::Verdict::reject)
      {
        // The bending defect: the discrete W changed by more than the bending force's work. Where it is most of
        // the rise of F + ∫D, the tangential node motion of the mesh law put the energy in, at a rate that no τ
        // removes (doc/scheme.md, "The discrete energy law"): with `energy law = retry` the step is retried with
        // the mesh law slowed down, before any other remedy.
        const SurfaceStep::Result::EnergyBudget &budget = step.result.energy_budget;
        const double bending_defect = budget.bending_solved - budget.bending_start + step.tau * budget.bending_power;
        bool slowed = false;
        if (energy_control->wants_mesh_slowdown(bending_defect, step.tau, decision.law_rise))
          {
            slowed = model.step().slow_down_mesh_law();
            if (!slowed)
              energy_control->forget_mesh_slowdown();
          }
        if (slowed)
          {
            model.restore_last_state();
            time.repeat_step();
            energy_control->forget_rejection();
            pcout << "    step rejected (" << decision.reason << ", bending defect " << std::setprecision(3)
                  << bending_defect << "); retried at the same τ with the mesh law slowed down "
                  << model.step().mesh_law_slowdown() << "-fold" << std::endl;
          }
        else if (decision.law_only)
          retry(step.tau, StepFailure::energy_rise, decision.reason, "");
        else if (model.step().start_corrected_steps())
          {
            model.restore_last_state();
            time.repeat_step();
            energy_control->forget_rejection();
            pcout << "    step rejected (" << decision.reason << "); retried at the same τ with the iterated geometry"
                  << std::endl;
          }
        else if (model.step().fall_back_to_backward_euler(time.backward_euler_steps_after_rejection()))
          {
            model.restore_last_state();
            time.repeat_step();
            energy_control->forget_rejection();
            pcout << "    step rejected (" << decision.reason << "); retried at the same τ as a backward-Euler step"
                  << std::endl;
          }
        else
          retry(step.tau, StepFailure::energy_rise, decision.reason, "");
        return std::nullopt;
      }
    accept(step.tau, step.result.error_estimate, decision);
    return step;
  }

  void
  StepController::retry(const double       tau,
                        const StepFailure  failure,
                        const std::string &reason,
                        const std::string &solver_report,
                        const double       factor)
  {
    model.restore_last_state();
    if (!solver_report.empty() && Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ostringstream entry;
        entry << "step " << time.step_number() + 1 << " at t = " << time.time() << " with τ = " << tau << ": "
              << reason << '\n'
              << solver_report;
        append_to_error_log(output_directory, entry.str());
      }
    const std::string advice = FluidSurface::advice(failure, output_directory + "error.log");
    time.reject(reason,
                advice + "the output up to the last accepted step, the summary and the last checkpoint are intact",
                factor);
  }

  void
  StepController::accept(const double tau, const double error_estimate, const EnergyStepController::Decision &decision)
  {
    if (decision.verdict == EnergyStepController::Verdict::accept_with_warning)
      pcout << "    warning: F + ∫D rose by " << std::setprecision(3) << decision.law_rise << " (ΔF = " << decision.rise
            << ") at t = " << time.time()
            << " at a rate that does not fall with τ (space discretization); step accepted" << std::endl;
    if (decision.step_size)
      time.set_step_size(*decision.step_size);
    if (model.accept(time.time() + tau))
      pcout << "    mesh law anchored at t = " << time.time() + tau
            << ": the membrane energy now pulls towards this surface, with full weight" << std::endl;
    time.accept(tau, error_estimate);
  }
} // namespace FluidSurface
