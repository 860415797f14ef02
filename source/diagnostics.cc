#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <fluid_surface/checkpoint.h>
#include <fluid_surface/diagnostics.h>
#include <fluid_surface/parameter_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace FluidSurface
{
  using namespace dealii;

  void
  Diagnostics::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("diagnostics");
    prm.declare_entry("axis",
                      "0, 0, 1",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "Axis e of the angular velocity ω(t) = (1/|S|)∫(u·e_φ)/r (through the centre of mass).");
    prm.declare_entry("angular velocity window",
                      "5, 10",
                      Patterns::List(Patterns::Double(0), 2, 2),
                      "Time window [t₀, t₁] of the mean angular velocity ⟨ω⟩ in the summary.");
    prm.leave_subsection();
  }

  void
  Diagnostics::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("diagnostics");
    const auto a = Utilities::split_string_list(prm.get("axis"));
    for (unsigned int d = 0; d < 3; ++d)
      axis[d] = Utilities::string_to_double(a[d]);
    if (axis.norm() == 0)
      throw_invalid_entry("diagnostics/axis", prm.get("axis"), "a non-zero vector");
    axis /= axis.norm();
    const auto w = Utilities::split_string_list(prm.get("angular velocity window"));
    window_begin = Utilities::string_to_double(w[0]);
    window_end   = Utilities::string_to_double(w[1]);
    if (!(window_end > window_begin))
      throw_invalid_entry("diagnostics/angular velocity window",
                          prm.get("angular velocity window"),
                          "t₀ < t₁");
    prm.leave_subsection();
  }

  Diagnostics::Values
  Diagnostics::evaluate(const SurfaceGeometry &geometry, const DoFHandler<2, 3> &dofs, const VectorType &state) const
  {
    const SurfaceGeometry::Measures m = geometry.measure();
    Values                          v;
    v.area           = m.area;
    v.volume         = m.volume;
    v.reduced_volume = m.reduced_volume;
    v.mesh_quality   = m.mesh_quality;
    const Point<3> c(m.centre_of_mass);

    const QGauss<2>                  q = geometry.quadrature();
    FEValues<2, 3>                   fe_values(geometry.mapping(), dofs.get_fe(), q,
                                               update_values | update_quadrature_points | update_normal_vectors |
                                                 update_JxW_values);
    const FEValuesExtractors::Vector velocity(0);
    std::vector<Tensor<1, 3>>        u(q.size());
    // [0] F_kin, [1] ∫ω-integrand, [2..4] ∫u, [5..7] L, [8..16] I
    double local[17] = {};
    double max_un    = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[velocity].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const double       dA = fe_values.JxW(k);
              const Tensor<1, 3> x  = fe_values.quadrature_point(k) - c;
              const Tensor<1, 3> radial = x - (x * axis) * axis;
              const double       r      = radial.norm();
              local[0] += 0.5 * u[k].norm_square() * dA;
              if (r > 1e-12)
                local[1] += (u[k] * cross_product_3d(axis, radial)) / (r * r) * dA;
              const Tensor<1, 3> L = cross_product_3d(x, u[k]);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  local[2 + d] += u[k][d] * dA;
                  local[5 + d] += L[d] * dA;
                  for (unsigned int e = 0; e < 3; ++e)
                    local[8 + 3 * d + e] += ((d == e ? x.norm_square() : 0.0) - x[d] * x[e]) * dA;
                }
              max_un = std::max(max_un, std::abs(u[k] * fe_values.normal_vector(k)));
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(local, 17), geometry.get_communicator(), ArrayView<double>(local, 17));
    v.max_normal_velocity = Utilities::MPI::max(max_un, geometry.get_communicator());
    v.kinetic_energy      = local[0];
    v.angular_velocity    = local[1] / m.area;
    LAPACKFullMatrix<double> inertia(3, 3);
    Tensor<2, 3>             I;
    for (unsigned int d = 0; d < 3; ++d)
      {
        v.linear_momentum[d]  = local[2 + d];
        v.angular_momentum[d] = local[5 + d];
        for (unsigned int e = 0; e < 3; ++e)
          {
            I[d][e] = local[8 + 3 * d + e];
            inertia(d, e) = I[d][e];
          }
      }
    FullMatrix<double> eigenvectors;
    Vector<double>     eigenvalues;
    inertia.compute_eigenvalues_symmetric(-1e300, 1e300, 0, eigenvalues, eigenvectors);
    // LAPACK returns them ascending.
    for (unsigned int d = 0; d < 3; ++d)
      {
        v.eigenvalues[d]     = eigenvalues(d);
        v.elongation_axis[d] = eigenvectors(d, 0);
      }
    // A sign convention makes the axis reproducible: its largest component is positive.
    unsigned int largest = 0;
    for (unsigned int d = 1; d < 3; ++d)
      if (std::abs(v.elongation_axis[d]) > std::abs(v.elongation_axis[largest]))
        largest = d;
    if (v.elongation_axis[largest] < 0)
      v.elongation_axis *= -1.0;
    const double gap01 = eigenvalues(1) - eigenvalues(0), gap12 = eigenvalues(2) - eigenvalues(1);
    v.symmetry_deviation = std::min(gap01, gap12) / ((eigenvalues(0) + eigenvalues(1) + eigenvalues(2)) / 3.0);
    v.rotation_vector    = invert(I) * v.angular_momentum;
    const double omega_norm = v.rotation_vector.norm();
    v.tilt_angle = omega_norm > 0 ? std::acos(std::min(1.0, std::abs(v.rotation_vector * v.elongation_axis) / omega_norm)) *
                                      180.0 / numbers::PI :
                                    0.0;
    v.rigid_fraction = v.kinetic_energy > 0 ? 0.5 * (v.rotation_vector * v.angular_momentum) / v.kinetic_energy : 0.0;
    return v;
  }

  void
  Diagnostics::record(const Values &v, const double time, const double tau)
  {
    if (!have_initial)
      {
        initial      = v;
        have_initial = true;
      }
    area_drift   = std::max(area_drift, std::abs(v.area - initial.area) / initial.area);
    volume_drift = std::max(volume_drift, std::abs(v.volume - initial.volume) / initial.volume);
    const double L0 = initial.angular_momentum.norm();
    if (L0 > 0)
      angular_momentum_drift =
        std::max(angular_momentum_drift, (v.angular_momentum - initial.angular_momentum).norm() / L0);
    if (std::isnan(crossing_1e4) && v.symmetry_deviation > 1e-4)
      crossing_1e4 = time;
    if (std::isnan(crossing_1e2) && v.symmetry_deviation > 1e-2)
      crossing_1e2 = time;
    // ⟨ω⟩ by the rectangle rule over the steps ending inside the window.
    if (tau > 0 && time > window_begin && time - tau < window_end)
      {
        const double overlap = std::min(time, window_end) - std::max(time - tau, window_begin);
        omega_integral += v.angular_velocity * overlap;
        omega_time += overlap;
      }
  }

  void
  Diagnostics::add_to_statistics(const Values &v, StatisticsFile &statistics) const
  {
    const char *xyz[3] = {" x", " y", " z"};
    statistics.add_value("area", v.area);
    statistics.add_value("volume", v.volume);
    statistics.add_value("reduced volume", v.reduced_volume);
    statistics.add_value("angular velocity", v.angular_velocity);
    for (unsigned int d = 0; d < 3; ++d)
      statistics.add_value(std::string("angular momentum") + xyz[d], v.angular_momentum[d]);
    for (unsigned int d = 0; d < 3; ++d)
      statistics.add_value(std::string("linear momentum") + xyz[d], v.linear_momentum[d]);
    for (unsigned int d = 0; d < 3; ++d)
      statistics.add_value("inertia eigenvalue " + std::to_string(d + 1), v.eigenvalues[d]);
    for (unsigned int d = 0; d < 3; ++d)
      statistics.add_value(std::string("elongation axis") + xyz[d], v.elongation_axis[d]);
    for (unsigned int d = 0; d < 3; ++d)
      statistics.add_value(std::string("rotation vector") + xyz[d], v.rotation_vector[d]);
    statistics.add_value("tilt angle", v.tilt_angle);
    statistics.add_value("rigid fraction", v.rigid_fraction);
    statistics.add_value("symmetry deviation", v.symmetry_deviation);
    statistics.add_value("max normal velocity", v.max_normal_velocity);
    statistics.add_value("mesh quality", v.mesh_quality);
  }

  void
  Diagnostics::write_summary(std::ostream      &out,
                             const double        final_total_energy,
                             const unsigned int  steps,
                             const unsigned int  rejected_steps,
                             const double        wall_time) const
  {
    auto time_or_never = [](const double t) { return std::isnan(t) ? std::string("never") : std::to_string(t); };
    out << std::setprecision(10);
    out << "t_sym_1e-4: " << time_or_never(crossing_1e4) << '\n'
        << "t_sym_1e-2: " << time_or_never(crossing_1e2) << '\n'
        << "mean angular velocity: ";
    if (omega_time > 0)
      out << omega_integral / omega_time << '\n';
    else
      out << "n/a (the run did not reach the window)\n";
    out << "final total energy: " << final_total_energy << '\n'
        << "max area drift: " << area_drift << '\n'
        << "max volume drift: " << volume_drift << '\n'
        << "max angular momentum drift: " << angular_momentum_drift << '\n'
        << "steps: " << steps << '\n'
        << "rejected steps: " << rejected_steps << '\n'
        << "wall time: " << wall_time << '\n';
  }

  void
  Diagnostics::save(CheckpointData &data) const
  {
    data.set("diagnostics/have initial", have_initial);
    data.set("diagnostics/initial area", initial.area);
    data.set("diagnostics/initial volume", initial.volume);
    data.set("diagnostics/initial angular momentum", initial.angular_momentum);
    data.set("diagnostics/max area drift", area_drift);
    data.set("diagnostics/max volume drift", volume_drift);
    data.set("diagnostics/max angular momentum drift", angular_momentum_drift);
    data.set("diagnostics/t_sym_1e-4", crossing_1e4);
    data.set("diagnostics/t_sym_1e-2", crossing_1e2);
    data.set("diagnostics/omega integral", omega_integral);
    data.set("diagnostics/omega time", omega_time);
  }

  void
  Diagnostics::load(const CheckpointData &data)
  {
    have_initial             = data.get_bool("diagnostics/have initial");
    initial.area             = data.get_double("diagnostics/initial area");
    initial.volume           = data.get_double("diagnostics/initial volume");
    initial.angular_momentum = data.get_tensor("diagnostics/initial angular momentum");
    area_drift               = data.get_double("diagnostics/max area drift");
    volume_drift             = data.get_double("diagnostics/max volume drift");
    angular_momentum_drift   = data.get_double("diagnostics/max angular momentum drift");
    crossing_1e4             = data.get_double("diagnostics/t_sym_1e-4");
    crossing_1e2             = data.get_double("diagnostics/t_sym_1e-2");
    omega_integral           = data.get_double("diagnostics/omega integral");
    omega_time               = data.get_double("diagnostics/omega time");
  }
} // namespace FluidSurface
