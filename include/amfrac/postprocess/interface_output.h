#pragma once

#include <amfrac/parameters/parameters.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace amfrac
{
  using namespace dealii;

  /** The state of one cohesive interface point, for output. */
  template <int dim>
  struct InterfacePointRecord
  {
    /** Status codes of the `status` field. */
    enum Status : unsigned char
    {
      intact    = 0, ///< no damage
      softening = 1, ///< damaged, still bonded
      debonded  = 2, ///< no bond left, faces apart
      contact   = 3  ///< no bond left, faces pressed together
    };

    /** The interface field of a point on a crack inserted inside a ply
     * (Crack insertion). */
    static constexpr unsigned int crack = 1000000;

    Point<dim>     position;     ///< reference configuration
    Tensor<1, dim> displacement; ///< mean of the two faces
    /** Interface index k (plies k, k+1), or crack. */
    unsigned int   interface;
    double         damage;   ///< 0 intact .. 1 debonded
    Tensor<1, dim> gap;      ///< local frame: opening, sliding
    Tensor<1, dim> traction; ///< local frame: normal, shear
    Status         status;
  };

  /**
   * The interface points as a VTU point cloud per output step (one piece
   * per rank, a PVTU record and a PVD series `<base>-interfaces.pvd`), with
   * the fields interface, status (0 intact, 1 softening, 2 debonded, 3 in
   * contact), damage, opening, sliding, normal_traction, shear_traction and
   * the vector displacement (ParaView: Warp By Vector, Point Gaussian).
   */
  template <int dim>
  class InterfaceOutput : public DataOutInterface<0, dim>
  {
  public:
    InterfaceOutput(const parameters::Output &parameters, const MPI_Comm comm);

    void
    write(const unsigned int                            step,
          const double                                  time,
          const std::vector<InterfacePointRecord<dim>> &points);

    /** Checkpoint: the series written so far. */
    const std::vector<std::pair<double, std::string>> &
    series() const
    {
      return pvd_records;
    }

    /** A restart: continue the series from @p records and rewrite the
     * PVD file with them. */
    void
    restore(const std::vector<std::pair<double, std::string>> &records);

  private:
    const parameters::Output                   &parameters;
    const MPI_Comm                              comm;
    std::vector<DataOutBase::Patch<0, dim>>     patches;
    std::vector<std::pair<double, std::string>> pvd_records;

    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;
  };
} // namespace amfrac
