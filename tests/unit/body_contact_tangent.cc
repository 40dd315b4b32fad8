// The static tangent of contact between two bodies against central
// differences of the contact forces: two unit blocks of 2 x 2 x 1 cells
// (2D: 2 x 1) stacked across an unbonded face, the upper one pushed into
// the lower one by `push` and moved sideways by 1 % of a cell (so that its
// nodes project just inside the lower block's faces, and those on its
// outer edge just past them: clamped projections), every node displaced
// at random by 1e-4 (warped faces), in a random direction d.
// add_tangent_product() and add_tangent() (into the couplings of
// add_couplings()) agree with each other to round-off, and with the
// differences to 1e-8 of |K d| at push = 3e-4 mm (6e-4 of a cell) and at
// ten times that (measured: at most 1.3e-9): the tangent is the full
// linearization (the closest point moves with the nodes, the normal with
// the nodes and the closest point, the penalty k = -(A . n) with the
// normal). Each of those terms left out gives an error of 2e-7 (the
// normal's turning with the closest point on faces warped by 1e-4) to
// 2e-2 here. With friction (mu = 0.3, static: the history committed at the
// pressed state), the upper block then slid by 1e-5 mm (every node sticks)
// or 1e-3 mm (every node slips): 1e-8 too.
#include "../check.h"

#include <amfrac/contact/body_contact.h>
#include <amfrac/dofs/tied_copy_dofs.h>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <random>

using namespace amfrac;
using TrilinosVector = TrilinosWrappers::MPI::Vector;

namespace
{
  /** The residual's share of the contact at @p u: minus its forces. */
  template <int dim>
  TrilinosVector
  residual(BodyContact<dim> &contact, const TrilinosVector &u)
  {
    TrilinosVector force(u);
    contact.evaluate(u, force);
    force *= -1;
    return force;
  }

  /** |K d - FD| / |K d| at a penetration @p push. With @p slide >= 0:
   * friction (mu = 0.3, static), the history committed at the pressed
   * state, then the upper block moved along x by @p slide; @p slipping
   * tells whether every node in contact slips (friction = mu N). */
  template <int dim>
  double
  tangent_error(const double push,
                const double slide    = -1,
                bool        *slipping = nullptr)
  {
    Triangulation<dim>        tria;
    std::vector<unsigned int> cells(dim, 2);
    cells[dim - 1] = 2;
    Point<dim> top;
    for (unsigned int d = 0; d < dim; ++d)
      top[d] = d == dim - 1 ? 2 : 1;
    GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), top);
    TiedCopyDoFs<dim> dofs(tria, 1);
    // The faces at the middle height are released: two bodies.
    const auto released = [](const auto &cell, const unsigned int f) {
      return !cell->at_boundary(f)
             && std::abs(cell->face(f)->center()[dim - 1] - 1) < 1e-12;
    };
    dofs.distribute(released);
    parameters::Contact p;
    p.active            = true;
    p.penalty           = 1e3;
    p.friction          = slide >= 0 ? 0.3 : 0;
    p.tangential_factor = 1;
    BodyContact<dim> contact(p, MPI_COMM_WORLD);
    if (slide >= 0)
      contact.set_static();
    contact.setup(dofs, released, {});

    const IndexSet &owned = dofs.locally_owned_dofs();
    TrilinosVector  u(owned, MPI_COMM_WORLD), d(owned, MPI_COMM_WORLD);
    std::mt19937    random(7);
    std::uniform_real_distribution<double> small(-1e-4, 1e-4), unit(-1, 1);
    // The upper block moves down into the lower one and sideways by 1 %
    // of a cell (the nodes leave the other block's vertices).
    std::vector<bool>                    upper(dofs.n_dofs(), false);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.copy_handler().active_cell_iterators())
      if (cell->center()[dim - 1] > 1)
        {
          dofs.get_dof_indices(cell, indices);
          for (const auto i : indices)
            upper[i] = true;
        }
    for (const auto i : owned)
      {
        const unsigned int component = dofs.component(i);
        // One write per entry: a Trilinos vector takes inserts or adds
        // between compresses, not both.
        double value = small(random);
        if (upper[i] && component == dim - 1)
          value -= push;
        if (upper[i] && component < dim - 1)
          value += 0.005;
        u(i) = value;
        d(i) = unit(random);
      }
    u.compress(VectorOperation::insert);
    d.compress(VectorOperation::insert);
    if (slide >= 0)
      {
        // The friction history of the pressed state, then the slide.
        TrilinosVector force(u), shift(owned, MPI_COMM_WORLD);
        contact.evaluate(u, force);
        contact.commit();
        for (const auto i : owned)
          if (upper[i] && dofs.component(i) == 0)
            shift(i) = slide;
        shift.compress(VectorOperation::insert);
        u += shift;
      }

    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    contact.add_couplings(u, pattern);
    pattern.compress();
    const TrilinosVector base    = residual(contact, u);
    const auto           columns = contact.columns();
    const double friction = columns[2].second, normal = columns[1].second;
    std::cout << dim << "D: " << columns[0].second << " nodes in contact";
    if (slide >= 0)
      std::cout << ", friction / (mu N) " << friction / (0.3 * normal);
    std::cout << std::endl;
    CHECK(columns[0].second >= (dim == 3 ? 9 : 3));
    if (slipping)
      *slipping = std::abs(friction / (0.3 * normal) - 1) < 1e-12;

    TrilinosWrappers::SparseMatrix matrix(pattern);
    AffineConstraints<double>      none;
    none.close();
    contact.add_tangent(none, matrix);
    matrix.compress(VectorOperation::add);
    TrilinosVector product(owned, MPI_COMM_WORLD);
    contact.add_tangent_product(d, product);
    TrilinosVector assembled(owned, MPI_COMM_WORLD);
    matrix.vmult(assembled, d);

    const double   eps = 1e-7;
    TrilinosVector plus(u), minus(u);
    plus.add(eps, d);
    minus.add(-eps, d);
    TrilinosVector difference = residual(contact, plus);
    difference -= residual(contact, minus);
    difference /= 2 * eps;

    TrilinosVector error = product;
    error -= difference;
    TrilinosVector mismatch = assembled;
    mismatch -= product;
    std::cout << "  |K d| " << product.l2_norm() << ", |K d - FD| "
              << error.l2_norm() << ", |assembled - product| "
              << mismatch.l2_norm() << std::endl;
    CHECK(product.l2_norm() > 0);
    CHECK(mismatch.l2_norm() < 1e-12 * product.l2_norm());
    return error.l2_norm() / product.l2_norm();
  }

  template <int dim>
  void
  check_tangent()
  {
    const double near = tangent_error<dim>(3e-4),
                 far  = tangent_error<dim>(3e-3);
    std::cout << "  relative error " << near << " at push 3e-4, " << far
              << " at 3e-3" << std::endl;
    CHECK(near < 1e-8);
    CHECK(far < 1e-8);
    // Friction: sticking (a slide of a tenth of mu g, the stick springs'
    // reach) and slipping (ten times mu g).
    bool         stick_slips = true, slip_slips = false;
    const double stick = tangent_error<dim>(3e-4, 1e-5, &stick_slips),
                 slip  = tangent_error<dim>(3e-4, 1e-3, &slip_slips);
    std::cout << "  with friction: relative error " << stick << " sticking, "
              << slip << " slipping" << std::endl;
    CHECK(!stick_slips && slip_slips);
    CHECK(stick < 1e-8);
    CHECK(slip < 1e-8);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_tangent<2>();
  check_tangent<3>();
  return amfrac_test::summary();
}
