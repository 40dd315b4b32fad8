#pragma once

#include <amfrac/dofs/tied_copy_dofs.h>
#include <amfrac/material/ply_table.h>
#include <amfrac/parameters/parameters.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /** Strain, stress in model and ply axes, and the Hoffman index, from
   * the displacement gradient and the ply of each cell. With finite
   * strain (total Lagrangian), the strain is the Green-Lagrange strain
   * and the stress the second Piola-Kirchhoff stress, both on the
   * reference configuration's axes (the ply axes turn with the
   * material). */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    StressPostprocessor(const std::vector<PlyProperties<dim>> &plies,
                        const bool                             finite_strain);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<dealii::Vector<double>>        &computed) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

    /** The plastic strain of every active cell (3D, laminate axes; its
     * mean over the cell's quadrature points), taken off the strain for
     * the stresses; empty: none. */
    std::vector<SymmetricTensor<2, 3>> plastic_strain;

  private:
    const std::vector<PlyProperties<dim>> &plies;
    const bool                             finite_strain;
  };



  /**
   * Field output: per step one VTU per rank with a PVTU record and a PVD
   * time series, and/or one HDF5 file with an XDMF record. Every file is
   * written under a temporary name and renamed.
   */
  template <int dim>
  class FieldOutput
  {
  public:
    /** @p finite_strain: the strain and stress of total Lagrangian
     * kinematics (see StressPostprocessor). */
    FieldOutput(const parameters::Output              &parameters,
                const TiedCopyDoFs<dim>               &dofs,
                const std::vector<PlyProperties<dim>> &plies,
                const bool                             finite_strain = false);

    /** @p copy_values: the displacement on the copy layer (owned cells). */
    void
    write(const unsigned int            step,
          const double                  time,
          const dealii::Vector<double> &copy_values);

    /** A per-cell field (one value per active cell) written with every
     * later step until replaced. */
    void
    set_cell_field(const std::string &name, const dealii::Vector<float> &values)
    {
      cell_fields[name] = values;
    }

    /** Forget the per-cell fields (the mesh changed). */
    void
    clear_cell_fields()
    {
      cell_fields.clear();
      postprocessor.plastic_strain.clear();
    }

    /** Plastic plies: the cell means of the plastic strain (3D, laminate
     * axes, every active cell), taken off the strain for the stresses of
     * the following steps. */
    void
    set_plastic_strain(const std::vector<SymmetricTensor<2, 3>> &values)
    {
      postprocessor.plastic_strain = values;
    }

    /** Checkpoint: the VTU series written so far. */
    const std::vector<std::pair<double, std::string>> &
    series() const
    {
      return pvd_records;
    }

    /** Checkpoint: the XDMF entries written so far, serialized. */
    std::string
    xdmf_state() const;

    /** A restart: continue the series from @p records and @p xdmf
     * (series() and xdmf_state() of the checkpoint) and rewrite the PVD
     * and XDMF files with them. Collective. */
    void
    restore(const std::vector<std::pair<double, std::string>> &records,
            const std::string                                 &xdmf);

  private:
    std::map<std::string, dealii::Vector<float>> cell_fields;
    const parameters::Output                    &parameters;
    const TiedCopyDoFs<dim>                     &dofs;
    StressPostprocessor<dim>                     postprocessor;
    std::vector<std::pair<double, std::string>>  pvd_records;
    std::vector<XDMFEntry>                       xdmf_entries;

    std::string
    path(const std::string &name) const;
  };
} // namespace amfrac
