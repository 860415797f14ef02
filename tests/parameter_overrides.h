// SPDX-License-Identifier: LGPL-2.1-or-later
// Test parameters as a list of ("subsection/entry", value) pairs set on a ParameterHandler
// (shared by the flow and checkpoint tests).
#ifndef fluid_surface_tests_parameter_overrides_h
#define fluid_surface_tests_parameter_overrides_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  using Overrides = std::vector<std::pair<std::string, std::string>>;

  /// Sets every ("subsection/entry", value) of @p overrides (one subsection level) in @p prm.
  inline void
  set_overrides(dealii::ParameterHandler &prm, const Overrides &overrides)
  {
    for (const auto &[path, value] : overrides)
      {
        const auto slash = path.rfind('/');
        prm.enter_subsection(path.substr(0, slash));
        prm.set(path.substr(slash + 1), value);
        prm.leave_subsection();
      }
  }
} // namespace FluidSurface

#endif
