// SPDX-License-Identifier: LGPL-2.1-or-later
// time stepping/relaxation end time t_r and relaxation maximum time step τ_r: every step that starts before t_r is
// at most τ_r (also the first, whose `time step` is larger, and a step proposed by the error control); after t_r τ
// grows by the growth factor, never faster (BDF2's step ratio stays ≤ 2), up to τ_max. τ_r outside [τ_min, τ_max]
// is refused with the entry's name; t_r = 0 gives the steps of a run without these entries. A run resumed before t_r
// from a checkpoint written with a larger step starts at τ_r.
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/time_stepping/time_stepper.h>

#include <algorithm>
#include <iostream>
#include <string>

using namespace FluidSurface;

namespace
{
  TimeStepper
  stepper(const std::string &entries)
  {
    dealii::ParameterHandler prm;
    TimeStepper::declare_parameters(prm);
    prm.parse_input_from_string("subsection time stepping\n  set end time = 1\n  set time step = 0.01\n"
                                "  set maximum time step = 0.1\n  set easy steps before growth = 1\n" +
                                entries + "end\n");
    TimeStepper time;
    time.parse_parameters(prm);
    return time;
  }

  /// Runs @p time to its end; prints the largest step before t_r, the first step after it, the largest ratio of
  /// two successive steps and the number of steps.
  void
  run(const std::string &name, TimeStepper time, const double relaxation_end)
  {
    double       largest_before = 0, first_after = 0, largest_ratio = 0, previous = 0;
    unsigned int steps = 0;
    while (time.before_end())
      {
        const double tau = time.step_size();
        if (time.time() < relaxation_end)
          largest_before = std::max(largest_before, tau);
        else if (first_after == 0)
          first_after = tau;
        if (previous > 0)
          largest_ratio = std::max(largest_ratio, tau / previous);
        previous = tau;
        time.accept(tau);
        ++steps;
      }
    std::cout << name << ": largest τ before t_r " << largest_before << ", first after " << first_after
              << ", largest step ratio " << largest_ratio << ", " << steps << " steps" << std::endl;
  }
} // namespace

int
main()
{
  run("t_r = 0.3, τ_r = 0.005", stepper("  set relaxation end time = 0.3\n  set relaxation maximum time step = 0.005\n"),
      0.3);
  run("t_r = 0", stepper(""), 0);
  run("t_r = 0 (τ_r set)", stepper("  set relaxation maximum time step = 0.005\n"), 0);

  // The error control proposes τ·2 after an error-free step: still at most τ_r before t_r.
  TimeStepper controlled =
    stepper("  set relaxation end time = 0.3\n  set relaxation maximum time step = 0.005\n  set error tolerance = 1e-3\n");
  controlled.accept(controlled.step_size(), 0);
  std::cout << "error control, after an error-free step at t = " << controlled.time() << ": τ = "
            << controlled.step_size() << std::endl;

  // A checkpoint at t = 0.2 with τ = 0.1 (written without t_r), resumed with t_r = 0.3 and τ_r = 0.005.
  TimeStepper unbounded = stepper("");
  while (unbounded.time() < 0.2 - 1e-12)
    unbounded.accept(std::min(unbounded.step_size(), 0.2 - unbounded.time()));
  unbounded.set_step_size(0.1);
  CheckpointData checkpoint;
  unbounded.save(checkpoint);
  TimeStepper resumed = stepper("  set relaxation end time = 0.3\n  set relaxation maximum time step = 0.005\n");
  resumed.load(checkpoint);
  std::cout << "checkpoint at t = " << unbounded.time() << " with τ = " << unbounded.step_size()
            << ", resumed with τ_r = 0.005: τ = " << resumed.step_size() << std::endl;

  for (const std::string value : {"0.2", "1e-8"})
    try
      {
        stepper("  set relaxation end time = 0.3\n  set relaxation maximum time step = " + value +
                "\n  set minimum time step = 1e-7\n");
        std::cout << "τ_r = " << value << ": accepted" << std::endl;
      }
    catch (const InputError &error)
      {
        std::cout << "τ_r = " << value << ": " << error.what() << std::endl;
      }
}
