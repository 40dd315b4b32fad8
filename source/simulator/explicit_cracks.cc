// Crack insertion in explicit runs (Time integration = explicit with
// Crack insertion = hoffman): the time step bound that holds for any crack
// pattern, and the insertion of every face that fails in a step with the
// state carried to the new numbering.
#include <amfrac/base/mpi_max.h>
#include <amfrac/simulator/simulator.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <sstream>

namespace amfrac
{
  namespace
  {
    /** The impactor's springs on the copies of one cell (a corner of a cell
     * can become a fragment, as the cracks' bound assumes): 2 k_a / m_a
     * with k_a = @p penalty times the integral of N_a over the cell's face
     * on @p boundary_id, m_a the cell's lumped mass (k_a / m_a for a
     * prescribed sphere, which is no unknown: @p coupling 1 instead of 2).
     * Collective. */
    template <int dim, typename ElementMass>
    double
    impactor_copy_frequency_squared(const TiedCopyDoFs<dim> &dofs,
                                    const ElementMass       &element_mass,
                                    const unsigned int       boundary_id,
                                    const double             penalty,
                                    const double             coupling,
                                    const MPI_Comm           comm)
    {
      const auto            &fe = dofs.get_fe();
      FEFaceValues<dim>      face_values(dofs.get_mapping(),
                                    fe,
                                    QGauss<dim - 1>(fe.degree + 1),
                                    update_values | update_JxW_values);
      dealii::Vector<double> mass(fe.n_dofs_per_cell());
      double                 largest = 0;
      for (const auto &cell : dofs.copy_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f)
                && cell->face(f)->boundary_id() == boundary_id)
              {
                face_values.reinit(cell, f);
                element_mass(cell, mass);
                for (const unsigned int a : dofs.dofs_on_face(f))
                  {
                    double area = 0;
                    for (const unsigned int q :
                         face_values.quadrature_point_indices())
                      area
                        += face_values.shape_value(a, q) * face_values.JxW(q);
                    if (mass(a) > 0)
                      largest = std::max(largest,
                                         coupling * penalty * area / mass(a));
                  }
              }
      return Utilities::MPI::max(largest, comm);
    }
  } // namespace



  template <int dim>
  double
  Simulator<dim>::crack_frequency_squared(Point<dim> &where) const
  {
    const auto element_mass
      = [this](const auto &cell, dealii::Vector<double> &mass) {
          assembler.element_lumped_mass(cell, mass);
        };
    const auto may_crack = [this](const auto &cell, const unsigned int f) {
      return crack_candidate(cell, f);
    };
    // Contact between the bodies: BodyContact's rows, 4 (k + k_t) with
    // k = Penalty x area / 2, are the cohesive rows 2 k' area of a penalty
    // k' = (1 + k_t / k) Penalty, on every face a node may be split along.
    const auto  &contact = parameters.contact;
    const double tangent = contact.friction > 0 ? contact.tangential_factor : 0;
    const double penalty = contact.active ? (1 + tangent) * contact.penalty : 0;
    const auto   released = released_faces();
    const double local    = interfaces->crack_frequency_squared(
      dof_layer, element_mass, may_crack, where, penalty, released);
    const double cracks = max_and_where(local, where, comm);
    // A copy on the impactor's face feels its spring besides the cracks'
    // (Gershgorin's rows add; the sum of the two largest bounds them): the
    // normal spring k, or the stick spring k_t = factor k if it is stiffer
    // (a node's contact matrix k n n^T + k_t (I - n n^T) has both as
    // eigenvalues).
    const auto &sphere = parameters.impactor;
    if (!sphere.active)
      return cracks;
    const double stiffest
      = sphere.friction > 0 ? std::max(1., sphere.tangential_factor) : 1.;
    return cracks
           + impactor_copy_frequency_squared(dof_layer,
                                             element_mass,
                                             sphere.boundary_id,
                                             stiffest * sphere.penalty,
                                             sphere.prescribed ? 1. : 2.,
                                             comm);
  }



  template <int dim>
  void
  Simulator<dim>::insert_explicit_cracks(const std::vector<FailingFace> &chosen,
                                         const std::vector<Vector *> &carried)
  {
    for (const FailingFace &face : chosen)
      interfaces->add_crack(face.cell, face.face);
    // The copies keep their values: only the ties change.
    std::vector<dealii::Vector<double>> copies(carried.size());
    for (unsigned int i = 0; i < carried.size(); ++i)
      dof_layer.expand_all(dof_layer.replicate(*carried[i]), copies[i]);
    rebuild_after_mesh_change(true);
    for (unsigned int i = 0; i < carried.size(); ++i)
      {
        carried[i]->reinit(dof_layer.locally_owned_dofs(), comm);
        dof_layer.gather(copies[i], *carried[i]);
      }
    // The first carried vector is the displacement: a new crack starts
    // from its traction, which is also its onset.
    relevant_solution.reinit(dof_layer.locally_owned_dofs(),
                             dof_layer.locally_relevant_dofs(),
                             comm);
    relevant_solution = *carried[0];
    rebuild_crack_elements(relevant_solution, relevant_solution);
  }



  template <int dim>
  void
  Simulator<dim>::log_crack_event(
    const std::vector<std::pair<std::string, double>> &row)
  {
    if (!crack_events)
      crack_events
        = std::make_unique<History>(parameters.output.directory + "/cracks.csv",
                                    Utilities::MPI::this_mpi_process(comm)
                                      == 0);
    crack_events->add_row(row);
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace amfrac
