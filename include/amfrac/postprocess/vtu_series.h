#pragma once

#include <amfrac/postprocess/atomic_file.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /** VTU flags of all amfrac output: zlib's fastest level (the default,
   * best compression, took 5x longer on the impact scene's fields, for
   * files 3 % smaller). */
  inline dealii::DataOutBase::VtkFlags
  fast_vtk_flags()
  {
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    return flags;
  }

  /** Rank 0 rewrites the PVD series @p pvd_name in @p directory with
   * @p records (a restart drops the steps after its checkpoint). */
  inline void
  rewrite_pvd(const std::string                                 &directory,
              const std::string                                 &pvd_name,
              const std::vector<std::pair<double, std::string>> &records,
              const MPI_Comm                                     comm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0 || records.empty())
      return;
    write_atomically(directory + "/" + pvd_name, [&](std::ostream &o) {
      dealii::DataOutBase::write_pvd_record(o, records);
    });
  }

  /**
   * One step of a VTU time series: every rank writes its piece
   * `<stem>.<rank>.vtu` of @p out into @p directory, then rank 0 writes the
   * PVTU record `<stem>.pvtu` and the PVD series @p pvd_name with
   * (@p time, `<stem>.pvtu`) appended to @p records. Every file is written
   * atomically; @p records changes only once the PVD file is written.
   * Collective.
   */
  template <int dim, int spacedim>
  void
  write_vtu_step(const dealii::DataOutInterface<dim, spacedim> &out,
                 const std::string                             &directory,
                 const std::string                             &stem,
                 const std::string                             &pvd_name,
                 const double                                   time,
                 std::vector<std::pair<double, std::string>>   &records,
                 const MPI_Comm                                 comm)
  {
    using dealii::Utilities::int_to_string;
    const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
    const auto         piece = [&](const unsigned int r) {
      return stem + "." + int_to_string(r, 4) + ".vtu";
    };
    write_atomically(directory + "/" + piece(rank),
                     [&](std::ostream &o) { out.write_vtu(o); });
    MPI_Barrier(comm);
    if (rank != 0)
      return;
    std::vector<std::string> pieces;
    for (unsigned int r = 0; r < dealii::Utilities::MPI::n_mpi_processes(comm);
         ++r)
      pieces.push_back(piece(r));
    write_atomically(directory + "/" + stem + ".pvtu", [&](std::ostream &o) {
      out.write_pvtu_record(o, pieces);
    });
    auto extended = records;
    extended.emplace_back(time, stem + ".pvtu");
    write_atomically(directory + "/" + pvd_name, [&](std::ostream &o) {
      dealii::DataOutBase::write_pvd_record(o, extended);
    });
    records = extended;
  }
} // namespace amfrac
