// A user program built against the installed/exported amfrac package: it
// reads a stacking sequence and prints the ply stiffness of its second ply.
#include <amfrac/geometry/stacking_sequence.h>
#include <amfrac/material/orthotropic.h>
#include <iostream>

int
main()
{
  const auto               plies = amfrac::parse_stacking_sequence("[0/90]s");
  amfrac::ElasticConstants c;
  c.E1 = 135000, c.E2 = c.E3 = 10000, c.G12 = c.G13 = 5000, c.G23 = 3448;
  c.nu12 = c.nu13 = 0.3, c.nu23 = 0.45;
  const auto C = amfrac::rotate(amfrac::stiffness_in_material_axes(c),
                                amfrac::ply_rotation(plies[1].angle));
  std::cout << plies.size()
            << " plies, C_yyyy of the 90-degree ply = " << C[1][1][1][1]
            << std::endl;
  return plies.size() == 4 && C[1][1][1][1] > C[0][0][0][0] ? 0 : 1;
}
