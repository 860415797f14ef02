#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/time_stepping/steady_state.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  void
  SteadyState::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("steady state");
    prm.declare_entry("energy rate tolerance",
                      "0",
                      RealRange::closed(0, 1),
                      "δ, 0 ≤ δ ≤ 1: the run ends (status completed) once |F(t) − F(t − T_w)| < δ T_w |F(t)| and "
                      "the kinetic energy exceeds |L|²/(2λ₃) by less than ε_K |F| (a rigid rotation about the axis "
                      "of largest inertia, the only terminal state with angular momentum L). 0: run to the end "
                      "time.");
    prm.declare_entry("window",
                      "1",
                      RealRange::left_open(0, 1e6),
                      "T_w, 0 < T_w ≤ 1e6: the time over which F must be flat.");
    prm.declare_entry("kinetic energy excess tolerance",
                      "1e-4",
                      RealRange::closed(0, 1),
                      "ε_K, 0 ≤ ε_K ≤ 1: the largest (K − |L|²/(2λ₃))/|F| of an end state (K kinetic energy, L "
                      "angular momentum, λ₃ largest eigenvalue of the inertia tensor).");
    prm.leave_subsection();
  }

  void
  SteadyState::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("steady state");
    energy_rate_tolerance    = prm.get_double("energy rate tolerance");
    window                   = prm.get_double("window");
    kinetic_excess_tolerance = prm.get_double("kinetic energy excess tolerance");
    prm.leave_subsection();
  }

  bool
  SteadyState::reached(const double time, const double total_energy, const double kinetic_excess)
  {
    if (!enabled())
      return false;
    if (samples.empty() || time - samples.back().first >= window / 20)
      samples.emplace_back(time, total_energy);
    // Keep one sample at or before t − T_w.
    while (samples.size() > 1 && samples[1].first <= time - window)
      samples.erase(samples.begin());
    const auto [t_old, F_old] = samples.front();
    if (time - t_old < window)
      return false;
    last_energy_rate    = std::abs(total_energy - F_old) / ((time - t_old) * std::abs(total_energy));
    last_kinetic_excess = kinetic_excess / std::abs(total_energy);
    return last_energy_rate < energy_rate_tolerance && last_kinetic_excess < kinetic_excess_tolerance;
  }

  std::string
  SteadyState::description() const
  {
    std::ostringstream text;
    text << std::setprecision(3) << "|ΔF|/(T_w |F|) = " << last_energy_rate << " < δ = " << energy_rate_tolerance
         << " over T_w = " << window << ", (K − |L|²/(2λ₃))/|F| = " << last_kinetic_excess
         << " < ε_K = " << kinetic_excess_tolerance;
    return text.str();
  }

  void
  SteadyState::save(CheckpointData &data) const
  {
    data.set("steady state/samples", static_cast<unsigned int>(samples.size()));
    for (unsigned int k = 0; k < samples.size(); ++k)
      {
        data.set("steady state/time " + std::to_string(k), samples[k].first);
        data.set("steady state/energy " + std::to_string(k), samples[k].second);
      }
  }

  void
  SteadyState::load(const CheckpointData &data)
  {
    samples.clear();
    // Checkpoints written before this check existed have no samples: the window starts again.
    if (!data.has("steady state/samples"))
      return;
    for (unsigned int k = 0; k < data.get_unsigned("steady state/samples"); ++k)
      samples.emplace_back(data.get_double("steady state/time " + std::to_string(k)),
                           data.get_double("steady state/energy " + std::to_string(k)));
  }
} // namespace FluidSurface
