#pragma once

#include <string>
#include <vector>

namespace amfrac
{
  /** One ply of a laminate: fibre angle (degrees, about the laminate
   * normal) and the name of its material ("" means the first material). */
  struct Ply
  {
    double      angle = 0;
    std::string material;

    bool
    operator==(const Ply &other) const
    {
      return angle == other.angle && material == other.material;
    }
  };

  /**
   * Parse a stacking sequence in the usual laminate notation into a flat
   * list of plies, first ply at the bottom of the laminate (smallest
   * thickness coordinate). Accepted forms, freely combined:
   *  - `[0/90/45/-45]`  plies separated by '/';
   *  - `[0_4/0_16]`     a ply repeated n times;
   *  - `[(0/90)_2]`     a group repeated n times;
   *  - `[±45]`, `[+-45]`, `[-+45]`  an angle pair (+45,-45) or (-45,+45);
   *  - `[0/90]s`, `[0/90]_2s`       whole sequence repeated, then mirrored;
   *  - `[0@glass/90]`   a ply of the named material.
   * Throws std::invalid_argument naming the offending position.
   */
  std::vector<Ply>
  parse_stacking_sequence(const std::string &sequence);
} // namespace amfrac
