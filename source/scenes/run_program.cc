// SPDX-License-Identifier: LGPL-2.1-or-later
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
  fluid_surface --equilibrium FILE.prm   compute a rotating axisymmetric equilibrium shape (and, with subsection
                                         second variation, the eigenvalues of its second variation per m)
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
     * @p err), InputError → 2 (an EntryError after "@p file: ", the parameter
     * file as @p body last set it), any other std::exception → 1 (RunFailed: a
     * computation that could not go on; its message on one line).
     */
    int
    exit_status_of(const std::function<int()> &body,
                   std::ostream               &out,
                   std::ostream               &err,
                   const MPI_Comm              communicator,
                   const std::string          &file)
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
      catch (const EntryError &exc)
        {
          error_message(file + ": " + exc.what(), err, communicator);
          return 2;
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

    /// What `fluid_surface --equilibrium FILE` reads: subsections equilibrium (AxisymmetricEquilibrium) and second
    /// variation (SecondVariation).
    const ParametersRead equilibrium_command_reads = {"--equilibrium", {"equilibrium", "second variation"}, {}};

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
      {
        // The scene rule: the file is read with every declaration, so that an entry of another subsection is
        // named as one --equilibrium does not read.
        dealii::ParameterHandler every_parameter;
        Simulation::declare_parameters(every_parameter);
        reject_entries_not_read(parse_parameter_file(every_parameter, args[1]), equilibrium_command_reads);
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
    const bool  root = dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    std::string file_label = ParameterFile().label();
    return exit_status_of(
      [&]() {
        if (args.empty() || args[0] == "--help" || args[0] == "-h")
          {
            if (root)
              out << usage;
            return args.empty() ? 2 : 0;
          }
        if (args[0] == "--equilibrium")
          {
            if (args.size() == 2)
              file_label = args[1];
            return run_equilibrium(args, out, err, communicator);
          }
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
        file_label                         = file;
        const ParameterFile parameter_file = parse_parameter_file(prm, file);
        if (!validate_only)
          return run_simulation(prm, out, err, communicator, parameter_file);
        Simulation simulation(communicator, out);
        simulation.parse_parameters(prm, parameter_file);
        if (root)
          out << file << ": valid" << std::endl;
        return 0;
      },
      out,
      err,
      communicator,
      file_label);
  }

  int
  run_simulation(dealii::ParameterHandler &prm,
                 std::ostream             &out,
                 std::ostream             &err,
                 const MPI_Comm            communicator,
                 const ParameterFile      &file)
  {
    return exit_status_of(
      [&]() {
        Simulation simulation(communicator, out);
        simulation.parse_parameters(prm, file);
        simulation.run(prm);
        return 0;
      },
      out,
      err,
      communicator,
      file.label());
  }
} // namespace FluidSurface
