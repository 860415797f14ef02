// SPDX-License-Identifier: LGPL-2.1-or-later
// Stationary surface Stokes on the unit sphere, manufactured solution u = n × ∇(xyz + x²y),
// p = xy² + z, Re = 1, Q2 geometry, refinements 1..3: errors ‖u − u_h‖, ‖∇_P(u − u_h)‖,
// ‖p − p_h‖, ‖u_h·ν‖ and their rates (expected 3, 2, 2, 3). Also run with mpirun -np 2.
#include "flow_common.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double previous[4] = {0, 0, 0, 0};
  for (unsigned int r = 1; r <= 3; ++r)
    {
      const auto result = FlowTest::run({{"geometry/shape", "sphere"},
                                         {"geometry/refinement", std::to_string(r)},
                                         {"geometry/position degree", "2"},
                                         {"fixed surface/problem", "manufactured sphere"}});
      const double e[4] = {result.errors.velocity, result.errors.gradient, result.errors.pressure,
                           result.errors.normal_velocity};
      if (FlowTest::is_root())
        {
          std::printf("refinement %u  dofs %llu\n", r, (unsigned long long)result.n_dofs);
          const char *names[4] = {"u", "grad_P u", "p", "u.n"};
          for (unsigned int i = 0; i < 4; ++i)
            {
              std::printf("  %-8s error %s", names[i], FlowTest::scientific(e[i]).c_str());
              if (r > 1)
                std::printf("  rate %.2f", std::log2(previous[i] / e[i]));
              std::printf("\n");
            }
        }
      for (unsigned int i = 0; i < 4; ++i)
        previous[i] = e[i];
    }
}
