#include <deal.II/base/mpi.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/scenes/run_program.h>
#include <fluid_surface/scenes/simulation.h>

#include <functional>
#include <sstream>

namespace FluidSurface
{
  namespace
  {
    const char *usage = R"(Usage:
  fluid_surface FILE.prm                 run the experiment described by FILE.prm
  fluid_surface --validate FILE.prm      read and check FILE.prm, compute nothing
  fluid_surface --equilibrium FILE.prm   compute a rotating axisymmetric equilibrium shape
  fluid_surface --print-parameters       print every parameter with default, pattern and help
  fluid_surface --help                   this text

Runs in parallel with mpirun -np N. Results go to the `output directory` of FILE.prm.
Exit status: 0 success (or stopped after 'checkpoint/steps per run'), 1 a computation failed, 2 bad input
(the message names file and entry), 130/143 stopped by SIGINT/SIGTERM after writing a checkpoint.
)";

    /// Prints "fluid_surface: error: @p message" on rank 0.
    void
    error_message(const std::string &message, std::ostream &err, const MPI_Comm communicator)
    {
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        err << "fluid_surface: error: " << message << std::endl;
    }

    /**
     * Calls @p body and returns its exit status, or that of the exception it
     * throws: RunStopped → its own (its message on @p out if 0, else on
     * @p err), InputError → 2, any other std::exception → 1 (RunFailed: a
     * computation that could not go on; its message on one line).
     */
    int
    exit_status_of(const std::function<int()> &body,
                   std::ostream               &out,
                   std::ostream               &err,
                   const MPI_Comm              communicator)
    {
      try
        {
          return body();
        }
      catch (const RunStopped &exc)
        {
          if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
            (exc.exit_status() == 0 ? out : err) << "fluid_surface: " << exc.what() << std::endl;
          return exc.exit_status();
        }
      catch (const InputError &exc)
        {
          error_message(exc.what(), err, communicator);
          return 2;
        }
      catch (const std::exception &exc)
        {
          // A deal.II exception's what() holds the source location and a stack trace: not for the screen.
          error_message(one_line_message(exc, std::string::npos), err, communicator);
          return 1;
        }
    }

    /// `fluid_surface --equilibrium FILE`: the equilibrium's report on @p out.
    int
    run_equilibrium(const std::vector<std::string> &args,
                    std::ostream                   &out,
                    std::ostream                   &err,
                    const MPI_Comm                  communicator)
    {
      if (args.size() != 2)
        {
          error_message("--equilibrium needs exactly one parameter file; see fluid_surface --help", err, communicator);
          return 2;
        }
      std::ostringstream report;
      const int          status = run_equilibrium_command(args[1], report);
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        out << report.str();
      return status;
    }
  } // namespace

  int
  run_program(const std::vector<std::string> &args,
              std::ostream                   &out,
              std::ostream                   &err,
              const MPI_Comm                  communicator)
  {
    const bool root = dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    return exit_status_of(
      [&]() {
        if (args.empty() || args[0] == "--help" || args[0] == "-h")
          {
            if (root)
              out << usage;
            return args.empty() ? 2 : 0;
          }
        if (args[0] == "--equilibrium")
          return run_equilibrium(args, out, err, communicator);
        dealii::ParameterHandler prm;
        Simulation::declare_parameters(prm);
        if (args[0] == "--print-parameters")
          {
            if (root)
              print_documented_parameters(prm, out);
            return 0;
          }
        const bool        validate_only = (args[0] == "--validate");
        const std::string file          = (validate_only && args.size() > 1) ? args[1] : args[0];
        if ((validate_only && args.size() != 2) || (!validate_only && args.size() != 1) ||
            (!validate_only && file.rfind("--", 0) == 0))
          {
            error_message("unexpected arguments; see fluid_surface --help", err, communicator);
            return 2;
          }
        parse_parameter_file(prm, file);
        if (!validate_only)
          return run_simulation(prm, out, err, communicator);
        Simulation simulation(communicator, out);
        simulation.parse_parameters(prm);
        if (root)
          out << file << ": valid" << std::endl;
        return 0;
      },
      out,
      err,
      communicator);
  }

  int
  run_simulation(dealii::ParameterHandler &prm, std::ostream &out, std::ostream &err, const MPI_Comm communicator)
  {
    return exit_status_of(
      [&]() {
        Simulation simulation(communicator, out);
        simulation.parse_parameters(prm);
        simulation.run(prm);
        return 0;
      },
      out,
      err,
      communicator);
  }
} // namespace FluidSurface
