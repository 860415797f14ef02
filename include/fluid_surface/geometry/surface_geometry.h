// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_geometry_surface_geometry_h
#define fluid_surface_geometry_surface_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fluid_surface/base/types.h>
#include <fluid_surface/reference/axisymmetric_equilibrium.h>

#include <functional>
#include <memory>
#include <string>

namespace FluidSurface
{
  /// The vector type of every distributed field (position, velocity, curvature).
  /**
   * The moving closed surface S: a parallel::distributed::Triangulation<2,3>
   * of quadrilaterals, the position field X ∈ [Q_k]³ and the MappingFEField
   * that makes X the geometry of every finite element computation.
   *
   * It measures what needs no flow: area |S|, enclosed volume V = ⅓∫X·ν,
   * reduced volume v = 6√π V / |S|^{3/2}, centre of mass, the weak curvature
   * vector κ = Hν from (κ, η) = −(∇_S X, ∇_S η) (so H = −2/R on a sphere of
   * radius R with the outward normal ν), the Willmore energy ½∫|κ|², a
   * continuous unit normal ñ (L2 projection of the cell normals), and a mesh
   * quality figure.
   */
  class SurfaceGeometry
  {
  public:
    /// The initial shape.
    enum class Shape
    {
      sphere,
      ellipsoid,
      mesh_file,
      equilibrium ///< a rotating axisymmetric equilibrium of `subsection equilibrium`
    };

    /// `subsection geometry`, parsed once by parse_parameters(); the scenes that check the shape read it here.
    struct Parameters
    {
      Shape            shape  = Shape::ellipsoid;
      double           radius = 1.0;                       ///< R of shape = sphere
      dealii::Point<3> semi_axes{0.61, 0.61, 2.02};        ///< (a, b, c) of the ellipsoid, or of the projection
      std::string      mesh_file;                          ///< shape = mesh file
      bool             project_onto_ellipsoid = true;      ///< of the nodes of a mesh file
      unsigned int     refinement             = 3;         ///< global refinements
      unsigned int     position_degree        = 2;         ///< k of X ∈ [Q_k]³
    };

    /// The name of @p shape in the parameter file (`geometry/shape`).
    static std::string
    shape_name(const Shape shape);

    /// Integral measures of the surface.
    struct Measures
    {
      double               area           = 0; ///< |S| = ∫1
      double               volume         = 0; ///< V = ⅓∫X·ν
      double               reduced_volume = 0; ///< v = V / (4π/3 (|S|/4π)^{3/2})
      dealii::Tensor<1, 3> centre_of_mass;     ///< x_c = ∫X / |S|
      double               mesh_quality = 0;   ///< min over cells of σ_min/σ_max of the cell Jacobian
    };

    /**
     * The data derived from the position: the weak curvature vector κ = Hν from (κ, η) = −(∇_S X, ∇_S η), the
     * continuous normal ñ from (ñ, η) = (ν_h, η) (normalized at the nodes), the nodal H = κ·ñ and the Willmore
     * energy ½∫|κ|². A value: a copy keeps the data of the surface it was taken of.
     */
    struct Curvature
    {
      VectorType vector;         ///< κ, ghosted
      VectorType normal;         ///< ñ, ghosted
      VectorType mean_curvature; ///< H at the nodes, in all three components of each node, ghosted
      double     willmore_energy = 0; ///< ½∫|κ|²
    };

    /// The largest `refinement`: 6·4⁷ cells for the sphere (memory and time grow 4× per refinement).
    static constexpr unsigned int max_refinement = 7;
    /// The most cells a refined mesh may have (also for a gmsh mesh with more coarse cells).
    static constexpr unsigned int max_cells = 6 * 16384;

    explicit SurfaceGeometry(const MPI_Comm communicator);

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Builds the mesh, the position field X and the mapping from the parameters.
    void
    create();

    /**
     * Moves every node of the position field: X ↦ f(X). Used for the initial
     * shape (sphere → ellipsoid, projection of a gmsh mesh, an equilibrium
     * shape) and for shape perturbations.
     */
    void
    transform_nodes(const std::function<dealii::Point<3>(const dealii::Point<3> &)> &f);

    /// Replaces the position field (a step's new X, locally owned entries); its curvature follows when asked for.
    void
    set_position(const VectorType &new_position);
    /// Replaces the position field by @p new_position whose curvature is @p new_curvature (a restore: no solve).
    void
    set_position(const VectorType &new_position, const Curvature &new_curvature);

    const dealii::parallel::distributed::Triangulation<2, 3> &
    triangulation() const
    {
      return tria;
    }
    dealii::parallel::distributed::Triangulation<2, 3> &
    triangulation()
    {
      return tria;
    }
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return position_dofs;
    }
    const dealii::FESystem<2, 3> &
    fe() const
    {
      return *position_fe;
    }
    /// The position field X, ghosted.
    const VectorType &
    position() const
    {
      return position_ghosted;
    }
    const dealii::Mapping<2, 3> &
    mapping() const
    {
      return *surface_mapping;
    }
    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }
    const dealii::IndexSet &
    locally_relevant_dofs() const
    {
      return relevant_dofs;
    }
    unsigned int
    degree() const
    {
      return params.position_degree;
    }
    /// A Gauss quadrature exact enough for integrals over the curved cells.
    dealii::QGauss<2>
    quadrature() const
    {
      return dealii::QGauss<2>(params.position_degree + 2);
    }
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /// Area, volume, reduced volume, centre of mass and mesh quality.
    Measures
    measure() const;


    /**
     * The curvature of the current position: computed (collectively) when first asked for after the position
     * changed, and kept until it changes again.
     */
    const Curvature &
    curvature() const;
    /// κ = Hν of the current surface, ghosted.
    const VectorType &
    curvature_vector() const
    {
      return curvature().vector;
    }
    /// ñ of the current surface, ghosted.
    const VectorType &
    normal_field() const
    {
      return curvature().normal;
    }
    /// Nodal mean curvature H = κ·ñ of the current surface, in all three components of each node, ghosted.
    const VectorType &
    mean_curvature_nodes() const
    {
      return curvature().mean_curvature;
    }
    /// The Willmore energy ½∫|κ|² of the current surface.
    double
    willmore_energy() const
    {
      return curvature().willmore_energy;
    }

    /// The entries of `subsection geometry`.
    const Parameters &
    parameters() const
    {
      return params;
    }

    /**
     * The rotating axisymmetric equilibrium the initial surface was mapped onto (shape = equilibrium), or
     * nullptr. Its axis is z through the origin.
     */
    const AxisymmetricEquilibrium *
    equilibrium_shape() const
    {
      return equilibrium.get();
    }

    /// A short description of the shape for the screen ("ellipsoid [0.61, 0.61, 2.02]").
    std::string
    description() const;

  private:
    void
    read_mesh_file();
    void
    setup_position_space();
    void
    check_closed_and_outward() const;

    /// Assembles the mass matrix of [Q_k]³ and the right-hand sides −(∇_S X, ∇_S η) of κ and (ν_h, η) of ñ.
    void
    assemble_curvature_system(dealii::TrilinosWrappers::SparseMatrix &mass,
                              VectorType                             &rhs_curvature,
                              VectorType                             &rhs_normal) const;

    /// Solves for the curvature of the current position.
    Curvature
    compute_curvature() const;

    /// Normalizes ñ node by node.
    void
    normalize_normal_field(VectorType &normal) const;

    /// Nodal H = κ·ñ of @p curvature, repeated in the three components of each node.
    void
    update_nodal_mean_curvature(Curvature &curvature) const;

    /// Willmore energy ½∫|κ|² of @p kappa.
    double
    integrate_willmore_energy(const VectorType &kappa) const;

    MPI_Comm communicator;

    Parameters             params;
    std::unique_ptr<AxisymmetricEquilibrium> equilibrium;

    dealii::parallel::distributed::Triangulation<2, 3> tria;
    std::unique_ptr<dealii::FESystem<2, 3>>           position_fe;
    dealii::DoFHandler<2, 3>                          position_dofs;
    dealii::IndexSet                                  owned_dofs;
    dealii::IndexSet                                  relevant_dofs;
    dealii::AffineConstraints<double>                 constraints;
    /// The sparsity of the mass matrix of [Q_k]³ (components uncoupled), built with the DoFs.
    dealii::TrilinosWrappers::SparsityPattern mass_pattern;

    VectorType position_ghosted;
    /// The curvature of position_ghosted, once asked for (curvature()).
    mutable Curvature derived;
    mutable bool      derived_current = false;

    std::unique_ptr<dealii::MappingFEField<2, 3, VectorType>> surface_mapping;
  };
} // namespace FluidSurface

#endif
