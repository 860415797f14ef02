// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>

#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/model/mesh_redistribution.h>

#include <vector>

namespace FluidSurface
{
  using namespace dealii;

  void
  MeshRedistribution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    prm.declare_entry("law",
                      "reference",
                      Patterns::Selection("bgn|reference"),
                      "The tangential motion of the nodes. bgn (the earlier default): the tangential part of "
                      "κñ = Δ_S Y (a conformal parametrization of the current surface, Barrett–Garcke–Nürnberg), "
                      "damped towards X^m + τR. "
                      "reference: the nodes are carried by the exact rigid motion of the shape (a rotation, not its "
                      "linearization) and relax on the time scale T_r towards a minimizer of a membrane energy "
                      "relative to the initial surface S₀ (shear stiffness μ, area stiffness K): a rigid motion "
                      "does not change the mesh, and element shape and size stay close to those of S₀ "
                      "(doc/scheme.md). Needs lumped = true.");
    prm.declare_entry("tangential law",
                      "membrane",
                      Patterns::Selection("membrane|conformal"),
                      "What moves the nodes tangentially under law reference (the exact carry and the carried frame "
                      "stay). membrane: the membrane energy relative to the initial surface S₀ (μ, K). conformal: "
                      "BGN's tangential rows (∇_S Y, ∇_S η) on the current surface (a conformal parametrization of "
                      "it) added to the membrane energy's (μ = K = 0: BGN's alone). The candidates are measured side "
                      "by side in doc/scheme.md (issue 22).");
    prm.declare_entry("shear stiffness",
                      "1",
                      RealRange::closed(0, 1e6),
                      "μ, 0 ≤ μ ≤ 1e6, of law reference: the weight of the shear energy ∫_{S₀}(½|∇_{S₀}Y|² − J), zero iff the "
                      "map from the initial surface S₀ is conformal.");
    prm.declare_entry("area stiffness",
                      "1",
                      RealRange::closed(0, 1e6),
                      "K, 0 ≤ K ≤ 1e6, of law reference: the weight of the area energy ½∫_{S₀}(J − 1)², J the element area "
                      "over its initial area (normalized by the total area).");
    prm.declare_entry("pull onset quality",
                      "1",
                      RealRange::closed(0, 1),
                      "q₀, 0 ≤ q₀ ≤ 1, of law reference: the membrane energy (μ, K) is weighted by the largest w(q) of "
                      "the run so far, q the mesh quality of S^m (min over cells of σ_min/σ_max), w = 0 for q ≥ q₀ "
                      "rising smoothly to 1 at `full pull quality` q₁ (q₁ = q₀: a switch). Used with tangential law "
                      "= conformal: the nodes keep BGN's conformal distribution until the mesh first degrades, then "
                      "are pulled towards the membrane energy's minimizer (doc/scheme.md). 1 (with q₁ = 1): the full "
                      "weight always.");
    prm.declare_entry("full pull quality",
                      "1",
                      RealRange::closed(0, 1),
                      "q₁, 0 ≤ q₁ ≤ q₀, of law reference: below this mesh quality the membrane energy acts with its "
                      "full weight (see `pull onset quality`).");
    prm.declare_entry("anchor time",
                      "-1",
                      Patterns::Double(-1, 1e6),
                      "t_a, −1 or 0 ≤ t_a ≤ 1e6, of law reference: at the first accepted step ending at t ≥ t_a the "
                      "reference surface S₀ of the membrane energy becomes the current surface and the energy "
                      "acts with its full weight from then on (the latch of `pull onset quality` set to 1). With "
                      "tangential law = conformal: the nodes keep BGN's distribution through the initial relaxation "
                      "and are then held where they are, instead of creeping along the conformal distribution (which "
                      "feeds energy into a rotating steady state); later deformations pull towards that mesh, not "
                      "the initial one (doc/scheme.md). −1: never.");
    prm.declare_entry("anchor non-rigid energy",
                      "0",
                      Patterns::Double(0, 1),
                      "ε_a, 0 ≤ ε_a ≤ 1, of law reference: the mesh law is also anchored (as at `anchor time`) at "
                      "the first accepted step whose non-rigid kinetic energy F_kin − ½Ω·L is at most ε_a|F|, i.e. "
                      "once the initial transformation is over and the body rotates rigidly. With the membrane "
                      "energy relative to the initial mesh, a tangential mode of the nodes grows in a rigidly "
                      "spinning body and feeds energy in; anchored at the current mesh, the energy holds the nodes "
                      "(doc/scheme.md, \"The discrete energy law\"). Whichever of the two comes first anchors. 0: off.");
    prm.declare_entry("lumped",
                      "true",
                      Patterns::Bool(),
                      "Nodal (Gauss–Lobatto) quadrature for (Y·ñ, φ) and (κñ, η), as in the BGN scheme.");
    prm.declare_entry("relaxation time",
                      "0.05",
                      RealRange::closed(0, 1e6),
                      "T_r, 0 ≤ T_r ≤ 1e6, of the tangential damping (T_r/τ)(P̃(Y − W), η)_h (W = X^m + τR for law "
                      "bgn, the carried position for law reference): the mesh relaxes towards the minimizer of its "
                      "law on the time scale T_r instead of jumping there within one step, so that steps τ → 0 "
                      "change nothing. 0: no damping (plain BGN).");
    prm.declare_entry("follow rigid motion",
                      "true",
                      Patterns::Bool(),
                      "The mesh follows R = U + Ω × (x − x_c), the rigid motion of the shape (its normal part R·ν "
                      "fits u^m·ν in L²): law bgn damps the nodes towards X^m + τR (no effect when T_r = 0), law "
                      "reference carries them by the exact flow of R and solves the step in that frame. A rotating "
                      "or translating body carries its mesh along instead of moving through it, while a body "
                      "spinning about its own axis of symmetry (R·ν ≡ 0) leaves its mesh in place.");
    prm.declare_entry("rigid motion cutoff",
                      "0.01",
                      RealRange::left_open(0, 1e6),
                      "ε, 0 < ε ≤ 1e6, of the fit of R, c the coefficients of R in the basis e_d, e_d × (x − x_c)/R_g "
                      "(R_g the radius of gyration), G the Gram matrix of their normal parts: law bgn minimizes "
                      "∫(u·ν − R·ν)² + ε|S||c|²; law reference fits the eigenmodes of G with eigenvalue ≥ 2ε|S| "
                      "exactly and drops those ≤ ε|S| (a smooth step between). Rigid motions that hardly move the "
                      "surface (the spin of an axisymmetric body) are not followed.");
    prm.declare_entry("mesh quality floor",
                      "0.02",
                      RealRange::closed(0, 1),
                      "q_min, 0 ≤ q_min ≤ 1: the run stops when min over cells of σ_min/σ_max of the Jacobian falls below.");
    prm.leave_subsection();
  }

  void
  MeshRedistribution::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("mesh redistribution");
    law                 = prm.get("law") == "reference" ? Law::reference : Law::bgn;
    conformal_tangential = prm.get("tangential law") == "conformal";
    shear_stiffness     = prm.get_double("shear stiffness");
    area_stiffness      = prm.get_double("area stiffness");
    pull_onset_quality  = prm.get_double("pull onset quality");
    full_pull_quality   = prm.get_double("full pull quality");
    anchor_time         = prm.get_double("anchor time");
    anchor_non_rigid_energy = prm.get_double("anchor non-rigid energy");
    lumped              = prm.get_bool("lumped");
    relaxation_time     = prm.get_double("relaxation time");
    follow_rigid_motion = prm.get_bool("follow rigid motion");
    rigid_motion_cutoff = prm.get_double("rigid motion cutoff");
    mesh_quality_floor  = prm.get_double("mesh quality floor");
    const std::string onset_text = prm.get("pull onset quality"), full_text = prm.get("full pull quality");
    const std::string anchor_text = prm.get("anchor time");
    prm.leave_subsection();
    if (law == Law::reference && shear_stiffness == 0 && area_stiffness == 0 && relaxation_time == 0)
      throw_invalid_entry("mesh redistribution/shear stiffness", "0",
                          "μ > 0, K > 0 or T_r > 0 with law = reference (otherwise nothing fixes the tangential "
                          "position of the nodes)");
    if (full_pull_quality > pull_onset_quality)
      throw_invalid_entry("mesh redistribution/full pull quality", full_text,
                          "a number ≤ 'pull onset quality' = " + onset_text);
    if (law == Law::reference && pull_onset_quality < 1 && !conformal_tangential)
      throw_invalid_entry("mesh redistribution/pull onset quality", onset_text,
                          "1 unless tangential law = conformal (the membrane energy is then the only tangential "
                          "law, and it must always act)");
    if (anchor_time >= 0 && law != Law::reference)
      throw_invalid_entry("mesh redistribution/anchor time", anchor_text,
                          "−1 unless law = reference (only its membrane energy has a reference surface)");
    if (anchor_non_rigid_energy > 0 && law != Law::reference)
      throw_invalid_entry("mesh redistribution/anchor non-rigid energy", std::to_string(anchor_non_rigid_energy),
                          "0 unless law = reference (only its membrane energy has a reference surface)");
    if (anchor_time < 0 && anchor_time != -1)
      throw_invalid_entry("mesh redistribution/anchor time", anchor_text, "−1 or a time ≥ 0");
    if (law == Law::reference && !lumped)
      throw_invalid_entry("mesh redistribution/lumped", "false", "true with law = reference (its tangential "
                                                                  "projection acts at the nodes)");
  }

  double
  MeshRedistribution::membrane_weight(const double quality) const
  {
    if (quality <= full_pull_quality)
      return 1.0;
    if (quality >= pull_onset_quality)
      return 0.0;
    const double x = (pull_onset_quality - quality) / (pull_onset_quality - full_pull_quality);
    return x * x * (3.0 - 2.0 * x);
  }

  Quadrature<2>
  MeshRedistribution::nodal_quadrature(const Quadrature<2> &gauss, const unsigned int degree) const
  {
    if (lumped)
      return QGaussLobatto<2>(degree + 1);
    return gauss;
  }

  void
  MeshRedistribution::assemble_kinematics(const NodalPointValues &point,
                                          const DofLayout        &dofs,
                                          const double            tau,
                                          const Point<3>         &start,
                                          FullMatrix<double>     &matrix,
                                          Vector<double>         &rhs) const
  {
    const double        inv_tau = 1.0 / tau;
    const double        dA      = point.JxW;
    const Tensor<1, 3> &nt      = point.smooth_normal;
    for (const unsigned int i : dofs.curvature)
      {
        const double phi = point.curvature[i];
        rhs(i) += inv_tau * (start * nt) * phi * dA;
        for (const unsigned int j : dofs.new_position)
          matrix(i, j) += inv_tau * (point.new_position[j] * nt) * phi * dA;
        for (const unsigned int j : dofs.velocity)
          matrix(i, j) -= (point.velocity[j] * nt) * phi * dA;
      }
  }

  void
  MeshRedistribution::assemble_surface_laplacian(const SurfacePointValues &point,
                                                 const DofLayout          &dofs,
                                                 FullMatrix<double>       &matrix) const
  {
    const double dA = point.flow.JxW;
    // ∇_S η of Y's component d at a node is nonzero in row d only: (∇_S η_i, ∇_S η_j) couples equal components.
    for (const auto &row_node : dofs.new_position_nodes)
      for (const auto &column_node : dofs.new_position_nodes)
        for (unsigned int d = 0; d < 3; ++d)
          matrix(row_node[d], column_node[d]) +=
            (point.new_position_gradient[row_node[d]][d] * point.new_position_gradient[column_node[d]][d]) * dA;
  }

  void
  MeshRedistribution::assemble_nodal_terms(const NodalPointValues &point,
                                           const DofLayout        &dofs,
                                           const double            tau,
                                           const Point<3>         &target,
                                           FullMatrix<double>     &matrix,
                                           Vector<double>         &rhs) const
  {
    const double        damping_factor = damping(tau);
    const double        dA             = point.JxW;
    const Tensor<1, 3> &nt             = point.smooth_normal;
    for (const unsigned int i : dofs.new_position)
      {
        // (κñ, η)_h, and the tangential damping (T_r/τ)(P̃(Y − W), η)_h.
        const Tensor<1, 3> &eta         = point.new_position[i];
        const Tensor<1, 3>  eta_tangent = eta - (eta * nt) * nt;
        rhs(i) += damping_factor * (target * eta_tangent) * dA;
        for (const unsigned int j : dofs.curvature)
          matrix(i, j) += point.curvature[j] * (nt * eta) * dA;
        if (damping_factor > 0)
          for (const unsigned int j : dofs.new_position)
            matrix(i, j) += damping_factor * (point.new_position[j] * eta_tangent) * dA;
      }
  }

  void
  MeshRedistribution::assemble_reference_terms(const SurfacePointValues &point,
                                               const Tensor<2, 3>       &reference_gradient,
                                               const Tensor<2, 3>       &rotation,
                                               const double              area_scale,
                                               const double              weight,
                                               const DofLayout          &dofs,
                                               FullMatrix<double>       &matrix,
                                               Vector<double>           &rhs) const
  {
    const double        dA = point.flow.JxW;
    const Tensor<1, 3> &nu = point.flow.normal;
    // M = G₀ᵀG₀ acts on the tangent plane of S^m (M ν = 0); its 2D trace and determinant.
    const Tensor<2, 3> M        = transpose(reference_gradient) * reference_gradient;
    const double       trace    = dealii::trace(M);
    const double       det2     = 0.5 * (trace * trace - scalar_product(M, M));
    const double       root     = std::sqrt(det2);
    const double       J        = 1.0 / root; // area of S^m over S₀
    Tensor<2, 3>       tangent  = unit_symmetric_tensor<3>();
    tangent -= outer_product(nu, nu);
    const Tensor<2, 3> A        = (trace * tangent - M) / root;
    const double       mu       = weight * shear_stiffness;
    const double       K        = weight * area_stiffness * area_scale;
    const double       sJ       = area_scale * J;
    // The trial function's parts, once per j: ∇Y A and R : ∇Y (which is also div η for the test function).
    thread_local std::vector<Tensor<2, 3>> stretched;
    thread_local std::vector<double>       divergence;
    stretched.resize(point.new_position_gradient.size());
    divergence.resize(point.new_position_gradient.size());
    for (const unsigned int j : dofs.new_position)
      {
        stretched[j]  = point.new_position_gradient[j] * A;
        divergence[j] = scalar_product(rotation, point.new_position_gradient[j]);
      }
    for (const unsigned int i : dofs.new_position)
      {
        const Tensor<2, 3> &grad_eta = point.new_position_gradient[i];
        const double        div_eta  = divergence[i];
        rhs(i) += (mu + K * (sJ + 1.0)) * div_eta * dA;
        for (const unsigned int j : dofs.new_position)
          matrix(i, j) += (mu * scalar_product(stretched[j], grad_eta) + K * sJ * divergence[j] * div_eta) * dA;
      }
  }

  void
  MeshRedistribution::project_position_rows(const std::vector<Tensor<1, 3>> &node_normals,
                                            const DofLayout                 &dofs,
                                            const FullMatrix<double>        &normal_rows,
                                            const FullMatrix<double>        &tangential_rows,
                                            const Vector<double>            &tangential_rhs,
                                            FullMatrix<double>              &matrix,
                                            Vector<double>                  &rhs)
  {
    AssertDimension(node_normals.size(), dofs.new_position_nodes.size());
    const unsigned int n_columns = matrix.n();
    for (unsigned int n = 0; n < node_normals.size(); ++n)
      {
        const auto         &rows = dofs.new_position_nodes[n];
        const Tensor<1, 3> &nt   = node_normals[n];
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int e = 0; e < 3; ++e)
            {
              const double normal_part     = nt[d] * nt[e];
              const double tangential_part = (d == e ? 1.0 : 0.0) - normal_part;
              rhs(rows[d]) += tangential_part * tangential_rhs(rows[e]);
              for (unsigned int j = 0; j < n_columns; ++j)
                matrix(rows[d], j) +=
                  normal_part * normal_rows(rows[e], j) + tangential_part * tangential_rows(rows[e], j);
            }
      }
  }
} // namespace FluidSurface
