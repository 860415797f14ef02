// fluid_surface: fluid deformable surfaces (surface Navier–Stokes + Helfrich bending) with deal.II.
#include <deal.II/base/mpi.h>

#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/scenes/simulation.h>

#include <iostream>
#include <sstream>
#include <string>

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

  void
  error_message(const std::string &message)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "fluid_surface: error: " << message << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace FluidSurface;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);

  const std::vector<std::string> args(argv + 1, argv + argc);
  try
    {
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cout << usage;
          return args.empty() ? 2 : 0;
        }
      if (args[0] == "--equilibrium")
        {
          if (args.size() != 2)
            {
              error_message("--equilibrium needs exactly one parameter file; see fluid_surface --help");
              return 2;
            }
          std::ostringstream out;
          const int          status = run_equilibrium_command(args[1], out);
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cout << out.str();
          return status;
        }
      dealii::ParameterHandler prm;
      Simulation::declare_parameters(prm);
      if (args[0] == "--print-parameters")
        {
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            print_documented_parameters(prm, std::cout);
          return 0;
        }
      const bool        validate_only = (args[0] == "--validate");
      const std::string file          = (validate_only && args.size() > 1) ? args[1] : args[0];
      if ((validate_only && args.size() != 2) || (!validate_only && args.size() != 1) ||
          (!validate_only && file.rfind("--", 0) == 0))
        {
          error_message("unexpected arguments; see fluid_surface --help");
          return 2;
        }
      parse_parameter_file(prm, file);
      Simulation simulation(MPI_COMM_WORLD);
      simulation.parse_parameters(prm);
      if (validate_only)
        {
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cout << file << ": valid" << std::endl;
          return 0;
        }
      simulation.run(prm);
    }
  catch (const RunStopped &exc)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        (exc.exit_status() == 0 ? std::cout : std::cerr) << "fluid_surface: " << exc.what() << std::endl;
      return exc.exit_status();
    }
  catch (const InputError &exc)
    {
      error_message(exc.what());
      return 2;
    }
  catch (const std::exception &exc)
    {
      error_message(exc.what());
      return 1;
    }
  return 0;
}
