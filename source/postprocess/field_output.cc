#include <amfrac/assembly/displacement_gradients.h>
#include <amfrac/postprocess/atomic_file.h>
#include <amfrac/postprocess/field_output.h>
#include <amfrac/postprocess/vtu_series.h>
#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_out.h>
#include <fstream>
#include <sstream>

namespace amfrac
{
  namespace
  {
    const char *material_axis_names[6]
      = {"sigma_11", "sigma_22", "sigma_33", "tau_23", "tau_13", "tau_12"};
  } // namespace



  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const std::vector<PlyProperties<dim>> &plies,
    const bool                             finite_strain)
    : plies(plies)
    , finite_strain(finite_strain)
  {}



  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names;
    for (const char *pair : voigt_names)
      names.push_back(std::string("strain_") + pair);
    for (const char *pair : voigt_names)
      names.push_back(std::string("stress_") + pair);
    for (const char *name : material_axis_names)
      names.emplace_back(name);
    names.emplace_back("hoffman_index");
    return names;
  }



  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    return std::vector<
      DataComponentInterpretation::DataComponentInterpretation>(
      get_names().size(), DataComponentInterpretation::component_is_scalar);
  }



  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients;
  }



  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<dealii::Vector<double>>        &computed) const
  {
    const auto                   cell = inputs.template get_cell<dim>();
    const auto                  &ply  = plies[cell->material_id()];
    const SymmetricTensor<2, 3> *plastic
      = plastic_strain.empty() ? nullptr :
                                 &plastic_strain[cell->active_cell_index()];
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        Tensor<2, dim> gradient;
        for (unsigned int d = 0; d < dim; ++d)
          gradient[d] = inputs.solution_gradients[q][d];
        const SymmetricTensor<2, dim> strain
          = strain_measure(gradient, finite_strain);
        const PlyStress stress = evaluate_ply_stress(ply, strain, plastic);
        SymmetricTensor<2, 3> strain_3d;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = a; b < dim; ++b)
            strain_3d[a][b] = strain[a][b];
        for (unsigned int k = 0; k < 6; ++k)
          {
            const unsigned int i = voigt_pairs[k][0], j = voigt_pairs[k][1];
            computed[q](k)      = strain_3d[i][j];
            computed[q](6 + k)  = stress.model[i][j];
            computed[q](12 + k) = stress.material[i][j];
          }
        computed[q](18) = stress.hoffman;
      }
  }



  template <int dim>
  FieldOutput<dim>::FieldOutput(const parameters::Output &parameters,
                                const TiedCopyDoFs<dim>  &dofs,
                                const std::vector<PlyProperties<dim>> &plies,
                                const bool finite_strain)
    : parameters(parameters)
    , dofs(dofs)
    , postprocessor(plies, finite_strain)
  {}



  template <int dim>
  std::string
  FieldOutput<dim>::path(const std::string &name) const
  {
    return parameters.directory + "/" + name;
  }



  template <int dim>
  void
  FieldOutput<dim>::write(const unsigned int            step,
                          const double                  time,
                          const dealii::Vector<double> &copy_values)
  {
    const auto    &dof_handler = dofs.copy_handler();
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

    DataOut<dim> data_out;
    data_out.set_flags(fast_vtk_flags());
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      copy_values,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(copy_values, postprocessor);
    dealii::Vector<float> ply(dof_handler.get_triangulation().n_active_cells());
    dealii::Vector<float> owner(ply.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        ply(cell->active_cell_index())   = cell->material_id();
        owner(cell->active_cell_index()) = cell->subdomain_id();
      }
    data_out.add_data_vector(ply, "ply", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(owner, "mpi_rank", DataOut<dim>::type_cell_data);
    for (const auto &[name, values] : cell_fields)
      if (values.size() == ply.size())
        data_out.add_data_vector(values, name, DataOut<dim>::type_cell_data);
    // deal.II 9.4 subdivides hypercube patches only: wedges are written
    // as linear wedges on their vertices (a P2 field shows its vertex
    // values).
    data_out.build_patches(dofs.get_mapping(),
                           dofs.reference_cell().is_hyper_cube() ?
                             dofs.get_fe().degree :
                             1,
                           DataOut<dim>::curved_boundary);

    const std::string stem
      = parameters.base_name + "-" + Utilities::int_to_string(step, 5);
    if (parameters.write_vtu)
      write_vtu_step(data_out,
                     parameters.directory,
                     stem,
                     parameters.base_name + ".pvd",
                     time,
                     pvd_records,
                     comm);
    if (parameters.write_xdmf)
      {
        DataOutBase::DataOutFilter filter(
          DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/false,
                                          /*xdmf_hdf5_output=*/true));
        data_out.write_filtered_data(filter);
        const std::string h5 = stem + ".h5";
        data_out.write_hdf5_parallel(filter, path(h5 + ".tmp"), comm);
        MPI_Barrier(comm);
        if (rank == 0)
          rename_or_throw(path(h5 + ".tmp"), path(h5));
        xdmf_entries.push_back(
          data_out.create_xdmf_entry(filter, h5, time, comm));
        const std::string xdmf = path(parameters.base_name + ".xdmf");
        data_out.write_xdmf_file(xdmf_entries, xdmf + ".tmp", comm);
        if (rank == 0)
          rename_or_throw(xdmf + ".tmp", xdmf);
      }
  }

  template <int dim>
  std::string
  FieldOutput<dim>::xdmf_state() const
  {
    std::ostringstream            text;
    boost::archive::text_oarchive archive(text);
    archive << xdmf_entries;
    return text.str();
  }



  template <int dim>
  void
  FieldOutput<dim>::restore(
    const std::vector<std::pair<double, std::string>> &records,
    const std::string                                 &xdmf)
  {
    const MPI_Comm comm
      = dofs.copy_handler().get_triangulation().get_communicator();
    xdmf_entries.clear();
    if (!xdmf.empty())
      {
        std::istringstream            text(xdmf);
        boost::archive::text_iarchive archive(text);
        archive >> xdmf_entries;
      }
    if (parameters.write_xdmf && !xdmf_entries.empty())
      {
        const std::string name = path(parameters.base_name + ".xdmf");
        DataOut<dim>      data_out;
        data_out.write_xdmf_file(xdmf_entries, name + ".tmp", comm);
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          rename_or_throw(name + ".tmp", name);
      }
    // Rank 0 alone, after the collective XDMF record.
    pvd_records = records;
    if (parameters.write_vtu)
      rewrite_pvd(parameters.directory,
                  parameters.base_name + ".pvd",
                  records,
                  comm);
  }



  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
  template class FieldOutput<2>;
  template class FieldOutput<3>;
} // namespace amfrac
