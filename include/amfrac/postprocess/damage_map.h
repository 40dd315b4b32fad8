#pragma once

#include <amfrac/postprocess/interface_output.h>
#include <string>
#include <vector>

namespace amfrac
{
  /** Write an 8-bit RGB image (@p rgb: rows from the top, 3 bytes per
   * pixel) as a PNG file, atomically. */
  void
  write_png(const std::string                &path,
            const unsigned int                width,
            const unsigned int                height,
            const std::vector<unsigned char> &rgb);

  /**
   * The seed's Figure 7 view: for each cohesive interface of a 3D
   * laminate, a PNG top view (x to the right, y up) of its damage,
   * `<directory>/damage-interface-<k>-<step>.png`: each pixel shows the
   * nearest interface point, white intact, yellow to red softening with
   * the damage, black debonded, blue debonded and in contact. Gathered on
   * rank 0, which writes; returns the file names written. In 2D nothing
   * is written.
   */
  template <int dim>
  std::vector<std::string>
  write_damage_maps(const std::string                            &directory,
                    const unsigned int                            step,
                    const std::vector<InterfacePointRecord<dim>> &points,
                    const MPI_Comm                                comm);
} // namespace amfrac
