// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_nodal_vector_field_h
#define fluid_surface_model_nodal_vector_field_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <fluid_surface/geometry/surface_geometry.h>

#include <array>
#include <complex>
#include <vector>

namespace FluidSurface
{
  /**
   * A vector unknown of a nodal element (three consecutive components of an FESystem of FE_Q) seen node by node:
   * the DoF triples of the locally owned nodes and their points on the surface. What the time-map stability
   * analysis (StabilityScene) needs of the position X and the velocity u: a rigid rotation of the field, and its
   * azimuthal content about an axis (the wavenumber and parity of a mode).
   */
  class NodalVectorField
  {
  public:
    /// The nodes of components @p first_component … + 2 of @p dof_handler, at their support points under @p mapping.
    NodalVectorField(const dealii::DoFHandler<2, 3> &dof_handler,
                     const unsigned int              first_component,
                     const dealii::Mapping<2, 3>    &mapping);

    /**
     * out := factor Q (a − b) on the field's DoFs, 0 on the other DoFs of @p out (owned, the partition of the
     * DoFHandler); @p a and @p b may be ghosted.
     */
    void
    rotated_difference(const VectorType           &a,
                       const VectorType           &b,
                       const double                factor,
                       const dealii::Tensor<2, 3> &Q,
                       VectorType                 &out) const;

    /**
     * The rotation Q about @p centre that best carries the nodal values @p from (positions) onto @p to (least
     * squares, Kabsch), and the largest normal distance |(x − Qᵀy)·n| of a node y of @p to, turned back, from its
     * node x of @p from, with @p normal the unit nodal normal of @p from (ghosted): how far the shape moved beyond
     * the rotation (the nodes may also slide along it). Over all ranks.
     */
    std::pair<dealii::Tensor<2, 3>, double>
    fit_rotation(const VectorType       &from,
                 const VectorType       &to,
                 const dealii::Point<3> &centre,
                 const VectorType       &normal) const;

    /**
     * The angle θ of the rotation R about @p axis through @p centre that carries the surface @p from onto @p to:
     * the minimizer of Σ ((x − R(θ)ᵀy)·n)² over the nodes (normal distances only, so that nodes sliding along the
     * surface do not count), searched within ±0.5 rad of @p guess; and the largest normal distance at θ. For a surface that is not
     * axisymmetric about the axis (an end state): the turn of the body, when its nodes slide. On an axisymmetric
     * surface (Σ((e × x)·n)² below 1e-4 Σ|e × x|²) the turn is not seen: θ = @p guess.
     */
    std::pair<double, double>
    fit_shape_rotation(const VectorType           &from,
                       const VectorType           &to,
                       const dealii::Point<3>     &centre,
                       const VectorType           &normal,
                       const dealii::Tensor<1, 3> &axis,
                       const double                guess) const;

    /**
     * The field ε δ(x̂) x̂ on the nodes (0 on the other DoFs of @p out, owned): x̂ the unit vector from @p centre
     * to the node, δ the function of it (a radial displacement of the surface when the field is the position).
     */
    template <typename Displacement>
    void
    radial_field(const dealii::Point<3> &centre, const Displacement &delta, VectorType &out) const
    {
      out = 0;
      for (unsigned int n = 0; n < triples.size(); ++n)
        {
          dealii::Tensor<1, 3> r = points[n] - centre;
          r /= r.norm();
          const double d = delta(r);
          for (unsigned int c = 0; c < 3; ++c)
            out[triples[n][c]] = d * r[c];
        }
      out.compress(dealii::VectorOperation::insert);
    }

    /**
     * The azimuthal content of the complex field @p re + i @p im about @p axis through @p centre: for each
     * wavenumber −M ≤ k ≤ M (index k + M) and parity (0 even, 1 odd under reflection through the plane normal to
     * the axis at the centre), Σ_c |Σ_nodes a_c t_c e^{−ikφ}|² / N² over the cylindrical components a_c (radial,
     * azimuthal, axial) with the parity's test signs t_c (even: 1, 1, sgn ζ; odd: sgn ζ, sgn ζ, 1); summed over
     * ranks. A field ∝ e^{imφ} of one parity has its content at (m, that parity) only, up to the mesh's
     * non-uniformity.
     */
    std::vector<std::array<double, 2>>
    azimuthal_content(const VectorType            &re,
                      const VectorType            &im,
                      const dealii::Tensor<1, 3> &axis,
                      const dealii::Point<3>     &centre,
                      const unsigned int          M) const;

    /**
     * Σ|z·n|² / Σ|z|² over the nodes for the complex field z = @p re + i @p im and the unit nodal field @p normal
     * (ghosted): the share of a displacement of the surface that is normal to it, i.e. changes the shape (the rest
     * moves nodes along the surface). Over all ranks.
     */
    double
    normal_share(const VectorType &re, const VectorType &im, const VectorType &normal) const;

    /**
     * The share of the normal displacement w = z·n of the complex field z = @p re + i @p im (@p normal as in
     * normal_share()) that the rigid motions of a body rotating about @p axis through @p centre at fixed A, V and L
     * give: |Pw|²/|w|² over the nodes, P the orthogonal projection onto the span of e_k·n (the three translations)
     * and (@p axis × (x − c))·n (the turn about the axis). ≈ 1 for the neutral modes of a rigidly rotating state;
     * normal parts only, so that nodes sliding along the surface do not count. A generator whose normal part
     * vanishes (the turn of a body of revolution about its axis) drops out. Over all ranks.
     */
    double
    symmetry_share(const VectorType           &re,
                   const VectorType           &im,
                   const VectorType           &normal,
                   const dealii::Tensor<1, 3> &axis,
                   const dealii::Point<3>     &centre) const;

  private:
    std::vector<std::array<dealii::types::global_dof_index, 3>> triples; ///< the DoFs of the locally owned nodes
    std::vector<dealii::Point<3>>                               points;  ///< their support points
    MPI_Comm                                                    communicator;
  };

} // namespace FluidSurface

#endif
