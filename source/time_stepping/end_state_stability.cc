// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>
#include <fluid_surface/reference/second_variation.h>
#include <fluid_surface/time_stepping/end_state_stability.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  void
  EndStateStability::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("steady state");
    prm.declare_entry("saddle check",
                      "true",
                      Patterns::Bool(),
                      "Whether an end state that is a body of revolution spinning about its symmetry axis (or at "
                      "rest) is classified by the second variation of the rotating axisymmetric equilibrium with its "
                      "A, v, |L| and Be at fixed A, V and L (m = 0…4, both parities; doc/stability.md). A saddle, "
                      "some eigenvalue λ < −1e-7, is not an end state: the surface is displaced along the class of "
                      "the lowest λ by `saddle perturbation` and the run goes on; the summary lists the saddles "
                      "left and the class of the end state.");
    prm.declare_entry("saddle perturbation",
                      "1e-3",
                      RealRange::closed(1e-8, 0.1),
                      "ε_s, 1e-8 ≤ ε_s ≤ 0.1: the amplitude of the displacement along the falling class at a "
                      "saddle, relative to the distance from the centre of mass (the azimuthal harmonic of `initial "
                      "state/perturbation form = azimuthal` about the symmetry axis).");
    prm.declare_entry("axisymmetry tolerance",
                      "1e-3",
                      RealRange::closed(0, 0.1),
                      "ε_a, 0 ≤ ε_a ≤ 0.1: an end state is a body of revolution when two inertia eigenvalues agree "
                      "to ε_a λ₃ and the third differs from them by more (λ₁ ≈ λ₂: an oblate about the axis of λ₃; "
                      "λ₂ ≈ λ₃: a prolate about the axis of λ₁), and it rotates about that axis or not at all.");
    prm.leave_subsection();
  }

  void
  EndStateStability::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("steady state");
    check                 = prm.get_bool("saddle check");
    amplitude             = prm.get_double("saddle perturbation");
    axisymmetry_tolerance = prm.get_double("axisymmetry tolerance");
    prm.leave_subsection();
  }

  EndStateStability::Assessment
  EndStateStability::assess(const Measures &state) const
  {
    Assessment   result;
    const double lambda3 = state.inertia[2];
    const bool   oblate  = state.inertia[1] - state.inertia[0] < axisymmetry_tolerance * lambda3 &&
                        state.inertia[2] - state.inertia[1] >= axisymmetry_tolerance * lambda3;
    const bool prolate = state.inertia[2] - state.inertia[1] < axisymmetry_tolerance * lambda3 &&
                         state.inertia[1] - state.inertia[0] >= axisymmetry_tolerance * lambda3;
    const std::string stability_scene = " (its class: scene stability with `base state = checkpoint`, "
                                        "doc/stability.md)";
    if (!oblate && !prolate)
      {
        result.description = (state.inertia[2] - state.inertia[0] < axisymmetry_tolerance * lambda3 ?
                                "a sphere to the axisymmetry tolerance: not classified" :
                                "triaxial, not a body of revolution") +
                             stability_scene;
        return result;
      }
    result.axis = oblate ? state.largest_inertia_axis : state.least_inertia_axis;
    // A body of revolution rotating about a transverse axis (a tumbling prolate) is not an axisymmetric equilibrium.
    const double omega = state.rotation_vector.norm();
    if (omega > 0 && std::abs(state.rotation_vector * result.axis) < (1 - 1e-3) * omega &&
        state.angular_momentum.norm() > 1e-8 * std::sqrt(lambda3 * std::abs(state.total_energy)))
      {
        result.description = "a body of revolution rotating about a transverse axis" + stability_scene;
        return result;
      }
    result.axisymmetric = true;

    AxisymmetricEquilibrium::Parameters parameters;
    parameters.area             = state.area;
    parameters.reduced_volume   = state.reduced_volume;
    parameters.branch           = oblate ? AxisymmetricEquilibrium::Branch::oblate : AxisymmetricEquilibrium::Branch::prolate;
    parameters.bending_number   = state.bending_number;
    parameters.prescribed       = AxisymmetricEquilibrium::Prescribed::angular_momentum;
    parameters.angular_momentum = state.angular_momentum.norm();
    std::ostringstream text;
    text << std::setprecision(6) << "a body of revolution (" << (oblate ? "oblate" : "prolate") << ", v = "
         << state.reduced_volume << ", |L| = " << parameters.angular_momentum << ")";
    try
      {
        AxisymmetricEquilibrium equilibrium(parameters);
        equilibrium.solve();
        SecondVariation::Parameters variation_parameters;
        variation_parameters.modes = {0, 1, 2, 3, 4};
        SecondVariation variation(variation_parameters);
        variation.compute(equilibrium);
        result.classified = true;
        bool first        = true;
        for (const SecondVariation::Spectrum &spectrum : variation.spectra())
          {
            if (spectrum.energy != SecondVariation::Energy::isolated || spectrum.eigenvalues.empty())
              continue;
            for (const double value : spectrum.eigenvalues)
              if (value < -1e-7)
                result.directions += spectrum.m == 0 ? 1 : 2;
            if (first || spectrum.eigenvalues[0] < result.lowest)
              {
                result.lowest = spectrum.eigenvalues[0];
                result.m      = spectrum.m;
                result.odd    = spectrum.odd;
                first         = false;
              }
          }
        const double equilibrium_energy = equilibrium.bending_energy() + equilibrium.kinetic_energy();
        text << ", the equilibrium's F = " << std::setprecision(9) << equilibrium_energy << " (the run's "
             << state.total_energy << "): " << std::setprecision(4);
        if (result.directions == 0)
          text << "a minimum at fixed A, V, L (lowest eigenvalue " << result.lowest << ", m = " << result.m << ' '
               << (result.odd ? "odd" : "even") << ")";
        else
          text << "a saddle, " << result.directions << " falling directions (lowest eigenvalue " << result.lowest
               << ", m = " << result.m << ' ' << (result.odd ? "odd" : "even") << ")";
      }
    catch (const std::exception &exc)
      {
        text << ": not classified (no equilibrium: " << exc.what() << ")";
      }
    result.description = text.str();
    return result;
  }

  void
  EndStateStability::record_saddle(const double time, const Assessment &assessment)
  {
    std::ostringstream entry;
    entry << (n_saddles == 0 ? "" : "; ") << "t = " << std::setprecision(6) << time << ": m = " << assessment.m
          << ' ' << (assessment.odd ? "odd" : "even") << ", λ = " << std::setprecision(4) << assessment.lowest;
    saddle_history += entry.str();
    ++n_saddles;
  }

  std::string
  EndStateStability::saddles_left() const
  {
    return n_saddles == 0 ? std::string("none") : std::to_string(n_saddles) + " (" + saddle_history + ")";
  }

  void
  EndStateStability::save(CheckpointData &data) const
  {
    data.set("steady state/saddles left", n_saddles);
    if (n_saddles > 0)
      data.set("steady state/saddle history", saddle_history);
  }

  void
  EndStateStability::load(const CheckpointData &data)
  {
    n_saddles      = data.has("steady state/saddles left") ? data.get_unsigned("steady state/saddles left") : 0;
    saddle_history = data.has("steady state/saddle history") ? data.get_string("steady state/saddle history") : "";
  }
} // namespace FluidSurface
