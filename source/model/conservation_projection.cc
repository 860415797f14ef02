// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <fluid_surface/model/conservation_projection.h>

#include <cmath>
#include <tuple>

namespace FluidSurface
{
  using namespace dealii;

  void
  ConservationProjection::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("conservation projection");
    prm.declare_entry("enabled",
                      "true",
                      Patterns::Bool(),
                      "After each step, move the nodes along ñ so that the area A and (with the volume constraint) "
                      "the volume V equal their initial values, and (with flow/conserve momenta) add the rigid "
                      "motion to u that restores ∫u and ∫x × u: the drifts of the first-order step vanish to "
                      "round-off (doc/scheme.md).");
    prm.leave_subsection();
  }

  void
  ConservationProjection::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("conservation projection");
    enabled = prm.get_bool("enabled");
    prm.leave_subsection();
  }

  double
  ConservationProjection::project_area_and_volume(SurfaceGeometry                  &geometry,
                                                  const SurfaceGeometry::Curvature &modes,
                                                  const double                      target_area,
                                                  const double     target_volume,
                                                  const bool       hold_volume) const
  {
    const MPI_Comm   comm = geometry.get_communicator();
    const IndexSet  &owned = geometry.locally_owned_dofs();
    // The two modes ñ and Hñ at the nodes (H repeated in the three components of a node).
    VectorType normal(owned, comm), curved(owned, comm);
    normal = modes.normal;
    curved = modes.mean_curvature;
    curved.scale(normal);
    const FEValuesExtractors::Vector vector(0);
    double                           largest = 0;
    for (unsigned int iteration = 0; iteration < 8; ++iteration)
      {
        const SurfaceGeometry::Measures m = geometry.measure();
        const double                    volume_error = m.volume - target_volume, area_error = m.area - target_area;
        if (std::abs(area_error) <= 1e-13 * target_area &&
            (!hold_volume || std::abs(volume_error) <= 1e-13 * std::abs(target_volume)))
          break;
        // The first variations dV = ∫δ·ν, dA = ∫Hδ·ν of the two modes on the current surface.
        const Quadrature<2>       q = geometry.quadrature();
        FEValues<2, 3>            fe_values(geometry.mapping(), geometry.fe(), q,
                                            update_values | update_normal_vectors | update_JxW_values);
        std::vector<Tensor<1, 3>> n(q.size()), h(q.size());
        std::array<double, 4>     sums{}; // ∫ñ·ν, ∫Hñ·ν, (unused), ∫H²ñ·ν
        for (const auto &cell : geometry.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              fe_values[vector].get_function_values(modes.normal, n);
              fe_values[vector].get_function_values(modes.vector, h);
              for (unsigned int k = 0; k < q.size(); ++k)
                {
                  const Tensor<1, 3> &nu = fe_values.normal_vector(k);
                  const double        H  = h[k] * nu, dA = fe_values.JxW(k);
                  sums[0] += (n[k] * nu) * dA;
                  sums[1] += H * (n[k] * nu) * dA;
                  sums[3] += H * H * (n[k] * nu) * dA;
                }
            }
        Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), comm,
                            ArrayView<double>(sums.data(), sums.size()));
        // κ = Hν is the weak Δ_S X (H < 0 on an outward sphere), so dA = −∫Hδ·ν.
        const double dV_da = sums[0], dV_db = sums[1], dA_da = -sums[1], dA_db = -sums[3];
        // V alone: the mode ñ.
        const auto hold_volume_only = [&]() { return std::make_pair(-volume_error / dV_da, 0.0); };
        auto [a, b] = hold_volume ? hold_volume_only() : std::make_pair(-area_error / dA_da, 0.0);
        // A and V: the modes ñ and Hñ. Near a sphere (H nearly constant) the two modes change A and V almost
        // alike, and the A-fixing part of the correction, of size |δA|/A · R / s for a relative spread s of
        // H, grows without bound as s → 0 (at s = 0 the system is singular, and A is at its minimum for V).
        // The pair is used only while the correction stays within 100 times the errors' own scale; otherwise
        // V alone is held (A's drift is then of second order).
        const double det = dV_da * dA_db - dV_db * dA_da;
        if (hold_volume && det != 0)
          {
            const double pair_a = -(dA_db * volume_error - dV_db * area_error) / det;
            const double pair_b = -(-dA_da * volume_error + dV_da * area_error) / det;
            const double scale  = std::sqrt(m.area / (4 * numbers::PI)) *
                                 (std::abs(area_error) / m.area + std::abs(volume_error) / std::abs(m.volume));
            VectorType correction(owned, comm);
            correction.add(pair_a, normal, pair_b, curved);
            if (correction.linfty_norm() <= 100 * scale)
              std::tie(a, b) = std::make_pair(pair_a, pair_b);
          }
        VectorType position(owned, comm);
        position = geometry.position();
        position.add(a, normal, b, curved);
        geometry.set_position(position);
        largest = std::max(largest, std::abs(a) + std::abs(b) * curved.linfty_norm());
      }
    return largest;
  }

  namespace
  {
    /// Σ_k c_k r_k(x) with r = e_d, e_d × x in the first three of @p n_components components.
    class RigidVelocity : public Function<3>
    {
    public:
      RigidVelocity(const Vector<double> &c, const unsigned int n_components)
        : Function<3>(n_components)
      {
        for (unsigned int d = 0; d < 3; ++d)
          {
            translation[d] = c(d);
            rotation[d]    = c(3 + d);
          }
      }
      double
      value(const Point<3> &x, const unsigned int component) const override
      {
        return component < 3 ? (translation + cross_product_3d(rotation, x))[component] : 0.0;
      }

    private:
      Tensor<1, 3> translation, rotation;
    };
  } // namespace

  std::array<double, 6>
  ConservationProjection::momenta(const SurfaceGeometry &geometry, const DoFHandler<2, 3> &dofs, const VectorType &state)
  {
    const Quadrature<2>       q = geometry.quadrature();
    FEValues<2, 3>            fe_values(geometry.mapping(), dofs.get_fe(), q,
                                        update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 3>> u(q.size());
    std::array<double, 6>     sums{};
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(state, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const Tensor<1, 3> L = cross_product_3d(fe_values.quadrature_point(k), u[k]);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  sums[d] += u[k][d] * fe_values.JxW(k);
                  sums[3 + d] += L[d] * fe_values.JxW(k);
                }
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), geometry.get_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    return sums;
  }

  double
  ConservationProjection::project_momenta(const SurfaceGeometry          &geometry,
                                          const DoFHandler<2, 3>         &dofs,
                                          const std::array<double, 6>    &targets,
                                          VectorType                     &state) const
  {
    const Quadrature<2>              q = geometry.quadrature();
    FEValues<2, 3>                   fe_values(geometry.mapping(), dofs.get_fe(), q,
                                               update_values | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector velocity(0);
    std::vector<Tensor<1, 3>>        u(q.size());
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    VectorType ghosted(dofs.locally_owned_dofs(), relevant, geometry.get_communicator());
    ghosted = state;
    // [0..5] (r_k, u); [6..41] (r_k, r_l).
    std::array<double, 42> sums{};
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[velocity].get_function_values(ghosted, u);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const Point<3> &x  = fe_values.quadrature_point(k);
              const double    dA = fe_values.JxW(k);
              Tensor<1, 3>    r[6];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  r[d][d]  = 1;
                  Tensor<1, 3> e;
                  e[d]     = 1;
                  r[3 + d] = cross_product_3d(e, x);
                }
              for (unsigned int j = 0; j < 6; ++j)
                {
                  sums[j] += (r[j] * u[k]) * dA;
                  for (unsigned int l = 0; l < 6; ++l)
                    sums[6 + 6 * j + l] += (r[j] * r[l]) * dA;
                }
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), geometry.get_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    FullMatrix<double> gram(6, 6), inverse(6, 6);
    Vector<double>     defect(6), c(6);
    for (unsigned int j = 0; j < 6; ++j)
      {
        defect(j) = targets[j] - sums[j];
        for (unsigned int l = 0; l < 6; ++l)
          gram(j, l) = sums[6 + 6 * j + l];
      }
    inverse.invert(gram);
    inverse.vmult(c, defect);
    // The rigid field at the velocity nodes (VectorTools::interpolate with a component mask left the third
    // component at zero on this FESystem in deal.II 9.4, so ∫u_z and L_x, L_y were not corrected).
    const RigidVelocity              rigid(c, 3);
    const FiniteElement<2, 3>       &fe = dofs.get_fe();
    FEValues<2, 3>                   at_nodes(geometry.mapping(), fe, Quadrature<2>(fe.get_unit_support_points()),
                                              update_quadrature_points);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    const IndexSet                  &owned = dofs.locally_owned_dofs();
    VectorType                       correction(owned, geometry.get_communicator());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          at_nodes.reinit(cell);
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const unsigned int component = fe.system_to_component_index(i).first;
              if (component < 3 && owned.is_element(indices[i]))
                correction[indices[i]] = rigid.value(at_nodes.quadrature_point(i), component);
            }
        }
    correction.compress(VectorOperation::insert);
    state += correction;
    return defect.l2_norm();
  }
} // namespace FluidSurface
