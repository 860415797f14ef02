#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <fluid_surface/geometry/azimuthal_harmonic.h>
#include <fluid_surface/model/nodal_vector_field.h>
#include <fluid_surface/model/rigid_motion.h>

#include <cmath>
#include <map>

namespace FluidSurface
{
  using namespace dealii;

  NodalVectorField::NodalVectorField(const DoFHandler<2, 3> &dof_handler,
                                     const unsigned int      first_component,
                                     const Mapping<2, 3>    &mapping)
    : communicator(dof_handler.get_communicator())
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);
    const IndexSet                                                       owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, std::array<types::global_dof_index, 3>> nodes; // by the DoF of component 0
    const FiniteElement<2, 3>           &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          // The DoFs of one node share the index within the base element.
          std::map<unsigned int, std::array<types::global_dof_index, 3>> cell_nodes;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, index] = fe.system_to_component_index(i);
              if (component >= first_component && component < first_component + 3)
                cell_nodes[index][component - first_component] = dofs[i];
            }
          for (const auto &node : cell_nodes)
            if (owned.is_element(node.second[0]))
              nodes[node.second[0]] = node.second;
        }
    for (const auto &node : nodes)
      {
        triples.push_back(node.second);
        points.push_back(support_points.at(node.first));
      }
  }

  void
  NodalVectorField::rotated_difference(const VectorType     &a,
                                       const VectorType     &b,
                                       const double          factor,
                                       const Tensor<2, 3>   &Q,
                                       VectorType           &out) const
  {
    out = 0;
    for (const auto &dofs : triples)
      {
        Tensor<1, 3> d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = factor * (a[dofs[c]] - b[dofs[c]]);
        const Tensor<1, 3> r = Q * d;
        for (unsigned int c = 0; c < 3; ++c)
          out[dofs[c]] = r[c];
      }
    out.compress(VectorOperation::insert);
  }

  std::pair<double, double>
  NodalVectorField::fit_rotation(const VectorType   &from,
                                 const VectorType   &to,
                                 const Tensor<1, 3> &axis,
                                 const Point<3>     &centre) const
  {
    const auto value = [&](const VectorType &v, const std::array<types::global_dof_index, 3> &dofs) {
      Tensor<1, 3> x;
      for (unsigned int c = 0; c < 3; ++c)
        x[c] = v[dofs[c]] - centre[c];
      return x;
    };
    // θ maximizes Σ (Q(θ) x₀)·x₁ = Σ cos θ (x₀⊥·x₁⊥) + sin θ (e·(x₀ × x₁)) + const.
    double sums[2] = {0, 0};
    for (const auto &dofs : triples)
      {
        const Tensor<1, 3> x0 = value(from, dofs), x1 = value(to, dofs);
        sums[0] += x0 * x1 - (x0 * axis) * (x1 * axis);
        sums[1] += axis * cross_product_3d(x0, x1);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    const double       theta = std::atan2(sums[1], sums[0]);
    RigidMotion turn;
    turn.rotation           = theta * axis;
    const Tensor<2, 3> Q     = turn.rotation_over(1.0);
    double             distance = 0;
    for (const auto &dofs : triples)
      distance = std::max(distance, (Q * value(from, dofs) - value(to, dofs)).norm());
    return {theta, Utilities::MPI::max(distance, communicator)};
  }

  std::vector<std::array<double, 2>>
  NodalVectorField::azimuthal_content(const VectorType   &re,
                                      const VectorType   &im,
                                      const Tensor<1, 3> &axis,
                                      const Point<3>     &centre,
                                      const unsigned int  M) const
  {
    const std::array<Tensor<1, 3>, 2> frame = AzimuthalHarmonic::transverse_frame(axis);
    // sums[((k + M)·2 + parity)·3 + c] of a_c t_c e^{−ikφ}, real and imaginary parts interleaved.
    const unsigned int  n_wave = 2 * M + 1;
    std::vector<double> sums(2 * n_wave * 2 * 3, 0.0);
    double              n_nodes = 0;
    for (unsigned int n = 0; n < triples.size(); ++n)
      {
        const Tensor<1, 3> x   = points[n] - centre;
        const double       x1  = x * frame[0], x2 = x * frame[1], zeta = x * axis;
        const double       rho = std::hypot(x1, x2);
        if (rho < 1e-8 * x.norm())
          continue; // on the axis φ is undefined
        n_nodes += 1;
        const double       phi = std::atan2(x2, x1);
        const Tensor<1, 3> e_rho = (x1 * frame[0] + x2 * frame[1]) / rho;
        const Tensor<1, 3> e_phi = cross_product_3d(axis, e_rho);
        std::array<std::complex<double>, 3> a;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const std::complex<double> v(re[triples[n][c]], im[triples[n][c]]);
            a[0] += v * e_rho[c];
            a[1] += v * e_phi[c];
            a[2] += v * axis[c];
          }
        const double sign = zeta > 0 ? 1.0 : (zeta < 0 ? -1.0 : 0.0);
        for (unsigned int w = 0; w < n_wave; ++w)
          {
            const double               k = static_cast<double>(w) - M;
            const std::complex<double> phase(std::cos(k * phi), -std::sin(k * phi));
            for (unsigned int parity = 0; parity < 2; ++parity)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double               t = ((c == 2) == (parity == 0)) ? sign : 1.0;
                  const std::complex<double> term = a[c] * t * phase;
                  const unsigned int         i    = 2 * (((w * 2) + parity) * 3 + c);
                  sums[i] += term.real();
                  sums[i + 1] += term.imag();
                }
          }
      }
    Utilities::MPI::sum(sums, communicator, sums);
    n_nodes = Utilities::MPI::sum(n_nodes, communicator);
    std::vector<std::array<double, 2>> content(n_wave, {{0, 0}});
    for (unsigned int w = 0; w < n_wave; ++w)
      for (unsigned int parity = 0; parity < 2; ++parity)
        for (unsigned int c = 0; c < 3; ++c)
          {
            const unsigned int i = 2 * (((w * 2) + parity) * 3 + c);
            content[w][parity] += (sums[i] * sums[i] + sums[i + 1] * sums[i + 1]) / (n_nodes * n_nodes);
          }
    return content;
  }
} // namespace FluidSurface
