// SPDX-License-Identifier: LGPL-2.1-or-later
// Stationary surface Stokes on the ellipsoid [1.27, 1.27, 0.47] (one Killing field, rotation
// about z), manufactured solution u = n × ∇(xyz + x²y), p = xy² + z, Re = 1, geometry degree
// 2 and 3, refinements 1..3: errors and rates (asymptotically 3, 2, 2, 3).
#include "flow_common.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (unsigned int k = 2; k <= 3; ++k)
    {
      double previous[4] = {0, 0, 0, 0};
      for (unsigned int r = 1; r <= 3; ++r)
        {
          const auto result = FlowTest::run({{"geometry/shape", "ellipsoid"},
                                             {"geometry/semi-axes", "1.27, 1.27, 0.47"},
                                             {"geometry/refinement", std::to_string(r)},
                                             {"geometry/position degree", std::to_string(k)},
                                             {"fixed surface/problem", "manufactured ellipsoid"}});
          const double e[4] = {result.errors.velocity, result.errors.gradient, result.errors.pressure,
                               result.errors.normal_velocity};
          if (FlowTest::is_root())
            {
              std::printf("k %u refinement %u  dofs %llu\n", k, r, (unsigned long long)result.n_dofs);
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
}
