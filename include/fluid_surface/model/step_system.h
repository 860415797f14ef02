// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_step_system_h
#define fluid_surface_model_step_system_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/dof_layout.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FluidSurface
{
  class CheckpointData;
  class RigidMotion;
  struct LocalSystem;

  /**
   * The linear system of one step of scene full, as step-38 sets it up: the element of (u, p, κ, y, Y) =
   * [Q2]³ × Q1 × Q_k × Q_k × [Q_k]³ (k the geometry's degree), its DoFs, hanging-node constraints and sparsity,
   * the matrix, right-hand side and the global columns (the volume column (ñ, v), the six rigid-motion columns
   * and rows), and the node maps between the flow DoFs and the geometry's position DoFs.
   */
  class StepSystem
  {
  public:
    using GlobalIndex = dealii::types::global_dof_index;
    /// The three DoFs of one node of a vector unknown.
    using Node = std::array<GlobalIndex, 3>;

    /// The system on @p geometry (kept by reference).
    explicit StepSystem(SurfaceGeometry &geometry);

    /// Distributes the DoFs on the current mesh, sizes the matrix and vectors and builds the node maps.
    void
    setup_system();
    /// Zeroes the matrix, the right-hand side and the global columns and rows before an assembly.
    void
    zero();
    /// Adds the contributions of all ranks (after an assembly); the rigid-motion columns only if @p rigid.
    void
    compress(const bool rigid);

    /// The element of (u, p, κ, y, Y).
    const dealii::FESystem<2, 3> &
    fe() const
    {
      return *element;
    }
    /// The local DoFs of u, p, κ, y, Y in a cell.
    const DofLayout &
    layout() const
    {
      return *dof_layout;
    }
    /// The DoFs of (u, p, κ, y, Y).
    const dealii::DoFHandler<2, 3> &
    dof_handler() const
    {
      return dofs;
    }
    /// The hanging-node constraints of the flow DoFs.
    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return hanging_nodes;
    }
    /// The geometry the system lives on.
    SurfaceGeometry &
    geometry() const
    {
      return surface;
    }
    /// A vector of the flow DoFs, owned entries only.
    VectorType
    owned_vector() const;
    /// A vector of the flow DoFs with the ghost entries.
    VectorType
    ghosted_vector() const;
    /// The flow-numbered field @p name of a checkpoint (written on any number of ranks), ghosted.
    VectorType
    read_field(const CheckpointData &data, const std::string &name) const;

    /// The step matrix.
    dealii::TrilinosWrappers::SparseMatrix &
    matrix()
    {
      return system_matrix;
    }
    const dealii::TrilinosWrappers::SparseMatrix &
    matrix() const
    {
      return system_matrix;
    }
    /// The right-hand side (owned).
    VectorType &
    rhs()
    {
      return system_rhs;
    }
    const VectorType &
    rhs() const
    {
      return system_rhs;
    }
    /// (ñ, v): γ's column and the volume row.
    const VectorType &
    volume_column() const
    {
      return volume;
    }
    /// The columns (r_k, v) of the rigid motions r = e_1, e_2, e_3, e_1 × x, e_2 × x, e_3 × x.
    const std::array<VectorType, 6> &
    rigid_columns() const
    {
      return rigid_motion_columns;
    }
    /// The constraint rows of the rigid motions (MomentumConstraints).
    const std::array<VectorType, 6> &
    rigid_rows() const
    {
      return rigid_motion_rows;
    }
    /**
     * Whether the equations of component @p row (DofLayout's numbering) involve component @p column: the
     * momentum rows u, p, y and Y (convection by the mesh motion); the continuity rows u (and p, the prescribed
     * velocity's mass); the kinematics κ: u and Y; the bending scalar y: y and κ; the position rows Y: Y and κ.
     * The matrix stores only these blocks (at k = 2, 3553 of the 76² entries of a cell).
     */
    static bool
    couples(const unsigned int row, const unsigned int column);

    /**
     * Adds one cell's local system to the global one (the copier of the assembly). Throws if the local matrix
     * has a nonzero entry in a block that couples() leaves out (the sparse matrix would drop it).
     */
    void
    distribute_local_to_global(const LocalSystem &local, const bool rigid);

    /// The flow DoFs of the locally owned nodes of Y.
    const std::vector<Node> &
    new_position_nodes() const
    {
      return position_nodes;
    }
    /// The geometry DoFs of the components of each node of new_position_nodes().
    const std::vector<Node> &
    new_position_geometry_dofs() const
    {
      return position_geometry_dofs;
    }

    /**
     * Adds to Y of @p flow_vector, node by node, the part of Y of @p difference along the unit nodal field
     * @p normal (geometry numbering, ghosted): y += ((d·ñ)ñ).
     */
    void
    add_normal_part(const VectorType &difference, const VectorType &normal, VectorType &flow_vector) const;

    /// Y of @p flow_vector → the geometry's position field.
    void
    copy_new_position_to_geometry(const VectorType &flow_vector) const;
    /// Y of @p flow_vector (ghosted: a geometry DoF this rank owns may sit on a flow DoF another rank owns) in the
    /// geometry numbering (owned).
    VectorType
    new_position(const VectorType &flow_vector) const;
    /// The position @p x (geometry numbering) → the Y components of @p flow_vector (owned).
    void
    copy_position_into(const VectorType &x, VectorType &flow_vector) const;
    /// The dot product of the new positions Y of @p a and @p b over the nodes.
    double
    position_dot(const VectorType &a, const VectorType &b) const;
    /// The largest distance between the new positions Y of @p a and @p b over the nodes.
    double
    largest_node_move(const VectorType &a, const VectorType &b) const;
    /**
     * The rigid motion @p carried over the time @p tau applied to the nodal fields of @p solution: u ← Q(τ)u,
     * Y ← carry(Y, τ).
     */
    void
    carry_fields(const RigidMotion &carried, const double tau, VectorType &solution) const;
    /// The vector unknowns u and Y of @p v turned by @p rotation node by node (about the origin).
    void
    rotate_vector_unknowns(const dealii::Tensor<2, 3> &rotation, VectorType &v) const;

  private:
    /// velocity_nodes and position_nodes from the cells.
    void
    list_nodes();
    /// Each node of @p nodes in @p v turned by @p rotation (owned entries; the caller compresses).
    static void
    turn_nodes(const std::vector<Node> &nodes, const dealii::Tensor<2, 3> &rotation, VectorType &v);
    /// position_pairs and position_geometry_dofs: Y_d and X_d share the nodes of Q_k.
    void
    pair_position_dofs();

    SurfaceGeometry                        &surface;
    std::unique_ptr<dealii::FESystem<2, 3>> element;
    std::unique_ptr<const DofLayout>        dof_layout;
    /// couples() for the local DoFs of a cell: local_coupling[i][j].
    std::vector<std::vector<bool>>          local_coupling;
    /// Whether distribute_local_to_global() checked a cell against local_coupling since zero().
    bool                                    coupling_checked = false;
    dealii::DoFHandler<2, 3>               dofs;
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      hanging_nodes;

    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    VectorType                             system_rhs;
    VectorType                             volume;
    std::array<VectorType, 6>              rigid_motion_columns, rigid_motion_rows;

    /// The flow DoFs (components 0–2) of the locally owned nodes of u and of Y.
    std::vector<Node> velocity_nodes, position_nodes;
    /// (flow DoF of Y_d, geometry DoF of X_d) for the locally owned nodes.
    std::vector<std::pair<GlobalIndex, GlobalIndex>> position_pairs;
    /// The geometry DoFs of the components of each node of position_nodes.
    std::vector<Node> position_geometry_dofs;
  };
} // namespace FluidSurface

#endif
