// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <fluid_surface/base/vector_math.h>
#include <fluid_surface/flow/energy_functionals.h>
#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/postprocess/diagnostics.h>
#include <fluid_surface/io/parameter_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  void
  Diagnostics::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("diagnostics");
    prm.declare_entry("axis",
                      "0, 0, 1",
                      Patterns::List(RealRange::any(), 3, 3),
                      "Axis e of the angular velocity ω(t) = (1/|S|)∫(u·e_φ)/r (through the centre of mass): three "
                      "finite numbers, not all 0 (normalized).");
    prm.declare_entry("angular velocity window",
                      "5, 10",
                      Patterns::List(RealRange::at_least(0), 2, 2),
                      "Time window [t₀, t₁], 0 ≤ t₀ < t₁, of the mean angular velocity ⟨ω⟩ in the summary.");
    prm.declare_entry("reference equilibrium",
                      "none",
                      Patterns::Selection("none|prolate|oblate"),
                      "Branch of the reference shape S_O of the L² distance E(L²) (seed eq. 8): the rotating "
                      "axisymmetric equilibrium about e with the run's initial area, reduced volume and angular "
                      "momentum L·e (Be of subsection bending). none: E(L²) is not computed. The summary adds "
                      "the distance of the final surface to the equilibrium rotating with the measured ⟨ω⟩.");
    prm.declare_entry("section angles",
                      "256",
                      Patterns::Integer(16, 65536),
                      "Number n, 16 ≤ n ≤ 65536, of equispaced polar angles φ_j at which the sections of S and S_O are compared "
                      "in E(L²) (trapezoidal rule).");
    prm.declare_entry("azimuthal modes",
                      "",
                      Patterns::List(Patterns::Integer(1, 16), 0, 16),
                      "Wavenumbers m, 1 ≤ m ≤ 16, of the azimuthal moments Q_m = (1/|S|)∫ h_m(x − x_c) dA about e "
                      "through the centre of mass x_c, h_m = ξ^m (even; ξ(5ζ² − |x|²) for m = 1) and ζξ^m (odd), "
                      "ξ = x·e₁ + i x·e₂, ζ = x·e: "
                      "zero on a shape symmetric about e; on a perturbed rotating equilibrium |Q_m| grows or decays "
                      "with the m-th modes' rate and arg Q_m turns at m times the pattern's angular velocity. Columns "
                      "`mode m even amplitude`, `… phase`, `mode m odd amplitude`, `… phase`. Empty: none.");
    prm.leave_subsection();
  }

  void
  Diagnostics::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("diagnostics");
    axis = unit_vector(get_vector(prm, "axis"));
    if (axis.norm() == 0)
      throw_invalid_entry("diagnostics/axis", prm.get("axis"), "a non-zero vector");
    const auto w = Utilities::split_string_list(prm.get("angular velocity window"));
    angular_velocity_window[0] = Utilities::string_to_double(w[0]);
    angular_velocity_window[1] = Utilities::string_to_double(w[1]);
    if (!(angular_velocity_window[1] > angular_velocity_window[0]))
      throw_invalid_entry("diagnostics/angular velocity window",
                          prm.get("angular velocity window"),
                          "t₀ < t₁");
    const std::string branch = prm.get("reference equilibrium");
    reference_equilibrium.reset();
    if (branch != "none")
      reference_equilibrium =
        branch == "oblate" ? AxisymmetricEquilibrium::Branch::oblate : AxisymmetricEquilibrium::Branch::prolate;
    section_angles        = prm.get_integer("section angles");
    azimuthal_modes.clear();
    for (const auto &m : Utilities::split_string_list(prm.get("azimuthal modes")))
      azimuthal_modes.push_back(Utilities::string_to_int(m));
    prm.leave_subsection();
  }

  namespace
  {
    /// x(ξ) and ∂x/∂ξ of the position field on one cell, from its local DoF values.
    struct CellMap
    {
      const FiniteElement<2, 3> &fe;
      Vector<double>             X;

      Point<3>
      value(const Point<2> &xi) const
      {
        Point<3> x;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          x[fe.system_to_component_index(i).first] += X(i) * fe.shape_value(i, xi);
        return x;
      }
      Tensor<2, 3>
      jacobian(const Point<2> &xi) const ///< columns 0, 1: ∂x/∂ξ₁, ∂x/∂ξ₂
      {
        Tensor<2, 3> J;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const Tensor<1, 2> g = fe.shape_grad(i, xi);
            for (unsigned int a = 0; a < 2; ++a)
              J[fe.system_to_component_index(i).first][a] += X(i) * g[a];
          }
        return J;
      }
    };

    /// A piece of the piecewise linear section in one cell: end points in reference and plane coordinates.
    struct Segment
    {
      Point<2> xi[2];
      Point<2> p[2];
    };

    /// The plane of a section: its centre, the orthonormal in-plane directions e₁, e₂ and the normal n.
    struct SectionPlane
    {
      const Point<3>     &centre;
      const Tensor<1, 3> &e1, &e2;
      Tensor<1, 3>        n;
    };

    /// A ray of the section at polar angle φ: its direction in plane coordinates and in space, and the
    /// in-plane direction across it.
    struct SectionRay
    {
      Tensor<1, 2> dir;
      Tensor<1, 3> ray, across;
    };

    /// Whether the cell may meet the plane: cells whose nodes lie clearly on one side of it are skipped (the
    /// margin covers the bulge of a curved cell beyond its nodes).
    bool
    cell_may_meet_plane(const CellMap &map, const SectionPlane &plane)
    {
      // A Lagrange position field: the nodes are the DoF values.
      std::vector<Point<3>> nodes(map.fe.base_element(0).n_dofs_per_cell());
      for (unsigned int i = 0; i < map.fe.n_dofs_per_cell(); ++i)
        nodes[map.fe.system_to_component_index(i).second][map.fe.system_to_component_index(i).first] = map.X(i);
      double d_min = 1e300, d_max = -1e300, size = 0;
      for (const Point<3> &x : nodes)
        {
          const double d = (x - plane.centre) * plane.n;
          d_min          = std::min(d_min, d);
          d_max          = std::max(d_max, d);
          size           = std::max(size, x.distance(nodes[0]));
        }
      const double margin = 0.1 * size;
      return !(d_min > margin || d_max < -margin);
    }

    /// The piecewise linear section of one cell: the crossings of the plane with the two triangles of each
    /// of the m × m sub-squares of the reference cell.
    std::vector<Segment>
    linear_section(const CellMap &map, const SectionPlane &plane)
    {
      constexpr unsigned int m = 4;
      Point<2>               xi[m + 1][m + 1];
      Point<2>               in_plane[m + 1][m + 1];
      double                 dist[m + 1][m + 1];
      for (unsigned int a = 0; a <= m; ++a)
        for (unsigned int b = 0; b <= m; ++b)
          {
            xi[a][b]             = Point<2>(double(a) / m, double(b) / m);
            const Tensor<1, 3> x = map.value(xi[a][b]) - plane.centre;
            in_plane[a][b]       = Point<2>(x * plane.e1, x * plane.e2);
            dist[a][b]           = x * plane.n;
          }
      std::vector<Segment> segments;
      const unsigned int   triangles[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          for (const auto &t : triangles)
            {
              Segment      s;
              unsigned int n_crossings = 0;
              for (unsigned int e = 0; e < 3; ++e)
                {
                  const unsigned int a0 = a + t[e][0], b0 = b + t[e][1];
                  const unsigned int a1 = a + t[(e + 1) % 3][0], b1 = b + t[(e + 1) % 3][1];
                  const double       d0 = dist[a0][b0], d1 = dist[a1][b1];
                  if ((d0 >= 0) == (d1 >= 0) || n_crossings == 2)
                    continue;
                  const double w     = d0 / (d0 - d1);
                  s.xi[n_crossings]  = xi[a0][b0] + w * (xi[a1][b1] - xi[a0][b0]);
                  s.p[n_crossings]   = in_plane[a0][b0] + w * (in_plane[a1][b1] - in_plane[a0][b0]);
                  ++n_crossings;
                }
              if (n_crossings == 2)
                segments.push_back(s);
            }
      return segments;
    }

    /**
     * The distance from the centre along @p ray to the curved cell, where the ray crosses the linear segment
     * @p s (or its extension by half its length): Newton for (x(ξ) − c)·n = 0, (x(ξ) − c)·across = 0,
     * started on the segment. Returns −1 when the ray misses the segment or the point lies outside the cell.
     */
    double
    ray_distance(const CellMap &map, const SectionPlane &plane, const SectionRay &ray, const Segment &s)
    {
      const Tensor<1, 2> &dir = ray.dir;
      const Tensor<1, 3> &n = plane.n, &across = ray.across;
      // s·dir = p0 + w (p1 − p0) by Cramer's rule.
      const Tensor<1, 2> D   = s.p[1] - s.p[0];
      const double       det = -dir[0] * D[1] + D[0] * dir[1];
      if (std::abs(det) < 1e-14 * (D.norm() + 1e-300))
        return -1;
      const double w = (dir[0] * s.p[0][1] - dir[1] * s.p[0][0]) / det;
      const double r = (s.p[0][0] * (-D[1]) + D[0] * s.p[0][1]) / det;
      if (w < -0.5 || w > 1.5 || r <= 0)
        return -1;
      Point<2> z = s.xi[0] + std::clamp(w, 0.0, 1.0) * (s.xi[1] - s.xi[0]);
      bool     converged = false;
      for (unsigned int it = 0; it < 20 && !converged; ++it)
        {
          const Tensor<1, 3> x = map.value(z) - plane.centre;
          const Tensor<2, 3> J = map.jacobian(z);
          const double       g0 = x * n, g1 = x * across;
          double             A[2][2];
          for (unsigned int a = 0; a < 2; ++a)
            {
              A[0][a] = n[0] * J[0][a] + n[1] * J[1][a] + n[2] * J[2][a];
              A[1][a] = across[0] * J[0][a] + across[1] * J[1][a] + across[2] * J[2][a];
            }
          const double detA = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          if (detA == 0)
            break;
          const Point<2> dz((A[1][1] * g0 - A[0][1] * g1) / detA, (-A[1][0] * g0 + A[0][0] * g1) / detA);
          z -= dz;
          converged = dz.norm() < 1e-12;
          if (z.norm() > 3)
            break;
        }
      // A point a hair outside the cell (the polynomial map extends smoothly) is kept: near a cell edge the
      // neighbour's short sub-segment may miss the ray.
      const double slack = 1e-3;
      if (!converged || z[0] < -slack || z[0] > 1 + slack || z[1] < -slack || z[1] > 1 + slack)
        return -1;
      return (map.value(z) - plane.centre) * ray.ray;
    }
  } // namespace

  std::vector<double>
  section_polar_radius(const SurfaceGeometry &geometry,
                       const Point<3>        &centre,
                       const Tensor<1, 3>    &e1,
                       const Tensor<1, 3>    &e2,
                       const unsigned int     n_angles)
  {
    const SectionPlane  plane{centre, e1, e2, cross_product_3d(e1, e2)};
    std::vector<double> radius(n_angles, -1.0);
    CellMap             map{geometry.fe(), Vector<double>(geometry.fe().n_dofs_per_cell())};

    for (const auto &cell : geometry.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(geometry.position(), map.X);
          if (!cell_may_meet_plane(map, plane))
            continue;
          const std::vector<Segment> segments = linear_section(map, plane);
          if (segments.empty())
            continue;
          for (unsigned int j = 0; j < n_angles; ++j)
            {
              const double     phi = 2 * numbers::PI * j / n_angles;
              const SectionRay ray{Tensor<1, 2>({std::cos(phi), std::sin(phi)}),
                                   std::cos(phi) * e1 + std::sin(phi) * e2,
                                   -std::sin(phi) * e1 + std::cos(phi) * e2};
              for (const Segment &s : segments)
                {
                  const double distance = ray_distance(map, plane, ray, s);
                  if (distance > 0)
                    radius[j] = std::max(radius[j], distance);
                }
            }
        }
    Utilities::MPI::max(radius, geometry.get_communicator(), radius);
    for (double &r : radius)
      if (r < 0)
        r = std::numeric_limits<double>::quiet_NaN();
    return radius;
  }

  double
  polar_l2_distance(const std::vector<double> &r_E, const std::vector<double> &r_O)
  {
    AssertDimension(r_E.size(), r_O.size());
    double sum = 0;
    for (unsigned int j = 0; j < r_E.size(); ++j)
      sum += (r_O[j] - r_E[j]) * (r_O[j] - r_E[j]);
    return std::sqrt(sum * 2 * numbers::PI / r_E.size());
  }

  namespace
  {
    /// r_O(φ_j) = meridian_radius(φ_j), φ_j = 2πj/n.
    std::vector<double>
    meridian_radii(const AxisymmetricEquilibrium &shape, const unsigned int n)
    {
      std::vector<double> r(n);
      for (unsigned int j = 0; j < n; ++j)
        r[j] = shape.meridian_radius(2 * numbers::PI * j / n);
      return r;
    }
  } // namespace

  std::pair<double, double>
  Diagnostics::l2_distance(const SurfaceGeometry &geometry, const AxisymmetricEquilibrium &shape) const
  {
    return l2_distance(geometry, meridian_radii(shape, section_angles), shape.equatorial_radius());
  }

  std::pair<double, double>
  Diagnostics::l2_distance(const SurfaceGeometry     &geometry,
                           const std::vector<double> &meridian,
                           const double               equator) const
  {
    // e⊥: the unit vector normal to e closest to x (or y when e ∥ x).
    Tensor<1, 3> normal_direction({1., 0., 0.});
    if (std::abs(axis * normal_direction) > 0.9)
      normal_direction = Tensor<1, 3>({0., 1., 0.});
    normal_direction -= (normal_direction * axis) * axis;
    normal_direction /= normal_direction.norm();
    const Point<3> c(geometry.measure().centre_of_mass);
    // Axial section: φ is the polar angle from e towards e⊥, as in meridian_radius().
    const double axial =
      polar_l2_distance(section_polar_radius(geometry, c, axis, normal_direction, section_angles), meridian);
    const double equatorial =
      polar_l2_distance(section_polar_radius(geometry, c, normal_direction, cross_product_3d(axis, normal_direction),
                                             section_angles),
                        std::vector<double>(section_angles, equator));
    return {axial, equatorial};
  }

  void
  Diagnostics::set_reference(const Values &initial_values, const double bending_number, std::ostream &out)
  {
    reference_shape.reset();
    if (!reference_equilibrium)
      return;
    const std::string branch_name =
      *reference_equilibrium == AxisymmetricEquilibrium::Branch::oblate ? "oblate" : "prolate";
    AxisymmetricEquilibrium::Parameters p;
    p.area             = initial_values.area;
    p.reduced_volume   = initial_values.reduced_volume;
    p.branch           = *reference_equilibrium;
    p.bending_number   = bending_number;
    p.prescribed       = AxisymmetricEquilibrium::Prescribed::angular_momentum;
    p.angular_momentum = initial_values.angular_momentum * axis;
    reference_shape    = std::make_unique<AxisymmetricEquilibrium>(p);
    try
      {
        reference_shape->solve();
      }
    catch (const std::exception &exc)
      {
        throw EntryError("diagnostics/reference equilibrium = " + branch_name +
                         ": no rotating equilibrium with the run's area " + std::to_string(p.area) +
                         ", reduced volume " + std::to_string(p.reduced_volume) + " and angular momentum " +
                         std::to_string(p.angular_momentum) + " (" + exc.what() +
                         "); expected a branch that exists, or none.");
      }
    reference_meridian = meridian_radii(*reference_shape, section_angles);
    out << "   E(L2) reference: " << branch_name << " equilibrium at L = " << std::setprecision(8)
        << p.angular_momentum
        << ": ω = " << reference_shape->angular_velocity() << ", F_bend = " << reference_shape->bending_energy()
        << ", I_zz = " << reference_shape->inertia_zz() << std::endl;
  }

  void
  Diagnostics::compare_with_mean_rotation(const SurfaceGeometry &geometry)
  {
    if (!reference_shape)
      return;
    std::ostringstream text;
    text << std::setprecision(10);
    if (!(omega_time > 0))
      {
        text << "L2 distance to equilibrium at mean angular velocity: n/a (the run did not reach the window)\n";
        mean_rotation_comparison = text.str();
        return;
      }
    AxisymmetricEquilibrium::Parameters p = reference_shape->parameters();
    p.prescribed                          = AxisymmetricEquilibrium::Prescribed::angular_velocity;
    p.angular_velocity                    = omega_integral / omega_time;
    AxisymmetricEquilibrium shape(p);
    try
      {
        shape.solve();
        const auto d = l2_distance(geometry, shape);
        text << "mean-rotation equilibrium bending energy: " << shape.bending_energy() << '\n'
             << "mean-rotation equilibrium inertia zz: " << shape.inertia_zz() << '\n'
             << "mean-rotation equilibrium angular momentum: " << shape.angular_momentum() << '\n'
             << "L2 distance to equilibrium at mean angular velocity: " << std::hypot(d.first, d.second) << '\n';
      }
    catch (const std::exception &exc)
      {
        text << "L2 distance to equilibrium at mean angular velocity: n/a (" << exc.what() << ")\n";
      }
    mean_rotation_comparison = text.str();
  }

  namespace
  {
    /**
     * The values of @p v that follow from the inertia tensor @p I and the angular momentum and kinetic energy
     * already in @p v: the eigenvalues λ₁ ≤ λ₂ ≤ λ₃, the elongation axis, e(λ), Ω = I⁻¹L, the tilt angle and the
     * rigid fraction.
     */
    void
    set_inertia_values(const Tensor<2, 3> &I, Diagnostics::Values &v)
    {
      LAPACKFullMatrix<double> inertia(3, 3);
      for (unsigned int d = 0; d < 3; ++d)
        for (unsigned int e = 0; e < 3; ++e)
          inertia(d, e) = I[d][e];
      FullMatrix<double> eigenvectors;
      Vector<double>     eigenvalues;
      inertia.compute_eigenvalues_symmetric(-1e300, 1e300, 0, eigenvalues, eigenvectors);
      // LAPACK returns them ascending.
      for (unsigned int d = 0; d < 3; ++d)
        {
          v.eigenvalues[d]     = eigenvalues(d);
          v.elongation_axis[d] = eigenvectors(d, 0);
          v.largest_inertia_axis[d] = eigenvectors(d, 2);
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
    }
  } // namespace

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
    // [0] F_kin, [1] ∫ω-integrand, [2..4] ∫u, [5..7] L, [8..16] I, then Re and Im of ∫h_m (even, odd) per m
    std::vector<AzimuthalHarmonic> harmonics;
    for (const unsigned int mode : azimuthal_modes)
      for (const bool odd : {false, true})
        harmonics.emplace_back(axis, mode, odd);
    std::vector<double> local(17 + 2 * harmonics.size());
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
              local[0] += EnergyFunctionals::kinetic_energy_density(u[k]) * dA;
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
              for (unsigned int j = 0; j < harmonics.size(); ++j)
                {
                  const std::complex<double> h = harmonics[j](x);
                  local[17 + 2 * j] += h.real() * dA;
                  local[18 + 2 * j] += h.imag() * dA;
                }
              max_un = std::max(max_un, std::abs(u[k] * fe_values.normal_vector(k)));
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(local.data(), local.size()), geometry.get_communicator(),
                        ArrayView<double>(local.data(), local.size()));
    for (unsigned int j = 0; j < harmonics.size(); ++j)
      v.azimuthal_moments.emplace_back(local[17 + 2 * j] / m.area, local[18 + 2 * j] / m.area);
    v.max_normal_velocity = Utilities::MPI::max(max_un, geometry.get_communicator());
    v.kinetic_energy      = local[0];
    v.angular_velocity    = local[1] / m.area;
    Tensor<2, 3> I;
    for (unsigned int d = 0; d < 3; ++d)
      {
        v.linear_momentum[d]  = local[2 + d];
        v.angular_momentum[d] = local[5 + d];
        for (unsigned int e = 0; e < 3; ++e)
          I[d][e] = local[8 + 3 * d + e];
      }
    set_inertia_values(I, v);
    if (reference_shape)
      {
        const auto d = l2_distance(geometry, reference_meridian, reference_shape->equatorial_radius());
        v.l2_distance_axial      = d.first;
        v.l2_distance_equatorial = d.second;
        v.l2_distance            = std::hypot(d.first, d.second);
      }
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
    // The scale of L: |L₀|, or |P₀|R (R = √(A₀/4π)) for a translating body whose |L₀| is round-off (a drift of
    // round-off over round-off says nothing, and differs between machines).
    const double L0 = std::max(initial.angular_momentum.norm(),
                               initial.linear_momentum.norm() * std::sqrt(initial.area / (4 * numbers::PI)));
    if (L0 > 0)
      angular_momentum_drift =
        std::max(angular_momentum_drift, (v.angular_momentum - initial.angular_momentum).norm() / L0);
    // e(λ) grows exponentially between two steps: the crossing of a level is interpolated in ln e(λ).
    const auto crossing = [&](const double level) {
      if (!(last_deviation > 0) || !(last_deviation <= level) || !(v.symmetry_deviation > last_deviation))
        return time;
      return last_time + (time - last_time) * std::log(level / last_deviation) /
                           std::log(v.symmetry_deviation / last_deviation);
    };
    if (std::isnan(crossing_1e4) && v.symmetry_deviation > 1e-4)
      crossing_1e4 = crossing(1e-4);
    if (std::isnan(crossing_1e2) && v.symmetry_deviation > 1e-2)
      crossing_1e2 = crossing(1e-2);
    last_time             = time;
    last_deviation        = v.symmetry_deviation;
    last_angular_velocity = v.angular_velocity;
    if (reference_shape && std::isfinite(v.l2_distance) && !(v.l2_distance >= min_l2_distance))
      {
        min_l2_distance = v.l2_distance;
        min_l2_time     = time;
      }
    // ⟨ω⟩ by the rectangle rule over the steps ending inside the window.
    const double t0 = angular_velocity_window[0], t1 = angular_velocity_window[1];
    if (tau > 0 && time > t0 && time - tau < t1)
      {
        const double overlap = std::min(time, t1) - std::max(time - tau, t0);
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
    if (reference_shape)
      {
        statistics.add_value("L2 distance to equilibrium", v.l2_distance);
        statistics.add_value("L2 distance axial section", v.l2_distance_axial);
        statistics.add_value("L2 distance equatorial section", v.l2_distance_equatorial);
      }
    for (unsigned int j = 0; j < v.azimuthal_moments.size(); ++j)
      {
        const std::string name = "mode " + std::to_string(azimuthal_modes[j / 2]) + (j % 2 ? " odd" : " even");
        statistics.add_value(name + " amplitude", std::abs(v.azimuthal_moments[j]));
        statistics.add_value(name + " phase", std::arg(v.azimuthal_moments[j]));
      }
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
        << "final angular velocity: " << last_angular_velocity << '\n'
        << "max area drift: " << area_drift << '\n'
        << "max volume drift: " << volume_drift << '\n'
        << "max angular momentum drift: " << angular_momentum_drift << '\n'
        << "steps: " << steps << '\n'
        << "rejected steps: " << rejected_steps << '\n'
        << "wall time: " << wall_time << '\n';
    if (reference_shape)
      out << "reference equilibrium angular velocity: " << reference_shape->angular_velocity() << '\n'
          << "reference equilibrium bending energy: " << reference_shape->bending_energy() << '\n'
          << "reference equilibrium inertia zz: " << reference_shape->inertia_zz() << '\n'
          << "min L2 distance to equilibrium: " << min_l2_distance << '\n'
          << "time of min L2 distance: " << min_l2_time << '\n'
          << mean_rotation_comparison;
  }

  void
  Diagnostics::save(CheckpointData &data) const
  {
    data.set("diagnostics/have initial", have_initial);
    data.set("diagnostics/initial area", initial.area);
    data.set("diagnostics/initial volume", initial.volume);
    data.set("diagnostics/initial reduced volume", initial.reduced_volume);
    data.set("diagnostics/min L2 distance", min_l2_distance);
    data.set("diagnostics/min L2 time", min_l2_time);
    data.set("diagnostics/initial angular momentum", initial.angular_momentum);
    data.set("diagnostics/max area drift", area_drift);
    data.set("diagnostics/max volume drift", volume_drift);
    data.set("diagnostics/max angular momentum drift", angular_momentum_drift);
    data.set("diagnostics/t_sym_1e-4", crossing_1e4);
    data.set("diagnostics/t_sym_1e-2", crossing_1e2);
    data.set("diagnostics/last time", last_time);
    data.set("diagnostics/last symmetry deviation", last_deviation);
    data.set("diagnostics/last angular velocity", last_angular_velocity);
    data.set("diagnostics/omega integral", omega_integral);
    data.set("diagnostics/omega time", omega_time);
  }

  void
  Diagnostics::load(const CheckpointData &data)
  {
    have_initial             = data.get_bool("diagnostics/have initial");
    initial.area             = data.get_double("diagnostics/initial area");
    initial.volume           = data.get_double("diagnostics/initial volume");
    initial.reduced_volume   = data.get_double("diagnostics/initial reduced volume");
    min_l2_distance          = data.get_double("diagnostics/min L2 distance");
    min_l2_time              = data.get_double("diagnostics/min L2 time");
    initial.angular_momentum = data.get_tensor("diagnostics/initial angular momentum");
    area_drift               = data.get_double("diagnostics/max area drift");
    volume_drift             = data.get_double("diagnostics/max volume drift");
    angular_momentum_drift   = data.get_double("diagnostics/max angular momentum drift");
    crossing_1e4             = data.get_double("diagnostics/t_sym_1e-4");
    crossing_1e2             = data.get_double("diagnostics/t_sym_1e-2");
    const bool has_last      = data.has("diagnostics/last time"); // not in checkpoints before the interpolation
    last_time                = has_last ? data.get_double("diagnostics/last time") : std::numeric_limits<double>::quiet_NaN();
    last_deviation =
      has_last ? data.get_double("diagnostics/last symmetry deviation") : std::numeric_limits<double>::quiet_NaN();
    last_angular_velocity    = data.has("diagnostics/last angular velocity") ?
                                 data.get_double("diagnostics/last angular velocity") :
                                 std::numeric_limits<double>::quiet_NaN();
    omega_integral           = data.get_double("diagnostics/omega integral");
    omega_time               = data.get_double("diagnostics/omega time");
  }
} // namespace FluidSurface
