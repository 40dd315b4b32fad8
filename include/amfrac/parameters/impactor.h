#pragma once

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace amfrac
{
  namespace parameters
  {
    using namespace dealii;

    /** `subsection Impactor`: a rigid sphere or cylinder that touches one face
     * of the laminate through penalty contact (RigidImpactor): free, with a
     * mass and an initial velocity (explicit runs), or prescribed, its centre
     * moving at a constant velocity or along a path (static runs); with
     * Coulomb friction or without. */
    struct Impactor
    {
      bool active = false;
      /** The laminate face it may touch (x-, ..., z+) and its boundary id. */
      std::string  face;
      unsigned int boundary_id = 0;
      double       radius      = 0;
      /** A cylinder along the unit vector axis (in the face's plane), or a
       * sphere (axis zero; always in 2D). */
      bool                cylinder = false;
      std::vector<double> axis;
      double              mass = 0;
      /** Initial centre and velocity (3 components). */
      std::vector<double> center, velocity;
      /** Contact pressure per unit penetration [N/mm^3]. */
      double penalty = 0;
      /** The centre follows Center + Velocity t (static runs), or
       * Center + Path(t). */
      bool prescribed = false;
      /** Path: the centre's displacement from Center as expressions of t
       * (one per component, `;`-separated); empty: Velocity t. */
      std::vector<std::string> path;
      /** Coulomb friction between the sphere and the face nodes, and the
       * stick stiffness over the normal penalty. */
      double friction = 0, tangential_factor = 1;
      /** A free sphere moves along the face's normal only. */
      bool guided = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);

    private:
      /** Normalizes a 3D cylinder's axis and refuses one off the face's
       * plane; zero for a sphere. */
      void
      check_axis(const unsigned int dim);
    };
  } // namespace parameters
} // namespace amfrac
