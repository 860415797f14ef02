// SPDX-License-Identifier: LGPL-2.1-or-later
// A scene rejects an entry that the parameter file sets outside the subsections it reads, or that it ignores,
// before any computation (an InputError: exit status 2 of fluid_surface), with a message naming the file, the
// line, the entry and the scene: scene full with an entry of `fixed surface solver` or `fixed surface`, scene
// fixed surface with entries of the deformable surface (bending, flow/conserve momenta, time stepping/maximum
// time step). The same entries in the scene that uses them are accepted.
#include <deal.II/base/mpi.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/scenes/simulation.h>

#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string full  = "subsection model\n  set scene = full\nend\n";
  const std::string fixed = "subsection model\n  set scene = fixed surface\nend\n"
                            "subsection geometry\n  set shape = sphere\nend\n";
  const std::vector<std::pair<std::string, std::string>> files = {
    {"full_fixed_solver.prm", full + "subsection fixed surface solver\n  set time scheme = BDF1\nend\n"},
    {"full_fixed_problem.prm", full + "# a comment\nsubsection fixed surface\n  set problem = \\\n  killing\nend\n"},
    {"full_used.prm",
     full + "subsection flow\n  set Re = 2\n  set conserve momenta = true\nend\nsubsection bending\n  set Be = 2\nend\n"},
    {"fixed_bending.prm", fixed + "subsection bending\n  set Be = 2\nend\n"},
    {"fixed_conserve_momenta.prm", fixed + "subsection flow\n  set Re = 2\n  set conserve momenta = true\nend\n"},
    {"fixed_maximum_step.prm", fixed + "subsection time stepping\n  set maximum time step = 0.1\nend\n"},
    {"fixed_used.prm",
     fixed + "subsection flow\n  set Re = 2\nend\nsubsection fixed surface solver\n  set time scheme = BDF1\nend\n"
             "subsection time stepping\n  set time step = 0.1\nend\n"}};
  for (const auto &[name, content] : files)
    {
      std::ofstream(name) << content;
      dealii::ParameterHandler prm;
      Simulation::declare_parameters(prm);
      std::string outcome = name + ": accepted";
      try
        {
          const ParameterFile file = parse_parameter_file(prm, name);
          Simulation(MPI_COMM_WORLD).parse_parameters(prm, file);
        }
      catch (const InputError &error)
        {
          outcome = error.what();
        }
      std::cout << outcome << std::endl;
    }
}
