// A scene rejects an entry that the parameter file sets but the scene would not use, before any
// computation (an InputError: exit status 2 of fluid_surface), with a message naming the file, the line and
// the entry: scene full with an entry of `fixed surface solver`, scene fixed surface with entries of the
// deformable surface (bending, flow/conserve momenta, time stepping/maximum time step). The same entries in
// the scene that uses them are accepted.
#include <deal.II/base/mpi.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/scenes/simulation.h>

#include <fstream>
#include <iostream>

using namespace FluidSurface;

namespace
{
  void
  try_file(const std::string &name, const std::string &content)
  {
    std::ofstream(name) << content;
    dealii::ParameterHandler prm;
    Simulation::declare_parameters(prm);
    try
      {
        parse_parameter_file(prm, name);
        Simulation simulation(MPI_COMM_WORLD);
        simulation.parse_parameters(prm);
        std::cout << name << ": accepted" << std::endl;
      }
    catch (const InputError &error)
      {
        std::cout << error.what() << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string full  = "subsection model\n  set scene = full\nend\n";
  const std::string fixed = "subsection model\n  set scene = fixed surface\nend\n"
                            "subsection geometry\n  set shape = sphere\nend\n";
  try_file("full_fixed_solver.prm", full + "subsection fixed surface solver\n  set time scheme = BDF1\nend\n");
  try_file("full_fixed_problem.prm", full + "# a comment\nsubsection fixed surface\n  set problem = \\\n  killing\nend\n");
  try_file("full_used.prm", full + "subsection flow\n  set Re = 2\n  set conserve momenta = true\nend\n"
                                   "subsection bending\n  set Be = 2\nend\n");
  try_file("fixed_bending.prm", fixed + "subsection bending\n  set Be = 2\nend\n");
  try_file("fixed_conserve_momenta.prm", fixed + "subsection flow\n  set Re = 2\n  set conserve momenta = true\nend\n");
  try_file("fixed_maximum_step.prm", fixed + "subsection time stepping\n  set maximum time step = 0.1\nend\n");
  try_file("fixed_used.prm", fixed + "subsection flow\n  set Re = 2\nend\n"
                                     "subsection fixed surface solver\n  set time scheme = BDF1\nend\n"
                                     "subsection time stepping\n  set time step = 0.1\nend\n");
}
