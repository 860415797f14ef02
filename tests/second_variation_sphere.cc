// SPDX-License-Identifier: LGPL-2.1-or-later
// The second variation of `fluid_surface --equilibrium` (subsection second variation) on the unit sphere at rest
// (A = 4π, v = 1, Be = 1, σ = P = 0), against the known spectrum (doc/stability.md, "Verification: the sphere"): on
// the spherical harmonics of degree l, δ²W = λ_l ∫f² dA with λ_l = (l − 1) l (l + 1)(l + 2), 2l + 1 times
// (azimuthal numbers |m| ≤ l; parity even when l − m is even). l = 0 is removed by δA = δV = 0 and l = 1 (the
// translations) by the orthogonality to them, so the lowest of (m, parity) is l = max(m, 2) of that parity.
// Modes m = 0..3, 3 eigenvalues each, 8 basis functions per parity (l − m ≤ 15: the harmonics are in the basis).
// Printed: per energy, m and parity the eigenvalues (6 decimals) beside λ_l, and whether all agree to 1e-9
// relative; then whether the eigenfunction of m = 2 even is sin²θ (Y_2^2) to 1e-8.
#include <deal.II/base/mpi.h>

#include <fluid_surface/scenes/run_program.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream("sphere.prm") << "subsection equilibrium\n  set reduced volume = 1\n  set output file = curve.csv\nend\n"
                                 "subsection second variation\n  set modes = 0, 1, 2, 3\n  set eigenvalues = 3\n"
                                 "  set basis size = 8\n  set eigenfunction file = modes.csv\nend\n";
  std::ostringstream screen, errors;
  const int          status = run_program({"--equilibrium", "sphere.prm"}, screen, errors, MPI_COMM_WORLD);
  std::cout << "exit status " << status << errors.str() << std::endl;

  double       largest_error = 0;
  unsigned int n_rows        = 0;
  std::istringstream report(screen.str());
  for (std::string line; std::getline(report, line);)
    {
      std::istringstream words(line);
      std::string        second, variation, energy, m_word, parity;
      unsigned int       m;
      if (!(words >> second >> variation >> energy >> m_word >> m >> parity) || m_word != "m")
        continue;
      parity.pop_back(); // the colon
      std::cout << energy << " m " << m << ' ' << parity << ':';
      // The lowest l ≥ max(m, 2) with l − m of the parity, then every second l.
      unsigned int l = std::max(m, 2u);
      if ((l - m) % 2 != (parity == "odd" ? 1u : 0u))
        ++l;
      for (double lambda; words >> lambda; l += 2)
        {
          const double exact = (l - 1.) * l * (l + 1.) * (l + 2.);
          largest_error      = std::max(largest_error, std::abs(lambda - exact) / exact);
          std::cout << std::fixed << std::setprecision(6) << "  l = " << l << ": " << lambda << " (" << exact << ')';
        }
      std::cout << std::endl;
      ++n_rows;
    }
  std::cout << n_rows << " rows; all within 1e-9 of (l − 1)l(l + 1)(l + 2): " << (largest_error < 1e-9 ? "yes" : "no")
            << std::endl;

  // The eigenfunction of m = 2 even, index 0: a(s) = sin²θ, θ = s on the unit sphere (normalized to max 1).
  std::ifstream csv("modes.csv");
  std::string   line;
  std::getline(csv, line);
  std::cout << "modes.csv header: " << line << std::endl;
  std::vector<std::pair<double, double>> curve;
  while (std::getline(csv, line))
    if (line.rfind("isolated,2,even,0,", 0) == 0)
      {
        std::vector<std::string> cells;
        std::stringstream        row(line);
        for (std::string cell; std::getline(row, cell, ',');)
          cells.push_back(cell);
        curve.emplace_back(std::stod(cells[5]), std::stod(cells[8]));
      }
  double largest = 0, deviation = 0;
  for (const auto &[s, a] : curve)
    largest = std::max(largest, std::abs(a));
  for (const auto &[s, a] : curve)
    deviation = std::max(deviation, std::abs(a / largest - std::pow(std::sin(s), 2)));
  std::cout << "m 2 even eigenfunction: " << curve.size() << " rows, sin²θ within 1e-8: " << (deviation < 1e-8 ? "yes" : "no")
            << std::endl;
}
