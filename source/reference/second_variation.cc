// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/reference/normal_graph_expansion.h>
#include <fluid_surface/reference/second_variation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <stdexcept>

namespace FluidSurface
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;
    namespace NG       = NormalGraphExpansion;
    using Matrix       = dealii::FullMatrix<double>;
    using Vector       = dealii::Vector<double>;

    /// The matrices of one azimuthal number and parity in the basis b_k (K functions).
    struct ModeMatrices
    {
      Matrix              isolated, driven; ///< the second variations of the two Lagrangians
      Matrix              mass;             ///< G: ∫f_i f_j dA
      std::vector<Vector> constraints;      ///< δA, δV and ∫f ν₀ dA (x, y, z): the rows of the constraints
      Vector              first_variation;  ///< δ of the Lagrangian (zero at an equilibrium)
      Vector              willmore_first_variation; ///< δW, for the scale of the residual
    };

    /// The trial functions a_i and their s-derivatives (a, a', a'') at one point (θ = πs/(2S), s), one row each.
    using TrialFunctions = std::function<std::vector<std::array<double, 3>>(const double theta, const double s)>;

    /// The basis b_k(θ(s)) = sin^m θ cos(kθ), k of the parity, K functions, with their s-derivatives.
    TrialFunctions
    basis(const unsigned int m, const bool odd, const unsigned int K, const double S)
    {
      return [=](const double theta, const double) {
        const double                       d = pi / (2 * S); // dθ/ds
        std::vector<std::array<double, 3>> B(K);
        for (unsigned int i = 0; i < K; ++i)
          {
            const std::array<double, 3> b = SecondVariation::basis_function(m, (odd ? 1 : 0) + 2 * i, theta);
            B[i]                          = {{b[0], b[1] * d, b[2] * d * d}};
          }
        return B;
      };
    }

    /// vv += factor · u uᵀ.
    void
    add_outer_product(Matrix &vv, const double factor, const Vector &u)
    {
      for (unsigned int i = 0; i < u.size(); ++i)
        for (unsigned int j = 0; j < u.size(); ++j)
          vv(i, j) += factor * u[i] * u[j];
    }

    /**
     * Assembles the second variations at @p equilibrium for f = a cos(mφ), a = Σ c_i a_i over the @p K @p trial
     * functions, with @p n_quadrature Gauss–Legendre points in θ = πs/(2S) ∈ (0, π).
     */
    ModeMatrices
    assemble_mode(const AxisymmetricEquilibrium &equilibrium, const unsigned int m, const TrialFunctions &trial,
                  const unsigned int K, const unsigned int n_quadrature)
    {
      const double S = 0.5 * equilibrium.curve_length(), omega = equilibrium.angular_velocity();
      const double Be = equilibrium.parameters().bending_number;
      // The multipliers of G = W − ½ω²I_zz + σA − PV (AxisymmetricEquilibrium::p0(), gamma()).
      const double sigma = -equilibrium.p0(), P = -equilibrium.gamma();
      std::array<double, NG::n_functionals> lagrangian{};
      lagrangian[NG::willmore]   = 1 / Be;
      lagrangian[NG::area]       = sigma;
      lagrangian[NG::volume]     = -P;
      lagrangian[NG::inertia_zz] = -0.5 * omega * omega;

      ModeMatrices result;
      result.driven.reinit(K, K);
      result.mass.reinit(K, K);
      std::vector<Vector> gradient(NG::n_functionals, Vector(K)), translation(3, Vector(K));
      std::array<double, NG::n_functionals> value{};

      const dealii::QGauss<1> gauss(n_quadrature);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double theta = pi * gauss.point(q)[0], s = 2 * S * gauss.point(q)[0], w = 2 * S * gauss.weight(q);
          const std::vector<double>   c = equilibrium.curve_point(s);
          const std::array<double, 2> k = equilibrium.meridian_curvature(s);
          const NG::LocalExpansion e = NG::expand({c[0], c[1], c[2], k[0], k[1]}, m, 2 * m + 4);
          const auto                  B = trial(theta, s);

          std::array<std::array<double, 3>, 3> local{};
          for (unsigned int f = 0; f < NG::n_functionals; ++f)
            {
              value[f] += w * e.value[f];
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  local[a][b] += lagrangian[f] * e.quadratic[f][a][b];
            }
          for (unsigned int i = 0; i < K; ++i)
            {
              for (unsigned int f = 0; f < NG::n_functionals; ++f)
                for (unsigned int a = 0; a < 3; ++a)
                  gradient[f][i] += w * e.linear[f][a] * B[i][a];
              for (unsigned int d = 0; d < 3; ++d)
                translation[d][i] += w * e.translation[d] * B[i][0];
              for (unsigned int j = 0; j < K; ++j)
                {
                  double bilinear = 0;
                  for (unsigned int a = 0; a < 3; ++a)
                    for (unsigned int b = 0; b < 3; ++b)
                      bilinear += B[i][a] * local[a][b] * B[j][b];
                  result.driven(i, j) += 2 * w * bilinear; // d²/dε² = 2 × the ε² coefficient
                  result.mass(i, j) += w * e.mass * B[i][0] * B[j][0];
                }
            }
        }

      // I_zz about the centre of mass: I_zz − (M_x² + M_y²)/A, whose Hessian adds −2(δM_x δM_xᵀ + δM_y δM_yᵀ)/A.
      add_outer_product(result.driven, omega * omega / value[NG::area], gradient[NG::moment_x]);
      add_outer_product(result.driven, omega * omega / value[NG::area], gradient[NG::moment_y]);
      // ½L·I⁻¹L at L = Le_z: its Hessian is −½ω² δ²I_zz + ω² Σ_k (δI_zk)²/I_kk (δI_yz vanishes for cos mφ).
      result.isolated = result.driven;
      add_outer_product(result.isolated, omega * omega / value[NG::inertia_zz], gradient[NG::inertia_zz]);
      add_outer_product(result.isolated, omega * omega / value[NG::inertia_xx], gradient[NG::inertia_xz]);

      result.constraints = {gradient[NG::area], gradient[NG::volume], translation[0], translation[1], translation[2]};
      result.first_variation.reinit(K);
      for (unsigned int f = 0; f < NG::n_functionals; ++f)
        result.first_variation.add(lagrangian[f], gradient[f]);
      result.willmore_first_variation = gradient[NG::willmore];
      return result;
    }

    /// Dense products: C = A B (transpose_A: Aᵀ B).
    Matrix
    product(const Matrix &A, const Matrix &B, const bool transpose_A = false)
    {
      Matrix C(transpose_A ? A.n() : A.m(), B.n());
      if (transpose_A)
        A.Tmmult(C, B);
      else
        A.mmult(C, B);
      return C;
    }

    /// The lowest @p n eigenpairs of Q c = λ G c on {c : g·c = 0 for every row g}, with cᵀGc = 1.
    void
    lowest_constrained_eigenpairs(const Matrix &Q, const Matrix &G, const std::vector<Vector> &constraints,
                                  const unsigned int n, const double constraint_scale, std::vector<double> &eigenvalues,
                                  std::vector<std::vector<double>> &coefficients)
    {
      const unsigned int K = Q.m();
      // G-orthonormal coordinates y = Lᵀc (G = LLᵀ): the constraint rows become L⁻¹g, normed in G's dual norm.
      Matrix L(K, K), L_inverse(K, K);
      L.cholesky(G);
      L_inverse.invert(L);
      Matrix L_inverse_T(K, K);
      L_inverse_T.copy_transposed(L_inverse);
      const Matrix Q_tilde = product(product(L_inverse, Q), L_inverse_T);

      // Orthonormal constraint directions; a row that vanishes (m ≥ 2) or repeats another (the sphere's δA ∥ δV) drops.
      std::vector<Vector> directions;
      for (const Vector &g : constraints)
        {
          Vector u(K);
          L_inverse.vmult(u, g);
          const double original = u.l2_norm();
          for (const Vector &d : directions)
            u.add(-(u * d), d);
          if (u.l2_norm() > 1e-8 * constraint_scale && u.l2_norm() > 1e-8 * original)
            {
              u /= u.l2_norm();
              directions.push_back(u);
            }
        }
      dealii::LAPACKFullMatrix<double> projector(K, K);
      for (unsigned int i = 0; i < K; ++i)
        {
          projector(i, i) = 1;
          for (const Vector &d : directions)
            for (unsigned int j = 0; j < K; ++j)
              projector(i, j) -= d[i] * d[j];
        }
      Vector nullspace_ones;
      Matrix Z;
      projector.compute_eigenvalues_symmetric(0.5, 1.5, 0, nullspace_ones, Z);

      dealii::LAPACKFullMatrix<double> reduced(Z.n(), Z.n());
      reduced = product(product(Z, Q_tilde, true), Z);
      Vector lambda;
      Matrix Y;
      reduced.compute_eigenvalues_symmetric(-1e300, 1e300, 0, lambda, Y);
      const Matrix C = product(product(L_inverse_T, Z), Y);

      eigenvalues.clear();
      coefficients.clear();
      for (unsigned int j = 0; j < std::min<unsigned int>(n, lambda.size()); ++j)
        {
          eigenvalues.push_back(lambda[j]);
          coefficients.emplace_back(K);
          for (unsigned int i = 0; i < K; ++i)
            coefficients.back()[i] = C(i, j);
        }
    }
  } // namespace

  void
  SecondVariation::declare_parameters(dealii::ParameterHandler &handler)
  {
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    handler.enter_subsection("second variation");
    handler.declare_entry("modes", "", List(Integer(0, 32), 0, 33, ","),
                          "Azimuthal numbers m (0 ≤ m ≤ 32, comma separated) at which fluid_surface --equilibrium "
                          "computes the second variation of the energy at the equilibrium, for normal perturbations "
                          "a(s) cos(mφ) of both parities, at fixed A, V and L (isolated: W + ½L·I⁻¹L) and at fixed A, "
                          "V and ω (driven: W − ½ω²I_zz); doc/stability.md. Empty: none (the report is unchanged).");
    handler.declare_entry("eigenvalues", "3", Integer(1, 20),
                          "Number of lowest eigenvalues λ of δ²E c = λ G c (G: ∫f² dA) reported per m, parity and "
                          "energy, 1 to 20.");
    handler.declare_entry("basis size", "24", Integer(4, 64),
                          "K, 4 ≤ K ≤ 64: basis functions sin^m θ cos(kθ) per parity (θ = πs/(2S), k = 0, 2, .. even; "
                          "1, 3, .. odd). The sphere's spectrum is exact for l − m ≤ 2K − 2; other shapes converge "
                          "spectrally in K.");
    handler.declare_entry("eigenfunction file", "", dealii::Patterns::Anything(),
                          "CSV of the reported eigenfunctions a(s) (columns energy,m,parity,index,eigenvalue,s,r,z,a; "
                          "∫f² dA = 1); its directory must exist. Empty: none.");
    handler.leave_subsection();
  }

  void
  SecondVariation::parse_parameters(dealii::ParameterHandler &handler)
  {
    handler.enter_subsection("second variation");
    Parameters p;
    for (const std::string &m : dealii::Utilities::split_string_list(handler.get("modes"), ','))
      p.modes.push_back(dealii::Utilities::string_to_int(m));
    p.n_eigenvalues      = handler.get_integer("eigenvalues");
    p.basis_size         = handler.get_integer("basis size");
    p.eigenfunction_file = handler.get("eigenfunction file");
    handler.leave_subsection();
    if (!p.eigenfunction_file.empty())
      {
        const std::filesystem::path file(p.eigenfunction_file), directory = file.parent_path();
        if (file.filename().empty() || std::filesystem::is_directory(file) ||
            !(directory.empty() || std::filesystem::is_directory(directory)))
          throw_invalid_entry("second variation/eigenfunction file", p.eigenfunction_file,
                              "a file name in an existing directory, or nothing");
      }
    prm = p;
  }

  SecondVariation::SecondVariation(const Parameters &parameters)
    : prm(parameters)
  {}

  std::array<double, 3>
  SecondVariation::basis_function(const unsigned int m, const unsigned int k, const double theta)
  {
    const double sn = std::sin(theta), cs = std::cos(theta);
    // f = sin^m θ, g = cos kθ: b = fg, b' = f'g + fg', b'' = f''g + 2f'g' + fg''.
    const double f   = std::pow(sn, m);
    const double f1  = (m >= 1 ? m * std::pow(sn, m - 1) * cs : 0.);
    const double f2  = (m >= 2 ? m * (m - 1.) * std::pow(sn, m - 2) * cs * cs : 0.) - m * f;
    const double g   = std::cos(k * theta), g1 = -1. * k * std::sin(k * theta), g2 = -1. * k * k * g;
    return {{f * g, f1 * g + f * g1, f2 * g + 2 * f1 * g1 + f * g2}};
  }

  void
  SecondVariation::compute(const AxisymmetricEquilibrium &base)
  {
    equilibrium = &base;
    results.clear();
    residual = 0;
    for (const unsigned int m : prm.modes)
      for (const bool odd : {false, true})
        compute_mode(m, odd);
  }

  void
  SecondVariation::compute_mode(const unsigned int m, const bool odd)
  {
    const unsigned int K            = prm.basis_size;
    const unsigned int n_quadrature = 4 * (m + 2 * K) + 64;
    const double       S            = 0.5 * equilibrium->curve_length();
    const ModeMatrices matrices     = assemble_mode(*equilibrium, m, basis(m, odd, K, S), K, n_quadrature);

    // The first variation of the Lagrangian in G's dual norm, relative to that of W.
    Matrix L(K, K), L_inverse(K, K);
    L.cholesky(matrices.mass);
    L_inverse.invert(L);
    Vector dual(K), dual_W(K);
    L_inverse.vmult(dual, matrices.first_variation);
    L_inverse.vmult(dual_W, matrices.willmore_first_variation);
    residual = std::max(residual, dual.l2_norm() / std::max(dual_W.l2_norm(), 1.));

    const double constraint_scale = std::sqrt(equilibrium->area());
    for (const Energy energy : {Energy::isolated, Energy::driven})
      {
        Spectrum spectrum;
        spectrum.m      = m;
        spectrum.odd    = odd;
        spectrum.energy = energy;
        lowest_constrained_eigenpairs(energy == Energy::isolated ? matrices.isolated : matrices.driven,
                                      matrices.mass, matrices.constraints, prm.n_eigenvalues, constraint_scale,
                                      spectrum.eigenvalues, spectrum.coefficients);
        results.push_back(spectrum);
      }
  }

  std::array<double, 2>
  SecondVariation::quadratic_form(const AxisymmetricEquilibrium                         &equilibrium,
                                  const unsigned int                                     m,
                                  const Energy                                           energy,
                                  const std::function<std::array<double, 3>(const double)> &a)
  {
    const ModeMatrices matrices = assemble_mode(
      equilibrium, m, [&](const double, const double s) { return std::vector<std::array<double, 3>>{a(s)}; }, 1,
      4 * (m + 48) + 64);
    return {{(energy == Energy::isolated ? matrices.isolated : matrices.driven)(0, 0), matrices.mass(0, 0)}};
  }

  void
  SecondVariation::print(std::ostream &out) const
  {
    const auto flags     = out.flags();
    const auto precision = out.precision();
    out << "second variation basis size: " << prm.basis_size << '\n';
    for (const Spectrum &spectrum : results)
      {
        out << "second variation " << (spectrum.energy == Energy::isolated ? "isolated" : "driven") << " m "
            << spectrum.m << (spectrum.odd ? " odd:" : " even:") << std::setprecision(10);
        for (const double lambda : spectrum.eigenvalues)
          out << ' ' << lambda;
        out << '\n';
      }
    out << std::setprecision(2) << std::scientific
        << "second variation first variation residual: " << first_variation_residual() << '\n';
    out.flags(flags);
    out.precision(precision);
  }

  void
  SecondVariation::write_eigenfunctions_csv(const std::string &file) const
  {
    std::ofstream out(file);
    if (!out)
      throw std::runtime_error("SecondVariation: cannot write '" + file + "'.");
    out << "energy,m,parity,index,eigenvalue,s,r,z,a\n" << std::setprecision(12);
    const double       S = 0.5 * equilibrium->curve_length();
    const unsigned int n = 101;
    for (const Spectrum &spectrum : results)
      for (unsigned int j = 0; j < spectrum.eigenvalues.size(); ++j)
        {
          std::vector<double> a(n, 0.);
          for (unsigned int p = 0; p < n; ++p)
            for (unsigned int i = 0; i < spectrum.coefficients[j].size(); ++i)
              a[p] += spectrum.coefficients[j][i] *
                      basis_function(spectrum.m, (spectrum.odd ? 1 : 0) + 2 * i, pi * p / (n - 1.))[0];
          const auto   largest = std::max_element(a.begin(), a.end(),
                                                  [](const double x, const double y) { return std::abs(x) < std::abs(y); });
          const double sign    = (*largest < 0 ? -1. : 1.);
          for (unsigned int p = 0; p < n; ++p)
            {
              const double              s = 2 * S * p / (n - 1.);
              const std::vector<double> c = equilibrium->curve_point(s);
              out << (spectrum.energy == Energy::isolated ? "isolated" : "driven") << ',' << spectrum.m << ','
                  << (spectrum.odd ? "odd" : "even") << ',' << j << ',' << spectrum.eigenvalues[j] << ',' << s << ','
                  << c[0] << ',' << c[1] << ',' << sign * a[p] << '\n';
            }
        }
  }
} // namespace FluidSurface
