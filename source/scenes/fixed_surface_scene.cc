// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/postprocess/speed_postprocessor.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>
#include <fluid_surface/scenes/fixed_surface_scene.h>

#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    using Ad1 = Sacado::Fad::DFad<double>; ///< first derivatives
    using Ad2 = Sacado::Fad::DFad<Ad1>;    ///< second derivatives

    /**
     * The manufactured Stokes solution on the level sets of φ = Σ x_i²/a_i²
     * (sphere: a_i = R): n = ∇φ/|∇φ|, u = n × ∇ψ with ψ = xyz + x²y
     * (tangential and surface divergence free on every level set), p = xy² + z.
     */
    template <typename Number>
    std::array<Number, 3>
    manufactured_velocity(const std::array<Number, 3> &x, const Tensor<1, 3> &axes)
    {
      std::array<Number, 3> g;
      for (unsigned int d = 0; d < 3; ++d)
        g[d] = x[d] / (axes[d] * axes[d]);
      const Number          norm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      std::array<Number, 3> n    = {{g[0] / norm, g[1] / norm, g[2] / norm}};
      const std::array<Number, 3> grad_psi = {
        {x[1] * x[2] + 2.0 * x[0] * x[1], x[0] * x[2] + x[0] * x[0], x[0] * x[1]}};
      return {{n[1] * grad_psi[2] - n[2] * grad_psi[1],
               n[2] * grad_psi[0] - n[0] * grad_psi[2],
               n[0] * grad_psi[1] - n[1] * grad_psi[0]}};
    }

    template <typename Number>
    std::array<Number, 3>
    level_set_normal(const std::array<Number, 3> &x, const Tensor<1, 3> &axes)
    {
      std::array<Number, 3> g;
      for (unsigned int d = 0; d < 3; ++d)
        g[d] = x[d] / (axes[d] * axes[d]);
      const Number norm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      return {{g[0] / norm, g[1] / norm, g[2] / norm}};
    }

    Tensor<1, 3>
    exact_normal(const Point<3> &x, const Tensor<1, 3> &axes)
    {
      const std::array<double, 3> n = level_set_normal<double>({{x[0], x[1], x[2]}}, axes);
      return Tensor<1, 3>({n[0], n[1], n[2]});
    }

    Tensor<2, 3>
    manufactured_velocity_gradient(const Point<3> &x, const Tensor<1, 3> &axes)
    {
      std::array<Ad1, 3> xa;
      for (unsigned int k = 0; k < 3; ++k)
        xa[k] = Ad1(3, k, x[k]);
      const std::array<Ad1, 3> u = manufactured_velocity(xa, axes);
      Tensor<2, 3>             J;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          J[i][j] = u[i].dx(j);
      return J;
    }

    /**
     * f = −(2/Re) P div_S σ(u) + P ∇p on the level set through x, with
     * σ = ½(P J P + (P J P)ᵀ), J = ∇u^e, (div_S σ)_i = Σ_jk P_jk ∂_k σ_ij,
     * all derivatives by forward-mode automatic differentiation (exact to rounding).
     */
    Tensor<1, 3>
    manufactured_force(const Point<3> &x, const Tensor<1, 3> &axes, const double Re)
    {
      std::array<Ad2, 3> x2;
      std::array<Ad1, 3> x1;
      for (unsigned int k = 0; k < 3; ++k)
        {
          x2[k] = Ad2(3, k, Ad1(3, k, x[k]));
          x1[k] = Ad1(3, k, x[k]);
        }
      const std::array<Ad2, 3> u = manufactured_velocity(x2, axes);
      // J_ij as a differentiable function: value ∂_j u_i, derivative ∂_k ∂_j u_i.
      Ad1 J[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            J[i][j] = Ad1(3, u[i].val().dx(j));
            for (unsigned int k = 0; k < 3; ++k)
              J[i][j].fastAccessDx(k) = u[i].dx(k).dx(j);
          }
      const std::array<Ad1, 3> n = level_set_normal(x1, axes);
      Ad1                      P[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          P[i][j] = (i == j ? 1.0 : 0.0) - n[i] * n[j];
      Ad1 PJP[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            PJP[i][j] = 0.0;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                PJP[i][j] += P[i][a] * J[a][b] * P[b][j];
          }
      Tensor<1, 3> div_sigma;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const Ad1 sigma_ij = 0.5 * (PJP[i][j] + PJP[j][i]);
            for (unsigned int k = 0; k < 3; ++k)
              div_sigma[i] += P[j][k].val() * sigma_ij.dx(k);
          }
      const Tensor<1, 3> grad_p({x[1] * x[1], 2.0 * x[0] * x[1], 1.0});
      Tensor<2, 3>       P_value;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          P_value[i][j] = P[i][j].val();
      return P_value * (-(2.0 / Re) * div_sigma + grad_p);
    }

    /// P_l'(z) and P_l''(z) of the Legendre polynomial P_l, by the recurrences P_l' = l P_{l−1} + z P_{l−1}'.
    std::array<double, 2>
    legendre_derivatives(const unsigned int l, const double z)
    {
      double p_prev = 1.0, p = z;     // P_0, P_1
      double d_prev = 0.0, d = 1.0;   // P_0', P_1'
      double dd_prev = 0.0, dd = 0.0; // P_0'', P_1''
      if (l == 0)
        return {{0.0, 0.0}};
      for (unsigned int k = 2; k <= l; ++k)
        {
          const double p_next  = ((2.0 * k - 1.0) * z * p - (k - 1.0) * p_prev) / k;
          const double d_next  = k * p + z * d;
          const double dd_next = (k + 1.0) * d + z * dd;
          p_prev = p, p = p_next;
          d_prev = d, d = d_next;
          dd_prev = dd, dd = dd_next;
        }
      (void)p_prev, (void)d_prev, (void)dd_prev;
      return {{d, dd}};
    }

    /// The manufactured Stokes solution on the level sets of Σ x_i²/a_i² with semi-axes @p axes.
    FlowField
    manufactured_solution(const Tensor<1, 3> &axes)
    {
      FlowField exact;
      exact.velocity = [axes](const Point<3> &x, const double) {
        const std::array<double, 3> u = manufactured_velocity<double>({{x[0], x[1], x[2]}}, axes);
        return Tensor<1, 3>({u[0], u[1], u[2]});
      };
      exact.velocity_gradient = [axes](const Point<3> &x, const double) {
        return manufactured_velocity_gradient(x, axes);
      };
      exact.pressure = [](const Point<3> &x, const double) { return x[0] * x[1] * x[1] + x[2]; };
      return exact;
    }

    /// The coordinate axes about which rotations map the ellipsoid with semi-axes @p axes onto itself.
    std::vector<Tensor<1, 3>>
    symmetry_axes(const Tensor<1, 3> &axes)
    {
      std::vector<Tensor<1, 3>> killing_axes;
      for (unsigned int d = 0; d < 3; ++d)
        if (std::abs(axes[(d + 1) % 3] - axes[(d + 2) % 3]) < 1e-12)
          killing_axes.push_back(Tensor<1, 3>({d == 0 ? 1.0 : 0.0, d == 1 ? 1.0 : 0.0, d == 2 ? 1.0 : 0.0}));
      return killing_axes;
    }

    /// The Killing field u = ω e_z × x with p = ½ω²(x² + y²).
    FlowField
    killing_solution(const double w)
    {
      FlowField exact;
      exact.velocity = [w](const Point<3> &x, const double) { return Tensor<1, 3>({-w * x[1], w * x[0], 0.0}); };
      exact.velocity_gradient = [w](const Point<3> &, const double) {
        Tensor<2, 3> J;
        J[0][1] = -w;
        J[1][0] = w;
        return J;
      };
      exact.pressure = [w](const Point<3> &x, const double) { return 0.5 * w * w * (x[0] * x[0] + x[1] * x[1]); };
      return exact;
    }

    /**
     * The decaying mode u = e^{−λt} curl_S Y_l⁰ on the unit sphere; curl_S Y = ν × ∇_S Y with
     * Y = P_l(z) gives u = P_l'(z) (y, −x, 0) e^{−λt}.
     */
    FlowField
    decaying_mode_solution(const unsigned int l, const double lambda, const bool with_convection)
    {
      FlowField exact;
      exact.velocity = [l, lambda](const Point<3> &x, const double t) {
        const double a = legendre_derivatives(l, x[2])[0] * std::exp(-lambda * t);
        return Tensor<1, 3>({a * x[1], -a * x[0], 0.0});
      };
      exact.velocity_gradient = [l, lambda](const Point<3> &x, const double t) {
        const std::array<double, 2> d = legendre_derivatives(l, x[2]);
        const double                e = std::exp(-lambda * t);
        Tensor<2, 3>                J;
        J[0][1] = d[0] * e;
        J[0][2] = d[1] * x[1] * e;
        J[1][0] = -d[0] * e;
        J[1][2] = -d[1] * x[0] * e;
        return J;
      };
      // With convection the zonal flow's ∇_u u = −U² cot θ e_θ is a gradient:
      // p(z) = −e^{−2λt} ∫₀^z s P_l'(s)² ds; without convection p = 0.
      exact.pressure = [l, lambda, with_convection](const Point<3> &x, const double t) {
        if (!with_convection)
          return 0.0;
        const QGauss<1> gauss(l + 2);
        double          integral = 0;
        for (unsigned int k = 0; k < gauss.size(); ++k)
          {
            const double s = x[2] * gauss.point(k)[0];
            const double d = legendre_derivatives(l, s)[0];
            integral += s * d * d * x[2] * gauss.weight(k);
          }
        return -std::exp(-2.0 * lambda * t) * integral;
      };
      return exact;
    }

  } // namespace

  void
  FixedSurfaceScene::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("fixed surface");
    prm.declare_entry("problem",
                      "manufactured sphere",
                      Patterns::Selection("manufactured sphere|manufactured ellipsoid|killing|decaying mode"),
                      "Verification problem on the fixed surface. manufactured sphere/ellipsoid: stationary "
                      "Stokes, u = n × ∇ψ, ψ = xyz + x²y, p = xy² + z, f = −(2/Re)P div_S σ(u) + ∇_S p "
                      "(shape = sphere / ellipsoid); killing: u = ω e_z × x on the sphere, a steady "
                      "Navier–Stokes flow with p = ½ω²(x² + y²); decaying mode: u = exp(−λt) curl_S Y_l⁰ on the "
                      "unit sphere, λ = (l(l+1) − 2)/Re.");
    prm.declare_entry("mode number",
                      "2",
                      Patterns::Integer(2, 10),
                      "Degree l, 2 ≤ l ≤ 10, of the zonal spherical harmonic Y_l⁰ of the decaying mode curl_S Y_l⁰.");
    prm.declare_entry("angular velocity",
                      "1",
                      RealRange::closed(-100, 100),
                      "ω, |ω| ≤ 100, of the Killing field u = ω e_z × x.");
    prm.leave_subsection();
    // `time stepping` is TimeStepper's (this scene reads its end time and time step only), `flow`
    // SurfaceFluid's and `fixed surface solver` SurfaceFlow's; the Simulation declares each once.
  }

  ParametersRead
  FixedSurfaceScene::parameters_read() const
  {
    return {"scene fixed surface",
            {"model",
             "geometry",
             "output",
             "flow",
             "fixed surface",
             "fixed surface solver",
             "linear solver",
             "time stepping"},
            {"flow/conserve momenta",
             "flow/rigid motion regularization",
             "flow/grad-div stabilization",
             "time stepping/adaptive",
             "time stepping/minimum time step",
             "time stepping/maximum time step",
             "time stepping/growth factor",
             "time stepping/shrink factor",
             "time stepping/easy steps before growth",
             "time stepping/energy tolerance",
             "time stepping/error tolerance",
             "time stepping/scheme",
             "time stepping/frame",
             "time stepping/backward Euler steps after rejection",
             "time stepping/energy budget"}};
  }

  void
  FixedSurfaceScene::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("fixed surface");
    const std::string name = prm.get("problem");
    problem     = name == "manufactured sphere"    ? Problem::manufactured_sphere :
                  name == "manufactured ellipsoid" ? Problem::manufactured_ellipsoid :
                  name == "killing"                ? Problem::killing :
                                                     Problem::decaying_mode;
    mode_number = prm.get_integer("mode number");
    omega       = prm.get_double("angular velocity");
    prm.leave_subsection();
    steps = TimeStepper::parse_constant_steps(prm, !is_stationary(), name);
    SurfaceFluid fluid;
    fluid.parse_parameters(prm);
    flow_parameters.parse(prm, fluid);

    const SurfaceGeometry::Parameters &shape_entries = geometry.parameters();
    const std::string                  shape         = SurfaceGeometry::shape_name(shape_entries.shape);
    sphere_radius                                    = shape_entries.radius;
    semi_axes                                        = shape_entries.semi_axes;
    const bool needs_sphere = problem != Problem::manufactured_ellipsoid;
    if (needs_sphere && shape != "sphere")
      throw_invalid_entry("geometry/shape", shape, "sphere (fixed surface/problem = " + name + ")");
    if (!needs_sphere && shape != "ellipsoid")
      throw_invalid_entry("geometry/shape", shape, "ellipsoid (fixed surface/problem = " + name + ")");
    if (problem == Problem::decaying_mode && sphere_radius != 1.0)
      throw_invalid_entry("geometry/radius",
                          std::to_string(sphere_radius),
                          "1 (the decaying mode's rate (l(l+1) − 2)/Re is for the unit sphere)");
    if (needs_sphere)
      semi_axes = Tensor<1, 3>({sphere_radius, sphere_radius, sphere_radius});
    if ((problem == Problem::killing || problem == Problem::decaying_mode) && !flow_parameters.fluid.inertia)
      throw_invalid_entry("flow/inertia", "false", "true for the time-dependent problem " + name);
  }

  FixedSurfaceScene::FixedSurfaceScene(SurfaceGeometry          &geometry,
                                       OutputWriter             &output,
                                       StatisticsFile           &statistics,
                                       const ConditionalOStream &pcout)
    : Scene(geometry, output, statistics, pcout)
  {}

  void
  FixedSurfaceScene::run()
  {
    wall_timer.restart();
    last_results = Results();

    SurfaceFlow     flow(geometry, flow_parameters);
    const FlowField exact         = set_up_problem(flow);
    last_results.n_dofs           = flow.dof_handler().n_dofs();
    last_results.exact_decay_rate = (problem == Problem::decaying_mode ? decay_rate() : 0.0);
    pcout << "-- fixed surface: " << geometry.description() << '\n'
          << "   " << flow.description() << std::endl;

    current_step = 0;
    current_time = 0;
    try
      {
        if (is_stationary())
          solve_stationary(flow, exact);
        else
          run_time_loop(flow, exact);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &exc)
      {
        // One line on the screen; the solver's own report (Trilinos, Amesos, GMRES) in error.log.
        std::ostringstream reason;
        reason << "step " << current_step << " failed at t = " << current_time << ": " << one_line_message(exc, 200);
        const auto *solver_error = dynamic_cast<const LinearSolverError *>(&exc);
        if (Utilities::MPI::this_mpi_process(geometry.get_communicator()) == 0)
          append_to_error_log(output.directory(),
                              reason.str() + '\n' + (solver_error ? solver_error->details() : std::string(exc.what())));
        throw RunFailed(reason.str(),
                        "the report is in " + output.directory() + "error.log; try 'fixed surface solver/linear "
                        "solver = direct', a larger 'fixed surface solver/max linear iterations' or a smaller "
                        "'time stepping/time step'");
      }
    last_results.wall_time = wall_timer.wall_time();
  }

  bool
  FixedSurfaceScene::is_stationary() const
  {
    return problem == Problem::manufactured_sphere || problem == Problem::manufactured_ellipsoid;
  }

  double
  FixedSurfaceScene::decay_rate() const
  {
    return (mode_number * (mode_number + 1.0) - 2.0) / flow_parameters.fluid.Re;
  }

  FlowField
  FixedSurfaceScene::set_up_problem(SurfaceFlow &flow) const
  {
    const Tensor<1, 3> axes = semi_axes;
    const double       Re   = flow_parameters.fluid.Re;
    flow.set_terms(!is_stationary(), flow_parameters.fluid.convection);
    flow.set_exact_normal([axes](const Point<3> &x) { return exact_normal(x, axes); });
    if (is_stationary())
      {
        flow.set_body_force([axes, Re](const Point<3> &x, const double) { return manufactured_force(x, axes, Re); });
        flow.setup(symmetry_axes(axes));
        return manufactured_solution(axes);
      }
    flow.setup();
    return problem == Problem::killing ? killing_solution(omega) :
                                         decaying_mode_solution(mode_number, decay_rate(), flow_parameters.fluid.convection);
  }

  void
  FixedSurfaceScene::solve_stationary(SurfaceFlow &flow, const FlowField &exact)
  {
    const SurfaceFlow::SolveInfo info = flow.solve_stationary();
    record(flow, exact, 0, 0.0, 0.0, info);
    write_output(flow, 0.0);
    last_results.initial_kinetic_energy = last_results.final_kinetic_energy;
  }

  void
  FixedSurfaceScene::run_time_loop(SurfaceFlow &flow, const FlowField &exact)
  {
    flow.set_initial_velocity(exact, 0.0);
    last_results.initial_kinetic_energy = record(flow, exact, 0, 0.0, steps.time_step, SurfaceFlow::SolveInfo());
    write_output(flow, 0.0);
    const unsigned int n_steps   = steps.n_steps;
    const double       time_step = steps.time_step;
    double             time      = 0;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        time                              = step * time_step;
        current_step                      = step;
        current_time                      = time;
        const SurfaceFlow::SolveInfo info = flow.advance(time, time_step);
        record(flow, exact, step, time, time_step, info);
        if (output.due(time) || step == n_steps)
          write_output(flow, time);
      }
    last_results.steps = n_steps;
    const double F0 = last_results.initial_kinetic_energy, F1 = last_results.final_kinetic_energy;
    last_results.energy_change       = std::abs(F1 - F0) / F0;
    last_results.measured_decay_rate = -std::log(F1 / F0) / (2.0 * time);
    if (problem == Problem::killing)
      pcout << "-- Killing field: relative change of the kinetic energy over t = " << time << ": "
            << last_results.energy_change << std::endl;
    if (problem == Problem::decaying_mode)
      pcout << "-- decaying mode l = " << mode_number << ": measured rate " << std::setprecision(8)
            << last_results.measured_decay_rate << ", exact " << decay_rate() << std::setprecision(6) << std::endl;
  }

  double
  FixedSurfaceScene::record(const SurfaceFlow            &flow,
                            const FlowField              &exact,
                            const unsigned int            step,
                            const double                  time,
                            const double                  tau,
                            const SurfaceFlow::SolveInfo &info)
  {
    const double              energy      = flow.kinetic_energy();
    const double              dissipation = flow.dissipation_rate();
    const SurfaceFlow::Errors errors      = flow.compute_errors(exact, time);
    statistics.add_value("time step", step);
    statistics.add_value("time", time);
    statistics.add_value("tau", tau);
    statistics.add_value("kinetic energy", energy);
    statistics.add_value("dissipation rate", dissipation);
    statistics.add_value("linear iterations", info.iterations);
    statistics.add_value("velocity error L2", errors.velocity);
    statistics.add_value("tangential velocity error L2", errors.tangential);
    statistics.add_value("velocity gradient error L2", errors.gradient);
    statistics.add_value("pressure error L2", errors.pressure);
    statistics.add_value("normal velocity L2", errors.normal_velocity);
    statistics.add_value("wall time", wall_timer.wall_time());
    statistics.end_row();
    last_results.errors               = errors;
    last_results.final_kinetic_energy = energy;
    last_results.total_iterations += info.iterations;
    last_results.max_iterations = std::max(last_results.max_iterations, info.iterations);
    last_results.factorizations += info.factorized;
    last_results.assemble_time += info.assemble_time;
    last_results.solve_time += info.solve_time;
    pcout << "*** Step " << step << "  t = " << time << "  τ = " << tau << "  (" << info.iterations << " its"
          << (info.factorized ? ", new factorization" : "") << ")\n"
          << std::setprecision(8) << "    F_kin = " << energy << "  D = " << dissipation << std::setprecision(3)
          << "  ‖u−u_h‖ = " << errors.velocity << "  ‖∇_P(u−u_h)‖ = " << errors.gradient
          << "  ‖p−p_h‖ = " << errors.pressure << "  ‖u_h·ν‖ = " << errors.normal_velocity << std::setprecision(6)
          << std::endl;
    return energy;
  }

  void
  FixedSurfaceScene::write_output(const SurfaceFlow &flow, const double time)
  {
    const SpeedPostprocessor speed;
    output.write(geometry, time, [&](DataOut<2, 3> &data_out) {
      std::vector<std::string> names(3, "velocity");
      names.emplace_back("pressure");
      std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
        3, DataComponentInterpretation::component_is_part_of_vector);
      interpretation.push_back(DataComponentInterpretation::component_is_scalar);
      if (flow.dof_handler().get_fe().n_components() == 5)
        {
          names.emplace_back("tangentiality_multiplier");
          interpretation.push_back(DataComponentInterpretation::component_is_scalar);
        }
      data_out.add_data_vector(flow.dof_handler(), flow.solution(), names, interpretation);
      data_out.add_data_vector(flow.dof_handler(), flow.solution(), speed);
    });
  }
} // namespace FluidSurface
