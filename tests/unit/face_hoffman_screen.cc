// FaceHoffmanScreen, the crack check's first round: its Hoffman index of
// every face of every owned cell equals that of the stress FEValues gives
// at the face centre (the crack check's former way), to round-off: where
// both cells of a face are owned here and of one ply, the smaller of the
// larger side's index and the mean's (a face cracks if a side fails and
// the mean does), else the cell's own; each face once; for
// - Q1 and Q2 in 2D and 3D, three plies at 0, 45 and 90 degrees;
// - a regular mesh (cells share their shape's matrix: one per ply and
//   cell size; a refined corner has cells of half the size) and a
//   distorted one (every cell its own shape);
// - strengths scaled per face, faces switched off by their bit;
// - a new numbering (faces released): the screen picks it up from the
//   state's map;
// and it returns exactly the faces at or above the limit. Runs on one and
// on two ranks. Also: gathered_columns_product(), the screen's kernel,
// against a plain double loop for the sizes it unrolls (8, 18, 24, 81)
// and others (5, 54); and the other user of the cell shapes on the same
// meshes: the static bulk matrix assembled from element matrices shared
// by shape (ElasticAssembler::assemble_matrix) equals the one assembled
// from every cell's own (to 1e-13 relative; exactly on the distorted
// mesh, whose cells compute their own).
#include "../check.h"
#include "two_plies.h"

#include <amfrac/assembly/elastic_assembler.h>
#include <amfrac/assembly/element_kernel.h>
#include <amfrac/assembly/face_hoffman_screen.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <random>

using namespace amfrac;
using namespace amfrac_test;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;

  template <int dim>
  std::vector<PlyProperties<dim>>
  three_plies()
  {
    return {plastic_ply<dim>(0, false),
            plastic_ply<dim>(45, false),
            plastic_ply<dim>(90, false)};
  }

  /** A random state on the numbering of @p dofs, ghosted. */
  template <int dim>
  Vector
  random_state(const TiedCopyDoFs<dim> &dofs, std::mt19937 &engine)
  {
    std::uniform_real_distribution<double> uniform(-2e-3, 2e-3);
    std::vector<double>                    all(dofs.n_dofs());
    for (auto &value : all)
      value = uniform(engine);
    Vector owned(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    for (const auto i : dofs.locally_owned_dofs())
      owned(i) = all[i];
    owned.compress(VectorOperation::insert);
    return ghosted(dofs, owned);
  }

  /** The material-axes stress at the centre of face @p f of @p cell as
   * the crack check computed it before the screen: FEValues at the face
   * centres. */
  template <int dim>
  SymmetricTensor<2, 3>
  reference_stress(const TiedCopyDoFs<dim>                     &dofs,
                   const std::vector<PlyProperties<dim>>       &plies,
                   const typename FaceHoffmanScreen<dim>::Cell &cell,
                   const unsigned int                           f,
                   const Vector                                &state)
  {
    FEValues<dim> values(dofs.get_mapping(),
                         dofs.get_fe(),
                         face_centre_points<dim>(),
                         update_gradients);
    values.reinit(cell);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    dofs.get_dof_indices(cell, indices);
    std::vector<double> local(indices.size());
    for (unsigned int i = 0; i < indices.size(); ++i)
      local[i] = state(indices[i]);
    std::vector<SymmetricTensor<2, dim>> strains(values.n_quadrature_points);
    values[FEValuesExtractors::Vector(0)]
      .get_function_symmetric_gradients_from_local_dof_values(local, strains);
    return evaluate_ply_stress(plies[cell->material_id()], strains[f]).material;
  }

  /** Whether the screen pairs face @p f of @p cell with the cell on its
   * other side (owned here, the same ply, a regular face). */
  template <int dim>
  bool
  paired(const typename FaceHoffmanScreen<dim>::Cell &cell,
         const unsigned int                           f)
  {
    return !cell->at_boundary(f) && cell->neighbor(f)->is_active()
           && !cell->neighbor_is_coarser(f)
           && cell->neighbor(f)->is_locally_owned()
           && cell->neighbor(f)->material_id() == cell->material_id();
  }

  /** The index the screen reports for face @p f of @p cell: the crack
   * check's rule, a side fails and so does the mean, if paired() (of the
   * sides with their bit in @p bits), else the cell's own. */
  template <int dim>
  double
  reference_index(const TiedCopyDoFs<dim>                     &dofs,
                  const std::vector<PlyProperties<dim>>       &plies,
                  const typename FaceHoffmanScreen<dim>::Cell &cell,
                  const unsigned int                           f,
                  const double                                 scale,
                  const std::vector<std::uint8_t>             &bits,
                  const Vector                                &state)
  {
    Strengths s = plies[cell->material_id()].strengths;
    for (double *value :
         {&s.Xt, &s.Xc, &s.Yt, &s.Yc, &s.Zt, &s.Zc, &s.S12, &s.S13, &s.S23})
      *value *= scale;
    const auto own   = reference_stress(dofs, plies, cell, f, state);
    double     index = hoffman_index(own, s);
    if (!paired<dim>(cell, f))
      return index;
    const auto         other      = cell->neighbor(f);
    const unsigned int other_face = cell->neighbor_of_neighbor(f);
    const auto         other_stress
      = reference_stress(dofs, plies, other, other_face, state);
    if ((bits[other->active_cell_index()] >> other_face) & 1u)
      index = std::max(index, hoffman_index(other_stress, s));
    return std::min(index, hoffman_index(0.5 * (own + other_stress), s));
  }

  template <int dim>
  void
  compare(const TiedCopyDoFs<dim>               &dofs,
          const std::vector<PlyProperties<dim>> &plies,
          const FaceHoffmanScreen<dim>          &screen,
          const Vector                          &state,
          const std::vector<std::uint8_t>       &bits,
          const std::vector<double>             &scale,
          const std::string                     &what)
  {
    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;
    const auto             all     = screen.failing(state,
                                    bits,
                                    scale,
                                    -std::numeric_limits<double>::infinity());
    // A paired face once, from the lower cell with the bit.
    const auto has_bit = [&](const auto &cell, const unsigned int f) {
      return ((bits[cell->active_cell_index()] >> f) & 1u) != 0;
    };
    unsigned int expected = 0, n_paired = 0;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int f = 0; f < n_faces; ++f)
          if (has_bit(cell, f))
            {
              if (paired<dim>(cell, f))
                {
                  const auto other = cell->neighbor(f);
                  if (has_bit(other, cell->neighbor_of_neighbor(f))
                      && other->active_cell_index() < cell->active_cell_index())
                    continue;
                  ++n_paired;
                }
              ++expected;
            }
    check(Utilities::MPI::sum(n_paired, MPI_COMM_WORLD) > 0,
          what + ": paired faces",
          __FILE__,
          __LINE__);
    check(all.size() == expected,
          what + ": every face with its bit",
          __FILE__,
          __LINE__);
    double              largest_error = 0, largest = 0;
    std::vector<double> indices;
    for (const auto &face : all)
      {
        const double reference = reference_index(
          dofs,
          plies,
          face.cell,
          face.face,
          scale[face.cell->active_cell_index() * n_faces + face.face],
          bits,
          state);
        largest_error
          = std::max(largest_error, std::abs(face.hoffman - reference));
        largest = std::max(largest, std::abs(reference));
        indices.push_back(face.hoffman);
      }
    check(largest > 0.1, what + ": indices of order one", __FILE__, __LINE__);
    check_close(largest_error / largest,
                0,
                1e-12,
                what + ": relative error",
                __FILE__,
                __LINE__);

    // The limit keeps exactly the faces at or above it.
    std::sort(indices.begin(), indices.end());
    const double limit   = indices[indices.size() / 2];
    const auto   above   = screen.failing(state, bits, scale, limit);
    unsigned int n_above = 0;
    for (const double index : indices)
      n_above += index >= limit;
    check(above.size() == n_above,
          what + ": faces at or above the limit",
          __FILE__,
          __LINE__);
    for (const auto &face : above)
      check(face.hoffman >= limit,
            what + ": a face below the limit",
            __FILE__,
            __LINE__);
  }

  template <int dim>
  void
  check_shared_stiffness(const TiedCopyDoFs<dim>               &dofs,
                         const std::vector<PlyProperties<dim>> &plies,
                         const bool                             distorted,
                         const std::string                     &what)
  {
    const ElasticAssembler<dim> assembler(dofs, plies);
    AffineConstraints<double>   none;
    none.close();
    TrilinosWrappers::SparseMatrix shared, own;
    assembler.reinit_matrix(none, shared);
    assembler.reinit_matrix(none, own);
    assembler.assemble_matrix(none, shared);
    FullMatrix<double>                   K;
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assembler.element_stiffness(cell, K);
          dofs.get_dof_indices(cell, indices);
          none.distribute_local_to_global(K, indices, own);
        }
    own.compress(VectorOperation::add);
    const double size = own.frobenius_norm();
    shared.add(-1., own);
    check(size > 0, what + ": a stiffness matrix", __FILE__, __LINE__);
    check_close(shared.frobenius_norm() / size,
                0,
                distorted ? 0 : 1e-13,
                what + ": shared element matrices, relative difference",
                __FILE__,
                __LINE__);
  }



  template <int dim>
  void
  run(const unsigned int degree, const bool distorted)
  {
    const std::string what = std::to_string(dim) + "D Q"
                             + std::to_string(degree)
                             + (distorted ? " distorted" : " regular");
    parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    std::vector<unsigned int>            cells(dim, 3);
    // In 2D 6 x 3: enough cells per shape (4) for the static assembly to
    // share element matrices.
    cells[0] = dim == 2 ? 6 : 3;
    Point<dim> top;
    for (unsigned int d = 0; d < dim; ++d)
      top[d] = d == dim - 1 ? 0.6 : 2.0;
    GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), top);
    if (distorted)
      GridTools::distort_random(0.2, tria, true, 7);
    // A refined corner: children are similar to their parents (the same
    // shape in units of their size) but not equal to them.
    tria.begin_active()->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(
        static_cast<unsigned int>(std::floor(cell->center()[dim - 1] / 0.2)));
    const auto plies = three_plies<dim>();

    TiedCopyDoFs<dim> dofs(tria, degree);
    const auto on_ply_interface = [](const auto &cell, const unsigned int f) {
      return !cell->at_boundary(f)
             && cell->neighbor(f)->material_id() != cell->material_id();
    };
    dofs.distribute(on_ply_interface);

    std::vector<typename FaceHoffmanScreen<dim>::Cell> owned;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        owned.push_back(cell);
    check_shared_stiffness(dofs, plies, distorted, what);
    const FaceHoffmanScreen<dim> screen(dofs, plies, owned);
    check(screen.n_cells() == owned.size(),
          what + ": all cells screened",
          __FILE__,
          __LINE__);
    if (!distorted)
      check(screen.n_shapes() <= 6,
            what + ": one matrix per ply and cell size",
            __FILE__,
            __LINE__);
    else
      check(screen.n_shapes() == owned.size(),
            what + ": a matrix per cell",
            __FILE__,
            __LINE__);

    constexpr unsigned int n_faces = GeometryInfo<dim>::faces_per_cell;
    std::mt19937           engine(11 + dim + degree);
    std::uniform_real_distribution<double> factor(0.5, 2.0);
    std::vector<double> scale(tria.n_active_cells() * n_faces);
    for (double &s : scale)
      s = factor(engine);
    std::vector<std::uint8_t> bits(tria.n_active_cells());
    for (auto &b : bits)
      b = static_cast<std::uint8_t>(engine() & ((1u << n_faces) - 1));

    compare(dofs, plies, screen, random_state(dofs, engine), bits, scale, what);

    // Crack insertion: faces inside the middle ply released, a new
    // numbering; the same screen follows the state's new map.
    const auto in_middle = [](const auto &cell, const unsigned int f) {
      return !cell->at_boundary(f) && cell->material_id() == 1
             && cell->neighbor(f)->material_id() == 1
             && std::abs(cell->face(f)->center()[0] - cell->center()[0]) > 1e-3;
    };
    const auto released = [&](const auto &cell, const unsigned int f) {
      return on_ply_interface(cell, f) || in_middle(cell, f);
    };
    std::vector<typename TiedCopyDoFs<dim>::Face> faces;
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      for (unsigned int f = 0; f < n_faces; ++f)
        if (in_middle(cell, f) && cell->id() < cell->neighbor(f)->id())
          faces.emplace_back(cell, f);
    const auto before = dofs.n_dofs();
    dofs.release(faces, released);
    check(dofs.n_dofs() > before,
          what + ": released faces add dofs",
          __FILE__,
          __LINE__);
    compare(dofs,
            plies,
            screen,
            random_state(dofs, engine),
            bits,
            scale,
            what + " released");
  }

  // The kernel gathers n entries of u (scattered, some repeated) and adds
  // n columns of column_length: the result equals a plain loop to
  // round-off, in every entry.
  void
  check_columns_product(const unsigned int n, std::mt19937 &engine)
  {
    std::uniform_real_distribution<double> value(-1, 1);
    std::uniform_int_distribution<int>     index(0, 3 * n);
    std::vector<double>                    A(n * column_length), u(3 * n + 1);
    std::vector<int>                       local(n);
    for (double &a : A)
      a = value(engine);
    for (double &x : u)
      x = value(engine);
    for (int &i : local)
      i = index(engine);
    double y[column_length];
    gathered_columns_product(A.data(), n, local.data(), u.data(), y);
    for (unsigned int r = 0; r < column_length; ++r)
      {
        double expected = 0;
        for (unsigned int i = 0; i < n; ++i)
          expected += A[i * column_length + r] * u[local[i]];
        check_close(y[r],
                    expected,
                    1e-14 * n,
                    "gathered_columns_product, n = " + std::to_string(n)
                      + ", entry " + std::to_string(r),
                    __FILE__,
                    __LINE__);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     engine(7);
  for (const unsigned int n : {5u, 8u, 18u, 24u, 54u, 81u})
    check_columns_product(n, engine);
  for (const bool distorted : {false, true})
    for (const unsigned int degree : {1u, 2u})
      {
        run<2>(degree, distorted);
        run<3>(degree, distorted);
      }
  return amfrac_test::summary();
}
