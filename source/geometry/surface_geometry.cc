// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/vector_tools.h>

#include <fluid_surface/geometry/exact_geometry.h>
#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/parameter_file.h>
#include <fluid_surface/io/run_stopped.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  SurfaceGeometry::SurfaceGeometry(const MPI_Comm communicator)
    : communicator(communicator)
    , tria(communicator)
    , position_dofs(tria)
  {}

  void
  SurfaceGeometry::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry");
    prm.declare_entry("shape",
                      "ellipsoid",
                      Patterns::Selection("sphere|ellipsoid|mesh file|equilibrium"),
                      "Initial shape of the closed surface S: a sphere of radius R, an ellipsoid with "
                      "semi-axes (a, b, c) along x, y, z (c > a: prolate, c < a: oblate), a gmsh mesh, or "
                      "the rotating axisymmetric equilibrium of subsection equilibrium (axis z; the nodes of "
                      "the refined cube sphere are placed on the exact generating curve, polar angle θ ↦ "
                      "arc length s = 2S θ/π).");
    prm.declare_entry("radius",
                      "1",
                      RealRange::closed(1e-3, 1e3),
                      "Radius R, 0.001 ≤ R ≤ 1000, of the sphere (shape = sphere).");
    prm.declare_entry("semi-axes",
                      "0.61, 0.61, 2.02",
                      Patterns::List(RealRange::closed(1e-3, 1e3), 3, 3),
                      "Semi-axes a, b, c of the ellipsoid x²/a² + y²/b² + z²/c² = 1 along x, y, z "
                      "(shape = ellipsoid, or the projection target of a mesh file): each in [0.001, 1000], and "
                      "for shape = ellipsoid the largest at most 20 times the smallest (the cube-sphere mesh of a "
                      "more elongated ellipsoid is too distorted for the mesh quality floor).");
    prm.declare_entry("mesh file",
                      "meshes/ellipsoid.msh",
                      Patterns::FileName(),
                      "gmsh mesh (ASCII msh 2.2 or 4.1) of a closed all-quadrilateral surface "
                      "(shape = mesh file); relative to the working directory.");
    prm.declare_entry("project onto ellipsoid",
                      "true",
                      Patterns::Bool(),
                      "Move the nodes of a mesh file radially onto the ellipsoid with the given semi-axes.");
    prm.declare_entry("refinement",
                      "3",
                      Patterns::Integer(0, max_refinement),
                      "Number of global refinements of the coarse mesh (6 cells for a sphere or ellipsoid), 0 to 7; "
                      "the refined mesh may have at most 98304 cells (6·4⁷; scene full: about 3.2 million "
                      "unknowns, 4× the unknowns per refinement).");
    prm.declare_entry("position degree",
                      "2",
                      Patterns::Integer(1, 3),
                      "Polynomial degree k, 1 to 3, of the position field X ∈ [Q_k]³ that defines the geometry.");
    prm.leave_subsection();
    // The equilibrium shape's inputs (read only for shape = equilibrium).
    AxisymmetricEquilibrium::declare_parameters(prm);
  }

  void
  SurfaceGeometry::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry");
    const std::string s = prm.get("shape");
    params.shape        = (s == "sphere"      ? Shape::sphere :
                           s == "ellipsoid"   ? Shape::ellipsoid :
                           s == "equilibrium" ? Shape::equilibrium :
                                                Shape::mesh_file);
    params.radius       = prm.get_double("radius");
    params.semi_axes    = get_vector(prm, "semi-axes");
    const Point<3> &a   = params.semi_axes;
    if (params.shape == Shape::ellipsoid && std::max({a[0], a[1], a[2]}) > 20 * std::min({a[0], a[1], a[2]}))
      throw_invalid_entry("geometry/semi-axes",
                          prm.get("semi-axes"),
                          "semi-axes whose largest is at most 20 times the smallest (shape = ellipsoid)");
    params.mesh_file              = prm.get("mesh file");
    params.project_onto_ellipsoid = prm.get_bool("project onto ellipsoid");
    params.refinement             = prm.get_integer("refinement");
    params.position_degree        = prm.get_integer("position degree");
    if (params.shape == Shape::mesh_file)
      {
        std::ifstream in(params.mesh_file);
        if (!in)
          throw_invalid_entry("geometry/mesh file", params.mesh_file, "a readable gmsh mesh file");
      }
    prm.leave_subsection();
    equilibrium.reset();
    if (params.shape == Shape::equilibrium)
      {
        equilibrium = std::make_unique<AxisymmetricEquilibrium>();
        equilibrium->parse_parameters(prm);
      }
  }

  std::string
  SurfaceGeometry::shape_name(const Shape shape)
  {
    return shape == Shape::sphere      ? "sphere" :
           shape == Shape::ellipsoid   ? "ellipsoid" :
           shape == Shape::equilibrium ? "equilibrium" :
                                         "mesh file";
  }

  std::string
  SurfaceGeometry::description() const
  {
    std::ostringstream out;
    if (params.shape == Shape::sphere)
      out << "sphere R = " << params.radius;
    else if (params.shape == Shape::equilibrium)
      out << (equilibrium->parameters().branch == AxisymmetricEquilibrium::Branch::prolate ? "prolate" : "oblate")
          << " rotating equilibrium, A = " << equilibrium->parameters().area
          << ", v = " << equilibrium->parameters().reduced_volume;
    else
      {
        if (params.shape == Shape::mesh_file)
          out << "mesh " << std::filesystem::path(params.mesh_file).filename().string() << (params.project_onto_ellipsoid ? " projected onto " : "");
        if (params.shape == Shape::ellipsoid || params.project_onto_ellipsoid)
          out << "ellipsoid [" << params.semi_axes[0] << ", " << params.semi_axes[1] << ", " << params.semi_axes[2] << "]";
      }
    out << ", Q" << params.position_degree << " geometry, refinement " << params.refinement;
    return out.str();
  }

  void
  SurfaceGeometry::read_mesh_file()
  {
    // A coarse mesh is small: every rank reads it.
    Triangulation<2, 3> coarse;
    GridIn<2, 3>        grid_in;
    grid_in.attach_triangulation(coarse);
    std::ifstream in(params.mesh_file);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &exc)
      {
        std::string reader = one_line_message(exc, 200);
        if (!reader.empty() && reader.back() == '.')
          reader.pop_back();
        throw_invalid_entry("geometry/mesh file",
                            params.mesh_file,
                            "an ASCII gmsh mesh (msh 2.2 or 4.1) of quadrilaterals; the reader says: " + reader);
      }
    if (!coarse.all_reference_cells_are_hyper_cube())
      throw InputError(params.mesh_file + ": the mesh has triangles; expected an all-quadrilateral surface mesh "
                                   "(recombine in gmsh: Mesh.RecombineAll = 1, Mesh.SubdivisionAlgorithm = 1).");
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          throw InputError(params.mesh_file + ": the surface has a boundary edge at " +
                           Utilities::to_string(cell->face(f)->center()[0]) + ", " +
                           Utilities::to_string(cell->face(f)->center()[1]) + ", " +
                           Utilities::to_string(cell->face(f)->center()[2]) +
                           "; expected a closed surface.");
    if (coarse.n_active_cells() * std::pow(4.0, params.refinement) > max_cells)
      {
        unsigned int allowed = 0;
        while (coarse.n_active_cells() * std::pow(4.0, allowed + 1) <= max_cells)
          ++allowed;
        throw_invalid_entry("geometry/refinement",
                            std::to_string(params.refinement),
                            "at most " + std::to_string(max_cells) + " cells after refinement: the mesh " + params.mesh_file +
                              " has " + std::to_string(coarse.n_active_cells()) + " cells" +
                              (coarse.n_active_cells() > max_cells ?
                                 std::string(" (too many even without refinement)") :
                                 ", so at most " + std::to_string(allowed) + " refinements"));
      }
    tria.copy_triangulation(coarse);
  }

  void
  SurfaceGeometry::create()
  {
    if (params.shape == Shape::mesh_file)
      read_mesh_file();
    else
      {
        GridGenerator::hyper_sphere(tria, Point<3>(), 1.0);
        tria.set_all_manifold_ids(0);
        tria.set_manifold(0, SphericalManifold<2, 3>(Point<3>()));
      }
    tria.refine_global(params.refinement);
    setup_position_space();

    // Nodes of the refined coarse geometry (on the unit sphere for the
    // generated shapes), then moved onto the requested shape.
    {
      VectorType owned(owned_dofs, communicator);
      VectorTools::get_position_vector(MappingQ<2, 3>(params.position_degree), position_dofs, owned);
      set_position(owned);
    }
    if (params.shape == Shape::sphere)
      transform_nodes([this](const Point<3> &x) { return Point<3>(params.radius / x.norm() * x); });
    else if (params.shape == Shape::ellipsoid)
      transform_nodes([this](const Point<3> &x) {
        const Point<3> u = x / x.norm();
        return Point<3>(params.semi_axes[0] * u[0], params.semi_axes[1] * u[1], params.semi_axes[2] * u[2]);
      });
    else if (params.shape == Shape::equilibrium)
      {
        solve_equilibrium_of_entries(*equilibrium);
        transform_nodes([this](const Point<3> &x) { return equilibrium->map_from_sphere(Point<3>(x / x.norm())); });
      }
    else if (params.project_onto_ellipsoid)
      transform_nodes([this](const Point<3> &x) {
        double s = 0;
        for (unsigned int d = 0; d < 3; ++d)
          s += x[d] * x[d] / (params.semi_axes[d] * params.semi_axes[d]);
        return Point<3>(x / std::sqrt(s));
      });
    // The manifold describes only the unit sphere; the position field is the geometry from now on.
    tria.reset_all_manifolds();
    check_closed_and_outward();
  }

  void
  SurfaceGeometry::setup_position_space()
  {
    position_fe = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(params.position_degree), 3);
    position_dofs.distribute_dofs(*position_fe);
    owned_dofs = position_dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(position_dofs, relevant_dofs);
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(position_dofs, constraints);
    constraints.close();

    // The mass matrix of [Q_k]³ couples each component only with itself.
    Table<2, DoFTools::Coupling> same_component(3, 3);
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int d = 0; d < 3; ++d)
        same_component(c, d) = c == d ? DoFTools::always : DoFTools::none;
    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(position_dofs, same_component, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, communicator, relevant_dofs);
    mass_pattern.reinit(owned_dofs, owned_dofs, dsp, communicator);

    position_ghosted.reinit(owned_dofs, relevant_dofs, communicator);
    derived_current = false;
    surface_mapping = std::make_unique<MappingFEField<2, 3, VectorType>>(position_dofs, position_ghosted);
  }

  void
  SurfaceGeometry::set_position(const VectorType &new_position)
  {
    VectorType owned(owned_dofs, communicator);
    owned = new_position;
    // Hanging nodes must follow their parents, or the surface cracks.
    constraints.distribute(owned);
    position_ghosted = owned;
    derived_current  = false;
  }

  void
  SurfaceGeometry::set_position(const VectorType &new_position, const Curvature &new_curvature)
  {
    set_position(new_position);
    derived         = new_curvature;
    derived_current = true;
  }

  const SurfaceGeometry::Curvature &
  SurfaceGeometry::curvature() const
  {
    if (!derived_current)
      {
        derived         = compute_curvature();
        derived_current = true;
      }
    return derived;
  }

  namespace
  {
    /**
     * Calls f(i, j) for the three DoF indices of every locally owned support
     * point of a [Q_k]³ field: the position of node i is (X[i0], X[i1], X[i2]).
     */
    void
    for_each_owned_node(const DoFHandler<2, 3>                                          &dofs,
                        const std::function<void(const std::array<types::global_dof_index, 3> &)> &f)
    {
      const FiniteElement<2, 3>           &fe = dofs.get_fe();
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      std::vector<bool>                    visited(dofs.locally_owned_dofs().n_elements(), false);
      const IndexSet                      &owned = dofs.locally_owned_dofs();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.system_to_component_index(i).first == 0 && owned.is_element(indices[i]) &&
                  !visited[owned.index_within_set(indices[i])])
                {
                  std::array<types::global_dof_index, 3> node;
                  const unsigned int base = fe.system_to_component_index(i).second;
                  for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                    if (fe.system_to_component_index(j).second == base)
                      node[fe.system_to_component_index(j).first] = indices[j];
                  visited[owned.index_within_set(indices[i])] = true;
                  f(node);
                }
          }
    }
  } // namespace

  void
  SurfaceGeometry::transform_nodes(const std::function<Point<3>(const Point<3> &)> &f)
  {
    VectorType owned(owned_dofs, communicator);
    owned = position_ghosted;
    const VectorType &old_position = position_ghosted;
    for_each_owned_node(position_dofs, [&](const std::array<types::global_dof_index, 3> &node) {
      // All three components of an owned node are owned (same support point, same owner).
      const Point<3> x(old_position[node[0]], old_position[node[1]], old_position[node[2]]);
      const Point<3> y = f(x);
      for (unsigned int d = 0; d < 3; ++d)
        owned[node[d]] = y[d];
    });
    owned.compress(VectorOperation::insert);
    set_position(owned);
  }

  SurfaceGeometry::Measures
  SurfaceGeometry::measure() const
  {
    const QGauss<2>   q = quadrature();
    FEValues<2, 3>    fe_values(mapping(), fe(), q, update_quadrature_points | update_normal_vectors |
                                                  update_JxW_values | update_jacobians);
    double            local[5]    = {0, 0, 0, 0, 0};
    double            min_quality = 1.0;
    for (const auto &cell : position_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const Point<3> &x  = fe_values.quadrature_point(k);
              const double    dA = fe_values.JxW(k);
              local[0] += dA;
              local[1] += x * fe_values.normal_vector(k) * dA / 3.0;
              for (unsigned int d = 0; d < 3; ++d)
                local[2 + d] += x[d] * dA;
              // Singular values of the 3×2 Jacobian from its 2×2 Gram matrix.
              const DerivativeForm<1, 2, 3> &J = fe_values.jacobian(k);
              double                         g[3] = {0, 0, 0};
              for (unsigned int d = 0; d < 3; ++d)
                {
                  g[0] += J[d][0] * J[d][0];
                  g[1] += J[d][0] * J[d][1];
                  g[2] += J[d][1] * J[d][1];
                }
              const double mean = 0.5 * (g[0] + g[2]);
              const double dev  = std::sqrt(0.25 * (g[0] - g[2]) * (g[0] - g[2]) + g[1] * g[1]);
              min_quality       = std::min(min_quality, std::sqrt(std::max(mean - dev, 0.0) / (mean + dev)));
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(local, 5), communicator, ArrayView<double>(local, 5));
    Measures m;
    m.area   = local[0];
    m.volume = local[1];
    for (unsigned int d = 0; d < 3; ++d)
      m.centre_of_mass[d] = local[2 + d] / m.area;
    m.reduced_volume = reduced_volume_of(m.area, m.volume);
    m.mesh_quality   = Utilities::MPI::min(min_quality, communicator);
    return m;
  }

  void
  SurfaceGeometry::check_closed_and_outward() const
  {
    // Outward normals: ν·(x − x_c) > 0 at every cell centre of the initial
    // (star-shaped) surface; a mesh with inward or mixed orientation is rejected.
    const Measures     m = measure();
    const QGauss<2>    q(1);
    FEValues<2, 3>     fe_values(mapping(), fe(), q, update_quadrature_points | update_normal_vectors);
    unsigned int       n_inward = 0;
    for (const auto &cell : position_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if ((fe_values.quadrature_point(0) - Point<3>(m.centre_of_mass)) * fe_values.normal_vector(0) <= 0)
            ++n_inward;
        }
    n_inward = Utilities::MPI::sum(n_inward, communicator);
    if (n_inward > 0)
      {
        const std::string source = (params.shape == Shape::mesh_file ? params.mesh_file : std::string("generated mesh"));
        throw InputError(source + ": " + Utilities::to_string(n_inward) + " of " +
                         Utilities::to_string(tria.n_global_active_cells()) +
                         " cells have inward normals; expected a closed, star-shaped surface whose cells "
                         "are all ordered counter-clockwise seen from outside (gmsh: Reverse Surface).");
      }
  }

  void
  SurfaceGeometry::assemble_curvature_system(TrilinosWrappers::SparseMatrix &mass,
                                             VectorType                     &rhs_curvature,
                                             VectorType                     &rhs_normal) const
  {
    mass.reinit(mass_pattern);
    rhs_curvature.reinit(owned_dofs, communicator);
    rhs_normal.reinit(owned_dofs, communicator);

    const QGauss<2>                      q = quadrature();
    FEValues<2, 3>                       fe_values(mapping(), fe(), q, update_values | update_gradients |
                                                                  update_normal_vectors | update_JxW_values);
    const FEValuesExtractors::Vector     vec(0);
    const unsigned int                   n = fe().n_dofs_per_cell();
    FullMatrix<double>                   cell_mass(n, n);
    Vector<double>                       cell_rhs_curvature(n), cell_rhs_normal(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<unsigned int>            component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe().system_to_component_index(i).first;
    for (const auto &cell : position_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_mass          = 0;
          cell_rhs_curvature = 0;
          cell_rhs_normal    = 0;
          for (unsigned int k = 0; k < q.size(); ++k)
            {
              const double          dA = fe_values.JxW(k);
              const Tensor<1, 3>   &nu = fe_values.normal_vector(k);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Tensor<1, 3> phi_i = fe_values[vec].value(i, k);
                  // ∇_S X = P, so (∇_S X, ∇_S η) = (P, ∇_S η) = div_S η.
                  cell_rhs_curvature(i) -= fe_values[vec].divergence(i, k) * dA;
                  cell_rhs_normal(i) += phi_i * nu * dA;
                  for (unsigned int j = 0; j < n; ++j)
                    if (component[j] == component[i])
                      cell_mass(i, j) += fe_values.shape_value(i, k) * fe_values.shape_value(j, k) * dA;
                }
            }
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_mass, cell_rhs_curvature, indices, mass, rhs_curvature);
          constraints.distribute_local_to_global(cell_rhs_normal, indices, rhs_normal);
        }
    mass.compress(VectorOperation::add);
    rhs_curvature.compress(VectorOperation::add);
    rhs_normal.compress(VectorOperation::add);
  }

  void
  SurfaceGeometry::normalize_normal_field(VectorType &normal) const
  {
    VectorType owned(owned_dofs, communicator);
    owned = normal;
    const VectorType &n = normal;
    for_each_owned_node(position_dofs, [&](const std::array<types::global_dof_index, 3> &node) {
      const double norm = std::sqrt(n[node[0]] * n[node[0]] + n[node[1]] * n[node[1]] + n[node[2]] * n[node[2]]);
      for (unsigned int d = 0; d < 3; ++d)
        owned[node[d]] = n[node[d]] / norm;
    });
    owned.compress(VectorOperation::insert);
    normal = owned;
  }

  void
  SurfaceGeometry::update_nodal_mean_curvature(Curvature &curvature) const
  {
    VectorType        owned(owned_dofs, communicator);
    const VectorType &n = curvature.normal;
    const VectorType &k = curvature.vector;
    for_each_owned_node(position_dofs, [&](const std::array<types::global_dof_index, 3> &node) {
      const double h = k[node[0]] * n[node[0]] + k[node[1]] * n[node[1]] + k[node[2]] * n[node[2]];
      for (unsigned int d = 0; d < 3; ++d)
        owned[node[d]] = h;
    });
    owned.compress(VectorOperation::insert);
    curvature.mean_curvature.reinit(owned_dofs, relevant_dofs, communicator);
    curvature.mean_curvature = owned;
  }

  double
  SurfaceGeometry::integrate_willmore_energy(const VectorType &kappa_field) const
  {
    const QGauss<2>                  q = quadrature();
    const FEValuesExtractors::Vector vec(0);
    double                           local_energy = 0;
    std::vector<Tensor<1, 3>>        kappa(q.size());
    FEValues<2, 3>                   fe_values_kappa(mapping(), fe(), q, update_values | update_JxW_values);
    for (const auto &cell : position_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values_kappa.reinit(cell);
          fe_values_kappa[vec].get_function_values(kappa_field, kappa);
          for (unsigned int k = 0; k < q.size(); ++k)
            local_energy += 0.5 * kappa[k].norm_square() * fe_values_kappa.JxW(k);
        }
    return Utilities::MPI::sum(local_energy, communicator);
  }

  SurfaceGeometry::Curvature
  SurfaceGeometry::compute_curvature() const
  {
    TrilinosWrappers::SparseMatrix mass;
    VectorType                     rhs_curvature, rhs_normal;
    assemble_curvature_system(mass, rhs_curvature, rhs_normal);

    TrilinosWrappers::PreconditionJacobi jacobi;
    jacobi.initialize(mass);
    auto solve = [&](const VectorType &rhs, VectorType &ghosted) {
      VectorType    solution(owned_dofs, communicator);
      SolverControl control(1000, 1e-14 * rhs.l2_norm());
      SolverCG<VectorType> cg(control);
      cg.solve(mass, solution, rhs, jacobi);
      constraints.distribute(solution);
      ghosted = solution;
    };
    Curvature curvature;
    curvature.vector.reinit(owned_dofs, relevant_dofs, communicator);
    curvature.normal.reinit(owned_dofs, relevant_dofs, communicator);
    solve(rhs_curvature, curvature.vector);
    solve(rhs_normal, curvature.normal);
    normalize_normal_field(curvature.normal);
    update_nodal_mean_curvature(curvature);
    curvature.willmore_energy = integrate_willmore_energy(curvature.vector);
    return curvature;
  }
} // namespace FluidSurface
