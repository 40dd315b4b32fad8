#include <amfrac/material/ply_table.h>

namespace amfrac
{
  template <int dim>
  std::vector<PlyProperties<dim>>
  make_ply_table(const Laminate &laminate, const parameters::Materials &m)
  {
    std::vector<PlyProperties<dim>> table;
    for (unsigned int p = 0; p < laminate.n_plies(); ++p)
      {
        const OrthotropicMaterial &material
          = m.materials[laminate.material_of_ply[p]];
        PlyProperties<dim> ply;
        ply.rotation = ply_rotation(laminate.plies[p].angle);
        ply.stiffness_3d
          = rotate(stiffness_in_material_axes(material.elastic), ply.rotation);
        ply.stiffness = restrict_to_model<dim>(ply.stiffness_3d);
        ply.strengths = material.strengths;
        ply.density   = material.elastic.density;
        table.push_back(ply);
      }
    return table;
  }

  template std::vector<PlyProperties<2>>
  make_ply_table<2>(const Laminate &, const parameters::Materials &);
  template std::vector<PlyProperties<3>>
  make_ply_table<3>(const Laminate &, const parameters::Materials &);
} // namespace amfrac
