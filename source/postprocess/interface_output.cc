#include <amfrac/postprocess/interface_output.h>
#include <amfrac/postprocess/vtu_series.h>
#include <deal.II/base/utilities.h>

namespace amfrac
{
  namespace
  {
    const char            *scalar_names[] = {"interface",
                                             "status",
                                             "damage",
                                             "opening",
                                             "sliding",
                                             "normal_traction",
                                             "shear_traction"};
    constexpr unsigned int n_scalars      = 7;
  } // namespace



  template <int dim>
  InterfaceOutput<dim>::InterfaceOutput(const parameters::Output &parameters,
                                        const MPI_Comm            comm)
    : parameters(parameters)
    , comm(comm)
  {
    this->set_flags(fast_vtk_flags());
  }



  template <int dim>
  void
  InterfaceOutput<dim>::write(
    const unsigned int                            step,
    const double                                  time,
    const std::vector<InterfacePointRecord<dim>> &points)
  {
    patches.resize(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const auto &p     = points[i];
        auto       &patch = patches[i];
        patch.vertices[0] = p.position;
        patch.patch_index = i;
        patch.data.reinit(n_scalars + dim, 1);
        double sliding = 0, shear = 0;
        for (unsigned int d = 1; d < dim; ++d)
          {
            sliding += p.gap[d] * p.gap[d];
            shear += p.traction[d] * p.traction[d];
          }
        const double values[n_scalars] = {double(p.interface),
                                          double(p.status),
                                          p.damage,
                                          p.gap[0],
                                          std::sqrt(sliding),
                                          p.traction[0],
                                          std::sqrt(shear)};
        for (unsigned int k = 0; k < n_scalars; ++k)
          patch.data(k, 0) = values[k];
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(n_scalars + d, 0) = p.displacement[d];
      }

    write_vtu_step(*this,
                   parameters.directory,
                   parameters.base_name + "-interfaces-"
                     + Utilities::int_to_string(step, 5),
                   parameters.base_name + "-interfaces.pvd",
                   time,
                   pvd_records,
                   comm);
  }



  template <int dim>
  void
  InterfaceOutput<dim>::restore(
    const std::vector<std::pair<double, std::string>> &records)
  {
    pvd_records = records;
    rewrite_pvd(parameters.directory,
                parameters.base_name + "-interfaces.pvd",
                records,
                comm);
  }



  template <int dim>
  const std::vector<DataOutBase::Patch<0, dim>> &
  InterfaceOutput<dim>::get_patches() const
  {
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  InterfaceOutput<dim>::get_dataset_names() const
  {
    std::vector<std::string> names(std::begin(scalar_names),
                                   std::end(scalar_names));
    for (unsigned int d = 0; d < dim; ++d)
      names.emplace_back("displacement");
    return names;
  }



  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  InterfaceOutput<dim>::get_nonscalar_data_ranges() const
  {
    return {std::make_tuple(
      n_scalars,
      n_scalars + dim - 1,
      std::string("displacement"),
      DataComponentInterpretation::component_is_part_of_vector)};
  }

  template class InterfaceOutput<2>;
  template class InterfaceOutput<3>;
} // namespace amfrac
